#include "simcore/collision/broad_phase.h"

#include <algorithm>
#include <cassert>

namespace simcore {

namespace {

BodyPair orderedPair(std::uint32_t x, std::uint32_t y) { return x < y ? BodyPair{x, y} : BodyPair{y, x}; }

// Sorting 64-bit keys is faster than comparing the two fields.
void sortAndDeduplicate(std::vector<BodyPair>& pairs) {
    const auto key = [](const BodyPair& p) { return (std::uint64_t{p.a} << 32) | p.b; };
    std::sort(pairs.begin(), pairs.end(), [&](const BodyPair& x, const BodyPair& y) { return key(x) < key(y); });
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

}  // namespace

BroadPhase::BroadPhase(const AabbTreeSettings& settings, std::size_t initialProxyCapacity)
    : tree_(settings, initialProxyCapacity) {
    flags_.resize(tree_.capacity(), 0);
    moveBuffer_.reserve(initialProxyCapacity);
}

ProxyId BroadPhase::addProxy(const Aabb& tight, std::uint32_t userData, bool active, const Vec3& displacement) {
    const ProxyId id = tree_.createProxy(tight, userData, displacement);
    if (flags_.size() < tree_.capacity()) flags_.resize(tree_.capacity(), 0);  // the pool grows geometrically
    flags_[id] = static_cast<std::uint8_t>((flags_[id] & kBuffered) | kAlive | (active ? kActive : 0));
    markMoved(id);
    return id;
}

void BroadPhase::removeProxy(ProxyId id) {
    assert(flags_[id] & kAlive);
    tree_.destroyProxy(id);
    flags_[id] &= kBuffered;  // its buffer entry is skipped, then cleared, by updatePairs
}

bool BroadPhase::moveProxy(ProxyId id, const Aabb& tight, const Vec3& displacement) {
    assert(flags_[id] & kAlive);
    if (!tree_.moveProxy(id, tight, displacement)) return false;
    markMoved(id);
    return true;
}

void BroadPhase::moveProxies(const std::vector<DynamicAabbTree::ProxyMove>& moves) {
    for (const DynamicAabbTree::ProxyMove& move : moves) {
        assert(flags_[move.id] & kAlive);
        markMoved(move.id);
    }
    tree_.moveProxies(moves);
}

void BroadPhase::setActive(ProxyId id, bool active) {
    assert(flags_[id] & kAlive);
    const bool wasActive = isActive(id);
    if (active) {
        flags_[id] |= kActive;
        if (!wasActive) markMoved(id);
    } else {
        flags_[id] &= static_cast<std::uint8_t>(~kActive);
    }
}

void BroadPhase::touchProxy(ProxyId id) {
    assert(flags_[id] & kAlive);
    markMoved(id);
}

void BroadPhase::markMoved(ProxyId id) {
    if (!(flags_[id] & kBuffered)) moveBuffer_.push_back(id);
    flags_[id] |= kMoved | kBuffered;
}

std::size_t BroadPhase::movedCount() const {
    return static_cast<std::size_t>(
        std::count_if(moveBuffer_.begin(), moveBuffer_.end(), [this](ProxyId id) { return (flags_[id] & kMoved) != 0; }));
}

void BroadPhase::updatePairs(std::vector<BodyPair>& pairs, TaskPool& pool) {
    // Moved proxies per chunk: each query costs about half a microsecond (pile1k, where a thousand
    // falling bodies leave their fat boxes in the same step).
    constexpr std::size_t kQueryGrain = 64;
    const std::size_t chunks = TaskPool::chunkCount(moveBuffer_.size(), kQueryGrain);
    if (chunkPairs_.size() < chunks) chunkPairs_.resize(chunks);  // only when the work grew
    pool.parallelFor(moveBuffer_.size(), kQueryGrain, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
        std::vector<BodyPair>& found = chunkPairs_[chunk];
        found.clear();
        for (std::size_t k = begin; k < end; ++k) findPairsOfMoved(moveBuffer_[k], found);
    });
    pairs.clear();
    for (std::size_t chunk = 0; chunk < chunks; ++chunk)
        pairs.insert(pairs.end(), chunkPairs_[chunk].begin(), chunkPairs_[chunk].end());
    clearMovedAndSort(pairs);
}

void BroadPhase::updatePairs(std::vector<BodyPair>& pairs) {
    pairs.clear();
    for (const ProxyId moved : moveBuffer_) findPairsOfMoved(moved, pairs);
    clearMovedAndSort(pairs);
}

void BroadPhase::clearMovedAndSort(std::vector<BodyPair>& pairs) {
    for (const ProxyId id : moveBuffer_) flags_[id] &= static_cast<std::uint8_t>(~(kMoved | kBuffered));
    moveBuffer_.clear();
    sortAndDeduplicate(pairs);
}

void BroadPhase::findPairsOfMoved(ProxyId moved, std::vector<BodyPair>& pairs) const {
    const std::uint8_t movedFlags = flags_[moved];
    if (!(movedFlags & kMoved)) return;  // removed after it moved
    const bool movedActive = (movedFlags & kActive) != 0;
    const std::uint32_t movedData = tree_.userData(moved);
    tree_.query(tree_.fatBounds(moved), [&](ProxyId other) {
        if (other == moved) return;
        const std::uint8_t otherFlags = flags_[other];
        if ((otherFlags & kMoved) && other < moved) return;  // reported when `other` queries
        if (!movedActive && !(otherFlags & kActive)) return;
        const std::uint32_t otherData = tree_.userData(other);
        if (otherData == movedData) return;
        pairs.push_back(orderedPair(movedData, otherData));
    });
}

void BroadPhase::findAllPairs(std::vector<BodyPair>& pairs) const {
    pairs.clear();
    // Every reported pair has an active side, so querying from active proxies finds them all.
    for (ProxyId id = 0; id < flags_.size(); ++id) {
        if ((flags_[id] & (kAlive | kActive)) != (kAlive | kActive)) continue;
        const std::uint32_t data = tree_.userData(id);
        tree_.query(tree_.fatBounds(id), [&](ProxyId other) {
            if (other == id) return;
            if ((flags_[other] & kActive) && other < id) return;  // found from `other` too
            const std::uint32_t otherData = tree_.userData(other);
            if (otherData == data) return;
            pairs.push_back(orderedPair(data, otherData));
        });
    }
    sortAndDeduplicate(pairs);
}

}  // namespace simcore
