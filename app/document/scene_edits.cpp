#include "app/document/scene_edits.h"

#include <glm/gtc/quaternion.hpp>

#include <map>

namespace interplay {
namespace {

template <typename NewIndex>
void renumberJointBodies(simcore::Scene& scene, NewIndex newIndex) {
    const auto renumber = [&newIndex](std::size_t& body) { body = static_cast<std::size_t>(newIndex(static_cast<int>(body))); };
    for (simcore::SceneJoint& joint : scene.joints) {
        renumber(joint.bodyA);
        if (joint.bodyB) renumber(*joint.bodyB);
    }
}

}  // namespace

int indexAfterInsert(int i, int index) {
    return i >= index ? i + 1 : i;
}

int indexAfterRemove(int i, int index) {
    return i > index ? i - 1 : i;
}

int indexAfterMove(int i, int from, int to) {
    if (i == from) return to;
    if (from < to && i > from && i <= to) return i - 1;
    if (to < from && i >= to && i < from) return i + 1;
    return i;
}

void insertSceneBody(simcore::Scene& scene, int index, simcore::SceneBody body) {
    scene.bodies.insert(scene.bodies.begin() + index, std::move(body));
    renumberJointBodies(scene, [index](int i) { return indexAfterInsert(i, index); });
}

simcore::SceneBody takeSceneBody(simcore::Scene& scene, int index) {
    simcore::SceneBody body = std::move(scene.bodies[static_cast<std::size_t>(index)]);
    scene.bodies.erase(scene.bodies.begin() + index);
    renumberJointBodies(scene, [index](int i) { return indexAfterRemove(i, index); });
    return body;
}

void moveSceneBody(simcore::Scene& scene, int from, int to) {
    moveItem(scene.bodies, from, to);
    renumberJointBodies(scene, [from, to](int i) { return indexAfterMove(i, from, to); });
}

simcore::Vec3 carriedPoint(const simcore::Transform& from, const simcore::Transform& to, const simcore::Vec3& point) {
    return to.position + carriedDirection(from.rotation, to.rotation, point - from.position);
}

simcore::Vec3 carriedDirection(const simcore::Quat& from, const simcore::Quat& to, const simcore::Vec3& direction) {
    return to * (glm::inverse(from) * direction);
}

std::vector<std::pair<int, simcore::SceneJoint>> jointsCarriedWith(const simcore::Scene& scene, const QList<int>& indices,
                                                                   const std::vector<simcore::SceneBody>& after) {
    const auto pose = [](const simcore::BodyCreationSettings& body) { return simcore::Transform{body.position, body.orientation}; };
    std::map<std::size_t, simcore::Transform> moved;  // scene body -> its new pose
    for (qsizetype i = 0; i < indices.size(); ++i) {
        const simcore::BodyCreationSettings& before = scene.bodies.at(static_cast<std::size_t>(indices[i])).body;
        const simcore::BodyCreationSettings& now = after.at(static_cast<std::size_t>(i)).body;
        if (before.position != now.position || before.orientation != now.orientation)
            moved[static_cast<std::size_t>(indices[i])] = pose(now);
    }
    // A body only moved carries its points by the offset: through its rotation and back they
    // would be rounded, and an axis would tilt by a few ulps.
    const auto carried = [](const simcore::Transform& from, const simcore::Transform& to, const simcore::Vec3& point) {
        return from.rotation == to.rotation ? point + (to.position - from.position) : carriedPoint(from, to, point);
    };
    std::vector<std::pair<int, simcore::SceneJoint>> joints;
    for (std::size_t j = 0; j < scene.joints.size(); ++j) {
        simcore::SceneJoint joint = scene.joints[j];
        const auto a = moved.find(joint.bodyA);
        // Only a distance joint holds a point of body B of its own.
        const auto b = joint.bodyB && joint.joint.type == simcore::JointType::Distance ? moved.find(*joint.bodyB) : moved.end();
        if (a == moved.end() && b == moved.end()) continue;
        if (a != moved.end()) {
            const simcore::Transform from = pose(scene.bodies[joint.bodyA].body);
            joint.joint.anchor = carried(from, a->second, joint.joint.anchor);
            if (from.rotation != a->second.rotation) joint.joint.axis = carriedDirection(from.rotation, a->second.rotation, joint.joint.axis);
        }
        if (b != moved.end()) joint.joint.anchorB = carried(pose(scene.bodies[*joint.bodyB].body), b->second, joint.joint.anchorB);
        joints.emplace_back(static_cast<int>(j), std::move(joint));
    }
    return joints;
}

}  // namespace interplay
