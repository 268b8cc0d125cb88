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

void Islands::unite(std::size_t a, std::size_t b) {
    // The smaller index becomes the root, so islands do not depend on contact or joint order.
    const std::uint32_t rootA = find(static_cast<std::uint32_t>(a));
    const std::uint32_t rootB = find(static_cast<std::uint32_t>(b));
    if (rootA < rootB) parent_[rootB] = rootA;
    else if (rootB < rootA) parent_[rootA] = rootB;
}

void Islands::build(const BodyStorage& bodies, const std::vector<Contact>& contacts, const JointStorage& joints) {
    parent_.resize(bodies.size());
    std::iota(parent_.begin(), parent_.end(), 0u);
    auto isDynamic = [&bodies](std::size_t i) { return bodies.motion[i] == MotionType::Dynamic; };
    for (const Contact& contact : contacts) {
        if (!contact.hasPoints()) continue;
        const std::size_t a = bodies.denseIndexOfSlot(contact.slotA);
        const std::size_t b = bodies.denseIndexOfSlot(contact.slotB);
        if (isDynamic(a) && isDynamic(b)) unite(a, b);
    }
    for (const Joint& joint : joints.joints) {
        if (!joint.bodyB.isValid()) continue;  // the world joins nothing
        const auto a = static_cast<std::size_t>(bodies.denseIndex(joint.bodyA));
        const auto b = static_cast<std::size_t>(bodies.denseIndex(joint.bodyB));
        if (isDynamic(a) && isDynamic(b)) unite(a, b);
    }
}

}  // namespace simcore
