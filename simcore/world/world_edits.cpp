// Changes to live bodies and joints: poses, velocities, forces, and the setters of what a body or
// joint is (Box2D v3's b2Body_Set* and b2Joint_Set*). Each checks its value as creation does.

#include "simcore/world/world.h"

#include "simcore/world/validation.h"

#include <string>

namespace simcore {

using namespace validation;

// ---- Poses, velocities and forces ------------------------------------------------------------------

void World::setTransform(BodyId id, const Vec3& position, const Quat& orientation) {
    const std::size_t i = indexOf(id);
    require(isFinite(position), "position must be finite");
    require(isFinite(orientation) && glm::length(orientation) > 1e-6f,
            "orientation must be a finite, non-zero quaternion");
    bodies_.orientation[i] = glm::normalize(orientation);
    bodies_.centerOfMass[i] = position + bodies_.orientation[i] * bodies_.localCenterOfMass[i];
    bodies_.refreshInverseInertiaWorld(i);
    bodies_.bounds[i] = worldBounds(bodies_.shape[i], bodies_.transform(i));
    broadPhase_.moveProxy(bodies_.proxy[i], bodies_.bounds[i], Vec3(0.0f));
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

// ---- What a body is -------------------------------------------------------------------------------

void World::setMotionType(BodyId id, MotionType motion) {
    const std::size_t i = indexOf(id);
    if (bodies_.motion[i] == motion) return;
    // Checked before anything changes: a shape with no usable mass cannot become dynamic.
    const MassProperties properties =
        bodyMassProperties(bodies_.shape[i], motion, bodies_.massSetting[i], bodies_.density[i]);
    wakeContactPartners(i);  // what rested on it, or was pushed by it, must notice
    bodies_.motion[i] = motion;
    bodies_.setMassProperties(i, properties);  // the centre of mass is the shape's whatever the motion
    bodies_.refreshInverseInertiaWorld(i);
    if (motion == MotionType::Static) {
        bodies_.linearVelocity[i] = Vec3(0.0f);
        bodies_.angularVelocity[i] = Vec3(0.0f);
        bodies_.force[i] = Vec3(0.0f);
        bodies_.torque[i] = Vec3(0.0f);
        bodies_.awake[i] = 0;
        bodies_.sleepTime[i] = 0.0f;
    } else {
        bodies_.awake[i] = 1;
        bodies_.sleepTime[i] = 0.0f;
    }
    // Contacts are made only for pairs with a dynamic body and count towards the cap by the
    // kinds they were made for: they are found again for the new kind.
    renewCollision(i);
}

void World::setShape(BodyId id, const Shape& shape) {
    const std::size_t i = indexOf(id);
    validateShape(shape);
    const MassProperties properties =
        bodyMassProperties(shape, bodies_.motion[i], bodies_.massSetting[i], bodies_.density[i]);
    const Vec3 origin = bodies_.origin(i);
    wakeContactPartners(i);
    bodies_.shape[i] = shape;
    const bool centreMoved = properties.centerOfMass != bodies_.localCenterOfMass[i];
    bodies_.setMassProperties(i, properties);
    // Recomputed only when it moved, so a shape centred like the old one rounds nothing.
    if (centreMoved) bodies_.centerOfMass[i] = origin + bodies_.orientation[i] * properties.centerOfMass;
    bodies_.refreshInverseInertiaWorld(i);
    bodies_.bounds[i] = worldBounds(shape, bodies_.transform(i));
    // The manifolds name the old shape's features, and its fat box may be far larger.
    renewCollision(i);
    wakeIndex(i);
}

void World::setMass(BodyId id, float mass) {
    const std::size_t i = indexOf(id);
    validateMass(mass);
    // Checked as for a dynamic body whatever the motion, so a static body keeps only a mass it can use.
    bodyMassProperties(bodies_.shape[i], MotionType::Dynamic, mass, bodies_.density[i]);
    const MassProperties properties = bodyMassProperties(bodies_.shape[i], bodies_.motion[i], mass, bodies_.density[i]);
    bodies_.massSetting[i] = mass;
    bodies_.setMassProperties(i, properties);
    bodies_.refreshInverseInertiaWorld(i);
    wakeIndex(i);
    wakeContactPartners(i);
}

void World::setDensity(BodyId id, float density) {
    const std::size_t i = indexOf(id);
    validateDensity(density);
    bodyMassProperties(bodies_.shape[i], MotionType::Dynamic, std::nullopt, density);  // as in setMass
    const MassProperties properties =
        bodyMassProperties(bodies_.shape[i], bodies_.motion[i], std::nullopt, density);
    bodies_.massSetting[i].reset();
    bodies_.density[i] = density;
    bodies_.setMassProperties(i, properties);
    bodies_.refreshInverseInertiaWorld(i);
    wakeIndex(i);
    wakeContactPartners(i);
}

void World::setFriction(BodyId id, float friction) {
    const std::size_t i = indexOf(id);
    validateFriction(friction);
    bodies_.friction[i] = friction;
    materialChanged(i);
}

void World::setRestitution(BodyId id, float restitution) {
    const std::size_t i = indexOf(id);
    validateRestitution(restitution);
    bodies_.restitution[i] = restitution;
    materialChanged(i);
}

void World::setRollingResistance(BodyId id, float coefficient) {
    const std::size_t i = indexOf(id);
    validateRollingResistance(coefficient);
    bodies_.rollingResistance[i] = coefficient;
    materialChanged(i);
}

void World::materialChanged(std::size_t i) {
    contactManager_.refreshMaterials(bodies_.idAt(i).index, bodies_);
    wakeIndex(i);
    wakeContactPartners(i);
}

void World::setCcd(BodyId id, bool ccd) {
    const std::size_t i = indexOf(id);
    bodies_.ccd[i] = ccd ? 1 : 0;
    wakeIndex(i);
}

void World::setName(BodyId id, const std::string& name) { bodies_.name[indexOf(id)] = name; }

void World::wakeContactPartners(std::size_t i) {
    const std::uint32_t slot = bodies_.idAt(i).index;
    for (const Contact& contact : contactManager_.contacts()) {
        if (contact.slotA == slot) wakeIndex(bodies_.denseIndexOfSlot(contact.slotB));
        else if (contact.slotB == slot) wakeIndex(bodies_.denseIndexOfSlot(contact.slotA));
    }
}

void World::renewCollision(std::size_t i) {
    const std::uint32_t slot = bodies_.idAt(i).index;
    contactManager_.removeContactsOf(slot);
    broadPhase_.removeProxy(bodies_.proxy[i]);
    // As createBody makes it: a new proxy counts as moved, so its pairs come in the next step.
    const bool active = bodies_.motion[i] != MotionType::Static && bodies_.awake[i];
    bodies_.proxy[i] = broadPhase_.addProxy(bodies_.bounds[i], slot, active);
}

// ---- Joints ----------------------------------------------------------------------------------------

void World::setJointLimits(JointId id, const std::optional<JointLimits>& limits) {
    Joint& joint = joints_.joints[indexOf(id)];
    validateJointLimits(joint.type, limits);
    joint.limits = limits;
    if (!limits) joint.impulses.lower = joint.impulses.upper = 0.0f;  // the rows are gone
    wakeJointBodies(joint);
}

void World::setJointMotor(JointId id, const std::optional<JointMotor>& motor) {
    Joint& joint = joints_.joints[indexOf(id)];
    validateJointMotor(joint.type, motor);
    joint.motor = motor;
    if (!motor) joint.impulses.motor = 0.0f;
    wakeJointBodies(joint);
}

void World::setJointSpring(JointId id, const std::optional<JointSpring>& spring) {
    Joint& joint = joints_.joints[indexOf(id)];
    validateJointSpring(joint.type, spring);
    validateJointLengths(joint.type, joint.restLength, spring.has_value(), joint.minLengthSetting, joint.maxLengthSetting);
    // With a spring or without, the axial row means another thing (a spring or a rigid rod).
    if (spring.has_value() != joint.spring.has_value()) joint.impulses.axial = 0.0f;
    joint.spring = spring;
    applyDistanceLengths(joint);
    wakeJointBodies(joint);
}

void World::setJointFrame(JointId id, const Vec3& anchor, const Vec3& axis, const Vec3& anchorB) {
    Joint& joint = joints_.joints[indexOf(id)];
    validateJointFrame(joint.type, anchor, axis, anchorB);
    if (joint.type == JointType::Distance)
        validateJointLengths(joint.type, glm::length(anchorB - anchor), joint.spring.has_value(), joint.minLengthSetting,
                             joint.maxLengthSetting);
    joints_.place(joint, anchor, axis, anchorB, bodies_);
    applyDistanceLengths(joint);
    wakeJointBodies(joint);
}

void World::setJointLengths(JointId id, std::optional<float> minLength, std::optional<float> maxLength) {
    Joint& joint = joints_.joints[indexOf(id)];
    validateJointLengths(joint.type, joint.restLength, joint.spring.has_value(), minLength, maxLength);
    joint.minLengthSetting = minLength;
    joint.maxLengthSetting = maxLength;
    applyDistanceLengths(joint);
    wakeJointBodies(joint);
}

void World::applyDistanceLengths(Joint& joint) {
    if (joint.type != JointType::Distance) return;  // only a distance joint has lengths
    const DistanceLengths lengths =
        distanceLengths(joint.restLength, joint.spring.has_value(), joint.minLengthSetting, joint.maxLengthSetting);
    joint.minLength = lengths.min;
    joint.maxLength = lengths.max;
    // A bound that is no longer solved must not warm-start (see the joint solver's distance rows).
    const bool range = joint.minLength < joint.maxLength;
    if (!range || !(joint.minLength > 0.0f)) joint.impulses.lower = 0.0f;
    if (!range || !std::isfinite(joint.maxLength)) joint.impulses.upper = 0.0f;
    if (range && !joint.spring) joint.impulses.axial = 0.0f;
}

void World::setJointCollideConnected(JointId id, bool collideConnected) {
    Joint& joint = joints_.joints[indexOf(id)];
    if (joint.collideConnected == collideConnected) return;
    joint.collideConnected = collideConnected;
    if (joint.bodyB.isValid()) {
        if (collideConnected) unfilterJointPair(joint.bodyA, joint.bodyB);
        else filterJointPair(joint.bodyA, joint.bodyB);
    }
    wakeJointBodies(joint);
}

void World::setJointName(JointId id, const std::string& name) { joints_.names[indexOf(id)] = name; }

void World::wakeJointBodies(const Joint& joint) {
    wakeIndex(indexOf(joint.bodyA));
    if (joint.bodyB.isValid()) wakeIndex(indexOf(joint.bodyB));
}

}  // namespace simcore
