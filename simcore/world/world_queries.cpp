// Read-only questions to the world: body and joint state, contacts, energies, ray casts.

#include "simcore/world/world.h"

#include "simcore/collision/ray_cast.h"

#include <algorithm>

namespace simcore {

std::vector<JointId> World::jointIds() const {
    std::vector<JointId> ids;
    ids.reserve(joints_.size());
    for (std::size_t i = 0; i < joints_.size(); ++i) ids.push_back(joints_.idAt(i));
    return ids;
}

JointType World::jointType(JointId id) const { return joints_.joints[indexOf(id)].type; }
BodyId World::jointBodyA(JointId id) const { return joints_.joints[indexOf(id)].bodyA; }
BodyId World::jointBodyB(JointId id) const { return joints_.joints[indexOf(id)].bodyB; }
const std::string& World::jointName(JointId id) const { return joints_.names[indexOf(id)]; }
JointError World::jointError(JointId id) const { return joints_.error(indexOf(id), bodies_); }

JointError World::worstJointError() const {
    JointError worst;
    for (std::size_t i = 0; i < joints_.size(); ++i) {
        const JointError e = joints_.error(i, bodies_);
        worst.position = std::max(worst.position, e.position);
        worst.angle = std::max(worst.angle, e.angle);
    }
    return worst;
}

std::vector<BodyId> World::bodyIds() const {
    std::vector<BodyId> ids;
    ids.reserve(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) ids.push_back(bodies_.idAt(i));
    return ids;
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

float World::friction(BodyId id) const { return bodies_.friction[indexOf(id)]; }
float World::restitution(BodyId id) const { return bodies_.restitution[indexOf(id)]; }
float World::rollingResistance(BodyId id) const { return bodies_.rollingResistance[indexOf(id)]; }
bool World::ccdEnabled(BodyId id) const { return bodies_.ccd[indexOf(id)] != 0; }
float World::density(BodyId id) const { return bodies_.density[indexOf(id)]; }
Mat3 World::localInertia(BodyId id) const { return bodies_.inertiaLocal[indexOf(id)]; }

const std::optional<JointLimits>& World::jointLimits(JointId id) const { return joints_.joints[indexOf(id)].limits; }
const std::optional<JointMotor>& World::jointMotor(JointId id) const { return joints_.joints[indexOf(id)].motor; }
const std::optional<JointSpring>& World::jointSpring(JointId id) const { return joints_.joints[indexOf(id)].spring; }
bool World::jointCollidesConnected(JointId id) const { return joints_.joints[indexOf(id)].collideConnected; }
Vec3 World::jointLocalAnchorA(JointId id) const { return joints_.joints[indexOf(id)].localAnchorA; }
Vec3 World::jointLocalAnchorB(JointId id) const { return joints_.joints[indexOf(id)].localAnchorB; }

DistanceLengths World::jointLengths(JointId id) const {
    const Joint& joint = joints_.joints[indexOf(id)];
    return {joint.restLength, joint.minLength, joint.maxLength};
}

ContactInfo World::contact(std::size_t index) const {
    const Contact& c = contactManager_.contacts().at(index);
    ContactInfo info;
    info.bodyA = bodies_.idAt(bodies_.denseIndexOfSlot(c.slotA));
    info.bodyB = bodies_.idAt(bodies_.denseIndexOfSlot(c.slotB));
    info.subShapeA = c.subShapeA;
    info.subShapeB = c.subShapeB;
    info.friction = c.friction;
    info.restitution = c.restitution;
    if (!c.hasPoints()) return info;
    const ManifoldRecord& record = contactManager_.manifoldOf(c);
    info.normal = record.manifold.normal;
    info.pointCount = record.manifold.pointCount;
    info.points = record.manifold.points;
    for (int k = 0; k < kMaxManifoldPoints; ++k) info.normalImpulses[k] = record.impulses[k].normal;
    info.frictionImpulse = record.frictionImpulse.linear;
    return info;
}

ContactLoad World::contactLoad(BodyId id) const {
    indexOf(id);  // throws for a stale id
    const std::uint32_t slot = id.index;
    float impulse = 0.0f;  // N s
    ContactLoad load;
    for (const Contact& c : contactManager_.contacts()) {
        if ((c.slotA != slot && c.slotB != slot) || !c.hasPoints()) continue;
        ++load.contacts;
        const ManifoldRecord& record = contactManager_.manifoldOf(c);
        for (int k = 0; k < record.manifold.pointCount; ++k) impulse += record.impulses[k].normal;
    }
    load.normalForce = impulse * static_cast<float>(settings_.substeps) / settings_.timeStep;
    return load;
}

double World::kineticEnergyAt(std::size_t i) const {
    if (bodies_.motion[i] != MotionType::Dynamic) return 0.0;
    const Vec3& v = bodies_.linearVelocity[i];
    const Vec3& w = bodies_.angularVelocity[i];
    const Mat3 r = glm::mat3_cast(bodies_.orientation[i]);
    const Vec3 wLocal = glm::transpose(r) * w;
    return 0.5 * bodies_.mass[i] * glm::dot(v, v) + 0.5 * glm::dot(wLocal, bodies_.inertiaLocal[i] * wLocal);
}

double World::kineticEnergy(BodyId id) const { return kineticEnergyAt(indexOf(id)); }

double World::kineticEnergy() const {
    double energy = 0.0;
    for (std::size_t i = 0; i < bodies_.size(); ++i) energy += kineticEnergyAt(i);
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

std::optional<WorldRayHit> World::castRay(const Vec3& origin, const Vec3& direction, float maxFraction) const {
    std::optional<WorldRayHit> closest;
    const RayCastInput ray{origin, direction, maxFraction};
    auto testBody = [&](std::size_t i, float currentMax) {
        const RayCastInput clipped{ray.origin, ray.direction, currentMax};
        if (const auto hit = rayCastShape(bodies_.shape[i], bodies_.transform(i), clipped)) {
            closest = WorldRayHit{bodies_.idAt(i), hit->fraction, hit->point, hit->normal, hit->subShape};
            return hit->fraction;
        }
        return currentMax;
    };
    if (proxiesStale_) {
        // The broad phase has not followed the bodies (contacts are off): test every body.
        float currentMax = maxFraction;
        for (std::size_t i = 0; i < bodies_.size(); ++i) currentMax = testBody(i, currentMax);
    } else {
        broadPhase_.tree().rayCast(origin, direction, maxFraction, [&](ProxyId proxy, float currentMax) {
            return testBody(bodies_.denseIndexOfSlot(broadPhase_.userData(proxy)), currentMax);
        });
    }
    return closest;
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
