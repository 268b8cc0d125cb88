#pragma once
// Stable handles for elements kept densely packed in parallel arrays. A handle names a slot and
// the slot's generation; the slot table maps slots to dense indices. Removing an element moves the
// last one into its place (the owner swaps its arrays, the map follows), so other handles stay
// valid, and bumps the slot's generation, so handles to the removed element are detected.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace simcore {

// Id: a struct with std::uint32_t members `index` (the slot) and `generation`.
template <typename Id>
class SlotMap {
public:
    std::size_t size() const { return denseToSlot_.size(); }

    // Registers an element appended at dense index size(); returns its handle.
    Id add() {
        std::uint32_t slot;
        if (!freeSlots_.empty()) {
            slot = freeSlots_.back();
            freeSlots_.pop_back();
        } else {
            slot = static_cast<std::uint32_t>(slotToDense_.size());
            slotToDense_.push_back(0);
            slotGeneration_.push_back(0);
        }
        slotToDense_[slot] = static_cast<std::uint32_t>(denseToSlot_.size());
        denseToSlot_.push_back(slot);
        return {slot, slotGeneration_[slot]};
    }

    // The element at `dense` was removed by moving the last element into its place.
    void removeAt(std::size_t dense) {
        const std::uint32_t removedSlot = denseToSlot_[dense];
        const std::uint32_t movedSlot = denseToSlot_.back();
        denseToSlot_[dense] = movedSlot;
        denseToSlot_.pop_back();
        slotToDense_[movedSlot] = static_cast<std::uint32_t>(dense);
        ++slotGeneration_[removedSlot];  // stale handles to this slot now fail denseIndex()
        freeSlots_.push_back(removedSlot);
    }

    // Dense index of a live element, or -1 for a stale or invalid handle.
    int denseIndex(Id id) const {
        if (id.index >= slotToDense_.size() || slotGeneration_[id.index] != id.generation) return -1;
        const std::uint32_t dense = slotToDense_[id.index];
        if (dense >= denseToSlot_.size() || denseToSlot_[dense] != id.index) return -1;
        return static_cast<int>(dense);
    }

    Id idAt(std::size_t dense) const {
        const std::uint32_t slot = denseToSlot_[dense];
        return {slot, slotGeneration_[slot]};
    }

    std::size_t denseIndexOfSlot(std::uint32_t slot) const { return slotToDense_[slot]; }  // slot must be live

private:
    std::vector<std::uint32_t> denseToSlot_;
    std::vector<std::uint32_t> slotToDense_;
    std::vector<std::uint32_t> slotGeneration_;
    std::vector<std::uint32_t> freeSlots_;
};

}  // namespace simcore
