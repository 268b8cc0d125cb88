#include "app/document/scene_edits.h"

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

}  // namespace interplay
