#pragma once
// A static terrain as a regular grid of heights: cheaper than the same surface as a TriangleMesh
// (one float per sample, no BVH: the cells under a box are found by dividing by the cell size).
// It offers the mesh's surface interface (triangle(), forEachTriangleOverlapping(), rayCast()), so
// collideTriangleConvex and the contact manager serve both.
//
// Layout, in the field's local frame: sample (row r, column c) lies at
// (c * cellSize, heights[r * columns + c] * heightScale, r * cellSize), so columns run along +x
// and rows along +z from the origin. Each cell (r, c) is two triangles facing +y, split along its
// diagonal from sample (r, c) to (r + 1, c + 1): triangle 2k = (r,c) (r+1,c) (r+1,c+1) and
// 2k + 1 = (r,c) (r+1,c+1) (r,c+1), with k = r * (columns - 1) + c. Active edges follow the
// mesh's rules (triangle_mesh.h), computed once at build, so a field and the mesh made of its
// triangles collide alike.

#include "simcore/shapes/triangle_mesh.h"

#include <cmath>

namespace simcore {

constexpr int kMinHeightFieldSamples = 2;  // per side: one cell

class HeightField {
public:
    struct BuildResult {
        std::shared_ptr<const HeightField> field;  // null on failure
        std::string error;                         // why it failed, naming the value
    };

    // Fails on: fewer than 2 rows or columns, more than kMaxMeshTriangles triangles, a heights
    // array of another size than rows * columns, a cell size or height scale that is not finite
    // and positive, a non-finite height, or a sample beyond kMaxMeshCoordinate.
    static BuildResult build(int rows, int columns, float cellSize, float heightScale, std::vector<float> heights);

    int rows() const { return rows_; }
    int columns() const { return columns_; }
    float cellSize() const { return cellSize_; }     // m
    float heightScale() const { return heightScale_; }
    const std::vector<float>& heights() const { return heights_; }  // unscaled, as given
    std::size_t triangleCount() const { return std::size_t(2) * (rows_ - 1) * (columns_ - 1); }
    Vec3 sample(int row, int column) const {
        return {float(column) * cellSize_, heights_[std::size_t(row) * columns_ + column] * heightScale_,
                float(row) * cellSize_};
    }
    Triangle triangle(std::uint32_t index) const {
        Triangle t = geometry(index);
        t.flags = flags_[index];
        return t;
    }
    const Aabb& bounds() const { return bounds_; }

    // Calls visit(triangleIndex) for every triangle whose bounding box overlaps `box`, each once.
    // Allocates nothing.
    template <class Visit>
    void forEachTriangleOverlapping(const Aabb& box, Visit&& visit) const;

    // Nearest hit along origin + t * direction, t in [0, maxFraction]; two-sided. Walks the cells
    // under the ray in order and stops at the first cell with a hit.
    std::optional<SurfaceRayHit> rayCast(const Vec3& origin, const Vec3& direction, float maxFraction = 1.0f) const;

private:
    HeightField() = default;
    Triangle geometry(std::uint32_t index) const;  // vertices and normal; flags left all active

    int rows_ = 0, columns_ = 0;
    float cellSize_ = 1.0f, heightScale_ = 1.0f;
    std::vector<float> heights_;
    std::vector<TriangleFeatureFlags> flags_;
    Aabb bounds_;
};

template <class Visit>
void HeightField::forEachTriangleOverlapping(const Aabb& box, Visit&& visit) const {
    if (!box.overlaps(bounds_)) return;
    // One cell of margin each side; the triangles' own bounds then decide exactly.
    const int c0 = std::max(0, int(std::floor(box.min.x / cellSize_)) - 1);
    const int c1 = std::min(columns_ - 2, int(std::floor(box.max.x / cellSize_)) + 1);
    const int r0 = std::max(0, int(std::floor(box.min.z / cellSize_)) - 1);
    const int r1 = std::min(rows_ - 2, int(std::floor(box.max.z / cellSize_)) + 1);
    for (int r = r0; r <= r1; ++r)
        for (int c = c0; c <= c1; ++c) {
            const std::uint32_t first = 2u * std::uint32_t(r * (columns_ - 1) + c);
            for (std::uint32_t t = first; t < first + 2; ++t) {
                const Triangle tri = geometry(t);
                Aabb bounds;
                for (const Vec3& v : tri.vertices) bounds.grow(v);
                if (bounds.overlaps(box)) visit(t);
            }
        }
}

}  // namespace simcore
