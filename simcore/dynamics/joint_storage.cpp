#include "simcore/dynamics/joint_storage.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace simcore {

std::string_view jointTypeName(JointType type) {
    switch (type) {
        case JointType::Ball: return "ball";
        case JointType::Hinge: return "hinge";
        case JointType::Slider: return "slider";
        case JointType::Fixed: return "fixed";
        case JointType::Distance: return "distance";
    }
    return "unknown";
}

DistanceLengths distanceLengths(const JointCreationSettings& s) {
    return distanceLengths(glm::length(s.anchorB - s.anchor), s.spring.has_value(), s.minLength, s.maxLength);
}

DistanceLengths distanceLengths(float restLength, bool hasSpring, std::optional<float> minLength,
                                std::optional<float> maxLength) {
    DistanceLengths lengths;
    lengths.rest = restLength;
    lengths.min = minLength.value_or(hasSpring ? 0.0f : restLength);
    lengths.max = maxLength.value_or(hasSpring ? std::numeric_limits<float>::infinity() : restLength);
    return lengths;
}

namespace {

// The same rotation with a non-negative scalar part: the short way round.
Quat shortestArc(const Quat& q) { return q.w < 0.0f ? -q : q; }

// Angle (rad) of the rotation q, in [0, pi].
float rotationAngle(const Quat& q) { return 2.0f * std::atan2(glm::length(Vec3(q.x, q.y, q.z)), std::abs(q.w)); }

}  // namespace

float JointGeometry::hingeAngle(const Joint& joint) const {
    // The twist of B's rotation relative to A about the axis, negated: A relative to B.
    const Quat q = shortestArc(relativeRotation);
    return -2.0f * std::atan2(glm::dot(Vec3(q.x, q.y, q.z), joint.localAxisA), q.w);
}

Vec3 JointGeometry::rotationError() const {
    const Quat q = shortestArc(relativeRotation);
    const Vec3 v(q.x, q.y, q.z);
    const float sine = glm::length(v);
    if (sine < 1e-12f) return 2.0f * (orientationA * v);  // the small-angle limit, without 0/0
    return (2.0f * std::atan2(sine, q.w) / sine) * (orientationA * v);
}

JointGeometry jointGeometry(const Joint& joint, const JointBodyPose& a, const JointBodyPose& b) {
    JointGeometry g;
    g.armA = a.orientation * joint.localAnchorA;
    g.armB = b.orientation * joint.localAnchorB;
    g.separation = (b.centerOfMass + g.armB) - (a.centerOfMass + g.armA);
    g.relativeRotation = glm::conjugate(a.orientation) * b.orientation * glm::conjugate(joint.restRotation);
    g.axisA = a.orientation * joint.localAxisA;
    g.axisB = b.orientation * joint.localAxisB;
    g.orientationA = a.orientation;
    return g;
}

JointId JointStorage::add(const JointCreationSettings& s, const BodyStorage& bodies) {
    Joint j;
    j.type = s.type;
    j.bodyA = s.bodyA;
    j.bodyB = s.bodyB;
    place(j, s.anchor, s.axis, s.anchorB, bodies);
    const JointBodyPose a = poseOf(s.bodyA, bodies);
    const JointBodyPose b = poseOf(s.bodyB, bodies);
    j.restRotation = glm::normalize(glm::conjugate(a.orientation) * b.orientation);
    j.limits = s.limits;
    j.motor = s.motor;
    j.spring = s.spring;
    const DistanceLengths lengths = distanceLengths(s);
    j.minLength = lengths.min;
    j.maxLength = lengths.max;
    j.minLengthSetting = s.minLength;
    j.maxLengthSetting = s.maxLength;
    j.collideConnected = s.collideConnected;

    joints.push_back(j);
    names.push_back(s.name);
    return slots_.add();
}

void JointStorage::remove(JointId id) {
    const int dense = denseIndex(id);
    assert(dense >= 0);
    if (dense < 0) return;
    const auto i = static_cast<std::size_t>(dense);
    if (i + 1 != joints.size()) {
        joints[i] = joints.back();
        names[i] = std::move(names.back());
    }
    joints.pop_back();
    names.pop_back();
    slots_.removeAt(i);
}

void JointStorage::place(Joint& j, const Vec3& anchor, const Vec3& axis, const Vec3& anchorB,
                         const BodyStorage& bodies) const {
    const JointBodyPose a = poseOf(j.bodyA, bodies);
    const JointBodyPose b = poseOf(j.bodyB, bodies);
    const Vec3 anchorOnB = j.type == JointType::Distance ? anchorB : anchor;
    j.localAnchorA = glm::conjugate(a.orientation) * (anchor - a.centerOfMass);
    j.localAnchorB = glm::conjugate(b.orientation) * (anchorOnB - b.centerOfMass);
    const Vec3 unitAxis = glm::normalize(axis);
    j.localAxisA = glm::conjugate(a.orientation) * unitAxis;
    j.localAxisB = glm::conjugate(b.orientation) * unitAxis;
    j.restLength = glm::length(anchorB - anchor);
}

JointBodyPose JointStorage::poseOf(BodyId body, const BodyStorage& bodies) const {
    const int i = bodies.denseIndex(body);
    if (i < 0) return {};
    return {bodies.centerOfMass[static_cast<std::size_t>(i)], bodies.orientation[static_cast<std::size_t>(i)]};
}

JointError JointStorage::error(std::size_t i, const BodyStorage& bodies) const {
    const Joint& j = joints[i];
    const JointBodyPose a = poseOf(j.bodyA, bodies);
    const JointGeometry g = jointGeometry(j, a, poseOf(j.bodyB, bodies));
    // How far a value lies outside [lower, upper].
    auto outside = [](float value, float lower, float upper) { return std::max({lower - value, value - upper, 0.0f}); };

    JointError e;
    switch (j.type) {
        case JointType::Ball: e.position = glm::length(g.separation); break;
        case JointType::Hinge: {
            e.position = glm::length(g.separation);
            e.angle = std::atan2(glm::length(glm::cross(g.axisA, g.axisB)), glm::dot(g.axisA, g.axisB));
            if (j.limits) e.angle = std::max(e.angle, outside(g.hingeAngle(j), j.limits->lower, j.limits->upper));
            break;
        }
        case JointType::Slider: {
            const float slide = g.slide();
            e.position = glm::length(g.separation + slide * g.axisA);
            if (j.limits) e.position = std::max(e.position, outside(slide, j.limits->lower, j.limits->upper));
            e.angle = rotationAngle(g.relativeRotation);
            break;
        }
        case JointType::Fixed:
            e.position = glm::length(g.separation);
            e.angle = rotationAngle(g.relativeRotation);
            break;
        case JointType::Distance:
            e.position = outside(glm::length(g.separation), j.minLength, j.maxLength);
            break;
    }
    return e;
}

}  // namespace simcore
