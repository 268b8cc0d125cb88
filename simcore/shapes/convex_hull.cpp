// Over 800 lines because it is one algorithm: the Quickhull class (whose robustness rules, listed
// below, depend on each other), then the merging of its coplanar triangles into faces that reads the
// Quickhull's triangles; only ConvexHull::build at the end is public.
//
// Quickhull in double precision with a tolerance relative to the cloud's size, followed by merging
// of coplanar triangles into convex polygon faces.
//
// Robustness strategy:
// - A point counts as outside a triangle only when it is more than the tolerance above its plane;
//   points within the tolerance of the hull are dropped as interior.
// - A triangle counts as visible from the eye point when the eye is above it by a small fraction
//   of the tolerance: well above rounding error, so exactly coplanar triangles are consistently
//   hidden, and well below the tolerance, so the hull stays convex to far better than it.
// - Where the hull is (numerically) flat the visible region can be ill-formed: a cone triangle
//   could fold back over a hidden neighbour or be a sliver, or the region could have a hole or two
//   fans touching at a vertex. The region is then grown over the offending hidden triangles until
//   the cone over its horizon is well formed.
// - Points dropped while lying just above some plane are re-checked against the finished hull, as
//   later triangles can tilt past them (near sharp edges a point can be close to both planes yet
//   well outside); any found outside are added after all.
#include "simcore/shapes/convex_hull.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>

namespace simcore {
namespace {

using DVec3 = glm::dvec3;

// Relative tolerance: points closer than this fraction of the cloud's extent to a plane are on it.
constexpr double kRelativeTolerance = 1e-5;
// Coordinates are floats, so no plane can be trusted to better than a few float ulps of the
// coordinates' magnitude, however small the cloud is relative to its distance from the origin.
constexpr double kFloatRoundingTolerance = 8.0 * std::numeric_limits<float>::epsilon();

// Triangles count as visible from a point above them by more than this fraction of the tolerance.
constexpr double kVisibilityFraction = 1e-3;
// Passes re-checking dropped near-surface points; one normally suffices.
constexpr int kMaxVerificationRounds = 8;

constexpr int kNoTriangle = -1;

struct Triangle {
    std::array<int, 3> v{};                                          // point indices, CCW from outside
    std::array<int, 3> adjacent{kNoTriangle, kNoTriangle, kNoTriangle};  // across edge v[i] -> v[i+1]
    DVec3 normal{0.0};
    double offset = 0.0;
    std::vector<int> outside;  // points more than the tolerance above this plane
    bool alive = true;
    int replacedBy = kNoTriangle;  // once dead: a triangle of the cone that replaced it
    int visitStamp = 0;  // marks triangles already tested in the current visibility search
};

struct HorizonEdge {
    int a = 0, b = 0;         // directed as in the visible triangle being removed
    int outer = kNoTriangle;  // the hidden triangle beyond, which stays
};

double distanceToLine(const DVec3& p, const DVec3& a, const DVec3& b) {
    const DVec3 ab = b - a;
    const double length = glm::length(ab);
    if (length == 0.0) return glm::length(p - a);
    return glm::length(glm::cross(p - a, ab)) / length;
}

class Quickhull {
public:
    Quickhull(std::vector<DVec3> points, double tolerance) : points_(std::move(points)), eps_(tolerance) {}

    // Returns an error sentence when the cloud has no volume, else builds the hull.
    std::string run() {
        if (std::string error = buildSimplex(); !error.empty()) return error;
        std::vector<int> pending;
        for (int t = 0; t < int(triangles_.size()); ++t) pending.push_back(t);
        for (int round = 0; round < kMaxVerificationRounds; ++round) {
            addOutsidePoints(pending);
            if (!reassignNearPoints(pending)) break;
        }
        return {};
    }

    const std::vector<DVec3>& points() const { return points_; }
    const std::vector<Triangle>& triangles() const { return triangles_; }
    double tolerance() const { return eps_; }

private:
    double height(int t, const DVec3& p) const {
        return glm::dot(triangles_[t].normal, p) - triangles_[t].offset;
    }
    double height(int t, int point) const { return height(t, points_[point]); }

    int makeTriangle(int a, int b, int c) {
        Triangle tri;
        tri.v = {a, b, c};
        const DVec3& pa = points_[a];
        const DVec3& pb = points_[b];
        const DVec3& pc = points_[c];
        const DVec3 n = glm::cross(pb - pa, pc - pa);
        tri.normal = n / glm::length(n);
        tri.offset = glm::dot(tri.normal, (pa + pb + pc) / 3.0);
        triangles_.push_back(std::move(tri));
        ++aliveCount_;
        return int(triangles_.size()) - 1;
    }

    void addOutsidePoints(std::vector<int>& pending) {
        while (!pending.empty()) {
            const int t = pending.back();
            pending.pop_back();
            if (!triangles_[t].alive || triangles_[t].outside.empty()) continue;
            const int eye = farthestOutsidePoint(t);
            if (!addPoint(t, eye, pending)) {
                // The region seen from this point could not be made a disc. Such points lie on
                // degenerate near-coplanar configurations; dropping one keeps the hull valid.
                auto& outside = triangles_[t].outside;
                outside.erase(std::find(outside.begin(), outside.end(), eye));
                pending.push_back(t);
            }
        }
    }

    void markNear(int point, int nearestTriangle) {
        if (isNear_[point]) return;
        isNear_[point] = 1;
        nearPoints_.push_back({point, nearestTriangle});
    }

    // The triangle the point is highest above, searched from `start` across neighbours the point
    // is at most the tolerance lower above than the best so far. Coplanar neighbours are level,
    // so the search crosses flat regions instead of stalling on them. Stops early once the point
    // is clearly outside.
    int highestTriangleNear(int p, int start) {
        ++stamp_;
        int best = start;
        double bestHeight = height(start, p);
        std::vector<int> stack{start};
        triangles_[start].visitStamp = stamp_;
        while (!stack.empty() && bestHeight <= eps_) {
            const int t = stack.back();
            stack.pop_back();
            for (int g : triangles_[t].adjacent) {
                if (triangles_[g].visitStamp == stamp_) continue;
                const double h = height(g, p);
                if (h < bestHeight - eps_) continue;
                triangles_[g].visitStamp = stamp_;
                stack.push_back(g);
                if (h > bestHeight) {
                    bestHeight = h;
                    best = g;
                }
            }
        }
        return best;
    }

    // Re-checks points that were dropped just above some plane against the current hull; returns
    // whether any turned out to be outside (they are then queued for adding). The search starts at
    // the triangle the point was nearest to, or whatever replaced it.
    bool reassignNearPoints(std::vector<int>& pending) {
        bool reassigned = false;
        std::vector<NearPoint> stillNear;
        for (auto [p, t] : nearPoints_) {
            while (!triangles_[t].alive) t = triangles_[t].replacedBy;
            t = highestTriangleNear(p, t);
            const double h = height(t, p);
            if (h > eps_) {
                triangles_[t].outside.push_back(p);
                pending.push_back(t);
                isNear_[p] = 0;
                reassigned = true;
            } else if (h > nearAbove()) {
                stillNear.push_back({p, t});
            } else {
                isNear_[p] = 0;
            }
        }
        nearPoints_ = std::move(stillNear);
        return reassigned;
    }

    // Heights below this are rounding error; above it a point is visibly off a plane.
    double nearAbove() const { return kVisibilityFraction * eps_; }

    int farthestOutsidePoint(int t) const {
        int best = triangles_[t].outside.front();
        double bestHeight = height(t, best);
        for (int p : triangles_[t].outside) {
            const double h = height(t, p);
            if (h > bestHeight) {
                bestHeight = h;
                best = p;
            }
        }
        return best;
    }

    std::string buildSimplex() {
        const int n = int(points_.size());

        // The two farthest-apart of the six axis-extreme points span the cloud well.
        std::array<int, 6> extremes{};
        for (int axis = 0; axis < 3; ++axis) {
            int lo = 0, hi = 0;
            for (int i = 1; i < n; ++i) {
                if (points_[i][axis] < points_[lo][axis]) lo = i;
                if (points_[i][axis] > points_[hi][axis]) hi = i;
            }
            extremes[2 * axis] = lo;
            extremes[2 * axis + 1] = hi;
        }
        int i0 = extremes[0], i1 = extremes[1];
        double bestDistance = -1.0;
        for (int i : extremes) {
            for (int j : extremes) {
                const double d = glm::length(points_[i] - points_[j]);
                if (d > bestDistance) {
                    bestDistance = d;
                    i0 = i;
                    i1 = j;
                }
            }
        }
        if (bestDistance <= eps_) return "all points are coincident: the hull has no volume";

        const DVec3 lineDirection = glm::normalize(points_[i1] - points_[i0]);
        int i2 = -1;
        bestDistance = -1.0;
        for (int i = 0; i < n; ++i) {
            const double d = glm::length(glm::cross(points_[i] - points_[i0], lineDirection));
            if (d > bestDistance) {
                bestDistance = d;
                i2 = i;
            }
        }
        if (bestDistance <= eps_) return "the points are collinear: the hull has no volume";

        const DVec3 planeNormal =
            glm::normalize(glm::cross(points_[i1] - points_[i0], points_[i2] - points_[i0]));
        int i3 = -1;
        double bestSigned = 0.0;
        bestDistance = -1.0;
        for (int i = 0; i < n; ++i) {
            const double d = glm::dot(points_[i] - points_[i0], planeNormal);
            if (std::abs(d) > bestDistance) {
                bestDistance = std::abs(d);
                bestSigned = d;
                i3 = i;
            }
        }
        if (bestDistance <= eps_) return "the points are coplanar: the hull has no volume";

        interior_ = (points_[i0] + points_[i1] + points_[i2] + points_[i3]) / 4.0;

        // The base triangle must face away from the apex.
        if (bestSigned > 0.0) std::swap(i1, i2);
        const std::array<int, 4> simplex{
            makeTriangle(i0, i1, i2), makeTriangle(i0, i3, i1), makeTriangle(i1, i3, i2),
            makeTriangle(i2, i3, i0)};
        for (int t : simplex) {
            for (int e = 0; e < 3; ++e) {
                const int a = triangles_[t].v[e], b = triangles_[t].v[(e + 1) % 3];
                for (int u : simplex) {
                    if (u != t && edgeIndex(u, b, a) >= 0) triangles_[t].adjacent[e] = u;
                }
            }
        }

        isNear_.assign(points_.size(), 0);
        std::vector<int> unused;
        for (int p = 0; p < n; ++p) {
            if (p == i0 || p == i1 || p == i2 || p == i3) continue;
            placePoint(p, simplex, {}, unused);
        }
        return {};
    }

    // Index e such that triangle t has the directed edge a -> b as v[e] -> v[e+1], or -1.
    int edgeIndex(int t, int a, int b) const {
        const auto& v = triangles_[t].v;
        for (int e = 0; e < 3; ++e) {
            if (v[e] == a && v[(e + 1) % 3] == b) return e;
        }
        return -1;
    }

    // Puts the point in the outside set of the first of `candidates`, then of `neighbours`, that it
    // is clearly above; otherwise it is dropped, and remembered if it was only just inside.
    void placePoint(int p, std::span<const int> candidates, std::span<const HorizonEdge> neighbours,
                    std::vector<int>& pending) {
        double highest = -std::numeric_limits<double>::max();
        int nearest = kNoTriangle;
        for (int t : candidates) {
            const double h = height(t, p);
            if (h > eps_) {
                triangles_[t].outside.push_back(p);
                return;
            }
            if (h > highest) {
                highest = h;
                nearest = t;
            }
        }
        for (const HorizonEdge& e : neighbours) {
            const double h = height(e.outer, p);
            if (h > eps_) {
                triangles_[e.outer].outside.push_back(p);
                pending.push_back(e.outer);
                return;
            }
            if (h > highest) {
                highest = h;
                nearest = e.outer;
            }
        }
        if (highest > nearAbove()) markNear(p, nearest);
    }

    std::vector<HorizonEdge> collectHorizon(const std::vector<int>& visibleSet) const {
        std::vector<HorizonEdge> horizon;
        for (int f : visibleSet) {
            for (int e = 0; e < 3; ++e) {
                const int g = triangles_[f].adjacent[e];
                if (!visible_[g]) horizon.push_back({triangles_[f].v[e], triangles_[f].v[(e + 1) % 3], g});
            }
        }
        return horizon;
    }

    void makeVisible(int t, std::vector<int>& visibleSet) {
        visible_[t] = 1;
        visibleSet.push_back(t);
    }

    // Orders the horizon edges into one closed loop; false if they do not form exactly one.
    static bool orderHorizon(std::vector<HorizonEdge>& horizon) {
        if (horizon.size() < 3) return false;
        std::unordered_map<int, int> startsAt;
        for (int k = 0; k < int(horizon.size()); ++k) {
            if (!startsAt.emplace(horizon[k].a, k).second) return false;  // two fans touch at a vertex
        }
        std::vector<HorizonEdge> ordered;
        ordered.reserve(horizon.size());
        int k = 0;
        for (std::size_t step = 0; step < horizon.size(); ++step) {
            ordered.push_back(horizon[k]);
            const auto next = startsAt.find(horizon[k].b);
            if (next == startsAt.end()) return false;
            k = next->second;
            if (k == 0 && step + 1 < horizon.size()) return false;  // more than one loop
        }
        if (k != 0) return false;
        horizon = std::move(ordered);
        return true;
    }

    // A horizon edge is folded when the cone triangle (a, b, eye) would face into the hull,
    // lying back over the hidden triangle beyond the edge instead of continuing the surface. Its
    // plane would then have the interior point on its outer side, which no face of a convex hull
    // containing the initial simplex can have. This happens only where the hull is numerically
    // flat or slightly dented, and the hidden triangle then belongs to the visible region.
    bool isFolded(const HorizonEdge& e, const DVec3& eye) const {
        const DVec3& a = points_[e.a];
        const DVec3 normal = glm::cross(points_[e.b] - a, eye - a);
        return glm::dot(normal, interior_ - a) >= 0.0;
    }

    // A horizon edge nearly in line with the eye would give a sliver cone triangle with a
    // meaningless normal; the hidden triangle beyond it must go too, so the cone passes around.
    bool isDegenerate(const HorizonEdge& e, const DVec3& eye) const {
        return distanceToLine(eye, points_[e.a], points_[e.b]) <= eps_;
    }

    // Grows the visible set so that its horizon can become a single loop: hidden triangles cut off
    // from the clearly hidden part of the hull (holes) and hidden triangles around vertices where
    // visible fans touch (pinches) are absorbed. Only near-coplanar configurations need this, so
    // whole-hull passes are affordable. Returns false when nothing sensible can be absorbed.
    bool absorbHolesAndPinches(int eye, std::vector<int>& visibleSet) {
        const int count = int(triangles_.size());
        int anchor = kNoTriangle;
        double lowest = std::numeric_limits<double>::max();
        for (int t = 0; t < count; ++t) {
            if (!triangles_[t].alive || visible_[t]) continue;
            const double h = height(t, eye);
            if (h < lowest) {
                lowest = h;
                anchor = t;
            }
        }
        if (anchor == kNoTriangle || lowest > -eps_) return false;

        // Hidden triangles reachable from the anchor without crossing the visible set.
        std::vector<char> reached(count, 0);
        std::vector<int> stack{anchor};
        reached[anchor] = 1;
        while (!stack.empty()) {
            const int t = stack.back();
            stack.pop_back();
            for (int g : triangles_[t].adjacent) {
                if (!reached[g] && !visible_[g]) {
                    reached[g] = 1;
                    stack.push_back(g);
                }
            }
        }
        bool grew = false;
        for (int t = 0; t < count; ++t) {
            if (triangles_[t].alive && !visible_[t] && !reached[t]) {
                makeVisible(t, visibleSet);
                grew = true;
            }
        }
        if (grew) return true;

        std::unordered_map<int, int> startCount;
        for (const HorizonEdge& e : collectHorizon(visibleSet)) ++startCount[e.a];
        for (int t = 0; t < count; ++t) {
            if (!triangles_[t].alive || visible_[t]) continue;
            for (int v : triangles_[t].v) {
                const auto it = startCount.find(v);
                if (it == startCount.end() || it->second < 2) continue;
                if (t == anchor) return false;
                makeVisible(t, visibleSet);
                grew = true;
                break;
            }
        }
        return grew;
    }

    bool addPoint(int seed, int eye, std::vector<int>& pending) {
        const DVec3& eyePoint = points_[eye];
        visible_.resize(triangles_.size(), 0);

        // Visible triangles, by depth-first search from the seed across shared edges.
        ++stamp_;
        std::vector<int> visibleSet;
        std::vector<int> stack{seed};
        triangles_[seed].visitStamp = stamp_;
        while (!stack.empty()) {
            const int t = stack.back();
            stack.pop_back();
            makeVisible(t, visibleSet);
            for (int g : triangles_[t].adjacent) {
                if (triangles_[g].visitStamp == stamp_) continue;
                triangles_[g].visitStamp = stamp_;
                if (height(g, eyePoint) > nearAbove()) stack.push_back(g);
            }
        }

        std::vector<HorizonEdge> horizon;
        const bool wellFormed = growUntilWellFormed(eye, visibleSet, horizon);
        for (int t : visibleSet) visible_[t] = 0;
        if (!wellFormed) return false;

        std::vector<int> orphans;
        for (int t : visibleSet) {
            Triangle& tri = triangles_[t];
            tri.alive = false;
            --aliveCount_;
            for (int p : tri.outside) {
                if (p != eye) orphans.push_back(p);
            }
            tri.outside.clear();
            tri.outside.shrink_to_fit();
        }

        // A cone of new triangles from the horizon to the eye. Triangle k is (a_k, b_k, eye) and
        // b_k == a_{k+1}, so its neighbours across the cone edges are triangles k+1 and k-1.
        const int h = int(horizon.size());
        std::vector<int> cone(h);
        for (int k = 0; k < h; ++k) {
            const HorizonEdge& e = horizon[k];
            const int t = makeTriangle(e.a, e.b, eye);
            cone[k] = t;
            triangles_[t].adjacent[0] = e.outer;
            triangles_[e.outer].adjacent[edgeIndex(e.outer, e.b, e.a)] = t;
        }
        for (int k = 0; k < h; ++k) {
            triangles_[cone[k]].adjacent[1] = cone[(k + 1) % h];
            triangles_[cone[k]].adjacent[2] = cone[(k + h - 1) % h];
        }
        for (int t : visibleSet) triangles_[t].replacedBy = cone.front();

        // Points outside a removed triangle are now outside a new one, or inside. Within the
        // tolerance that is not guaranteed, so the hidden neighbours of the cone are tried too.
        for (int p : orphans) placePoint(p, cone, horizon, pending);
        for (int t : cone) {
            if (!triangles_[t].outside.empty()) pending.push_back(t);
        }
        return true;
    }

    // Grows the visible region until its horizon is a single loop with no folded edge; `horizon`
    // is then that loop in order.
    bool growUntilWellFormed(int eye, std::vector<int>& visibleSet, std::vector<HorizonEdge>& horizon) {
        for (;;) {
            if (int(visibleSet.size()) >= aliveCount_) return false;
            bool grew = false;
            for (const HorizonEdge& e : collectHorizon(visibleSet)) {
                if (!visible_[e.outer] && (isFolded(e, points_[eye]) || isDegenerate(e, points_[eye]))) {
                    makeVisible(e.outer, visibleSet);
                    grew = true;
                }
            }
            if (grew) continue;
            horizon = collectHorizon(visibleSet);
            if (orderHorizon(horizon)) return true;
            if (!absorbHolesAndPinches(eye, visibleSet)) return false;
        }
    }

    std::vector<DVec3> points_;
    double eps_;
    std::vector<Triangle> triangles_;
    DVec3 interior_{0.0};  // centroid of the initial simplex, strictly inside the hull throughout
    int stamp_ = 0;
    int aliveCount_ = 0;
    std::vector<char> visible_;  // per triangle, set only while a point is being added
    struct NearPoint {
        int point;
        int triangle;  // the one it was highest above when dropped
    };
    std::vector<NearPoint> nearPoints_;  // dropped points that were within the tolerance above a plane
    std::vector<char> isNear_;           // per point: listed in nearPoints_
};

// A polygon face as a loop of point indices, CCW from outside.
using Polygon = std::vector<int>;

// The boundary of a set of triangles as one loop (CCW from outside), or empty if the boundary is
// not a single simple loop.
Polygon boundaryLoop(const std::vector<Triangle>& triangles, const std::vector<int>& members,
                     const std::vector<int>& group) {
    const int g = group[members.front()];
    std::unordered_map<int, int> next;
    for (int t : members) {
        for (int e = 0; e < 3; ++e) {
            if (group[triangles[t].adjacent[e]] == g) continue;
            if (!next.emplace(triangles[t].v[e], triangles[t].v[(e + 1) % 3]).second) return {};
        }
    }
    // Start from the lowest point index so the output does not depend on hash order.
    int start = next.begin()->first;
    for (const auto& entry : next) start = std::min(start, entry.first);
    Polygon loop;
    int v = start;
    do {
        loop.push_back(v);
        const auto it = next.find(v);
        if (it == next.end() || loop.size() > next.size()) return {};
        v = it->second;
    } while (v != start);
    if (loop.size() != next.size()) return {};  // more than one loop: the set has a hole
    return loop;
}

// Whether the loop turns left (seen from outside) at every vertex, allowing right turns of at most
// the tolerance, i.e. nearly collinear vertices.
bool isConvex(const Polygon& loop, const std::vector<DVec3>& points, const DVec3& normal, double eps) {
    const std::size_t n = loop.size();
    for (std::size_t i = 0; i < n; ++i) {
        const DVec3& p = points[loop[(i + n - 1) % n]];
        const DVec3& x = points[loop[i]];
        const DVec3& q = points[loop[(i + 1) % n]];
        if (glm::dot(glm::cross(x - p, q - x), normal) < -eps * glm::length(q - p)) return false;
    }
    return true;
}

// Merges adjacent hull triangles lying within the tolerance of a common plane into polygons.
// Groups grow from the largest triangles, whose planes are the most accurate. On a curved,
// finely sampled surface such a group can come out non-convex (or, rarely, not a disc); it is
// then left as separate triangles, since faces must be convex.
std::vector<Polygon> mergeCoplanarTriangles(const Quickhull& hull) {
    const auto& triangles = hull.triangles();
    const auto& points = hull.points();
    const double eps = hull.tolerance();

    std::vector<int> bySize;
    std::vector<double> area(triangles.size(), 0.0);
    for (int t = 0; t < int(triangles.size()); ++t) {
        if (!triangles[t].alive) continue;
        const auto& v = triangles[t].v;
        area[t] = glm::length(glm::cross(points[v[1]] - points[v[0]], points[v[2]] - points[v[0]]));
        bySize.push_back(t);
    }
    std::stable_sort(bySize.begin(), bySize.end(), [&](int x, int y) { return area[x] > area[y]; });

    std::vector<int> group(triangles.size(), -1);
    std::vector<Polygon> polygons;
    int groupCount = 0;
    for (int seed : bySize) {
        if (group[seed] >= 0) continue;
        const int g = groupCount++;
        const Triangle& plane = triangles[seed];
        std::vector<int> members;
        std::vector<int> stack{seed};
        group[seed] = g;
        while (!stack.empty()) {
            const int t = stack.back();
            stack.pop_back();
            members.push_back(t);
            for (int n : triangles[t].adjacent) {
                if (group[n] >= 0 || glm::dot(triangles[n].normal, plane.normal) <= 0.0) continue;
                bool onPlane = true;
                for (int v : triangles[n].v) {
                    onPlane = onPlane && std::abs(glm::dot(plane.normal, points[v]) - plane.offset) <= eps;
                }
                if (onPlane) {
                    group[n] = g;
                    stack.push_back(n);
                }
            }
        }

        Polygon loop = members.size() > 1 ? boundaryLoop(triangles, members, group) : Polygon{};
        if (!loop.empty() && isConvex(loop, points, plane.normal, eps)) {
            polygons.push_back(std::move(loop));
            continue;
        }
        for (int t : members) {
            const auto& v = triangles[t].v;
            polygons.push_back({v[0], v[1], v[2]});
        }
    }
    return polygons;
}

// A vertex shared by only two faces lies on their common edge line (convex faces cannot meet
// otherwise), left there by merging. It is removed from both; when one of the two is a sliver
// triangle, that triangle collapses onto the edge and disappears. Hull vertices are then corners
// where at least three faces meet, except on hulls within a few tolerances of flat, whose rim can
// be a knife edge between two faces.
void removeDegreeTwoVertices(std::vector<Polygon>& polygons, const std::vector<DVec3>& points, double eps) {
    std::unordered_map<int, std::vector<int>> facesOfVertex;
    for (int f = 0; f < int(polygons.size()); ++f) {
        for (int v : polygons[f]) facesOfVertex[v].push_back(f);
    }
    auto at = [](const Polygon& polygon, std::size_t i) { return polygon[i % polygon.size()]; };
    auto indexOf = [](const Polygon& polygon, int v) {
        return std::size_t(std::find(polygon.begin(), polygon.end(), v) - polygon.begin());
    };
    auto otherFaceHasEdge = [&](int from, int to, int exceptFace) {
        for (int f : facesOfVertex[from]) {
            const Polygon& polygon = polygons[f];
            if (f != exceptFace && at(polygon, indexOf(polygon, from) + 1) == to) return true;
        }
        return false;
    };
    auto forget = [&](int v, int face) {
        auto& faces = facesOfVertex[v];
        faces.erase(std::find(faces.begin(), faces.end(), face));
    };

    std::vector<int> work;
    for (const auto& [v, faces] : facesOfVertex) {
        if (faces.size() == 2) work.push_back(v);
    }
    std::sort(work.begin(), work.end());
    while (!work.empty()) {
        const int v = work.back();
        work.pop_back();
        std::vector<int>& faces = facesOfVertex[v];
        if (faces.size() != 2) continue;
        int first = faces[0], second = faces[1];
        if (polygons[first].size() > polygons[second].size()) std::swap(first, second);
        Polygon& small = polygons[first];
        Polygon& large = polygons[second];
        const std::size_t i = indexOf(small, v);
        const int u = at(small, i + small.size() - 1);
        const int w = at(small, i + 1);
        const std::size_t j = indexOf(large, v);
        if (at(large, j + large.size() - 1) != w || at(large, j + 1) != u) continue;
        // Both faces are convex up to the tolerance in their own planes, hence the slack.
        if (distanceToLine(points[v], points[u], points[w]) > 2.0 * eps) continue;
        if (small.size() > 3) {
            small.erase(small.begin() + std::ptrdiff_t(i));
            large.erase(large.begin() + std::ptrdiff_t(j));
            faces.clear();
            continue;
        }
        // `small` is the sliver (u, v, w); the large face takes over its edge w -> u.
        if (large.size() == 3 || otherFaceHasEdge(w, u, first)) continue;
        large.erase(large.begin() + std::ptrdiff_t(j));
        small.clear();
        faces.clear();
        for (int x : {u, w}) {
            forget(x, first);
            if (facesOfVertex[x].size() == 2) work.push_back(x);
        }
    }
    std::erase_if(polygons, [](const Polygon& polygon) { return polygon.empty(); });
}

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; }

}  // namespace

ConvexHull::BuildResult ConvexHull::build(const std::vector<Vec3>& points) {
    if (points.size() < 4) {
        return {nullptr, "a convex hull needs at least 4 points, got " + std::to_string(points.size())};
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!isFinite(points[i])) {
            return {nullptr, "point " + std::to_string(i) + " has a non-finite coordinate"};
        }
    }

    std::vector<DVec3> cloud(points.begin(), points.end());
    DVec3 lo = cloud.front(), hi = cloud.front();
    for (const DVec3& p : cloud) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const DVec3 size = hi - lo;
    const double extent = std::max({size.x, size.y, size.z});
    const DVec3 magnitude = glm::max(glm::abs(lo), glm::abs(hi));
    const double largestCoordinate = std::max({magnitude.x, magnitude.y, magnitude.z});
    const double tolerance =
        std::max(kRelativeTolerance * extent, kFloatRoundingTolerance * largestCoordinate);
    if (extent <= tolerance) {
        return {nullptr, "all points are coincident: the hull has no volume"};
    }

    Quickhull quickhull(std::move(cloud), tolerance);
    if (std::string error = quickhull.run(); !error.empty()) return {nullptr, error};

    std::vector<Polygon> polygons = mergeCoplanarTriangles(quickhull);
    removeDegreeTwoVertices(polygons, quickhull.points(), tolerance);

    auto hull = std::make_shared<ConvexHull>();
    hull->sourcePoints_ = points;

    // Keep only the points that are corners of some face, numbered in input order.
    std::vector<std::uint32_t> compact(points.size(), std::numeric_limits<std::uint32_t>::max());
    std::vector<char> used(points.size(), 0);
    for (const Polygon& polygon : polygons) {
        for (int v : polygon) used[v] = 1;
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!used[i]) continue;
        compact[i] = std::uint32_t(hull->vertices_.size());
        hull->vertices_.push_back(points[i]);
    }

    // Only a numerical failure of the construction could leave an edge without its twin.
    auto closeUpFailure = [] {
        return BuildResult{nullptr, "the hull could not be built: its faces do not close up"};
    };
    const auto& exact = quickhull.points();
    std::unordered_map<std::uint64_t, std::uint32_t> faceOfDirectedEdge;
    for (const Polygon& polygon : polygons) {
        // Newell's normal about the centroid: the best-fit direction for a slightly non-planar loop.
        DVec3 centroid(0.0);
        for (int v : polygon) centroid += exact[v];
        centroid /= double(polygon.size());
        DVec3 normal(0.0);
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            normal += glm::cross(exact[polygon[i]] - centroid, exact[polygon[(i + 1) % polygon.size()]] - centroid);
        }
        normal = glm::normalize(normal);
        // The plane touches the outermost corner, so every hull vertex is on or behind it.
        double offset = -std::numeric_limits<double>::max();
        for (int v : polygon) offset = std::max(offset, glm::dot(normal, exact[v]));

        HullFace face;
        face.normal = Vec3(normal);
        face.offset = float(offset);
        face.firstIndex = std::uint32_t(hull->faceVertexIndices_.size());
        face.vertexCount = std::uint32_t(polygon.size());
        const auto faceIndex = std::uint32_t(hull->faces_.size());
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const std::uint32_t a = compact[polygon[i]];
            const std::uint32_t b = compact[polygon[(i + 1) % polygon.size()]];
            hull->faceVertexIndices_.push_back(a);
            if (!faceOfDirectedEdge.emplace(edgeKey(a, b), faceIndex).second) return closeUpFailure();
        }
        hull->faces_.push_back(face);
    }

    for (const auto& [key, face] : faceOfDirectedEdge) {
        const auto a = std::uint32_t(key >> 32);
        const auto b = std::uint32_t(key & 0xFFFFFFFFu);
        if (a > b) continue;  // each edge once, from the face that walks it a -> b
        const auto twin = faceOfDirectedEdge.find(edgeKey(b, a));
        if (twin == faceOfDirectedEdge.end()) return closeUpFailure();
        hull->edges_.push_back({a, b, face, twin->second});
    }
    if (faceOfDirectedEdge.size() != 2 * hull->edges_.size()) return closeUpFailure();
    // Deterministic edge order regardless of hash-map iteration order.
    std::sort(hull->edges_.begin(), hull->edges_.end(),
              [](const HullEdge& x, const HullEdge& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });

    return {std::move(hull), {}};
}

Vec3 ConvexHull::support(const Vec3& direction) const {
    Vec3 best = vertices_.front();
    float bestDot = glm::dot(best, direction);
    for (const Vec3& v : vertices_) {
        const float d = glm::dot(v, direction);
        if (d > bestDot) {
            bestDot = d;
            best = v;
        }
    }
    return best;
}

}  // namespace simcore
