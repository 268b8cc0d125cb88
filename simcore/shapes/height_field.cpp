#include "simcore/shapes/height_field.h"

#include <algorithm>
#include <limits>

namespace simcore {

namespace {

// The samples of triangle `index`'s three vertices, as (row, column) pairs, and of the vertex across
// each of its edges (the neighbour's vertex off that edge), per the layout in height_field.h.
struct CellTriangle {
    int row, column;
    bool upper;  // the second triangle of the cell: (r,c) (r+1,c+1) (r,c+1)
};

CellTriangle locate(std::uint32_t index, int columns) {
    const std::uint32_t cell = index / 2;
    return {int(cell / std::uint32_t(columns - 1)), int(cell % std::uint32_t(columns - 1)), (index & 1u) != 0};
}

}  // namespace

HeightField::BuildResult HeightField::build(int rows, int columns, float cellSize, float heightScale,
                                            std::vector<float> heights) {
    if (rows < kMinHeightFieldSamples || columns < kMinHeightFieldSamples)
        return {nullptr, "a height field needs at least 2 rows and 2 columns, got " + std::to_string(rows) + " x " +
                             std::to_string(columns)};
    if (2.0 * double(rows - 1) * double(columns - 1) > double(kMaxMeshTriangles))
        return {nullptr, "a height field of " + std::to_string(rows) + " x " + std::to_string(columns) +
                             " samples has more than " + std::to_string(kMaxMeshTriangles) + " triangles"};
    if (heights.size() != std::size_t(rows) * std::size_t(columns))
        return {nullptr, "a height field of " + std::to_string(rows) + " x " + std::to_string(columns) + " needs " +
                             std::to_string(std::size_t(rows) * columns) + " heights, got " + std::to_string(heights.size())};
    if (!(isFinite(cellSize) && cellSize > 0.0f) || float(std::max(rows, columns) - 1) * cellSize > kMaxMeshCoordinate)
        return {nullptr, "the cell size must be positive and the field within " +
                             std::to_string(int(kMaxMeshCoordinate)) + " m, got " + std::to_string(cellSize) + " m"};
    if (!(isFinite(heightScale) && heightScale > 0.0f))
        return {nullptr, "the height scale must be finite and positive, got " + std::to_string(heightScale)};
    for (std::size_t i = 0; i < heights.size(); ++i) {
        const std::string where = "height (row " + std::to_string(i / columns) + ", column " + std::to_string(i % columns) + ")";
        if (!isFinite(heights[i])) return {nullptr, where + " is not finite"};
        if (!(std::abs(heights[i] * heightScale) <= kMaxMeshCoordinate))
            return {nullptr, where + " is beyond " + std::to_string(int(kMaxMeshCoordinate)) + " m once scaled"};
    }

    std::shared_ptr<HeightField> field(new HeightField());
    field->rows_ = rows;
    field->columns_ = columns;
    field->cellSize_ = cellSize;
    field->heightScale_ = heightScale;
    field->heights_ = std::move(heights);
    for (int r = 0; r < rows; r += rows - 1)
        for (int c = 0; c < columns; c += columns - 1) field->bounds_.grow(field->sample(r, c));
    for (float h : field->heights_) {
        field->bounds_.min.y = std::min(field->bounds_.min.y, h * heightScale);
        field->bounds_.max.y = std::max(field->bounds_.max.y, h * heightScale);
    }

    // Edge e of each triangle and the triangle across it, as (row, column, upper) offsets from its
    // cell; see the layout in height_field.h.
    struct Across {
        int dr, dc;
        bool upper;
    };
    constexpr Across kLowerAcross[3] = {{0, -1, true}, {1, 0, true}, {0, 0, true}};
    constexpr Across kUpperAcross[3] = {{0, 0, false}, {0, 1, false}, {-1, 0, false}};
    const std::size_t count = field->triangleCount();
    field->flags_.resize(count);
    for (std::uint32_t t = 0; t < count; ++t) {
        const CellTriangle at = locate(t, columns);
        const Triangle self = field->geometry(t);
        TriangleFeatureFlags edges = 0x7u;  // the field's rim: active
        for (int e = 0; e < 3; ++e) {
            const Across& across = at.upper ? kUpperAcross[e] : kLowerAcross[e];
            const int r = at.row + across.dr, c = at.column + across.dc;
            if (r < 0 || c < 0 || r > rows - 2 || c > columns - 2) continue;
            const Triangle other = field->geometry(2u * std::uint32_t(r * (columns - 1) + c) + (across.upper ? 1u : 0u));
            // The neighbour's vertex off the shared edge: the one not equal to either end of it.
            const Vec3& a = self.vertices[e];
            const Vec3& b = self.vertices[(e + 1) % 3];
            Vec3 opposite = other.vertices[0];
            for (const Vec3& v : other.vertices)
                if (v != a && v != b) opposite = v;
            if (!isActiveEdge(self.normal, a, other.normal, opposite))
                edges &= TriangleFeatureFlags(~(kEdgeActive0 << e));
        }
        field->flags_[t] = withVertexFlags(edges);
    }
    return {std::move(field), {}};
}

Triangle HeightField::geometry(std::uint32_t index) const {
    const CellTriangle at = locate(index, columns_);
    const int r = at.row, c = at.column;
    Triangle t;
    t.vertices = at.upper ? std::array<Vec3, 3>{sample(r, c), sample(r + 1, c + 1), sample(r, c + 1)}
                          : std::array<Vec3, 3>{sample(r, c), sample(r + 1, c), sample(r + 1, c + 1)};
    // As TriangleMesh::build computes it, so a field and its mesh agree to the bit.
    const Vec3 n = glm::cross(t.vertices[1] - t.vertices[0], t.vertices[2] - t.vertices[0]);
    t.normal = n / glm::length(n);
    return t;
}

std::optional<SurfaceRayHit> HeightField::rayCast(const Vec3& origin, const Vec3& direction, float maxFraction) const {
    if (!isFinite(origin) || !isFinite(direction) || !(maxFraction >= 0.0f) || lengthSquared(direction) == 0.0f)
        return std::nullopt;
    // The part of the ray inside the field's bounds.
    float enter = 0.0f, leave = maxFraction;
    for (int k = 0; k < 3; ++k) {
        if (direction[k] == 0.0f) {
            if (origin[k] < bounds_.min[k] || origin[k] > bounds_.max[k]) return std::nullopt;
            continue;
        }
        float t0 = (bounds_.min[k] - origin[k]) / direction[k];
        float t1 = (bounds_.max[k] - origin[k]) / direction[k];
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
        if (enter > leave) return std::nullopt;
    }
    // Walk the cells the ray crosses in x and z, in order (Amanatides and Woo's grid traversal).
    const Vec3 start = origin + enter * direction;
    int c = std::clamp(int(std::floor(start.x / cellSize_)), 0, columns_ - 2);
    int r = std::clamp(int(std::floor(start.z / cellSize_)), 0, rows_ - 2);
    const float infinity = std::numeric_limits<float>::infinity();
    const int stepC = direction.x > 0.0f ? 1 : -1, stepR = direction.z > 0.0f ? 1 : -1;
    auto boundary = [&](int cell, int step, float o, float d) {
        if (d == 0.0f) return infinity;
        return (float(cell + (step > 0 ? 1 : 0)) * cellSize_ - o) / d;
    };
    float nextC = boundary(c, stepC, origin.x, direction.x);
    float nextR = boundary(r, stepR, origin.z, direction.z);
    const float deltaC = direction.x != 0.0f ? cellSize_ / std::abs(direction.x) : infinity;
    const float deltaR = direction.z != 0.0f ? cellSize_ / std::abs(direction.z) : infinity;
    std::optional<SurfaceRayHit> best;
    while (true) {
        const std::uint32_t first = 2u * std::uint32_t(r * (columns_ - 1) + c);
        for (std::uint32_t t = first; t < first + 2; ++t) {
            auto hit = rayCastTriangle(triangle(t), origin, direction, best ? best->fraction : leave);
            if (hit && (!best || hit->fraction < best->fraction)) {
                hit->triangle = t;
                best = hit;
            }
        }
        const float exit = std::min(nextC, nextR);
        if ((best && best->fraction <= exit) || exit > leave) break;
        if (nextC < nextR) {
            c += stepC;
            nextC += deltaC;
        } else {
            r += stepR;
            nextR += deltaR;
        }
        if (c < 0 || r < 0 || c > columns_ - 2 || r > rows_ - 2) break;
    }
    return best;
}

}  // namespace simcore
