#pragma once
// Structural edits of a simcore::Scene that keep it consistent: joints refer to bodies by index, so
// inserting, removing and moving bodies renumbers them. The document applies these to the scene it
// edits, the simulation controller to its copy (the scene Reset returns to), so both stay equal.

#include "simcore/io/scene.h"

#include <algorithm>
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

}  // namespace interplay
