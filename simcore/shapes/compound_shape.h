#pragma once
// A compound shape's children: convex shapes, each placed in the body frame. Shared and immutable
// like a hull, so a Shape stays a small value. Each child's bounds in the body frame are kept for
// the contact manager's mid-phase; a short list scanned in order is enough at the sizes the
// loader allows (limits::kMaxCompoundChildren), and keeps the pairs it finds in a fixed order.

#include "simcore/math/aabb.h"
#include "simcore/math/math.h"
#include "simcore/shapes/shape.h"

#include <vector>

namespace simcore {

struct CompoundChild {
    Shape shape;     // convex (validation::validateShape checks)
    Transform pose;  // in the body frame: the child's local frame seen from the body's origin
};

class CompoundShape {
public:
    explicit CompoundShape(std::vector<CompoundChild> children);

    const std::vector<CompoundChild>& children() const { return children_; }
    std::size_t size() const { return children_.size(); }
    const Aabb& childBounds(std::size_t index) const { return childBounds_[index]; }  // body frame
    const Aabb& bounds() const { return bounds_; }  // all children, body frame

private:
    std::vector<CompoundChild> children_;
    std::vector<Aabb> childBounds_;
    Aabb bounds_;
};

// The child's transform in the world for a body at `bodyTransform`.
inline Transform childTransform(const CompoundChild& child, const Transform& bodyTransform) {
    return {bodyTransform.apply(child.pose.position), bodyTransform.rotation * child.pose.rotation};
}

}  // namespace simcore
