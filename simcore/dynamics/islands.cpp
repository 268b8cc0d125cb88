#include "simcore/dynamics/islands.h"

#include <numeric>

namespace simcore {

std::uint32_t Islands::find(std::uint32_t i) {
    while (parent_[i] != i) {
        parent_[i] = parent_[parent_[i]];  // path halving
        i = parent_[i];
    }
    return i;
}

void Islands::build(const BodyStorage& bodies, const std::vector<Contact>& contacts) {
    parent_.resize(bodies.size());
    std::iota(parent_.begin(), parent_.end(), 0u);
    for (const Contact& contact : contacts) {
        if (contact.manifold.pointCount == 0) continue;
        const std::size_t a = bodies.denseIndexOfSlot(contact.slotA);
        const std::size_t b = bodies.denseIndexOfSlot(contact.slotB);
        if (bodies.motion[a] != MotionType::Dynamic || bodies.motion[b] != MotionType::Dynamic) continue;
        const std::uint32_t rootA = find(static_cast<std::uint32_t>(a));
        const std::uint32_t rootB = find(static_cast<std::uint32_t>(b));
        // The smaller index becomes the root, so islands do not depend on contact order.
        if (rootA < rootB) parent_[rootB] = rootA;
        else if (rootB < rootA) parent_[rootA] = rootB;
    }
}

}  // namespace simcore
