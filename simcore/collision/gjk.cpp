// GJK with a Voronoi-region subalgorithm: each step finds the point of the current simplex nearest
// the origin, keeps only the vertices whose hull holds it, and asks C for its farthest point in the
// opposite direction. The loop ends on the first of:
//   - the simplex holds the origin (overlap), or the estimate is within rounding of it (touching);
//   - the support point does not get meaningfully closer to the origin than the estimate
//     (the lower bound |v| - dot(v, w)/|v| has met the relative tolerance);
//   - the support point is already in the simplex, or the estimate did not shrink (rounding has
//     taken over: nothing better can be computed, so the previous simplex is kept);
//   - the iteration cap, which does not happen for sane input.
// Tolerances scale with the coordinates involved, so the same configuration at 1 mm or 1 km
// behaves the same.

#include "simcore/collision/gjk.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace simcore {
namespace {

// The subalgorithm and the loop's bookkeeping run in double. Near convergence the simplex spans
// the shapes while the distance is small or changes in the 7th digit, and every step cancels
// large coordinates: float then cannot see the improvement a curved surface still offers and GJK
// stalls ~1e-4 short. The support points themselves stay float, exact points of the shapes as
// placed; only the arithmetic on them is wider.
using DVec3 = glm::dvec3;

constexpr double kFloatEpsilon = std::numeric_limits<float>::epsilon();
// Support points carry about an ulp of rounding of their coordinates, a little more after the
// transform; distances below this fraction of the coordinates' size are indistinguishable from 0.
constexpr double kCoordinateResolution = 8.0 * kFloatEpsilon;
// GJK stops once the distance is known to this relative accuracy, plus an ulp of the coordinates.
// Tighter than the touching resolution: on curved features the closest points (and the normal)
// are only as good as the square root of the distance's accuracy, so it pays to iterate on until
// the duplicate / no-progress checks say rounding has the last word.
constexpr double kRelativeTolerance = 1e-6;
constexpr double kConvergenceResolution = kFloatEpsilon;
// When progress stalls, bounds still further apart than this relative gap mean numerical trouble.
constexpr double kStalledTolerance = 1e-3;
// Simplices thinner than this (height against the longest edge) have no trustworthy plane or
// volume even in double.
constexpr double kDegenerateRatio = 1e-9;

double lengthSquaredD(const DVec3& v) { return glm::dot(v, v); }

struct Closest {
    std::array<int, 4> index{};
    std::array<double, 4> weight{};
    int count = 0;
    DVec3 point{0.0};
    double distanceSq = std::numeric_limits<double>::infinity();
};

Closest closestVertex(const DVec3* w, int i) {
    Closest c;
    c.index[0] = i;
    c.weight[0] = 1.0;
    c.count = 1;
    c.point = w[i];
    c.distanceSq = lengthSquaredD(w[i]);
    return c;
}

Closest nearer(const Closest& x, const Closest& y) { return y.distanceSq < x.distanceSq ? y : x; }

Closest closestOnSegment(const DVec3* w, int i, int j) {
    const DVec3 ab = w[j] - w[i];
    const double t = -glm::dot(w[i], ab);
    const double lengthSq = lengthSquaredD(ab);
    // Also covers a zero-length segment (t == 0).
    if (t <= 0.0) return closestVertex(w, i);
    if (t >= lengthSq) return closestVertex(w, j);
    const double s = t / lengthSq;
    Closest c;
    c.index[0] = i;
    c.index[1] = j;
    c.weight[0] = 1.0 - s;
    c.weight[1] = s;
    c.count = 2;
    c.point = w[i] + s * ab;
    c.distanceSq = lengthSquaredD(c.point);
    return c;
}

Closest closestOnTriangle(const DVec3* w, int i, int j, int k) {
    const DVec3& a = w[i];
    const DVec3& b = w[j];
    const DVec3& c = w[k];
    const DVec3 ab = b - a;
    const DVec3 ac = c - a;
    const DVec3 n = glm::cross(ab, ac);
    const double nSq = lengthSquaredD(n);
    const double longestSq = std::max({lengthSquaredD(ab), lengthSquaredD(ac), lengthSquaredD(c - b)});
    if (nSq <= kDegenerateRatio * kDegenerateRatio * longestSq * longestSq) {
        // A needle or a point: the plane is noise, the edges are not.
        return nearer(nearer(closestOnSegment(w, i, j), closestOnSegment(w, j, k)), closestOnSegment(w, k, i));
    }
    // Barycentric weights (times nSq) of the origin's projection onto the plane: the signed areas
    // of the sub-triangles opposite each vertex.
    const double weightA = glm::dot(n, glm::cross(b, c));
    const double weightB = glm::dot(n, glm::cross(c, a));
    const double weightC = glm::dot(n, glm::cross(a, b));
    if (weightA > 0.0 && weightB > 0.0 && weightC > 0.0) {
        const double sum = weightA + weightB + weightC;
        Closest r;
        r.index = {i, j, k, 0};
        r.weight = {weightA / sum, weightB / sum, weightC / sum, 0.0};
        r.count = 3;
        r.point = n * (glm::dot(n, a) / nSq);  // the projection itself: more accurate than the weighted sum
        r.distanceSq = lengthSquaredD(r.point);
        return r;
    }
    // The projection is outside: the nearest point lies on an edge the origin is beyond.
    Closest best;
    if (weightA <= 0.0) best = nearer(best, closestOnSegment(w, j, k));
    if (weightB <= 0.0) best = nearer(best, closestOnSegment(w, k, i));
    if (weightC <= 0.0) best = nearer(best, closestOnSegment(w, i, j));
    return best;
}

Closest closestOnTetrahedron(const DVec3* w, bool& enclosed) {
    enclosed = false;
    const DVec3& a = w[0];
    const DVec3& b = w[1];
    const DVec3& c = w[2];
    const DVec3& d = w[3];
    const double volume = glm::dot(b - a, glm::cross(c - a, d - a));
    const double longestSq = std::max({lengthSquaredD(b - a), lengthSquaredD(c - a), lengthSquaredD(d - a),
                                       lengthSquaredD(c - b), lengthSquaredD(d - b), lengthSquaredD(d - c)});
    // Flatness is the smallest height (volume over the largest face) against the longest edge, so
    // that a legitimately thin tetrahedron on a long sliver of a face still counts as a volume.
    const double largestFace =
        std::max({glm::length(glm::cross(b - a, c - a)), glm::length(glm::cross(b - a, d - a)),
                  glm::length(glm::cross(c - a, d - a)), glm::length(glm::cross(c - b, d - b))});
    if (std::abs(volume) <= kDegenerateRatio * std::sqrt(longestSq) * largestFace) {
        // Flat: no inside to speak of; the nearest of the four faces.
        return nearer(nearer(closestOnTriangle(w, 1, 2, 3), closestOnTriangle(w, 0, 2, 3)),
                      nearer(closestOnTriangle(w, 0, 1, 3), closestOnTriangle(w, 0, 1, 2)));
    }
    // Signed volumes of the tetrahedra with one vertex replaced by the origin: the origin's
    // barycentric weights times the volume.
    const double weightA = glm::dot(b, glm::cross(c, d));
    const double weightB = -glm::dot(a, glm::cross(c, d));
    const double weightC = glm::dot(a, glm::cross(b, d));
    const double weightD = -glm::dot(a, glm::cross(b, c));
    const double sign = volume > 0.0 ? 1.0 : -1.0;
    const bool beyondA = weightA * sign < 0.0;
    const bool beyondB = weightB * sign < 0.0;
    const bool beyondC = weightC * sign < 0.0;
    const bool beyondD = weightD * sign < 0.0;
    if (!beyondA && !beyondB && !beyondC && !beyondD) {
        enclosed = true;
        const double sum = weightA + weightB + weightC + weightD;
        Closest r;
        r.index = {0, 1, 2, 3};
        r.weight = {weightA / sum, weightB / sum, weightC / sum, weightD / sum};
        r.count = 4;
        r.point = DVec3(0.0);
        r.distanceSq = 0.0;
        return r;
    }
    // The nearest point lies on a face the origin is beyond (the face opposite a negative weight).
    Closest best;
    if (beyondA) best = nearer(best, closestOnTriangle(w, 1, 2, 3));
    if (beyondB) best = nearer(best, closestOnTriangle(w, 0, 2, 3));
    if (beyondC) best = nearer(best, closestOnTriangle(w, 0, 1, 3));
    if (beyondD) best = nearer(best, closestOnTriangle(w, 0, 1, 2));
    return best;
}

// The simplex being refined, with its weights in full precision.
struct WorkingSimplex {
    std::array<SupportPoint, 4> vertices{};
    std::array<double, 4> weights{};
    int count = 0;
};

// Reduces the simplex to the vertices supporting its point nearest the origin and returns that point.
DVec3 solveSimplex(WorkingSimplex& simplex, bool& enclosed) {
    std::array<DVec3, 4> w;
    for (int i = 0; i < simplex.count; ++i) w[i] = DVec3(simplex.vertices[i].w);
    enclosed = false;
    Closest c;
    switch (simplex.count) {
        case 1: c = closestVertex(w.data(), 0); break;
        case 2: c = closestOnSegment(w.data(), 0, 1); break;
        case 3: c = closestOnTriangle(w.data(), 0, 1, 2); break;
        default: c = closestOnTetrahedron(w.data(), enclosed); break;
    }
    WorkingSimplex reduced;
    for (int i = 0; i < c.count; ++i) {
        reduced.vertices[i] = simplex.vertices[c.index[i]];
        reduced.weights[i] = c.weight[i];
    }
    reduced.count = c.count;
    simplex = reduced;
    return c.point;
}

double magnitudeOf(const SupportPoint& p) {
    return std::sqrt(double(std::max(lengthSquared(p.a), lengthSquared(p.b))));
}

bool isDuplicate(const WorkingSimplex& simplex, const Vec3& w, double tolerance) {
    for (int i = 0; i < simplex.count; ++i) {
        if (double(lengthSquared(simplex.vertices[i].w - w)) <= tolerance * tolerance) return true;
    }
    return false;
}

Vec3 fallbackDirection(const CorePair& pair) {
    const Vec3 centres = pair.b.transform.position - pair.a.transform.position;
    const float lengthSq = lengthSquared(centres);
    if (lengthSq > 0.0f && isFinite(lengthSq)) return centres / std::sqrt(lengthSq);
    return Vec3(0.0f, 1.0f, 0.0f);
}

// The GJK loop. When `separatedEarly` is given, stops as soon as the lower bound on the core
// distance exceeds the radius sum by more than the resolution, and reports it there.
GjkCoreResult runGjk(const CorePair& pair, GjkCache* cache, bool* separatedEarly) {
    GjkCoreResult result;
    result.lastDirection = fallbackDirection(pair);

    WorkingSimplex simplex;
    if (cache != nullptr && cache->count >= 1 && cache->count <= 4) {
        simplex.count = cache->count;
        for (int i = 0; i < simplex.count; ++i) simplex.vertices[i] = pair.fromLocal(cache->localA[i], cache->localB[i]);
    } else {
        // Start from the points of A and B facing each other along the line between their origins.
        simplex.count = 1;
        simplex.vertices[0] = pair.support(-result.lastDirection);
    }

    double magnitude = 0.0;
    bool finite = true;
    for (int i = 0; i < simplex.count; ++i) {
        magnitude = std::max(magnitude, magnitudeOf(simplex.vertices[i]));
        finite = finite && isFinite(simplex.vertices[i].w);
    }
    if (!finite) {
        result.status = GjkStatus::Degenerate;
        if (cache != nullptr) cache->count = 0;
        return result;
    }

    bool enclosed = false;
    DVec3 v = solveSimplex(simplex, enclosed);
    double vv = lengthSquaredD(v);
    double tolerance = kCoordinateResolution * magnitude;
    double gap = 0.0;  // |v|^2 - dot(v, w) of the last support point: |v| times the distance's uncertainty
    bool stalled = false;
    DVec3 lastNonZero(0.0);  // the last estimate away from the origin, for the direction

    for (;;) {
        if (enclosed || vv <= tolerance * tolerance) {
            result.overlap = true;
            break;
        }
        lastNonZero = v;
        const double length = std::sqrt(vv);
        if (result.iterations == kGjkMaxIterations) {
            result.status = GjkStatus::MaxIterations;
            break;
        }
        ++result.iterations;

        const SupportPoint p = pair.support(Vec3(-v));
        if (!isFinite(p.w)) {
            result.status = GjkStatus::Degenerate;
            break;
        }
        magnitude = std::max(magnitude, magnitudeOf(p));
        tolerance = kCoordinateResolution * magnitude;

        const double vw = glm::dot(v, DVec3(p.w));
        const double radiusMargin = double(pair.radiusSum()) + tolerance;
        if (separatedEarly != nullptr && vw > radiusMargin * length) {
            *separatedEarly = true;
            break;
        }
        gap = vv - vw;
        if (gap <= length * (kRelativeTolerance * length + kConvergenceResolution * magnitude)) break;
        if (isDuplicate(simplex, p.w, tolerance)) {
            stalled = true;
            break;
        }

        const WorkingSimplex previous = simplex;
        simplex.vertices[simplex.count++] = p;
        const DVec3 next = solveSimplex(simplex, enclosed);
        const double nextSq = lengthSquaredD(next);
        if (!enclosed && !(nextSq < vv)) {
            // Not closer: rounding has the last word. The previous simplex is the best there is.
            simplex = previous;
            stalled = true;
            break;
        }
        v = enclosed ? DVec3(0.0) : next;
        vv = enclosed ? 0.0 : nextSq;
    }

    if (stalled) {
        const double length = std::sqrt(vv);
        if (gap > length * (kStalledTolerance * length + tolerance)) result.status = GjkStatus::Degenerate;
    }

    DVec3 pointA(0.0), pointB(0.0);
    for (int i = 0; i < simplex.count; ++i) {
        pointA += simplex.weights[i] * DVec3(simplex.vertices[i].a);
        pointB += simplex.weights[i] * DVec3(simplex.vertices[i].b);
        result.simplex.vertices[i] = simplex.vertices[i];
        result.simplex.weights[i] = float(simplex.weights[i]);
    }
    result.simplex.count = simplex.count;
    if (lastNonZero != DVec3(0.0)) result.lastDirection = Vec3(-glm::normalize(lastNonZero));
    result.pointA = Vec3(pointA);
    result.pointB = Vec3(pointB);
    result.closest = result.overlap && enclosed ? Vec3(0.0f) : Vec3(v);
    result.distance = result.overlap ? 0.0f : float(std::sqrt(vv));
    result.tolerance = float(tolerance);
    if (cache != nullptr) {
        cache->count = simplex.count;
        for (int i = 0; i < simplex.count; ++i) {
            cache->localA[i] = simplex.vertices[i].localA;
            cache->localB[i] = simplex.vertices[i].localB;
        }
    }
    return result;
}

}  // namespace

PlacedCore::PlacedCore(const Shape& shape, const Transform& transform)
    : shape(&shape), transform(transform), radius(0.0f), lowerDimensional(false) {
    if (shape.type == ShapeType::Sphere || shape.type == ShapeType::Capsule) {
        radius = shape.radius;
        lowerDimensional = true;
    }
}

Vec3 PlacedCore::localSupport(const Vec3& localDirection) const {
    switch (shape->type) {
        case ShapeType::Sphere: return Vec3(0.0f);
        case ShapeType::Capsule:
            return Vec3(0.0f, localDirection.y >= 0.0f ? shape->halfHeight : -shape->halfHeight, 0.0f);
        default: return support(*shape, localDirection);
    }
}

SupportPoint CorePair::support(const Vec3& direction) const {
    return fromLocal(a.localSupport(a.transform.rotateInverse(direction)),
                     b.localSupport(b.transform.rotateInverse(-direction)));
}

SupportPoint CorePair::fromLocal(const Vec3& localA, const Vec3& localB) const {
    SupportPoint p;
    p.localA = localA;
    p.localB = localB;
    p.a = a.transform.apply(localA);
    p.b = b.transform.apply(localB);
    p.w = p.a - p.b;
    return p;
}

GjkCoreResult gjkCoreDistance(const CorePair& pair, GjkCache* cache) {
    return runGjk(pair, cache, nullptr);
}

GjkResult gjkDistance(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, GjkCache* cache) {
    const CorePair pair(a, ta, b, tb);
    const GjkCoreResult core = gjkCoreDistance(pair, cache);

    GjkResult result;
    result.iterations = core.iterations;
    result.status = core.status;
    result.normal = core.lastDirection;
    if (core.simplex.count == 0) return result;  // non-finite input

    // Cores apart: lastDirection is exactly -closest/|closest|, and the surfaces are the radii closer.
    const Vec3& n = result.normal;
    result.pointA = core.pointA + pair.a.radius * n;
    result.pointB = core.pointB - pair.b.radius * n;
    if (core.overlap) {
        result.overlap = true;
        result.distance = 0.0f;
    } else {
        const float gap = core.distance - pair.radiusSum();
        result.overlap = gap <= core.tolerance;
        result.distance = std::max(gap, 0.0f);
    }
    return result;
}

bool gjkIntersect(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, GjkCache* cache) {
    const CorePair pair(a, ta, b, tb);
    bool separatedEarly = false;
    const GjkCoreResult core = runGjk(pair, cache, &separatedEarly);
    if (separatedEarly) return false;
    if (core.simplex.count == 0) return false;  // non-finite input
    // Same rule as gjkDistance's `overlap`.
    return core.overlap || core.distance - pair.radiusSum() <= core.tolerance;
}

}  // namespace simcore
