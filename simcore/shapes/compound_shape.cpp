#include "simcore/shapes/compound_shape.h"

namespace simcore {

CompoundShape::CompoundShape(std::vector<CompoundChild> children) : children_(std::move(children)) {
    childBounds_.reserve(children_.size());
    for (const CompoundChild& child : children_) {
        childBounds_.push_back(worldBounds(child.shape, child.pose));
        bounds_.grow(childBounds_.back());
    }
    // A compound without children still gets a point box so broad phases never see an empty one.
    if (children_.empty()) bounds_ = {Vec3(0.0f), Vec3(0.0f)};
}

}  // namespace simcore
