#include "simcore/collision/collide_mesh.h"

#include "simcore/collision/closest_points.h"
#include "simcore/collision/gjk.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace simcore {

namespace {

constexpr float kFlatAlignment = 0.98f;  // cos ~11 degrees: a face of the shape lies flat on the triangle
constexpr float kFlatLine = 0.2f;        // sin ~11.5 degrees: a line feature (edge, segment, side) lies flat
constexpr float kTieTolerance = 1e-5f;   // share of the triangle's size: vertices this level along an axis tie
constexpr int kCylinderCapPoints = 8;
constexpr int kMaxPolygonFace = 24;  // hull faces with more vertices are met at one vertex
constexpr int kMaxPolygon = kMaxPolygonFace + 8;

// Feature-id kinds (top byte), so a point keeps its id while the same features touch.
enum : std::uint32_t { kIdTriangleFace = 1u << 24, kIdShapeFace = 2u << 24, kIdEdge = 3u << 24, kIdClip = 0x80u };

struct Polygon {
    Vec3 points[kMaxPolygon];
    std::uint32_t ids[kMaxPolygon];
    int count = 0;
    void add(const Vec3& p, std::uint32_t id) {
        if (count < kMaxPolygon) {
            points[count] = p;
            ids[count++] = id;
        }
    }
};

struct Candidates {
    ContactCandidate items[kMaxPolygon];
    int count = 0;
};

enum class AxisKind { TriangleFace, ShapeFace, EdgePair, Closest };

struct Axis {
    AxisKind kind = AxisKind::TriangleFace;
    Vec3 direction{0.0f, 1.0f, 0.0f};  // unit, from the triangle to the shape
    float separation = -std::numeric_limits<float>::max();
    int shapeFace = -1;     // ShapeFace: box face (2k: +axis k, 2k+1: -axis k) or hull face
    int triangleEdge = -1;  // EdgePair: the triangle's edge; -1: one point, the shape's deepest along the axis
    int boxAxis = -1;       // EdgePair with a box: the local axis its edge runs along
    Vec3 shape0{0.0f}, shape1{0.0f};  // EdgePair: the shape's edge (world); Closest: core point in shape0
    Vec3 onTriangle{0.0f};            // Closest: the triangle's point
};

// The shape as its core plus radius, with the triangle it is tested against.
struct Setup {
    const Triangle& triangle;
    PlacedCore core;
    float size;  // the triangle's longest edge (m), for relative tolerances
    float separatedBeyond;  // (m) an axis separating by more than this ends the search: no contact
    Vec3 fromTriangle;      // the shape's centre minus the triangle's centroid: which way an axis points

    Vec3 coreSupport(const Vec3& worldDirection) const {
        return core.transform.apply(core.localSupport(core.transform.rotateInverse(worldDirection)));
    }
    float triangleTop(const Vec3& u) const {
        return std::max({glm::dot(triangle.vertices[0], u), glm::dot(triangle.vertices[1], u),
                         glm::dot(triangle.vertices[2], u)});
    }
    float separation(const Vec3& u) const { return glm::dot(coreSupport(-u), u) - core.radius - triangleTop(u); }
};

// Considers `axis` (any length) as a separating axis from the triangle to the shape. When
// `orient`, it is first turned to point from the triangle's centroid towards the shape's centre
// (edge pairs have no side of their own; a face normal is tried only outward).
void consider(const Setup& setup, Vec3 axis, bool orient, const Axis& candidate, Axis& best) {
    const float length = glm::length(axis);
    if (!(length > 1e-6f)) return;
    axis /= length;
    if (orient && glm::dot(axis, setup.fromTriangle) < 0.0f) axis = -axis;
    const float separation = setup.separation(axis);
    if (separation > best.separation) {
        best = candidate;
        best.direction = axis;
        best.separation = separation;
    }
}

Vec3 boxFaceNormal(const Transform& t, int face) {
    Vec3 local(0.0f);
    local[face / 2] = face % 2 ? -1.0f : 1.0f;
    return t.rotate(local);
}

// Corners of box face `face`, world frame, in order around it.
void boxFace(const Shape& box, const Transform& t, int face, Polygon& out) {
    const int k = face / 2, i = (k + 1) % 3, j = (k + 2) % 3;
    const float corners[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    for (int c = 0; c < 4; ++c) {
        Vec3 local(0.0f);
        local[k] = (face % 2 ? -1.0f : 1.0f) * box.halfExtents[k];
        local[i] = corners[c][0] * box.halfExtents[i];
        local[j] = corners[c][1] * box.halfExtents[j];
        out.add(t.apply(local), std::uint32_t(face * 4 + c));
    }
}

void hullFace(const ConvexHull& hull, const Transform& t, int face, Polygon& out) {
    const HullFace& f = hull.faces()[face];
    for (std::uint32_t k = 0; k < f.vertexCount; ++k) {
        const std::uint32_t v = hull.faceVertexIndices()[f.firstIndex + k];
        out.add(t.apply(hull.vertices()[v]), v);
    }
}

int faceCount(const Shape& shape) {
    if (shape.type == ShapeType::Box) return 6;
    if (shape.type == ShapeType::ConvexHull) return int(shape.hull->faces().size());
    return 0;
}

Vec3 faceNormal(const Shape& shape, const Transform& t, int face) {
    return shape.type == ShapeType::Box ? boxFaceNormal(t, face) : t.rotate(shape.hull->faces()[face].normal);
}

void facePolygon(const Shape& shape, const Transform& t, int face, Polygon& out) {
    if (shape.type == ShapeType::Box) boxFace(shape, t, face, out);
    else hullFace(*shape.hull, t, face, out);
}

// The SAT axes of the shape against the triangle (the triangle's own normal is tried first, by
// the caller). Stops early once an axis separates beyond setup.separatedBeyond.
void findBestAxis(const Setup& setup, const Shape& shape, const Transform& t, Axis& best) {
    const Triangle& tri = setup.triangle;
    const Vec3 edges[3] = {tri.vertices[1] - tri.vertices[0], tri.vertices[2] - tri.vertices[1],
                           tri.vertices[0] - tri.vertices[2]};
    Axis faceBest;  // best of the shape's faces and edge pairs, compared with the triangle's normal below
    for (int f = 0; f < faceCount(shape); ++f) {
        Axis a;
        a.kind = AxisKind::ShapeFace;
        a.shapeFace = f;
        consider(setup, -faceNormal(shape, t, f), false, a, faceBest);
        if (faceBest.separation > setup.separatedBeyond) {
            best = faceBest;
            return;
        }
    }
    auto edgePair = [&](int e, const Vec3& direction, const Vec3& s0, const Vec3& s1, int boxAxis) {
        Axis a;
        a.kind = AxisKind::EdgePair;
        a.triangleEdge = e;
        a.boxAxis = boxAxis;
        a.shape0 = s0;
        a.shape1 = s1;
        consider(setup, glm::cross(edges[e], direction), true, a, faceBest);
    };
    for (int e = 0; e < 3; ++e) {
        switch (shape.type) {
            case ShapeType::Box:
                // The box edge along each axis that supports the pair is found once the axis is chosen.
                for (int k = 0; k < 3; ++k) edgePair(e, boxFaceNormal(t, 2 * k), Vec3(0.0f), Vec3(0.0f), k);
                break;
            case ShapeType::ConvexHull:
                for (const HullEdge& h : shape.hull->edges()) {
                    const Vec3 a = t.apply(shape.hull->vertices()[h.a]);
                    const Vec3 b = t.apply(shape.hull->vertices()[h.b]);
                    edgePair(e, b - a, a, b, -1);
                }
                break;
            case ShapeType::Capsule:
            case ShapeType::Cylinder: {
                const Vec3 axis = t.rotate(Vec3(0, shape.halfHeight, 0));
                edgePair(e, axis, t.position - axis, t.position + axis, -1);
                break;
            }
            case ShapeType::Sphere:
            case ShapeType::Compound:
            case ShapeType::Mesh:
            case ShapeType::HeightField: break;  // no edges (or not convex: never passed here)
        }
        if (faceBest.separation > setup.separatedBeyond) {
            best = faceBest;
            return;
        }
    }
    if (shape.type == ShapeType::Cylinder) {
        const Vec3 axis = t.rotate(Vec3(0, 1, 0));
        for (int e = 0; e < 3; ++e) {
            // A cap's rim against a triangle edge: the edge crossed with the rim's tangent where the
            // rim reaches farthest out over that edge, and the edge's own side plane.
            Vec3 out = glm::cross(edges[e], tri.normal);
            Axis a;
            a.kind = AxisKind::EdgePair;  // met at the rim's deepest point: no segment to pair with
            a.triangleEdge = -1;
            consider(setup, out, true, a, faceBest);
            const Vec3 radial = -out - glm::dot(-out, axis) * axis;
            if (lengthSquared(radial) > 1e-12f) consider(setup, glm::cross(edges[e], glm::cross(axis, radial)), true, a, faceBest);
        }
        for (const Vec3& v : tri.vertices) {
            const Vec3 radial = (v - t.position) - glm::dot(v - t.position, axis) * axis;
            Axis a;
            a.kind = AxisKind::EdgePair;  // a vertex against the side: one point, like an edge pair
            a.triangleEdge = -1;
            consider(setup, radial, true, a, faceBest);
        }
    }
    if (shape.type == ShapeType::Capsule) {
        // Closest points of the segment and the triangle, unless the segment pierces it.
        const Vec3 s0 = t.apply(Vec3(0, -shape.halfHeight, 0)), s1 = t.apply(Vec3(0, shape.halfHeight, 0));
        if (!rayCastTriangle(tri, s0, s1 - s0, 1.0f)) {
            Vec3 onTriangle = closestPointOnTriangle(s0, tri.vertices[0], tri.vertices[1], tri.vertices[2]);
            Vec3 onCore = s0;
            auto offer = [&](const Vec3& q, const Vec3& c) {
                if (lengthSquared(c - q) < lengthSquared(onCore - onTriangle)) {
                    onTriangle = q;
                    onCore = c;
                }
            };
            offer(closestPointOnTriangle(s1, tri.vertices[0], tri.vertices[1], tri.vertices[2]), s1);
            for (int e = 0; e < 3; ++e) {
                Vec3 q, c;
                closestPointsOfSegments(tri.vertices[e], tri.vertices[(e + 1) % 3], s0, s1, q, c);
                offer(q, c);
            }
            Axis a;
            a.kind = AxisKind::Closest;
            a.onTriangle = onTriangle;
            a.shape0 = onCore;
            consider(setup, onCore - onTriangle, false, a, faceBest);  // already from the triangle to the core
        }
    }
    if (faceBest.separation > best.separation + kTriangleFacePreference) best = faceBest;
}

// Does the axis meet the triangle at an active feature? The triangle's points farthest along `u`
// are its feature nearest the shape: one vertex, an edge (two tie) or the face (all three).
bool meetsActiveFeature(const Triangle& tri, const Vec3& u, float size) {
    const float d[3] = {0.0f, glm::dot(tri.vertices[1] - tri.vertices[0], u), glm::dot(tri.vertices[2] - tri.vertices[0], u)};
    const float top = std::max({d[0], d[1], d[2]});
    bool tops[3];
    int count = 0;
    for (int k = 0; k < 3; ++k) count += (tops[k] = d[k] >= top - kTieTolerance * size);
    if (count == 3) return true;
    if (count == 1) {
        for (int k = 0; k < 3; ++k)
            if (tops[k]) return isVertexActive(tri.flags, k);
    }
    for (int e = 0; e < 3; ++e)
        if (tops[e] && tops[(e + 1) % 3]) return isEdgeActive(tri.flags, e);
    return true;
}

// Keeps the part of `poly` on the inner side of the plane through `q` with outward normal `m`.
void clipToPlane(Polygon& poly, const Vec3& m, const Vec3& q, std::uint32_t planeId) {
    if (poly.count == 0) return;
    Polygon kept;
    if (poly.count == 1) {
        if (glm::dot(m, poly.points[0] - q) <= 0.0f) kept = poly;
    } else if (poly.count == 2) {
        Vec3 a = poly.points[0], b = poly.points[1];
        const float da = glm::dot(m, a - q), db = glm::dot(m, b - q);
        if (da > 0.0f && db > 0.0f) {
            poly.count = 0;
            return;
        }
        kept = poly;
        if (da > 0.0f) {
            kept.points[0] = a + (b - a) * (da / (da - db));
            kept.ids[0] = planeId | kIdClip;
        } else if (db > 0.0f) {
            kept.points[1] = b + (a - b) * (db / (db - da));
            kept.ids[1] = planeId | kIdClip;
        }
    } else {
        for (int k = 0; k < poly.count; ++k) {
            const Vec3& a = poly.points[k];
            const Vec3& b = poly.points[(k + 1) % poly.count];
            const float da = glm::dot(m, a - q), db = glm::dot(m, b - q);
            if (da <= 0.0f) kept.add(a, poly.ids[k]);
            if ((da <= 0.0f) != (db <= 0.0f))
                kept.add(a + (b - a) * (da / (da - db)), planeId | kIdClip | (std::uint32_t(k) << 8));
        }
    }
    poly = kept;
}

// Clips to the prism over the convex polygon `around` (normal `normal`): one plane per edge.
void clipToPrism(Polygon& poly, const Vec3* around, int count, const Vec3& normal) {
    Vec3 centre(0.0f);
    for (int k = 0; k < count; ++k) centre += around[k];
    centre /= float(count);
    for (int k = 0; k < count && poly.count > 0; ++k) {
        const Vec3& a = around[k];
        Vec3 m = glm::cross(around[(k + 1) % count] - a, normal);
        if (glm::dot(m, centre - a) > 0.0f) m = -m;
        clipToPlane(poly, m, a, std::uint32_t(k));
    }
}

// The shape's core feature lowest along -n: what rests on the triangle.
void incidentFeature(const Setup& setup, const Shape& shape, const Transform& t, const Vec3& n, Polygon& out) {
    switch (shape.type) {
        case ShapeType::Box:
        case ShapeType::ConvexHull: {
            int bestFace = -1;
            float bestAlignment = kFlatAlignment;
            for (int f = 0; f < faceCount(shape); ++f) {
                const float alignment = -glm::dot(faceNormal(shape, t, f), n);
                if (alignment >= bestAlignment) {
                    bestAlignment = alignment;
                    bestFace = f;
                }
            }
            if (bestFace >= 0 && (shape.type == ShapeType::Box ||
                                  shape.hull->faces()[bestFace].vertexCount <= std::uint32_t(kMaxPolygonFace))) {
                facePolygon(shape, t, bestFace, out);
                return;
            }
            // A vertex, and the flattest edge leaving it when that lies flat.
            const Vec3 localLowest = setup.core.localSupport(t.rotateInverse(-n));
            const Vec3 lowest = t.apply(localLowest);
            out.add(lowest, 0);
            Vec3 flattest(0.0f);
            float flattestSlope = kFlatLine;
            auto offer = [&](const Vec3& other) {
                const Vec3 d = other - lowest;
                const float length = glm::length(d);
                if (length > 0.0f && glm::dot(d, n) / length < flattestSlope) {
                    flattestSlope = glm::dot(d, n) / length;
                    flattest = other;
                }
            };
            if (shape.type == ShapeType::Box) {
                for (int k = 0; k < 3; ++k) {
                    Vec3 other = localLowest;
                    other[k] = -other[k];
                    offer(t.apply(other));
                }
            } else {
                const auto& vertices = shape.hull->vertices();
                for (const HullEdge& e : shape.hull->edges()) {
                    if (vertices[e.a] == localLowest) offer(t.apply(vertices[e.b]));
                    if (vertices[e.b] == localLowest) offer(t.apply(vertices[e.a]));
                }
            }
            if (flattestSlope < kFlatLine) out.add(flattest, 1);
            return;
        }
        case ShapeType::Capsule: {
            const Vec3 s0 = t.apply(Vec3(0, -shape.halfHeight, 0)), s1 = t.apply(Vec3(0, shape.halfHeight, 0));
            const float slope = glm::dot(glm::normalize(s1 - s0), n);
            if (std::abs(slope) < kFlatLine) {
                out.add(s0, 0);
                out.add(s1, 1);
            } else {
                out.add(slope > 0.0f ? s0 : s1, slope > 0.0f ? 0 : 1);
            }
            return;
        }
        case ShapeType::Cylinder: {
            const Vec3 axis = t.rotate(Vec3(0, 1, 0));
            const float slope = glm::dot(axis, n);
            if (std::abs(slope) >= kFlatAlignment) {
                const float cap = slope > 0.0f ? -shape.halfHeight : shape.halfHeight;
                for (int k = 0; k < kCylinderCapPoints; ++k) {
                    const float angle = 2.0f * kPi * float(k) / kCylinderCapPoints;
                    out.add(t.apply(Vec3(shape.radius * std::cos(angle), cap, shape.radius * std::sin(angle))),
                            std::uint32_t(k));
                }
            } else if (std::abs(slope) < kFlatLine) {
                const Vec3 down = glm::normalize(-n - glm::dot(-n, axis) * axis);
                const Vec3 rim = t.position + shape.radius * down;
                out.add(rim - shape.halfHeight * axis, 0);
                out.add(rim + shape.halfHeight * axis, 1);
            } else {
                out.add(setup.coreSupport(-n), 0);
            }
            return;
        }
        case ShapeType::Sphere: out.add(t.position, 0); return;
        case ShapeType::Compound:
        case ShapeType::Mesh:
        case ShapeType::HeightField: return;  // not convex: collided sub-shape by sub-shape
    }
}

// At most four candidates, spanning the largest area in the plane of `normal`: the deepest, the
// farthest from it, the one making the largest triangle, then the one adding the most to it.
// reduceToManifold (contact_manifold.h) makes the same choice with a margin on depth and ties, which
// a stack of 32-sided wheels needed; here it moved a chaotic rocking cube on the terrain of
// test_mesh_bodies across that suite's bound (docs/testing.md), so triangles keep plain maxima.
void reduce(const Candidates& in, const Vec3& normal, ContactManifold& out) {
    if (in.count <= kMaxManifoldPoints) {
        for (int k = 0; k < in.count; ++k) {
            const ContactCandidate& c = in.items[k];
            out.points[k] = {c.pointA, c.pointB, c.separation, c.featureId};
        }
        out.pointCount = in.count;
        return;
    }
    int chosen[4];
    auto argmax = [&](auto score) {
        int best = 0;
        float bestScore = -std::numeric_limits<float>::max();
        for (int k = 0; k < in.count; ++k) {
            const float s = score(in.items[k].pointA);
            if (s > bestScore) {
                bestScore = s;
                best = k;
            }
        }
        return best;
    };
    chosen[0] = 0;
    for (int k = 1; k < in.count; ++k)
        if (in.items[k].separation < in.items[chosen[0]].separation) chosen[0] = k;
    const Vec3 p0 = in.items[chosen[0]].pointA;
    chosen[1] = argmax([&](const Vec3& p) { return lengthSquared(p - p0); });
    const Vec3 p1 = in.items[chosen[1]].pointA;
    auto signedArea = [&](const Vec3& a, const Vec3& b, const Vec3& c) { return glm::dot(glm::cross(b - a, c - a), normal); };
    chosen[2] = argmax([&](const Vec3& p) { return std::abs(signedArea(p0, p1, p)); });
    const Vec3 p2 = in.items[chosen[2]].pointA;
    const float orientation = signedArea(p0, p1, p2) >= 0.0f ? 1.0f : -1.0f;
    // Area the point adds outside the triangle's edges (negative signed area against one of them).
    chosen[3] = argmax([&](const Vec3& p) {
        return -orientation * std::min({signedArea(p0, p1, p), signedArea(p1, p2, p), signedArea(p2, p0, p)});
    });
    for (int k = 0; k < 4; ++k) {
        const ContactCandidate& c = in.items[chosen[k]];
        out.points[k] = {c.pointA, c.pointB, c.separation, c.featureId};
    }
    out.pointCount = 4;
}

// One point on the shape (its core point `core`, pushed out by the radius) and its image on the
// triangle's side along the axis.
void addPoint(Candidates& into, const Vec3& core, float radius, const Vec3& u, float separation, std::uint32_t id,
              float speculativeDistance) {
    if (separation > speculativeDistance || into.count >= kMaxPolygon) return;
    const Vec3 onShape = core - radius * u;
    into.items[into.count++] = {onShape - separation * u, onShape, separation, id};
}

}  // namespace

bool collideTriangleConvex(const Triangle& triangle, const Shape& shape, const Transform& transform,
                           float speculativeDistance, ContactManifold& out) {
    out.pointCount = 0;
    // A non-finite pose or triangle gives no contact rather than spreading NaN into the solver.
    if (!isFinite(transform.position) || !isFinite(transform.rotation) || !isFinite(triangle.normal) ||
        !isFinite(triangle.vertices[0]) || !isFinite(triangle.vertices[1]) || !isFinite(triangle.vertices[2]))
        return false;
    const Vec3& n = triangle.normal;
    const Vec3 centre = transform.apply(localBounds(shape).center());
    if (glm::dot(centre - triangle.vertices[0], n) < 0.0f) return false;  // behind: one-sided

    const Setup setup{triangle, PlacedCore(shape, transform),
                      std::sqrt(std::max({lengthSquared(triangle.vertices[1] - triangle.vertices[0]),
                                          lengthSquared(triangle.vertices[2] - triangle.vertices[1]),
                                          lengthSquared(triangle.vertices[0] - triangle.vertices[2])})),
                      speculativeDistance + kTriangleFacePreference,
                      centre - (triangle.vertices[0] + triangle.vertices[1] + triangle.vertices[2]) / 3.0f};
    const float radius = setup.core.radius;

    Axis best;
    best.kind = AxisKind::TriangleFace;
    best.direction = n;
    best.separation = setup.separation(n);
    if (best.separation > speculativeDistance) return false;  // the plane alone separates them
    Axis chosen = best;
    if (shape.type == ShapeType::Sphere) {
        const Vec3 q = closestPointOnTriangle(transform.position, triangle.vertices[0], triangle.vertices[1],
                                              triangle.vertices[2]);
        const float distance = glm::length(transform.position - q);
        if (distance > 1e-6f * setup.size) {
            chosen.kind = AxisKind::Closest;
            chosen.direction = (transform.position - q) / distance;
            chosen.separation = distance - radius;
            chosen.shape0 = transform.position;
            chosen.onTriangle = q;
        }
    } else {
        findBestAxis(setup, shape, transform, chosen);
    }
    if (chosen.separation > speculativeDistance) return false;
    // Internal edges: a contact on a flat or concave seam takes the face normal.
    if (chosen.kind != AxisKind::TriangleFace && !meetsActiveFeature(triangle, chosen.direction, setup.size))
        chosen = best;
    if (best.separation > speculativeDistance && chosen.kind == AxisKind::TriangleFace) return false;

    const Vec3 u = chosen.direction;
    Candidates candidates;
    switch (chosen.kind) {
        case AxisKind::TriangleFace: {
            Polygon feature;
            incidentFeature(setup, shape, transform, n, feature);
            clipToPrism(feature, triangle.vertices.data(), 3, n);
            for (int k = 0; k < feature.count; ++k) {
                const float separation = glm::dot(feature.points[k] - triangle.vertices[0], n) - radius;
                addPoint(candidates, feature.points[k], radius, n, separation, kIdTriangleFace | feature.ids[k],
                         speculativeDistance);
            }
            // The feature lies beside the prism (over a neighbour, or over a slight ridge between
            // two prisms): its deepest point alone, so a touching shape is never left without one.
            if (feature.count == 0)
                addPoint(candidates, setup.coreSupport(-n), radius, n, best.separation, kIdTriangleFace, speculativeDistance);
            break;
        }
        case AxisKind::ShapeFace: {
            if (shape.type == ShapeType::ConvexHull &&
                shape.hull->faces()[chosen.shapeFace].vertexCount > std::uint32_t(kMaxPolygonFace)) {
                addPoint(candidates, setup.coreSupport(-u), radius, u, chosen.separation, kIdShapeFace, speculativeDistance);
                break;
            }
            Polygon face;
            facePolygon(shape, transform, chosen.shapeFace, face);
            const Vec3 faceOut = -u;  // the face's outward normal, towards the triangle
            Polygon tri;
            for (int k = 0; k < 3; ++k) tri.add(triangle.vertices[k], std::uint32_t(k));
            clipToPrism(tri, face.points, face.count, faceOut);
            for (int k = 0; k < tri.count; ++k) {
                // The triangle's point, and its projection onto the face plane on the shape.
                const float separation = glm::dot(tri.points[k] - face.points[0], faceOut);
                if (separation > speculativeDistance) continue;
                const Vec3 onShape = tri.points[k] - separation * faceOut;
                candidates.items[candidates.count++] = {tri.points[k], onShape, separation,
                                                        kIdShapeFace | (std::uint32_t(chosen.shapeFace) << 16) | tri.ids[k]};
            }
            if (candidates.count == 0) {
                const Vec3 deepest = setup.coreSupport(-u);
                addPoint(candidates, deepest, radius, u, chosen.separation, kIdShapeFace, speculativeDistance);
            }
            break;
        }
        case AxisKind::EdgePair: {
            Vec3 onCore = setup.coreSupport(-u);
            if (chosen.triangleEdge >= 0) {
                Vec3 s0 = chosen.shape0, s1 = chosen.shape1;
                if (shape.type == ShapeType::Box) {
                    // The box edge along axis k through its vertex deepest along the axis.
                    const int k = chosen.boxAxis;
                    Vec3 local = setup.core.localSupport(transform.rotateInverse(-u));
                    s0 = transform.apply(local);
                    local[k] = -local[k];
                    s1 = transform.apply(local);
                } else if (shape.type == ShapeType::Cylinder) {
                    // The side line through the cylinder's deepest rim point.
                    Vec3 local = setup.core.localSupport(transform.rotateInverse(-u));
                    s0 = transform.apply(local);
                    local.y = -local.y;
                    s1 = transform.apply(local);
                }
                Vec3 onTriangle;
                const int e = chosen.triangleEdge;
                closestPointsOfSegments(triangle.vertices[e], triangle.vertices[(e + 1) % 3], s0, s1, onTriangle, onCore);
            }
            addPoint(candidates, onCore, radius, u, chosen.separation, kIdEdge | std::uint32_t(chosen.triangleEdge & 0xff),
                     speculativeDistance);
            break;
        }
        case AxisKind::Closest:
            addPoint(candidates, chosen.shape0, radius, u, chosen.separation, kIdEdge | 0xffu, speculativeDistance);
            break;
    }
    if (candidates.count == 0) return false;
    out.normal = u;
    reduce(candidates, u, out);
    return out.pointCount > 0;
}

}  // namespace simcore
