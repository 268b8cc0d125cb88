#pragma once
// Map from an unordered body pair to a contact index: open addressing with linear probing and
// backward-shift deletion, so lookups touch one cache line and steady-state use never allocates.

#include <cstdint>
#include <vector>

namespace simcore {

class PairTable {
public:
    static constexpr std::uint32_t kNotFound = 0xFFFFFFFFu;

    static std::uint64_t key(std::uint32_t a, std::uint32_t b) {
        return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
    }

    std::uint32_t find(std::uint64_t key) const;
    void insert(std::uint64_t key, std::uint32_t value);  // key must be absent
    void assign(std::uint64_t key, std::uint32_t value);  // key must be present
    void erase(std::uint64_t key);                        // key must be present
    void clear();
    std::size_t size() const { return size_; }

private:
    struct Entry {
        std::uint64_t key = kEmpty;
        std::uint32_t value = 0;
    };
    static constexpr std::uint64_t kEmpty = ~std::uint64_t(0);

    std::size_t slotOf(std::uint64_t key) const;  // home slot
    void grow();

    std::vector<Entry> entries_;  // size is a power of two (or zero)
    std::size_t size_ = 0;
};

}  // namespace simcore
