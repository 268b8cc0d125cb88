#include "simcore/collision/pair_table.h"

#include <cassert>

namespace simcore {

std::size_t PairTable::slotOf(std::uint64_t key) const {
    // Fibonacci hashing spreads the (a << 32 | b) keys, whose low bits alone cluster badly.
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 20) & (entries_.size() - 1);
}

std::uint32_t PairTable::find(std::uint64_t key) const {
    if (entries_.empty()) return kNotFound;
    const std::size_t mask = entries_.size() - 1;
    for (std::size_t i = slotOf(key);; i = (i + 1) & mask) {
        if (entries_[i].key == key) return entries_[i].value;
        if (entries_[i].key == kEmpty) return kNotFound;
    }
}

void PairTable::insert(std::uint64_t key, std::uint32_t value) {
    assert(find(key) == kNotFound);
    if (2 * (size_ + 1) > entries_.size()) grow();  // load factor <= 1/2 keeps probes short
    const std::size_t mask = entries_.size() - 1;
    std::size_t i = slotOf(key);
    while (entries_[i].key != kEmpty) i = (i + 1) & mask;
    entries_[i] = {key, value};
    ++size_;
}

void PairTable::assign(std::uint64_t key, std::uint32_t value) {
    const std::size_t mask = entries_.size() - 1;
    std::size_t i = slotOf(key);
    while (entries_[i].key != key) i = (i + 1) & mask;
    entries_[i].value = value;
}

void PairTable::erase(std::uint64_t key) {
    const std::size_t mask = entries_.size() - 1;
    std::size_t hole = slotOf(key);
    while (entries_[hole].key != key) hole = (hole + 1) & mask;
    // Backward shift: move later entries of the cluster into the hole when their home slot allows,
    // so no tombstones accumulate.
    for (std::size_t next = (hole + 1) & mask; entries_[next].key != kEmpty; next = (next + 1) & mask) {
        const std::size_t home = slotOf(entries_[next].key);
        const bool homeBetween = hole <= next ? (hole < home && home <= next) : (hole < home || home <= next);
        if (!homeBetween) {
            entries_[hole] = entries_[next];
            hole = next;
        }
    }
    entries_[hole] = Entry{};
    --size_;
}

void PairTable::clear() {
    for (Entry& e : entries_) e = Entry{};
    size_ = 0;
}

void PairTable::grow() {
    std::vector<Entry> old = std::move(entries_);
    entries_.assign(old.empty() ? 64 : 2 * old.size(), Entry{});
    size_ = 0;
    for (const Entry& e : old)
        if (e.key != kEmpty) insert(e.key, e.value);
}

}  // namespace simcore
