#pragma once
// Structural edits of a simcore::Scene that keep it consistent: joints refer to bodies by index, so
// inserting, removing and moving bodies renumbers them. The document applies these to the scene it
// edits, the simulation controller to its copy (the scene Reset returns to), so both stay equal.

#include "simcore/io/scene.h"

#include <QList>

#include <algorithm>
#include <utility>
#include <vector>

namespace interplay {

// Where index `i` of a list (of bodies, of joints) ends up when an item is inserted at `index`,
// removed from `index` (not `i` itself), or moved from `from` to `to` (the index it ends up at).
int indexAfterInsert(int i, int index);
int indexAfterRemove(int i, int index);
int indexAfterMove(int i, int from, int to);

// Moves item `from` of `items` to index `to`, keeping the order of the others.
template <typename T>
void moveItem(std::vector<T>& items, int from, int to) {
    if (from < to) {
        std::rotate(items.begin() + from, items.begin() + from + 1, items.begin() + to + 1);
    } else {
        std::rotate(items.begin() + to, items.begin() + from, items.begin() + from + 1);
    }
}

void insertSceneBody(simcore::Scene& scene, int index, simcore::SceneBody body);
// The body must have no joints (take them first).
simcore::SceneBody takeSceneBody(simcore::Scene& scene, int index);
void moveSceneBody(simcore::Scene& scene, int from, int to);

// A point (direction) fixed in a body that moves from pose `from` to pose `to`, where it is then.
simcore::Vec3 carriedPoint(const simcore::Transform& from, const simcore::Transform& to, const simcore::Vec3& point);
simcore::Vec3 carriedDirection(const simcore::Quat& from, const simcore::Quat& to, const simcore::Vec3& direction);

// The joints of `scene` that ride on bodies moved or turned to new poses (`indices[i]` to
// `after[i]`), re-expressed so that they hold the same points of them: anchor and axis move with
// body A, a distance joint's second anchor with body B. A joint on bodies that keep their pose
// keeps its anchors exactly. Returns (joint index, joint) pairs, ascending.
std::vector<std::pair<int, simcore::SceneJoint>> jointsCarriedWith(const simcore::Scene& scene, const QList<int>& indices,
                                                                   const std::vector<simcore::SceneBody>& after);

}  // namespace interplay
