#pragma once
// Broad phase: finds the pairs of bodies whose fat boxes overlap, so the narrow phase only looks at
// those. Owns a DynamicAabbTree and remembers which proxies moved since the last update.
//
// Design: the broad phase does not keep the pair set. updatePairs reports every overlapping pair in
// which at least one proxy moved since the previous call (Box2D's design): the work is proportional
// to what moved, not to how many pairs exist. The caller (the contact manager) adds the reported
// pairs it does not have yet and drops its pairs whose fat boxes no longer overlap (testOverlap);
// then its set equals findAllPairs. findAllPairs reports every overlapping pair at once, for a
// caller that rebuilds its pairs each step.
//
// Filtering: each proxy is active or not. A pair is reported only when at least one side is
// active, so give static and sleeping bodies inactive proxies: static-static, sleeping-sleeping and
// static-sleeping pairs are never reported. Proxies with equal userData (shapes of one body) never
// pair with each other.
//
// Pairs are of userData values, ordered (min, max), sorted, each pair once: the order depends only
// on the set of pairs, never on the tree's shape, so steps are reproducible.

#include "simcore/collision/dynamic_aabb_tree.h"
#include "simcore/parallel/task_pool.h"

#include <compare>
#include <cstdint>
#include <vector>

namespace simcore {

struct BodyPair {
    std::uint32_t a = 0;  // the smaller userData
    std::uint32_t b = 0;  // the larger
    friend auto operator<=>(const BodyPair&, const BodyPair&) = default;
};

class BroadPhase {
public:
    explicit BroadPhase(const AabbTreeSettings& settings = {}, std::size_t initialProxyCapacity = 16);

    // A new proxy counts as moved: its pairs are reported by the next updatePairs.
    ProxyId addProxy(const Aabb& tight, std::uint32_t userData, bool active, const Vec3& displacement = Vec3(0.0f));
    void removeProxy(ProxyId id);
    // Returns true when the fat box changed (the proxy then counts as moved).
    bool moveProxy(ProxyId id, const Aabb& tight, const Vec3& displacement);
    // Whether moveProxy would change the proxy's fat box (DynamicAabbTree::leavesFatBox).
    bool leavesFatBox(ProxyId id, const Aabb& tight, const Vec3& displacement) const {
        return tree_.leavesFatBox(id, tight, displacement);
    }
    // moveProxy for many proxies at once, each of which leaves its fat box
    // (DynamicAabbTree::moveProxies).
    void moveProxies(const std::vector<DynamicAabbTree::ProxyMove>& moves);
    // Activating a proxy counts as a move, so a body that wakes up gets its pairs reported again.
    void setActive(ProxyId id, bool active);
    bool isActive(ProxyId id) const { return (flags_[id] & kActive) != 0; }
    // Marks a proxy moved without changing its box (e.g. after its collision filter changed).
    void touchProxy(ProxyId id);

    // Overlapping pairs with at least one side moved since the last call; `pairs` is cleared first
    // and keeps its capacity, so a caller that reuses it allocates nothing in steady state. The
    // moved proxies' queries only read the tree, so they run on the pool; the pairs are the same
    // for any thread count.
    void updatePairs(std::vector<BodyPair>& pairs, TaskPool& pool);
    void updatePairs(std::vector<BodyPair>& pairs);  // on the calling thread alone
    // Every overlapping pair; leaves the moved set alone.
    void findAllPairs(std::vector<BodyPair>& pairs) const;

    bool testOverlap(ProxyId a, ProxyId b) const { return tree_.fatBounds(a).overlaps(tree_.fatBounds(b)); }
    const Aabb& fatBounds(ProxyId id) const { return tree_.fatBounds(id); }
    std::uint32_t userData(ProxyId id) const { return tree_.userData(id); }
    std::size_t proxyCount() const { return tree_.proxyCount(); }
    std::size_t movedCount() const;

    // For queries and ray casts against the fat boxes.
    const DynamicAabbTree& tree() const { return tree_; }

private:
    enum Flag : std::uint8_t {
        kAlive = 1,
        kActive = 2,
        kMoved = 4,     // moved since the last updatePairs (implies kBuffered)
        kBuffered = 8,  // listed in moveBuffer_ (stays set if the proxy is removed meanwhile)
    };
    void markMoved(ProxyId id);
    // Appends the pairs of one moved proxy that updatePairs reports.
    void findPairsOfMoved(ProxyId moved, std::vector<BodyPair>& pairs) const;
    // updatePairs' end, once every moved proxy's pairs are in `pairs`.
    void clearMovedAndSort(std::vector<BodyPair>& pairs);

    DynamicAabbTree tree_;
    std::vector<std::uint8_t> flags_;    // per proxy id
    std::vector<ProxyId> moveBuffer_;    // each id at most once
    std::vector<std::vector<BodyPair>> chunkPairs_;  // updatePairs' by chunk of moveBuffer_; reused
};

}  // namespace simcore
