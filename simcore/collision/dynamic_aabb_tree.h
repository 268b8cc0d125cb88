#pragma once
// Dynamic bounding volume hierarchy over enlarged ("fat") AABBs: the broad phase's spatial index.
// Leaves are proxies; each internal node bounds its two children exactly. Insertion descends to a
// sibling by the surface-area heuristic (SAH) cost, then tree rotations on the way back up undo the
// damage an unlucky insertion order does. A proxy keeps its leaf while its tight box stays inside
// its fat box, so a slowly moving body touches the tree only every few steps.
//
// All nodes live in one vector with an intrusive free list; it grows geometrically, so a tree whose
// proxy count has levelled off never allocates again. Queries and ray casts keep their traversal
// stack on the call stack.

#include "simcore/math/aabb.h"
#include "simcore/math/math.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace simcore {

// Handle to a proxy: the index of its leaf node, stable for the proxy's lifetime (reinsertion
// keeps the leaf). Reused after destroyProxy.
using ProxyId = std::uint32_t;
constexpr ProxyId kNullProxy = 0xFFFFFFFFu;

struct AabbTreeSettings {
    float margin = 0.1f;            // m added on every side of the tight box
    // The fat box also reaches this many predicted displacements (a step's travel) ahead: a body
    // that leaves its fat box costs a reinsertion and queries for its pairs, and a thousand falling
    // boxes left theirs every second or third step (pile1k's broad phase at 1 thread: 12 ms of its
    // 65 with 2 displacements, 8.6 with 4; with the boxes moved as one subtree, 8.0 against 6.2).
    // A fast body's longer box finds a few more pairs: bullets_vs_walls 0.0116 -> 0.0139 ms a step.
    float displacementScale = 4.0f;
    float shrinkAreaRatio = 4.0f;   // a fat box this many times the area of a fresh one is rebuilt
};

// A segment origin + t * direction, t in [0, maxFraction], prepared for many slab tests.
struct PreparedRay {
    Vec3 origin{0.0f};
    Vec3 direction{0.0f};
    Vec3 inverseDirection{0.0f};     // 1 / direction on the non-parallel axes
    std::array<bool, 3> parallel{};  // |direction| on this axis too small for 1/d (or zero)

    PreparedRay() = default;
    PreparedRay(const Vec3& rayOrigin, const Vec3& rayDirection) : origin(rayOrigin), direction(rayDirection) {
        for (int i = 0; i < 3; ++i) {
            parallel[i] = !(std::abs(rayDirection[i]) > 1e-30f);
            inverseDirection[i] = parallel[i] ? 0.0f : 1.0f / rayDirection[i];
        }
    }
};

// Slab test: the ray enters `box` at `entryFraction` in [0, maxFraction] (0 when the origin is
// inside). Rounding is monotone, so a box containing another is hit whenever the inner one is:
// the tree's pruning never loses a leaf that this test would hit.
inline bool intersectRayAabb(const PreparedRay& ray, const Aabb& box, float maxFraction, float& entryFraction) {
    float enter = 0.0f;
    float exit = maxFraction;
    for (int i = 0; i < 3; ++i) {
        if (ray.parallel[i]) {
            if (ray.origin[i] < box.min[i] || ray.origin[i] > box.max[i]) return false;
            continue;
        }
        const float t1 = (box.min[i] - ray.origin[i]) * ray.inverseDirection[i];
        const float t2 = (box.max[i] - ray.origin[i]) * ray.inverseDirection[i];
        enter = std::max(enter, std::min(t1, t2));
        exit = std::min(exit, std::max(t1, t2));
        if (enter > exit) return false;
    }
    entryFraction = enter;
    return true;
}

namespace detail {

// Depth-first traversal stack. A pop-one-push-two traversal never holds more than height + 1
// nodes, so the size is known up front; it lives on the call stack unless the tree is taller than
// any SAH tree of a realistic size (then it spills to the heap rather than overflow).
class NodeStack {
public:
    explicit NodeStack(int treeHeight) {
        const std::size_t needed = static_cast<std::size_t>(treeHeight) + 2;
        if (needed > inline_.size()) {
            spill_.resize(needed);
            data_ = spill_.data();
        }
    }
    NodeStack(const NodeStack&) = delete;
    NodeStack& operator=(const NodeStack&) = delete;

    bool empty() const { return size_ == 0; }
    void push(std::uint32_t node) { data_[size_++] = node; }
    std::uint32_t pop() { return data_[--size_]; }

private:
    std::array<std::uint32_t, 128> inline_;
    std::vector<std::uint32_t> spill_;
    std::uint32_t* data_ = inline_.data();
    std::size_t size_ = 0;
};

// Lets callbacks return void (always continue) or bool (false stops).
template <typename Callback>
bool invokeContinue(Callback& callback, std::uint32_t proxy) {
    if constexpr (std::is_void_v<std::invoke_result_t<Callback&, std::uint32_t>>) {
        callback(proxy);
        return true;
    } else {
        return static_cast<bool>(callback(proxy));
    }
}

}  // namespace detail

class DynamicAabbTree {
public:
    explicit DynamicAabbTree(const AabbTreeSettings& settings = {}, std::size_t initialProxyCapacity = 16);

    const AabbTreeSettings& settings() const { return settings_; }

    // The fat box of a proxy whose tight box is `tight` and which is expected to move by
    // `displacement` over the next step.
    Aabb enlarge(const Aabb& tight, const Vec3& displacement) const;

    // `tight` must be finite and non-empty. `userData` is returned with query hits and pairs.
    ProxyId createProxy(const Aabb& tight, std::uint32_t userData, const Vec3& displacement = Vec3(0.0f));
    void destroyProxy(ProxyId id);
    // Reinserts (and returns true) only when `tight`, swept by `displacement`, leaves the fat box,
    // or when the fat box has become much larger than a fresh one (a fast body that slowed down).
    bool moveProxy(ProxyId id, const Aabb& tight, const Vec3& displacement);
    // Whether moveProxy(id, tight, displacement) would reinsert the proxy; reads the tree only.
    bool leavesFatBox(ProxyId id, const Aabb& tight, const Vec3& displacement) const;

    struct ProxyMove {
        ProxyId id;
        Aabb tight;
        Vec3 displacement;
    };
    // moveProxy for proxies that each leave their fat box (leavesFatBox), all at once. When they
    // are at least kSubtreeShare of the proxies, they are taken out, built into a subtree of their
    // own and that is inserted, rather than each reinserted: a thousand boxes falling side by side
    // leave their fat boxes in the same step (pile1k at 1 thread: 0.42 ms to reinsert them one by
    // one, 0.08 ms as a subtree). The other leaves keep their places, so a large static box stays
    // high in the tree, where insertion put it.
    void moveProxies(const std::vector<ProxyMove>& moves);
    static constexpr float kSubtreeShare = 0.25f;

    const Aabb& fatBounds(ProxyId id) const { return nodes_[id].box; }
    std::uint32_t userData(ProxyId id) const { return nodes_[id].userData; }
    bool isProxy(ProxyId id) const { return id < nodes_.size() && nodes_[id].isAllocated() && nodes_[id].isLeaf(); }

    // Calls callback(ProxyId) for every proxy whose fat box overlaps `box`, in no particular order.
    // The callback returns void, or bool where false stops the query. It must not modify the tree.
    template <typename Callback>
    void query(const Aabb& box, Callback&& callback) const;

    // Casts origin + t * direction, t in [0, maxFraction], against the fat boxes. For each proxy
    // whose fat box the ray hits, calls callback(ProxyId, float currentMaxFraction) -> float: the
    // returned value becomes the new max fraction when smaller (a closest-hit query returns its hit
    // fraction; returning currentMaxFraction continues unclipped), and 0 or less ends the cast.
    template <typename Callback>
    void rayCast(const Vec3& origin, const Vec3& direction, float maxFraction, Callback&& callback) const;

    int height() const { return root_ == kNull ? 0 : nodes_[root_].height; }
    std::size_t nodeCount() const { return nodeCount_; }
    std::size_t proxyCount() const { return proxyCount_; }
    std::size_t capacity() const { return nodes_.size(); }  // node slots, free ones included
    // Sum of internal node surface areas over the root's: the SAH cost, for tuning and tests.
    float areaRatio() const;

    // Checks links, heights, exact parent bounds, the free list and the counts. On failure writes
    // the first violation to `error` when given.
    bool validate(std::string* error = nullptr) const;

private:
    static constexpr std::uint32_t kNull = 0xFFFFFFFFu;

    struct Node {
        Aabb box;                      // fat box for a leaf, union of the children otherwise
        std::uint32_t parent = kNull;  // next free node while on the free list
        std::uint32_t child1 = kNull;  // kNull for a leaf
        std::uint32_t child2 = kNull;
        std::uint32_t userData = 0;
        std::int32_t height = -1;      // 0 for a leaf, -1 while free

        bool isLeaf() const { return child1 == kNull; }
        bool isAllocated() const { return height >= 0; }
    };

    std::uint32_t allocateNode();
    void freeNode(std::uint32_t index);
    void linkFreeNodes(std::size_t first);
    void insertLeaf(std::uint32_t leaf);  // or a subtree's root
    void removeLeaf(std::uint32_t leaf);
    std::uint32_t findBestSibling(const Aabb& box) const;
    void refitAndRotateUpFrom(std::uint32_t index);
    void refitUpFrom(std::uint32_t index);
    std::uint32_t rotate(std::uint32_t index);  // returns the node the moved child went into, or kNull
    void swapWithGrandchild(std::uint32_t parent, std::uint32_t child, std::uint32_t grandchild);
    // Builds a subtree top-down over detached leaves, each node's split at the middle of its
    // leaves' centres along their widest axis; returns its root. A binned surface-area split gave
    // pile1k's trees a third of the area but took 160 us to build, against 60, and its pair
    // queries were no faster.
    struct BuildItem {
        Vec3 centre;  // doubled (min + max): only the centres' order and spread matter
        std::uint32_t leaf;
    };
    std::uint32_t buildSubtree(BuildItem* first, BuildItem* last, int depth);

    AabbTreeSettings settings_;
    std::vector<Node> nodes_;
    std::uint32_t root_ = kNull;
    std::uint32_t freeList_ = kNull;
    std::size_t nodeCount_ = 0;
    std::size_t proxyCount_ = 0;
    std::vector<BuildItem> buildItems_;  // moveProxies' scratch, kept for its capacity
};

template <typename Callback>
void DynamicAabbTree::query(const Aabb& box, Callback&& callback) const {
    if (root_ == kNull) return;
    detail::NodeStack stack(nodes_[root_].height);
    stack.push(root_);
    while (!stack.empty()) {
        const Node& node = nodes_[stack.pop()];
        if (!node.box.overlaps(box)) continue;
        if (node.isLeaf()) {
            if (!detail::invokeContinue(callback, static_cast<ProxyId>(&node - nodes_.data()))) return;
        } else {
            stack.push(node.child1);
            stack.push(node.child2);
        }
    }
}

template <typename Callback>
void DynamicAabbTree::rayCast(const Vec3& origin, const Vec3& direction, float maxFraction,
                              Callback&& callback) const {
    if (root_ == kNull || !(maxFraction >= 0.0f)) return;
    const PreparedRay ray(origin, direction);
    detail::NodeStack stack(nodes_[root_].height);
    stack.push(root_);
    while (!stack.empty()) {
        const std::uint32_t index = stack.pop();
        const Node& node = nodes_[index];
        float entry;
        if (!intersectRayAabb(ray, node.box, maxFraction, entry)) continue;
        if (node.isLeaf()) {
            const float result = callback(static_cast<ProxyId>(index), maxFraction);
            if (result <= 0.0f) return;
            maxFraction = std::min(maxFraction, result);
        } else {
            stack.push(node.child1);
            stack.push(node.child2);
        }
    }
}

}  // namespace simcore
