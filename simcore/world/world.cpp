#include "simcore/world/world.h"

#include "simcore/dynamics/integrator.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace simcore {

namespace {

void require(bool condition, const std::string& what) {
    if (!condition) throw std::invalid_argument(what);
}

bool isPositiveFinite(float v) { return isFinite(v) && v > 0.0f; }

void validateShape(const Shape& shape) {
    switch (shape.type) {
        case ShapeType::Sphere:
            require(isPositiveFinite(shape.radius), "shape.radius must be a positive finite number");
            break;
        case ShapeType::Box:
            require(isPositiveFinite(shape.halfExtents.x) && isPositiveFinite(shape.halfExtents.y) &&
                        isPositiveFinite(shape.halfExtents.z),
                    "shape.halfExtents must be positive finite numbers");
            break;
        case ShapeType::Capsule:
        case ShapeType::Cylinder:
            require(isPositiveFinite(shape.radius), "shape.radius must be a positive finite number");
            require(isPositiveFinite(shape.halfHeight), "shape.halfHeight must be a positive finite number");
            break;
        case ShapeType::ConvexHull:
            require(shape.hull != nullptr, "shape.hull is missing");
            break;
    }
}

void validateBody(const BodyCreationSettings& s) {
    validateShape(s.shape);
    require(isFinite(s.position), "position must be finite");
    require(isFinite(s.orientation) && glm::length(s.orientation) > 1e-6f,
            "orientation must be a finite, non-zero quaternion");
    require(isFinite(s.linearVelocity), "linearVelocity must be finite");
    require(isFinite(s.angularVelocity), "angularVelocity must be finite");
    if (s.mass) require(isPositiveFinite(*s.mass), "mass must be a positive finite number");
    require(isPositiveFinite(s.density), "density must be a positive finite number");
    require(isFinite(s.friction) && s.friction >= 0.0f, "friction must be finite and >= 0");
    require(isFinite(s.restitution) && s.restitution >= 0.0f && s.restitution <= 1.0f,
            "restitution must be in [0, 1]");
}

void validateSettings(const WorldSettings& s) {
    require(isFinite(s.gravity), "gravity must be finite");
    require(isPositiveFinite(s.timeStep), "timeStep must be a positive finite number");
    require(s.substeps >= 1, "substeps must be at least 1");
    require(s.solver.velocityIterations >= 0, "solver.velocityIterations must be >= 0");
    require(s.solver.positionIterations >= 0, "solver.positionIterations must be >= 0");
    require(isFinite(s.damping.linear) && s.damping.linear >= 0.0f, "damping.linear must be finite and >= 0");
    require(isFinite(s.damping.angular) && s.damping.angular >= 0.0f, "damping.angular must be finite and >= 0");
    require(isFinite(s.sleep.linearVelocity) && s.sleep.linearVelocity >= 0.0f,
            "sleep.linearVelocity must be finite and >= 0");
    require(isFinite(s.sleep.angularVelocity) && s.sleep.angularVelocity >= 0.0f,
            "sleep.angularVelocity must be finite and >= 0");
    require(isFinite(s.sleep.timeToSleep) && s.sleep.timeToSleep >= 0.0f,
            "sleep.timeToSleep must be finite and >= 0");
}

}  // namespace

World::World(const WorldSettings& settings) { setSettings(settings); }

void World::setSettings(const WorldSettings& settings) {
    validateSettings(settings);
    settings_ = settings;
    if (!settings_.effects[Effect::Sleeping] || !settings_.sleep.enabled) {
        for (std::size_t i = 0; i < bodies_.size(); ++i) {
            if (bodies_.motion[i] != MotionType::Static) bodies_.awake[i] = 1;
        }
    }
}

BodyId World::createBody(const BodyCreationSettings& settings) {
    validateBody(settings);
    MassProperties massProperties;
    if (settings.motion == MotionType::Dynamic) {
        massProperties = settings.mass ? massPropertiesForMass(settings.shape, *settings.mass)
                                       : simcore::massProperties(settings.shape, settings.density);
        require(isPositiveFinite(massProperties.mass), "the shape's mass is not a positive finite number");
    } else {
        // Static and kinematic bodies have infinite mass; only the centre of mass matters (as
        // the integrated point of a kinematic body).
        massProperties.centerOfMass = simcore::massProperties(settings.shape, 1.0f).centerOfMass;
    }
    return bodies_.add(settings, massProperties);
}

void World::destroyBody(BodyId id) { bodies_.remove(bodyIdChecked(id)); }

std::vector<BodyId> World::bodyIds() const {
    std::vector<BodyId> ids;
    ids.reserve(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) ids.push_back(bodies_.idAt(i));
    return ids;
}

World::Activity World::scanActivity() const {
    Activity activity;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (bodies_.motion[i] != MotionType::Dynamic || !bodies_.awake[i]) continue;
        activity.anyAwakeDynamic = true;
        if (lengthSquared(bodies_.angularVelocity[i]) > 0.0f) {
            activity.anySpinning = true;
            break;  // nothing more to learn
        }
    }
    return activity;
}

// An effect runs when the settings enable it and something in the world would be affected.
bool World::needs(Effect effect, const Activity& activity) const {
    if (!settings_.effects[effect]) return false;
    switch (effect) {
        case Effect::Gravity: return activity.anyAwakeDynamic && lengthSquared(settings_.gravity) > 0.0f;
        case Effect::Damping:
            return activity.anyAwakeDynamic && (settings_.damping.linear > 0.0f || settings_.damping.angular > 0.0f);
        case Effect::Gyroscopic: return activity.anySpinning;
        case Effect::Sleeping: return settings_.sleep.enabled && activity.anyAwakeDynamic;
        // The contact pipeline, joints and continuous collision are not part of the engine yet,
        // so nothing can need them.
        case Effect::Contacts:
        case Effect::Friction:
        case Effect::Restitution:
        case Effect::Joints:
        case Effect::Ccd:
        case Effect::Count: return false;
    }
    return false;
}

// One step, in order of execution:
//   for each substep of h = timeStep / substeps:
//     1. integrate velocities: gravity, external forces, gyroscopic torque, damping
//     2. integrate positions: centres of mass and orientations from the new velocities
//   3. sleep: bodies that stayed slow long enough stop being simulated
void World::step() {
    const auto stepStart = std::chrono::steady_clock::now();
    StepProfile profile;
    auto& ms = profile.stageMs;

    const Activity activity = scanActivity();
    const bool gravity = needs(Effect::Gravity, activity);
    const bool damping = needs(Effect::Damping, activity);
    const bool gyroscopic = needs(Effect::Gyroscopic, activity);
    const bool sleeping = needs(Effect::Sleeping, activity);

    const float h = settings_.timeStep / static_cast<float>(settings_.substeps);
    VelocityIntegration velocityParams;
    velocityParams.gravity = gravity ? settings_.gravity : Vec3(0.0f);
    velocityParams.gyroscopic = gyroscopic;
    if (damping) {
        velocityParams.linearRetention = std::exp(-settings_.damping.linear * h);
        velocityParams.angularRetention = std::exp(-settings_.damping.angular * h);
    }

    for (int substep = 0; substep < settings_.substeps; ++substep) {
        {
            ScopedStageTimer timer(ms[static_cast<int>(Stage::IntegrateVelocities)]);
            integrateVelocities(bodies_, velocityParams, h);
        }
        {
            ScopedStageTimer timer(ms[static_cast<int>(Stage::IntegratePositions)]);
            integratePositions(bodies_, h);
        }
    }
    if (sleeping) {
        ScopedStageTimer timer(ms[static_cast<int>(Stage::Sleep)]);
        updateSleep(settings_.timeStep);
    }

    if (gravity) countEffect(Effect::Gravity);
    if (damping) countEffect(Effect::Damping);
    if (gyroscopic) countEffect(Effect::Gyroscopic);
    if (sleeping) countEffect(Effect::Sleeping);

    StepCounters& counters = profile.counters;
    counters.bodies = static_cast<std::uint32_t>(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (bodies_.motion[i] == MotionType::Dynamic) ++counters.dynamicBodies;
        if (bodies_.awake[i]) ++counters.awakeBodies;
    }

    ++stepCount_;
    simulatedTime_ += settings_.timeStep;
    profile.totalMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - stepStart).count();
    lastProfile_ = profile;
}

void World::updateSleep(float dt) {
    const float linear2 = settings_.sleep.linearVelocity * settings_.sleep.linearVelocity;
    const float angular2 = settings_.sleep.angularVelocity * settings_.sleep.angularVelocity;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (bodies_.motion[i] != MotionType::Dynamic || !bodies_.awake[i]) continue;
        const bool slow = lengthSquared(bodies_.linearVelocity[i]) <= linear2 &&
                          lengthSquared(bodies_.angularVelocity[i]) <= angular2;
        bodies_.sleepTime[i] = slow ? bodies_.sleepTime[i] + dt : 0.0f;
        if (bodies_.sleepTime[i] >= settings_.sleep.timeToSleep) {
            bodies_.awake[i] = 0;
            bodies_.linearVelocity[i] = Vec3(0.0f);
            bodies_.angularVelocity[i] = Vec3(0.0f);
        }
    }
}

std::size_t World::indexOf(BodyId id) const {
    const int i = bodies_.denseIndex(id);
    if (i < 0) throw std::out_of_range("stale or invalid body id");
    return static_cast<std::size_t>(i);
}

BodyId World::bodyIdChecked(BodyId id) const {
    indexOf(id);
    return id;
}

Vec3 World::position(BodyId id) const { return bodies_.origin(indexOf(id)); }
Quat World::orientation(BodyId id) const { return bodies_.orientation[indexOf(id)]; }
Vec3 World::centerOfMass(BodyId id) const { return bodies_.centerOfMass[indexOf(id)]; }
Vec3 World::linearVelocity(BodyId id) const { return bodies_.linearVelocity[indexOf(id)]; }
Vec3 World::angularVelocity(BodyId id) const { return bodies_.angularVelocity[indexOf(id)]; }
bool World::isAwake(BodyId id) const { return bodies_.awake[indexOf(id)] != 0; }
const std::string& World::name(BodyId id) const { return bodies_.name[indexOf(id)]; }
const Shape& World::shape(BodyId id) const { return bodies_.shape[indexOf(id)]; }
MotionType World::motionType(BodyId id) const { return bodies_.motion[indexOf(id)]; }
float World::mass(BodyId id) const { return bodies_.mass[indexOf(id)]; }

void World::setTransform(BodyId id, const Vec3& position, const Quat& orientation) {
    const std::size_t i = indexOf(id);
    require(isFinite(position), "position must be finite");
    require(isFinite(orientation) && glm::length(orientation) > 1e-6f,
            "orientation must be a finite, non-zero quaternion");
    bodies_.orientation[i] = glm::normalize(orientation);
    bodies_.centerOfMass[i] = position + bodies_.orientation[i] * bodies_.localCenterOfMass[i];
    bodies_.refreshInverseInertiaWorld(i);
    wakeIndex(i);
}

void World::setLinearVelocity(BodyId id, const Vec3& velocity) {
    const std::size_t i = indexOf(id);
    require(isFinite(velocity), "linearVelocity must be finite");
    if (bodies_.motion[i] == MotionType::Static) return;
    bodies_.linearVelocity[i] = velocity;
    wakeIndex(i);
}

void World::setAngularVelocity(BodyId id, const Vec3& velocity) {
    const std::size_t i = indexOf(id);
    require(isFinite(velocity), "angularVelocity must be finite");
    if (bodies_.motion[i] == MotionType::Static) return;
    bodies_.angularVelocity[i] = velocity;
    wakeIndex(i);
}

void World::addForce(BodyId id, const Vec3& force) {
    const std::size_t i = indexOf(id);
    require(isFinite(force), "force must be finite");
    if (bodies_.motion[i] != MotionType::Dynamic) return;
    bodies_.force[i] += force;
    wakeIndex(i);
}

void World::addTorque(BodyId id, const Vec3& torque) {
    const std::size_t i = indexOf(id);
    require(isFinite(torque), "torque must be finite");
    if (bodies_.motion[i] != MotionType::Dynamic) return;
    bodies_.torque[i] += torque;
    wakeIndex(i);
}

void World::addImpulse(BodyId id, const Vec3& impulse, const Vec3& worldPoint) {
    const std::size_t i = indexOf(id);
    require(isFinite(impulse) && isFinite(worldPoint), "impulse and point must be finite");
    if (bodies_.motion[i] != MotionType::Dynamic) return;
    bodies_.linearVelocity[i] += bodies_.inverseMass[i] * impulse;
    bodies_.angularVelocity[i] +=
        bodies_.inverseInertiaWorld[i] * glm::cross(worldPoint - bodies_.centerOfMass[i], impulse);
    wakeIndex(i);
}

void World::wake(BodyId id) { wakeIndex(indexOf(id)); }

void World::wakeIndex(std::size_t i) {
    if (bodies_.motion[i] == MotionType::Static) return;
    bodies_.awake[i] = 1;
    bodies_.sleepTime[i] = 0.0f;
}

double World::kineticEnergy() const {
    double energy = 0.0;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (bodies_.motion[i] != MotionType::Dynamic) continue;
        const Vec3& v = bodies_.linearVelocity[i];
        const Vec3& w = bodies_.angularVelocity[i];
        const Mat3 r = glm::mat3_cast(bodies_.orientation[i]);
        const Vec3 wLocal = glm::transpose(r) * w;
        energy += 0.5 * bodies_.mass[i] * glm::dot(v, v) +
                  0.5 * glm::dot(wLocal, bodies_.inertiaLocal[i] * wLocal);
    }
    return energy;
}

double World::potentialEnergy() const {
    double energy = 0.0;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (bodies_.motion[i] != MotionType::Dynamic) continue;
        energy -= static_cast<double>(bodies_.mass[i]) * glm::dot(settings_.gravity, bodies_.centerOfMass[i]);
    }
    return energy;
}

Vec3 World::linearMomentum() const {
    Vec3 p(0.0f);
    for (std::size_t i = 0; i < bodies_.size(); ++i) p += bodies_.mass[i] * bodies_.linearVelocity[i];
    return p;
}

Vec3 World::angularMomentum() const {
    Vec3 l(0.0f);
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (bodies_.motion[i] != MotionType::Dynamic) continue;
        const Mat3 r = glm::mat3_cast(bodies_.orientation[i]);
        const Vec3 spin = r * (bodies_.inertiaLocal[i] * (glm::transpose(r) * bodies_.angularVelocity[i]));
        l += glm::cross(bodies_.centerOfMass[i], bodies_.mass[i] * bodies_.linearVelocity[i]) + spin;
    }
    return l;
}

std::optional<NonFiniteBody> World::findNonFiniteBody() const {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        const char* quantity = nullptr;
        if (!isFinite(bodies_.centerOfMass[i])) quantity = "position";
        else if (!isFinite(bodies_.orientation[i])) quantity = "orientation";
        else if (!isFinite(bodies_.linearVelocity[i])) quantity = "linearVelocity";
        else if (!isFinite(bodies_.angularVelocity[i])) quantity = "angularVelocity";
        if (quantity) return NonFiniteBody{bodies_.idAt(i), bodies_.name[i], quantity};
    }
    return std::nullopt;
}

}  // namespace simcore
