#include "simcore/collision/dynamic_aabb_tree.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace simcore {

namespace {

Aabb unionOf(const Aabb& a, const Aabb& b) { return {glm::min(a.min, b.min), glm::max(a.max, b.max)}; }

}  // namespace

DynamicAabbTree::DynamicAabbTree(const AabbTreeSettings& settings, std::size_t initialProxyCapacity)
    : settings_(settings) {
    nodes_.resize(std::max<std::size_t>(2 * initialProxyCapacity, 2));
    linkFreeNodes(0);
}

Aabb DynamicAabbTree::enlarge(const Aabb& tight, const Vec3& displacement) const {
    const Vec3 ahead = settings_.displacementScale * displacement;
    return {tight.min - settings_.margin + glm::min(ahead, Vec3(0.0f)),
            tight.max + settings_.margin + glm::max(ahead, Vec3(0.0f))};
}

// Links nodes_[first, size) into the free list, lowest index first.
void DynamicAabbTree::linkFreeNodes(std::size_t first) {
    for (std::size_t i = first; i < nodes_.size(); ++i) {
        nodes_[i] = Node{};
        nodes_[i].parent = i + 1 < nodes_.size() ? static_cast<std::uint32_t>(i + 1) : freeList_;
    }
    if (first < nodes_.size()) freeList_ = static_cast<std::uint32_t>(first);
}

std::uint32_t DynamicAabbTree::allocateNode() {
    if (freeList_ == kNull) {
        const std::size_t old = nodes_.size();
        nodes_.resize(2 * old);
        linkFreeNodes(old);
    }
    const std::uint32_t index = freeList_;
    Node& node = nodes_[index];
    freeList_ = node.parent;
    node = Node{};
    node.height = 0;
    ++nodeCount_;
    return index;
}

void DynamicAabbTree::freeNode(std::uint32_t index) {
    Node& node = nodes_[index];
    node = Node{};
    node.parent = freeList_;
    freeList_ = index;
    --nodeCount_;
}

ProxyId DynamicAabbTree::createProxy(const Aabb& tight, std::uint32_t userData, const Vec3& displacement) {
    assert(!tight.isEmpty() && isFinite(tight.min) && isFinite(tight.max));
    const std::uint32_t leaf = allocateNode();
    nodes_[leaf].box = enlarge(tight, displacement);
    nodes_[leaf].userData = userData;
    insertLeaf(leaf);
    ++proxyCount_;
    return leaf;
}

void DynamicAabbTree::destroyProxy(ProxyId id) {
    assert(isProxy(id));
    removeLeaf(id);
    freeNode(id);
    --proxyCount_;
}

bool DynamicAabbTree::leavesFatBox(ProxyId id, const Aabb& tight, const Vec3& displacement) const {
    assert(isProxy(id));
    assert(!tight.isEmpty() && isFinite(tight.min) && isFinite(tight.max));
    const Aabb& current = nodes_[id].box;
    // The fat box must hold where the body is going too, or a body fast enough to cross another
    // in one step would never be paired with it.
    const Aabb swept{glm::min(tight.min, tight.min + displacement), glm::max(tight.max, tight.max + displacement)};
    return !current.contains(swept) ||
           current.surfaceArea() > settings_.shrinkAreaRatio * enlarge(tight, displacement).surfaceArea();
}

bool DynamicAabbTree::moveProxy(ProxyId id, const Aabb& tight, const Vec3& displacement) {
    if (!leavesFatBox(id, tight, displacement)) return false;
    removeLeaf(id);
    nodes_[id].box = enlarge(tight, displacement);
    insertLeaf(id);
    return true;
}

void DynamicAabbTree::moveProxies(const std::vector<ProxyMove>& moves) {
    const bool asOneSubtree = static_cast<float>(moves.size()) >= kSubtreeShare * static_cast<float>(proxyCount_);
    buildItems_.clear();
    for (const ProxyMove& move : moves) {
        assert(leavesFatBox(move.id, move.tight, move.displacement));
        removeLeaf(move.id);
        Node& leaf = nodes_[move.id];
        leaf.box = enlarge(move.tight, move.displacement);
        if (asOneSubtree) buildItems_.push_back({leaf.box.min + leaf.box.max, move.id});
        else insertLeaf(move.id);
    }
    if (asOneSubtree && !buildItems_.empty())
        insertLeaf(buildSubtree(buildItems_.data(), buildItems_.data() + buildItems_.size(), 0));
}

// Returns the subtree's root. Its leaves are the items' (reordered).
std::uint32_t DynamicAabbTree::buildSubtree(BuildItem* first, BuildItem* last, int depth) {
    const std::ptrdiff_t count = last - first;
    if (count == 1) return first->leaf;
    Aabb centres{first->centre, first->centre};
    for (const BuildItem* item = first + 1; item != last; ++item) {
        centres.min = glm::min(centres.min, item->centre);
        centres.max = glm::max(centres.max, item->centre);
    }
    const Vec3 spread = centres.max - centres.min;
    const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : (spread.y >= spread.z ? 1 : 2);
    // Split at the middle of the centres' widest extent. Past this depth (leaves spaced ever wider
    // apart, each split cutting off one), split at the median instead: the height stays
    // logarithmic on any input.
    constexpr int kMaxMidpointDepth = 48;
    BuildItem* middle = first + count / 2;
    if (depth < kMaxMidpointDepth) {
        const float midpoint = 0.5f * (centres.min[axis] + centres.max[axis]);
        BuildItem* const split = std::partition(
            first, last, [axis, midpoint](const BuildItem& item) { return item.centre[axis] < midpoint; });
        if (split != first && split != last) middle = split;  // else the centres (nearly) coincide
    } else {
        std::nth_element(first, middle, last,
                         [axis](const BuildItem& a, const BuildItem& b) { return a.centre[axis] < b.centre[axis]; });
    }
    const std::uint32_t child1 = buildSubtree(first, middle, depth + 1);
    const std::uint32_t child2 = buildSubtree(middle, last, depth + 1);
    const std::uint32_t index = allocateNode();
    Node& node = nodes_[index];
    node.child1 = child1;
    node.child2 = child2;
    node.box = unionOf(nodes_[child1].box, nodes_[child2].box);
    node.height = 1 + std::max(nodes_[child1].height, nodes_[child2].height);
    nodes_[child1].parent = nodes_[child2].parent = index;
    return index;
}

// Choosing the sibling S for a new leaf costs, in SAH terms, the area of the new parent,
// SA(S u box), plus the growth it causes in every ancestor of S. A greedy descent (the cost descent
// of Box2D v3) offers each node on its path and its leaf children as candidates, and follows the
// child whose subtree has the lower cost bound until no subtree can beat the best candidate:
// O(height). An exhaustive branch-and-bound search (Catto, GDC 2019) was measured too: its trees
// were 10-20% cheaper, but an insertion among coincident or large boxes cost 20-120 us instead of
// 1-2 us, and capping its work made the trees far worse than the descent's (a capped search settles
// high in the tree).
//
// Equal costs are common where boxes coincide or nest (every choice then costs the same). Ties go
// to the sibling whose new parent ends up shallowest (its depth plus its height), and the descent
// continues through ties toward the nearer, then the shorter, child: otherwise every coincident
// box would be hung at the root and the tree would grow into a list.
namespace {

struct SiblingChoice {
    std::uint32_t node;
    float cost;
    int reach;  // depth + height of the chosen sibling: how deep the new parent's subtree reaches

    void offer(std::uint32_t candidate, float candidateCost, int candidateReach) {
        if (candidateCost < cost || (candidateCost == cost && candidateReach < reach)) {
            node = candidate;
            cost = candidateCost;
            reach = candidateReach;
        }
    }
};

}  // namespace

std::uint32_t DynamicAabbTree::findBestSibling(const Aabb& box) const {
    const float boxArea = box.surfaceArea();
    const Vec3 boxCenter = box.center();
    std::uint32_t index = root_;
    float direct = unionOf(nodes_[root_].box, box).surfaceArea();  // SA(node u box)
    float inherited = 0.0f;  // growth of the node's ancestors if box were inserted below them
    SiblingChoice best{root_, direct, nodes_[root_].height};

    for (int depth = 0; !nodes_[index].isLeaf(); ++depth) {
        const Node& node = nodes_[index];
        best.offer(index, direct + inherited, depth + node.height);
        inherited += direct - node.box.surfaceArea();

        const std::uint32_t children[2] = {node.child1, node.child2};
        float childDirect[2];
        float lowerBound[2];  // of choosing anything below the child; a leaf's exact cost is offered now
        for (int i = 0; i < 2; ++i) {
            const Node& child = nodes_[children[i]];
            childDirect[i] = unionOf(child.box, box).surfaceArea();
            if (child.isLeaf()) {
                best.offer(children[i], inherited + childDirect[i], depth + 1);
                lowerBound[i] = std::numeric_limits<float>::infinity();
            } else {
                // The child grows to SA(child u box) and the new parent is at least SA(box).
                lowerBound[i] = inherited + childDirect[i] + std::min(boxArea - child.box.surfaceArea(), 0.0f);
            }
        }
        if (best.cost < lowerBound[0] && best.cost < lowerBound[1]) break;
        int next;
        if (lowerBound[0] != lowerBound[1]) {
            next = lowerBound[0] < lowerBound[1] ? 0 : 1;
        } else {
            // Tied (typically both contain the box): the nearer centre, then the shorter subtree.
            const float distance0 = lengthSquared(nodes_[children[0]].box.center() - boxCenter);
            const float distance1 = lengthSquared(nodes_[children[1]].box.center() - boxCenter);
            next = distance0 != distance1 ? (distance0 < distance1 ? 0 : 1)
                                          : (nodes_[children[0]].height <= nodes_[children[1]].height ? 0 : 1);
        }
        index = children[next];
        direct = childDirect[next];
    }
    return best.node;
}

void DynamicAabbTree::insertLeaf(std::uint32_t leaf) {
    if (root_ == kNull) {
        root_ = leaf;
        nodes_[leaf].parent = kNull;
        return;
    }
    const std::uint32_t sibling = findBestSibling(nodes_[leaf].box);
    const std::uint32_t newParent = allocateNode();  // may reallocate nodes_: no references held
    const std::uint32_t oldParent = nodes_[sibling].parent;

    Node& parent = nodes_[newParent];
    parent.parent = oldParent;
    parent.child1 = sibling;
    parent.child2 = leaf;
    parent.box = unionOf(nodes_[sibling].box, nodes_[leaf].box);
    parent.height = nodes_[sibling].height + 1;
    nodes_[sibling].parent = newParent;
    nodes_[leaf].parent = newParent;

    if (oldParent == kNull) {
        root_ = newParent;
    } else if (nodes_[oldParent].child1 == sibling) {
        nodes_[oldParent].child1 = newParent;
    } else {
        nodes_[oldParent].child2 = newParent;
    }
    refitAndRotateUpFrom(newParent);
}

void DynamicAabbTree::removeLeaf(std::uint32_t leaf) {
    if (leaf == root_) {
        root_ = kNull;
        return;
    }
    const std::uint32_t parent = nodes_[leaf].parent;
    const std::uint32_t grandparent = nodes_[parent].parent;
    const std::uint32_t sibling = nodes_[parent].child1 == leaf ? nodes_[parent].child2 : nodes_[parent].child1;

    nodes_[sibling].parent = grandparent;
    freeNode(parent);
    nodes_[leaf].parent = kNull;
    if (grandparent == kNull) {
        root_ = sibling;
        return;
    }
    if (nodes_[grandparent].child1 == parent) {
        nodes_[grandparent].child1 = sibling;
    } else {
        nodes_[grandparent].child2 = sibling;
    }
    // Only refitted (as Box2D v3 does): insertions rotate, and moveProxy reinserts at once.
    // Rotating here too cost pile1k 3 % of its step's instructions and saved its queries 1 %.
    refitUpFrom(grandparent);
}

// Restores bounds and heights from `index` to the root.
void DynamicAabbTree::refitUpFrom(std::uint32_t index) {
    for (; index != kNull; index = nodes_[index].parent) {
        Node& node = nodes_[index];
        node.box = unionOf(nodes_[node.child1].box, nodes_[node.child2].box);
        node.height = 1 + std::max(nodes_[node.child1].height, nodes_[node.child2].height);
    }
}

// Restores bounds and heights from `index` to the root, rotating each node on the way. Every
// ancestor is visited even when its box did not change, because a rotation below may have changed
// its height and a rotation at it may now pay off.
void DynamicAabbTree::refitAndRotateUpFrom(std::uint32_t index) {
    while (index != kNull) {
        // A rotation moves a subtree down into its sibling. Follow it while rotations keep paying
        // off there, so it sinks to where it belongs instead of resting on top of a large subtree
        // it happens to lie inside: small leaves resting there pile up into chains of nodes as
        // large as that subtree. Each step goes one level down, so this ends.
        std::uint32_t deepest = kNull;
        for (std::uint32_t receiver = rotate(index); receiver != kNull; receiver = rotate(receiver)) {
            deepest = receiver;
        }
        for (std::uint32_t i = deepest; i != kNull && i != index; i = nodes_[i].parent) {
            Node& changed = nodes_[i];
            changed.height = 1 + std::max(nodes_[changed.child1].height, nodes_[changed.child2].height);
        }
        Node& node = nodes_[index];
        const Node& a = nodes_[node.child1];
        const Node& b = nodes_[node.child2];
        node.box = unionOf(a.box, b.box);
        node.height = 1 + std::max(a.height, b.height);
        index = node.parent;
    }
}

// Tree rotation at node A with children B and C: swapping B with a child of C (or C with a child of
// B) keeps A's box but changes the box of the child that receives the swap. Take the swap that
// shrinks that box's area the most, if any does: it lowers the SAH cost without touching anything
// above A. This is what keeps sorted or clustered insertion orders from degenerating into lists.
// Among swaps that leave the area unchanged, take one that lowers A's height: coincident boxes
// give the SAH no preference at all, and would otherwise pile up into a list.
// Returns the node that received the moved child, or kNull when nothing was swapped.
std::uint32_t DynamicAabbTree::rotate(std::uint32_t index) {
    const Node& a = nodes_[index];
    const std::uint32_t b = a.child1;
    const std::uint32_t c = a.child2;
    const Node& nodeB = nodes_[b];
    const Node& nodeC = nodes_[c];
    if (nodeB.isLeaf() && nodeC.isLeaf()) return kNull;  // nothing to swap

    float bestGain = 0.0f;
    int bestHeight = 1 + std::max(nodeB.height, nodeC.height);  // A's height without a rotation
    std::uint32_t bestChild = kNull;
    std::uint32_t bestGrandchild = kNull;
    const auto consider = [&](std::uint32_t child, const Node& other, std::uint32_t grandchild, std::uint32_t kept) {
        // `child` moves down into `other`, taking the place of `grandchild`; `other` keeps `kept`.
        const float gain = other.box.surfaceArea() - unionOf(nodes_[child].box, nodes_[kept].box).surfaceArea();
        const int otherHeight = 1 + std::max(nodes_[child].height, nodes_[kept].height);
        const int height = 1 + std::max(nodes_[grandchild].height, otherHeight);
        if (gain > bestGain || (gain == bestGain && height < bestHeight)) {
            bestGain = gain;
            bestHeight = height;
            bestChild = child;
            bestGrandchild = grandchild;
        }
    };
    if (!nodeB.isLeaf()) {
        consider(c, nodeB, nodeB.child1, nodeB.child2);
        consider(c, nodeB, nodeB.child2, nodeB.child1);
    }
    if (!nodeC.isLeaf()) {
        consider(b, nodeC, nodeC.child1, nodeC.child2);
        consider(b, nodeC, nodeC.child2, nodeC.child1);
    }
    if (bestChild == kNull) return kNull;
    swapWithGrandchild(index, bestChild, bestGrandchild);
    return nodes_[bestChild].parent;
}

void DynamicAabbTree::swapWithGrandchild(std::uint32_t parent, std::uint32_t child, std::uint32_t grandchild) {
    Node& a = nodes_[parent];
    const std::uint32_t other = a.child1 == child ? a.child2 : a.child1;
    Node& o = nodes_[other];

    if (a.child1 == child) {
        a.child1 = grandchild;
    } else {
        a.child2 = grandchild;
    }
    if (o.child1 == grandchild) {
        o.child1 = child;
    } else {
        o.child2 = child;
    }
    nodes_[grandchild].parent = parent;
    nodes_[child].parent = other;
    o.box = unionOf(nodes_[o.child1].box, nodes_[o.child2].box);
    o.height = 1 + std::max(nodes_[o.child1].height, nodes_[o.child2].height);
}

float DynamicAabbTree::areaRatio() const {
    if (root_ == kNull) return 0.0f;
    const float rootArea = nodes_[root_].box.surfaceArea();
    if (rootArea <= 0.0f) return 0.0f;
    double total = 0.0;
    for (const Node& node : nodes_) {
        if (node.isAllocated() && !node.isLeaf()) total += node.box.surfaceArea();
    }
    return static_cast<float>(total / rootArea);
}

bool DynamicAabbTree::validate(std::string* error) const {
    const auto fail = [error](std::string message) {
        if (error) *error = std::move(message);
        return false;
    };
    const auto at = [](const char* what, std::uint32_t i) { return std::string(what) + " at node " + std::to_string(i); };

    std::size_t freeCount = 0;
    for (std::uint32_t i = freeList_; i != kNull; i = nodes_[i].parent) {
        if (i >= nodes_.size()) return fail("free list leaves the pool");
        if (nodes_[i].isAllocated()) return fail(at("allocated node on the free list", i));
        if (++freeCount > nodes_.size()) return fail("free list has a cycle");
    }
    if (freeCount + nodeCount_ != nodes_.size()) return fail("free and allocated nodes do not add up to the pool");

    if (root_ == kNull) {
        if (nodeCount_ != 0 || proxyCount_ != 0) return fail("empty tree with allocated nodes");
        return true;
    }
    if (root_ >= nodes_.size() || !nodes_[root_].isAllocated()) return fail("root is not an allocated node");
    if (nodes_[root_].parent != kNull) return fail("root has a parent");

    // Walks the tree from the root; every allocated node must be reached exactly once.
    std::size_t reached = 0;
    std::size_t leaves = 0;
    std::vector<std::uint32_t> stack{root_};
    while (!stack.empty()) {
        const std::uint32_t i = stack.back();
        stack.pop_back();
        if (++reached > nodeCount_) return fail("more nodes reachable than allocated (cycle or shared child)");
        const Node& node = nodes_[i];
        if (node.isLeaf()) {
            if (node.child2 != kNull) return fail(at("leaf with a second child", i));
            if (node.height != 0) return fail(at("leaf with non-zero height", i));
            if (node.box.isEmpty()) return fail(at("leaf with an empty box", i));
            ++leaves;
            continue;
        }
        for (const std::uint32_t child : {node.child1, node.child2}) {
            if (child >= nodes_.size() || !nodes_[child].isAllocated()) return fail(at("child is not allocated", i));
            if (nodes_[child].parent != i) return fail(at("child's parent link is wrong", i));
            stack.push_back(child);
        }
        const Node& a = nodes_[node.child1];
        const Node& b = nodes_[node.child2];
        if (node.height != 1 + std::max(a.height, b.height)) return fail(at("wrong height", i));
        const Aabb expected = unionOf(a.box, b.box);
        if (node.box.min != expected.min || node.box.max != expected.max) {
            return fail(at("box is not the union of its children", i));
        }
    }
    if (reached != nodeCount_) return fail("allocated nodes unreachable from the root");
    if (leaves != proxyCount_) return fail("leaf count differs from proxy count");
    if (nodeCount_ != 2 * proxyCount_ - 1) return fail("node count is not 2 * proxies - 1");
    return true;
}

}  // namespace simcore
