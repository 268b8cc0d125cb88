// EPA on a polytope with fixed capacity. Faces are triangles wound counter-clockwise seen from
// outside, each knowing its neighbour across every edge. One expansion:
//   1. take the face nearest the origin and C's support point w along its normal;
//   2. stop if w is not meaningfully beyond the face (the face lies on C's surface);
//   3. otherwise walk from that face across edges, depth first, removing every face w sees; the
//      edges where the walk meets a face w does not see form the horizon, a closed loop;
//   4. fan new faces from w to the horizon.
// Walking over neighbours (rather than testing every face) keeps the removed region connected, so
// the horizon stays a single loop even when rounding makes the polytope slightly non-convex.
//
// The nearest face's distance only grows (it is a lower bound on the depth), while dot(w, normal)
// along any face normal is an upper bound along that direction. If the loop has to give up
// (capacity, broken horizon), the direction with the smallest upper bound is reported: moving B by
// that much along it certainly separates the shapes.

#include "simcore/collision/epa.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace simcore {
namespace {

// Planes, distances and weights are computed in double from the float support points: faces near
// the origin are spanned by points metres away, and float would lose the depth's last digits (and
// the polytope its convexity) to cancellation. The points themselves stay float.
using DVec3 = glm::dvec3;

constexpr double kFloatEpsilon = std::numeric_limits<float>::epsilon();
// The nearest face is on C's surface when the support point is no further beyond it than this
// fraction of the depth...
constexpr double kRelativeTolerance = 1e-4;
// ...or than this fraction of the coordinates' size, the rounding of the support points themselves
// (depths near zero: touching shapes).
constexpr double kAbsoluteTolerance = 8.0 * kFloatEpsilon;
// Triangles thinner than this (height against their longest edge) have no trustworthy normal.
constexpr double kDegenerateRatio = 1e-9;

// No member initialisers, here and in PolytopeVertex: the polytope's arrays (30 kB) are left
// uninitialised, and a slot is cleared when it is handed out.
struct Face {
    std::array<int, 3> vertex;
    std::array<int, 3> neighbor;             // face across edge i (vertex[i] -> vertex[i + 1])
    std::array<std::uint8_t, 3> neighborEdge;  // the index of that edge in the neighbour
    DVec3 normal;                            // outward unit normal (zero if degenerate)
    double distance;                         // signed distance of the plane from the origin
    bool alive;
    bool degenerate;
};

struct PolytopeVertex {
    Vec3 w;  // a - b
    Vec3 a;  // on A's core
    Vec3 b;  // on B's core
};

struct HorizonEdge {
    int face;  // the face w does not see
    int edge;  // its edge on the horizon
};

double magnitudeOf(const SupportPoint& p) { return std::sqrt(double(std::max(lengthSquared(p.a), lengthSquared(p.b)))); }

Vec3 anyPerpendicular(const Vec3& v) {
    const Vec3 axis = std::abs(v.x) < 0.57f * glm::length(v) ? Vec3(1.0f, 0.0f, 0.0f) : Vec3(0.0f, 1.0f, 0.0f);
    return glm::normalize(glm::cross(v, axis));
}

class Polytope {
public:
    int vertexCount() const { return vertexCount_; }
    int faceSlots() const { return faceSlots_; }
    const PolytopeVertex& vertex(int i) const { return vertices_[i]; }
    DVec3 position(int i) const { return DVec3(vertices_[i].w); }
    const Face& face(int i) const { return faces_[i]; }

    int addVertex(const SupportPoint& p) {
        if (vertexCount_ == kEpaMaxVertices) return -1;
        vertices_[vertexCount_] = {p.w, p.a, p.b};
        return vertexCount_++;
    }

    // Four points spanning a volume; the origin is inside or on the boundary.
    void initTetrahedron(const std::array<SupportPoint, 4>& points) {
        for (const SupportPoint& p : points) addVertex(p);
        const DVec3 p0 = position(0);
        const double volume = glm::dot(position(1) - p0, glm::cross(position(2) - p0, position(3) - p0));
        // With a negative volume, face (0, 1, 2) faces away from vertex 3, i.e. outwards.
        if (volume > 0.0) std::swap(vertices_[1], vertices_[2]);
        const int triangles[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
        for (const auto& t : triangles) {
            Face& f = faces_[allocateFace()];
            f.vertex = {t[0], t[1], t[2]};
            f.alive = true;
            computePlane(f);
        }
        // Each edge u -> v meets its twin v -> u in exactly one other face.
        for (int f = 0; f < 4; ++f) {
            for (int e = 0; e < 3; ++e) {
                const int u = faces_[f].vertex[e];
                const int v = faces_[f].vertex[(e + 1) % 3];
                for (int g = 0; g < 4; ++g) {
                    for (int j = 0; j < 3; ++j) {
                        if (g != f && faces_[g].vertex[j] == v && faces_[g].vertex[(j + 1) % 3] == u) {
                            faces_[f].neighbor[e] = g;
                            faces_[f].neighborEdge[e] = std::uint8_t(j);
                        }
                    }
                }
            }
        }
    }

    int nearestFace() const {
        int best = -1;
        double bestDistance = std::numeric_limits<double>::infinity();
        for (int i = 0; i < faceSlots_; ++i) {
            const Face& f = faces_[i];
            if (f.alive && !f.degenerate && f.distance < bestDistance) {
                bestDistance = f.distance;
                best = i;
            }
        }
        return best;
    }

    // Replaces the faces vertex `apex` sees, starting from `seenFace`, by a fan from the apex.
    // False if the horizon is not a single loop or the faces do not fit; the polytope is then unusable.
    bool expand(int seenFace, int apex) {
        const DVec3 w = position(apex);
        horizonCount_ = 0;
        removedCount_ = 0;
        faces_[seenFace].alive = false;
        removed_[removedCount_++] = seenFace;
        for (int e = 0; e < 3; ++e) walk(faces_[seenFace].neighbor[e], faces_[seenFace].neighborEdge[e], w);
        if (horizonCount_ < 3) return false;

        // The horizon must be one loop: every edge's end vertex is exactly one other edge's start.
        std::array<int, kEpaMaxFaces>& next = scratch_;
        for (int k = 0; k < horizonCount_; ++k) {
            const int end = horizonEnd(k);
            int found = -1;
            for (int m = 0; m < horizonCount_; ++m) {
                if (horizonStart(m) != end) continue;
                if (found >= 0) return false;
                found = m;
            }
            if (found < 0 || found == k) return false;
            next[k] = found;
        }
        int loopLength = 1;
        for (int k = next[0]; k != 0 && loopLength <= horizonCount_; k = next[k]) ++loopLength;
        if (loopLength != horizonCount_) return false;

        const int freeSlots = freeCount_ + removedCount_ + (kEpaMaxFaces - faceSlots_);
        if (horizonCount_ > freeSlots) return false;
        for (int i = 0; i < removedCount_; ++i) freeFaces_[freeCount_++] = removed_[i];

        std::array<int, kEpaMaxFaces>& created = removed_;  // no longer needed
        for (int k = 0; k < horizonCount_; ++k) {
            const HorizonEdge& h = horizon_[k];
            const int index = allocateFace();
            Face& f = faces_[index];
            f.vertex = {horizonStart(k), horizonEnd(k), apex};
            f.neighbor[0] = h.face;
            f.neighborEdge[0] = std::uint8_t(h.edge);
            f.alive = true;
            faces_[h.face].neighbor[h.edge] = index;
            faces_[h.face].neighborEdge[h.edge] = 0;
            computePlane(f);
            created[k] = index;
        }
        // Around the apex: edge 1 (end -> apex) of one new face is edge 2 (apex -> start) of the next.
        for (int k = 0; k < horizonCount_; ++k) {
            Face& f = faces_[created[k]];
            Face& g = faces_[created[next[k]]];
            f.neighbor[1] = created[next[k]];
            f.neighborEdge[1] = 2;
            g.neighbor[2] = created[k];
            g.neighborEdge[2] = 1;
        }
        return true;
    }

private:
    int allocateFace() {
        const int index = freeCount_ > 0 ? freeFaces_[--freeCount_] : faceSlots_++;
        faces_[index] = Face{};
        return index;
    }

    void computePlane(Face& f) {
        const DVec3 p0 = position(f.vertex[0]);
        const DVec3 p1 = position(f.vertex[1]);
        const DVec3 p2 = position(f.vertex[2]);
        const DVec3 n = glm::cross(p1 - p0, p2 - p0);
        const double length = glm::length(n);
        const double longestSq =
            std::max({glm::dot(p1 - p0, p1 - p0), glm::dot(p2 - p0, p2 - p0), glm::dot(p2 - p1, p2 - p1)});
        f.degenerate = !(length > kDegenerateRatio * longestSq);
        f.normal = length > 0.0 ? n / length : DVec3(0.0);
        // Average over the corners: less biased by which corner is taken as the base.
        f.distance = (glm::dot(f.normal, p0) + glm::dot(f.normal, p1) + glm::dot(f.normal, p2)) / 3.0;
    }

    bool sees(const Face& f, const DVec3& w) const { return glm::dot(f.normal, w) > f.distance; }

    // Entered face `index` across its edge `edge`. Depth first, so a face never gets cut off from
    // the removed region, however the rounding falls.
    void walk(int index, int edge, const DVec3& w) {
        Face& f = faces_[index];
        if (!f.alive) return;
        if (!sees(f, w)) {
            horizon_[horizonCount_++] = {index, edge};
            return;
        }
        f.alive = false;
        removed_[removedCount_++] = index;
        walk(f.neighbor[(edge + 1) % 3], f.neighborEdge[(edge + 1) % 3], w);
        walk(f.neighbor[(edge + 2) % 3], f.neighborEdge[(edge + 2) % 3], w);
    }

    // A horizon edge seen from the new face: it runs opposite to the kept face's edge.
    int horizonStart(int k) const { return faces_[horizon_[k].face].vertex[(horizon_[k].edge + 1) % 3]; }
    int horizonEnd(int k) const { return faces_[horizon_[k].face].vertex[horizon_[k].edge]; }

    std::array<PolytopeVertex, kEpaMaxVertices> vertices_;
    int vertexCount_ = 0;
    std::array<Face, kEpaMaxFaces> faces_;
    int faceSlots_ = 0;  // slots ever used
    std::array<int, kEpaMaxFaces> freeFaces_;
    int freeCount_ = 0;
    std::array<HorizonEdge, kEpaMaxFaces> horizon_;
    int horizonCount_ = 0;
    std::array<int, kEpaMaxFaces> removed_;
    int removedCount_ = 0;
    std::array<int, kEpaMaxFaces> scratch_;
};

// Barycentric weights of point q (on or near the face's plane) in the face's triangle.
std::array<double, 3> faceWeights(const Polytope& polytope, const Face& f, const DVec3& q) {
    const DVec3 a = polytope.position(f.vertex[0]);
    const DVec3 b = polytope.position(f.vertex[1]);
    const DVec3 c = polytope.position(f.vertex[2]);
    const double wa = glm::dot(f.normal, glm::cross(b - q, c - q));
    const double wb = glm::dot(f.normal, glm::cross(c - q, a - q));
    const double wc = glm::dot(f.normal, glm::cross(a - q, b - q));
    const double sum = wa + wb + wc;
    if (!(std::abs(sum) > 0.0)) return {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};
    return {wa / sum, wb / sum, wc / sum};
}

// A flat patch of C is split into several coplanar triangles at the same distance, and the nearest
// by a rounding error need not be the one holding the origin's projection: find the one that does.
int faceHoldingProjection(const Polytope& polytope, int nearest) {
    const Face& f = polytope.face(nearest);
    const DVec3 q = f.distance * f.normal;
    std::array<double, 3> weights = faceWeights(polytope, f, q);
    double bestLeast = std::min({weights[0], weights[1], weights[2]});
    int best = nearest;
    constexpr double kCoplanarCosine = 1.0 - 1e-9;
    for (int i = 0; i < polytope.faceSlots() && bestLeast < 0.0; ++i) {
        const Face& g = polytope.face(i);
        if (i == nearest || !g.alive || g.degenerate || glm::dot(g.normal, f.normal) < kCoplanarCosine) continue;
        weights = faceWeights(polytope, g, q);
        const double least = std::min({weights[0], weights[1], weights[2]});
        if (least > bestLeast) {
            bestLeast = least;
            best = i;
        }
    }
    return best;
}

// Deepest points of a face: the shape points behind the origin's projection onto it, with the
// weights clamped into the triangle against rounding.
void faceWitness(const Polytope& polytope, const Face& f, Vec3& pointA, Vec3& pointB) {
    std::array<double, 3> weights = faceWeights(polytope, f, f.distance * f.normal);
    for (double& w : weights) w = std::max(w, 0.0);
    double sum = weights[0] + weights[1] + weights[2];
    if (!(sum > 0.0)) {
        weights = {1.0, 1.0, 1.0};
        sum = 3.0;
    }
    DVec3 a(0.0), b(0.0);
    for (int k = 0; k < 3; ++k) {
        a += (weights[k] / sum) * DVec3(polytope.vertex(f.vertex[k]).a);
        b += (weights[k] / sum) * DVec3(polytope.vertex(f.vertex[k]).b);
    }
    pointA = Vec3(a);
    pointB = Vec3(b);
}

// Grows GJK's simplex (which holds the origin) to a tetrahedron by support points away from it.
bool startTetrahedron(const CorePair& pair, const GjkSimplex& simplex, float minimumSpan,
                      std::array<SupportPoint, 4>& points) {
    int count = simplex.count;
    for (int i = 0; i < count; ++i) points[i] = simplex.vertices[i];
    if (count == 0) return false;
    if (count == 1) {
        float best = minimumSpan;
        const Vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        for (const Vec3& axis : axes) {
            const SupportPoint p = pair.support(axis);
            const float span = glm::length(p.w - points[0].w);
            if (span > best) {
                best = span;
                points[1] = p;
                count = 2;
            }
        }
        if (count < 2) return false;
    }
    if (count == 2) {
        const Vec3 axis = glm::normalize(points[1].w - points[0].w);
        const Vec3 u = anyPerpendicular(axis);
        const Vec3 v = glm::cross(axis, u);
        float best = minimumSpan;
        for (const Vec3& direction : {u, -u, v, -v}) {
            const SupportPoint p = pair.support(direction);
            const float span = glm::length(glm::cross(p.w - points[0].w, axis));
            if (span > best) {
                best = span;
                points[2] = p;
                count = 3;
            }
        }
        if (count < 3) return false;
    }
    if (count == 3) {
        const Vec3 n = glm::normalize(glm::cross(points[1].w - points[0].w, points[2].w - points[0].w));
        if (!isFinite(n)) return false;
        // The origin lies in the triangle: either side is fine, the farther one gives a sturdier start.
        const SupportPoint above = pair.support(n);
        const SupportPoint below = pair.support(-n);
        const float heightAbove = glm::dot(above.w - points[0].w, n);
        const float heightBelow = glm::dot(points[0].w - below.w, n);
        if (std::max(heightAbove, heightBelow) <= minimumSpan) return false;
        points[3] = heightAbove >= heightBelow ? above : below;
    }
    return true;
}

// Both cores are points or segments: their difference is a point, segment or parallelogram through
// the origin, so the least separating direction is normal to it and the depth is the radius sum
// plus the (rounding-sized) extent of that core difference along it.
EpaResult roundPairPenetration(const CorePair& pair, const GjkCoreResult& core) {
    const auto axisOf = [](const PlacedCore& c) {
        return c.shape->type == ShapeType::Capsule ? c.transform.rotate(Vec3(0.0f, 1.0f, 0.0f)) : Vec3(0.0f);
    };
    const Vec3 axisA = axisOf(pair.a);
    const Vec3 axisB = axisOf(pair.b);
    const Vec3 centres = pair.b.transform.position - pair.a.transform.position;
    Vec3 normal(0.0f);
    const Vec3 across = glm::cross(axisA, axisB);
    if (lengthSquared(across) > 1e-6f) {
        normal = glm::normalize(across);
    } else {
        const Vec3 axis = lengthSquared(axisA) > 0.0f ? axisA : axisB;
        // Prefer the direction between the centres, off the axis.
        const Vec3 offAxis = centres - glm::dot(centres, axis) * axis;
        if (lengthSquared(offAxis) > 1e-12f * (lengthSquared(centres) + 1e-30f) && lengthSquared(offAxis) > 0.0f) {
            normal = glm::normalize(offAxis);
        } else if (lengthSquared(axis) > 0.0f) {
            normal = anyPerpendicular(axis);
        } else {
            normal = Vec3(0.0f, 1.0f, 0.0f);
        }
    }
    if (glm::dot(normal, centres) < 0.0f) normal = -normal;

    EpaResult result;
    const float coreExtent = std::max(glm::dot(pair.support(normal).w, normal), 0.0f);
    result.depth = pair.radiusSum() + coreExtent;
    result.normal = normal;
    result.pointA = core.pointA + pair.a.radius * normal;
    result.pointB = core.pointB - pair.b.radius * normal;
    return result;
}

}  // namespace

EpaResult epaCorePenetration(const CorePair& pair, const GjkSimplex& simplex) {
    EpaResult result;
    double magnitude = 0.0;
    for (int i = 0; i < simplex.count; ++i) magnitude = std::max(magnitude, magnitudeOf(simplex.vertices[i]));

    std::array<SupportPoint, 4> start;
    if (!startTetrahedron(pair, simplex, float(kAbsoluteTolerance * magnitude), start)) {
        // C has no volume around the origin: the shapes just touch (or are flat).
        result.status = EpaStatus::Degenerate;
        result.normal = glm::normalize(pair.b.transform.position - pair.a.transform.position);
        if (!isFinite(result.normal)) result.normal = Vec3(0.0f, 1.0f, 0.0f);
        for (int i = 0; i < simplex.count; ++i) {
            result.pointA += simplex.weights[i] * simplex.vertices[i].a;
            result.pointB += simplex.weights[i] * simplex.vertices[i].b;
        }
        return result;
    }
    for (const SupportPoint& p : start) magnitude = std::max(magnitude, magnitudeOf(p));

    Polytope polytope;
    polytope.initTetrahedron(start);

    // Best upper bound so far and the face it came from (its vertices stay in the polytope), for
    // when the loop has to give up.
    double bestUpper = std::numeric_limits<double>::infinity();
    Face bestFace{};

    const auto giveUp = [&](EpaStatus status) {
        result.status = status;
        if (std::isfinite(bestUpper)) {
            result.depth = float(std::max(bestUpper, 0.0));
            result.normal = Vec3(bestFace.normal);
            faceWitness(polytope, bestFace, result.pointA, result.pointB);
        }
        return result;
    };

    for (;;) {
        const int nearest = polytope.nearestFace();
        if (nearest < 0) return giveUp(EpaStatus::Degenerate);
        const Face& f = polytope.face(nearest);
        const SupportPoint p = pair.support(Vec3(f.normal));
        if (!isFinite(p.w)) return giveUp(EpaStatus::Degenerate);
        magnitude = std::max(magnitude, magnitudeOf(p));

        const double upper = glm::dot(f.normal, DVec3(p.w));
        if (upper < bestUpper) {
            bestUpper = upper;
            bestFace = f;
        }
        const double tolerance = std::max(kRelativeTolerance * std::abs(upper), kAbsoluteTolerance * magnitude);
        bool onSurface = upper - f.distance <= tolerance;
        // A support point the polytope already has cannot push this face out: rounding has won.
        for (int i = 0; i < polytope.vertexCount() && !onSurface; ++i) {
            onSurface = double(lengthSquared(polytope.vertex(i).w - p.w)) <= tolerance * tolerance;
        }
        if (onSurface) {
            result.depth = float(std::max(f.distance, 0.0));
            result.normal = Vec3(f.normal);
            faceWitness(polytope, polytope.face(faceHoldingProjection(polytope, nearest)), result.pointA, result.pointB);
            result.status = EpaStatus::Converged;
            return result;
        }
        if (result.iterations == kEpaMaxIterations) return giveUp(EpaStatus::MaxIterations);
        const int apex = polytope.addVertex(p);
        if (apex < 0) return giveUp(EpaStatus::MaxIterations);
        ++result.iterations;
        if (!polytope.expand(nearest, apex)) return giveUp(EpaStatus::Degenerate);
    }
}

ContactQuery penetrationOrDistance(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                                   GjkCache* cache) {
    const CorePair pair(a, ta, b, tb);
    const GjkCoreResult core = gjkCoreDistance(pair, cache);

    ContactQuery query;
    query.gjkIterations = core.iterations;
    query.gjkStatus = core.status;
    query.normal = core.lastDirection;
    if (core.simplex.count == 0) return query;  // non-finite input

    if (!core.overlap) {
        // Cores apart: the answer is GJK's, moved out to the surfaces by the radii.
        const Vec3& n = core.lastDirection;
        const float gap = core.distance - pair.radiusSum();
        query.pointA = core.pointA + pair.a.radius * n;
        query.pointB = core.pointB - pair.b.radius * n;
        if (gap > core.tolerance) {
            query.distance = gap;
        } else {
            query.penetrating = true;
            query.depth = std::max(-gap, 0.0f);
        }
        return query;
    }

    query.penetrating = true;
    EpaResult epa;
    if (pair.a.lowerDimensional && pair.b.lowerDimensional) {
        epa = roundPairPenetration(pair, core);
    } else {
        epa = epaCorePenetration(pair, core.simplex);
        query.epaUsed = true;
        // C of the shapes is C of the cores inflated by the radius sum: same direction, deeper.
        epa.depth += pair.radiusSum();
        epa.pointA += pair.a.radius * epa.normal;
        epa.pointB -= pair.b.radius * epa.normal;
    }
    query.depth = epa.depth;
    query.normal = epa.normal;
    query.pointA = epa.pointA;
    query.pointB = epa.pointB;
    query.epaIterations = epa.iterations;
    query.epaStatus = epa.status;
    return query;
}

EpaResult epaPenetration(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb) {
    const ContactQuery query = penetrationOrDistance(a, ta, b, tb);
    EpaResult result;
    result.normal = query.normal;
    result.pointA = query.pointA;
    result.pointB = query.pointB;
    result.iterations = query.epaIterations;
    if (!query.penetrating) {
        result.status = EpaStatus::Separated;
        return result;
    }
    result.depth = query.depth;
    result.status = query.epaStatus;
    return result;
}

}  // namespace simcore
