// Over 800 lines because every shape pair's narrow phase uses the same file-local helpers
// (manifold reduction, segment and polygon clipping, the box/hull polyhedron view), and the
// constexpr dispatch table at the end needs every pair function in view; split by pair, those helpers
// would become a private header read by every file. Sections, in order: candidates and reduction,
// small geometry, round pairs, polyhedra (SAT and clipping), box-box, dispatch.

#include "simcore/collision/collide_shapes.h"

#include "simcore/collision/closest_points.h"

#include "simcore/collision/epa.h"
#include "simcore/collision/gjk.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace simcore {

namespace {

// Feature choice and alignment tolerances. The solver tolerates a few millimetres of slop
// (kLinearSlop), so a feature only wins over a face when it is clearly better; this keeps resting
// stacks on stable face contacts instead of flickering to edge contacts from round-off.
constexpr float kEdgeRelativeTolerance = 0.05f;       // edge must beat the best face by 5% of it...
constexpr float kEdgeAbsoluteTolerance = 0.5f * kLinearSlop;  // ...plus this
constexpr float kFaceRelativeTolerance = 0.02f;       // B's face must beat A's face by 2% (plus this)
constexpr float kFaceAbsoluteTolerance = 0.1f * kLinearSlop;
constexpr float kFaceAlignment = 0.98f;               // cos(~11°): feature counts as lying flat on a face
// cos(~18°): an edge pair whose faces are this close to flat on each other takes the face manifold
// (faceManifoldServes); at kFaceAlignment, a bar rolling over another's edge at 10° a step still
// reached the next face a centimetre deep.
constexpr float kFlatPairAlignment = 0.95f;
constexpr float kLineParallel = 0.1f;                 // |cos| below which a segment lies along a face

constexpr int kMaxClipVertices = 64;  // clipping polygons and contact candidates
constexpr int kCylinderCapPoints = 8;

// ---- Contact candidates and manifold reduction --------------------------------------------------

struct Contacts {
    Vec3 normal{0.0f, 1.0f, 0.0f};
    int count = 0;
    ContactCandidate items[kMaxClipVertices];  // written before they are read: no 2 KB zero fill per call

    Contacts() = default;
    Contacts(const Contacts& other) : normal(other.normal), count(other.count) {
        std::copy(other.items, other.items + other.count, items);
    }
    Contacts& operator=(const Contacts& other) {
        normal = other.normal;
        count = other.count;
        std::copy(other.items, other.items + other.count, items);
        return *this;
    }

    void add(const Vec3& pointA, const Vec3& pointB, float separation, std::uint32_t featureId) {
        if (count < kMaxClipVertices) items[count++] = {pointA, pointB, separation, featureId};
    }

    float deepestSeparation() const {
        float deepest = std::numeric_limits<float>::max();
        for (int i = 0; i < count; ++i) deepest = std::min(deepest, items[i].separation);
        return deepest;
    }
};

// ---- Small geometry ------------------------------------------------------------------------------

Vec3 perpendicularTo(const Vec3& v) {
    const Vec3 other = std::abs(v.x) < 0.57f ? Vec3(1.0f, 0.0f, 0.0f) : Vec3(0.0f, 1.0f, 0.0f);
    return glm::normalize(glm::cross(v, other));
}

// Transform taking `inner`'s local frame into `outer`'s local frame.
Transform relativeTransform(const Transform& outer, const Transform& inner) {
    Transform t;
    t.rotation = glm::conjugate(outer.rotation) * inner.rotation;
    t.position = outer.rotateInverse(inner.position - outer.position);
    return t;
}

// Capsule/sphere core: a segment (degenerate for a sphere) in the world.
struct Segment {
    Vec3 p0{0.0f};
    Vec3 p1{0.0f};
};

Segment capsuleSegment(const Shape& capsule, const Transform& t) {
    return {t.apply(Vec3(0.0f, -capsule.halfHeight, 0.0f)), t.apply(Vec3(0.0f, capsule.halfHeight, 0.0f))};
}

// ---- Round pairs: sphere, capsule -----------------------------------------------------------------

// Contact of two spheres with the given core points and radii; `fallbackNormal` when they coincide.
void addRoundContact(const Vec3& coreA, float radiusA, const Vec3& coreB, float radiusB,
                     const Vec3& fallbackNormal, float speculativeDistance, Contacts& contacts) {
    const Vec3 d = coreB - coreA;
    const float distance = glm::length(d);
    const Vec3 n = distance > 1e-6f ? d / distance : fallbackNormal;
    const float separation = glm::dot(d, n) - radiusA - radiusB;
    if (separation > speculativeDistance) return;
    contacts.normal = n;
    contacts.add(coreA + radiusA * n, coreB - radiusB * n, separation, 0);
}

void collideSphereSphere(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, float spec,
                         Contacts& contacts) {
    addRoundContact(ta.position, a.radius, tb.position, b.radius, Vec3(0.0f, 1.0f, 0.0f), spec, contacts);
}

void collideSphereCapsule(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, float spec,
                          Contacts& contacts) {
    const Segment segment = capsuleSegment(b, tb);
    const Vec3 onAxis = closestPointOnSegment(ta.position, segment.p0, segment.p1);
    addRoundContact(ta.position, a.radius, onAxis, b.radius, perpendicularTo(tb.rotate(Vec3(0.0f, 1.0f, 0.0f))),
                    spec, contacts);
}

void collideCapsuleCapsule(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, float spec,
                           Contacts& contacts) {
    const Segment sa = capsuleSegment(a, ta);
    const Segment sb = capsuleSegment(b, tb);
    Vec3 onA, onB;
    closestPointsOfSegments(sa.p0, sa.p1, sb.p0, sb.p1, onA, onB);

    const Vec3 axisA = ta.rotate(Vec3(0.0f, 1.0f, 0.0f));
    const Vec3 axisB = tb.rotate(Vec3(0.0f, 1.0f, 0.0f));
    const Vec3 d = onB - onA;
    const float distance = glm::length(d);
    Vec3 n;
    if (distance > 1e-6f) {
        n = d / distance;
    } else {
        // Axes intersect: the common perpendicular separates them fastest.
        const Vec3 across = glm::cross(axisA, axisB);
        n = lengthSquared(across) > 1e-8f ? glm::normalize(across) : perpendicularTo(axisA);
        if (glm::dot(n, tb.position - ta.position) < 0.0f) n = -n;
    }
    const float radiusSum = a.radius + b.radius;
    if (glm::dot(d, n) - radiusSum > spec) return;
    contacts.normal = n;

    // Parallel capsules rest along a line: two points bound the overlap of the segments.
    const float lengthA = 2.0f * a.halfHeight;
    if (lengthA > 0.0f && b.halfHeight > 0.0f && lengthSquared(glm::cross(axisA, axisB)) < 1e-4f) {
        const float t0 = glm::dot(sb.p0 - sa.p0, axisA);
        const float t1 = glm::dot(sb.p1 - sa.p0, axisA);
        const float low = std::max(0.0f, std::min(t0, t1));
        const float high = std::min(lengthA, std::max(t0, t1));
        if (high - low > kLinearSlop) {
            const std::array<float, 2> ends{low, high};
            for (int i = 0; i < 2; ++i) {
                const Vec3 pa = sa.p0 + ends[i] * axisA;
                const Vec3 pb = closestPointOnSegment(pa, sb.p0, sb.p1);
                const float separation = glm::dot(pb - pa, n) - radiusSum;
                if (separation <= spec) {
                    contacts.add(pa + a.radius * n, pb - b.radius * n, separation, std::uint32_t(i + 1));
                }
            }
            if (contacts.count > 0) return;
        }
    }
    contacts.add(onA + a.radius * n, onB - b.radius * n, glm::dot(d, n) - radiusSum, 0);
}

// Box (A) and sphere (B): closest point of the box, or the nearest face when the centre is inside.
void collideBoxSphere(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, float spec,
                      Contacts& contacts) {
    const Vec3 centre = ta.applyInverse(tb.position);
    const Vec3& h = a.halfExtents;
    Vec3 onBox = glm::clamp(centre, -h, h);
    Vec3 localNormal;
    float separation;
    const Vec3 outside = centre - onBox;
    const float outsideDistance = glm::length(outside);
    if (outsideDistance > 1e-6f) {
        localNormal = outside / outsideDistance;
        separation = outsideDistance - b.radius;
    } else {
        // Inside: leave through the nearest face.
        int axis = 0;
        float nearest = std::numeric_limits<float>::max();
        for (int i = 0; i < 3; ++i) {
            const float toFace = h[i] - std::abs(centre[i]);
            if (toFace < nearest) nearest = toFace, axis = i;
        }
        const float sign = centre[axis] >= 0.0f ? 1.0f : -1.0f;
        localNormal = Vec3(0.0f);
        localNormal[axis] = sign;
        onBox = centre;
        onBox[axis] = sign * h[axis];
        separation = -nearest - b.radius;
    }
    if (separation > spec) return;
    contacts.normal = ta.rotate(localNormal);
    contacts.add(ta.apply(onBox), tb.position - b.radius * contacts.normal, separation, 0);
}

// An edge pair can win the SAT while the faces either side of the contact lie nearly flat on each
// other (the incident face within kFlatPairAlignment of the reference face): a bar landing across
// another, slightly turned, or nearly parallel edges, whose cross product may point anywhere. One
// edge point lets the body pivot onto the rest of its face within a step (Box3D's Edge Crossing
// went 3.9 cm deep), so such a pair takes the face manifold, whose clipped points hold the edge
// crossing and give the rest of the face speculative points - unless it is deeper than the edge
// point by more than the slop: then the faces overlap only beside each other and its depth is not
// the bodies'. Returns whether `face` replaces `edge`.
bool faceManifoldServes(float incidentAlignment, const Contacts& face, const Contacts& edge) {
    return incidentAlignment >= kFlatPairAlignment && face.count > 0 &&
           face.deepestSeparation() >= edge.deepestSeparation() - kLinearSlop;
}

// ---- Polyhedra: box and hull through one view -----------------------------------------------------

// A box or a hull as faces (CCW polygons with outward normals), edges with their two faces, and a
// support function, all in the shape's local frame. The box's topology is computed, not stored.
class Polyhedron {
public:
    explicit Polyhedron(const Shape& shape) {
        if (shape.type == ShapeType::Box) {
            halfExtents_ = shape.halfExtents;
        } else if (shape.hull && !shape.hull->faces().empty()) {
            hull_ = shape.hull.get();
        } else {
            valid_ = false;
        }
    }

    bool valid() const { return valid_; }

    int faceCount() const { return hull_ ? int(hull_->faces().size()) : 6; }
    // Box faces: 2k is +axis k, 2k+1 is -axis k.
    Vec3 faceNormal(int f) const {
        if (hull_) return hull_->faces()[f].normal;
        Vec3 n(0.0f);
        n[f / 2] = (f % 2 == 0) ? 1.0f : -1.0f;
        return n;
    }
    float faceOffset(int f) const { return hull_ ? hull_->faces()[f].offset : halfExtents_[f / 2]; }
    int faceVertexCount(int f) const { return hull_ ? int(hull_->faces()[f].vertexCount) : 4; }
    Vec3 faceVertex(int f, int i) const {
        if (hull_) {
            const HullFace& face = hull_->faces()[f];
            return hull_->vertices()[hull_->faceVertexIndices()[face.firstIndex + std::uint32_t(i)]];
        }
        // Corners (-,-), (+,-), (+,+), (-,+) in the face's (u, v) axes run CCW about +axis; the
        // negative face walks them backwards.
        const int axis = f / 2;
        const bool positive = f % 2 == 0;
        const int corner = positive ? i : 3 - i;
        const int u = (axis + 1) % 3;
        const int v = (axis + 2) % 3;
        Vec3 p;
        p[axis] = positive ? halfExtents_[axis] : -halfExtents_[axis];
        p[u] = (corner == 1 || corner == 2) ? halfExtents_[u] : -halfExtents_[u];
        p[v] = (corner >= 2) ? halfExtents_[v] : -halfExtents_[v];
        return p;
    }

    int edgeCount() const { return hull_ ? int(hull_->edges().size()) : 12; }
    void edge(int e, Vec3& p0, Vec3& p1, int& face0, int& face1) const {
        if (hull_) {
            const HullEdge& edge = hull_->edges()[e];
            p0 = hull_->vertices()[edge.a];
            p1 = hull_->vertices()[edge.b];
            face0 = int(edge.faceA);
            face1 = int(edge.faceB);
            return;
        }
        // Box edge e runs along axis e/4 at the corner of the u and v faces picked by e's low bits.
        const int axis = e / 4;
        const int u = (axis + 1) % 3;
        const int v = (axis + 2) % 3;
        const bool positiveU = (e & 1) != 0;
        const bool positiveV = (e & 2) != 0;
        p0[u] = positiveU ? halfExtents_[u] : -halfExtents_[u];
        p0[v] = positiveV ? halfExtents_[v] : -halfExtents_[v];
        p1 = p0;
        p0[axis] = -halfExtents_[axis];
        p1[axis] = halfExtents_[axis];
        face0 = 2 * u + (positiveU ? 0 : 1);
        face1 = 2 * v + (positiveV ? 0 : 1);
    }

    Vec3 support(const Vec3& direction) const {
        if (hull_) return hull_->support(direction);
        return {direction.x >= 0.0f ? halfExtents_.x : -halfExtents_.x,
                direction.y >= 0.0f ? halfExtents_.y : -halfExtents_.y,
                direction.z >= 0.0f ? halfExtents_.z : -halfExtents_.z};
    }

    // An interior point, to orient edge-edge axes outwards.
    Vec3 centroid() const {
        if (!hull_) return Vec3(0.0f);
        Vec3 sum(0.0f);
        for (const Vec3& v : hull_->vertices()) sum += v;
        return sum / float(hull_->vertices().size());
    }

    // The face whose outward normal (world) is most aligned with `worldDirection`.
    int mostAlignedFace(const Transform& t, const Vec3& worldDirection, float& alignment) const {
        const Vec3 local = t.rotateInverse(worldDirection);
        int best = 0;
        alignment = -std::numeric_limits<float>::max();
        for (int f = 0; f < faceCount(); ++f) {
            const float d = glm::dot(faceNormal(f), local);
            if (d > alignment) alignment = d, best = f;
        }
        return best;
    }

    // The face to clip against a reference face with world normal `referenceNormal`: the most
    // anti-parallel face among those holding the deepest vertex, so that vertex is never lost. (The
    // globally most anti-parallel face of an irregular hull can miss it.) For a box they coincide.
    int incidentFace(const Transform& t, const Vec3& referenceNormal) const {
        float alignment;
        if (!hull_) return mostAlignedFace(t, -referenceNormal, alignment);
        const Vec3 local = t.rotateInverse(-referenceNormal);
        const std::vector<Vec3>& vertices = hull_->vertices();
        std::uint32_t deepest = 0;
        for (std::uint32_t v = 1; v < vertices.size(); ++v) {
            if (glm::dot(vertices[v], local) > glm::dot(vertices[deepest], local)) deepest = v;
        }
        int best = -1;
        alignment = -std::numeric_limits<float>::max();
        const std::vector<std::uint32_t>& indices = hull_->faceVertexIndices();
        for (int f = 0; f < faceCount(); ++f) {
            const HullFace& face = hull_->faces()[f];
            const float d = glm::dot(face.normal, local);
            if (d <= alignment) continue;
            for (std::uint32_t i = 0; i < face.vertexCount; ++i) {
                if (indices[face.firstIndex + i] == deepest) {
                    alignment = d;
                    best = f;
                    break;
                }
            }
        }
        return best >= 0 ? best : mostAlignedFace(t, -referenceNormal, alignment);
    }

private:
    const ConvexHull* hull_ = nullptr;
    Vec3 halfExtents_{0.0f};
    bool valid_ = true;
};

struct FaceQuery {
    float separation = -std::numeric_limits<float>::max();
    int face = -1;
};

// Largest separation of `other` from the face planes of `reference` (both in reference's frame).
FaceQuery queryFaces(const Polyhedron& reference, const Polyhedron& other, const Transform& otherToReference) {
    FaceQuery query;
    for (int f = 0; f < reference.faceCount(); ++f) {
        const Vec3 n = reference.faceNormal(f);
        const Vec3 deepest = otherToReference.apply(other.support(otherToReference.rotateInverse(-n)));
        const float separation = glm::dot(n, deepest) - reference.faceOffset(f);
        if (separation > query.separation) query = {separation, f};
    }
    return query;
}

struct EdgeQuery {
    float separation = -std::numeric_limits<float>::max();
    int edgeA = -1;
    int edgeB = -1;
    Vec3 normal{0.0f};  // A's frame, from A to B
};

// Do arcs AB and CD of the Gauss map cross? Then the edges with those face normals form a face of
// the Minkowski difference and their cross product is a candidate axis (Gregorius, GDC 2013).
bool isMinkowskiFace(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const Vec3 bxa = glm::cross(b, a);
    const Vec3 dxc = glm::cross(d, c);
    const float cba = glm::dot(c, bxa);
    const float dba = glm::dot(d, bxa);
    const float adc = glm::dot(a, dxc);
    const float bdc = glm::dot(b, dxc);
    return cba * dba < 0.0f && adc * bdc < 0.0f && cba * bdc > 0.0f;
}

// Edge pairs of A and B, in A's frame. For two boxes this is the classic set of nine edge-cross
// axes, each tested at the pair of edges that actually supports it.
EdgeQuery queryEdges(const Polyhedron& a, const Polyhedron& b, const Transform& bToA) {
    EdgeQuery query;
    const Vec3 centreA = a.centroid();
    for (int eb = 0; eb < b.edgeCount(); ++eb) {
        Vec3 q0, q1;
        int fb0, fb1;
        b.edge(eb, q0, q1, fb0, fb1);
        q0 = bToA.apply(q0);
        q1 = bToA.apply(q1);
        const Vec3 edgeB = q1 - q0;
        // Minkowski difference A - B: B's Gauss map is negated.
        const Vec3 c = -bToA.rotate(b.faceNormal(fb0));
        const Vec3 d = -bToA.rotate(b.faceNormal(fb1));
        for (int ea = 0; ea < a.edgeCount(); ++ea) {
            Vec3 p0, p1;
            int fa0, fa1;
            a.edge(ea, p0, p1, fa0, fa1);
            if (!isMinkowskiFace(a.faceNormal(fa0), a.faceNormal(fa1), c, d)) continue;
            const Vec3 edgeA = p1 - p0;
            Vec3 axis = glm::cross(edgeA, edgeB);
            const float axisLength = glm::length(axis);
            // Nearly parallel edges: their faces give the same axis better.
            if (axisLength < 0.005f * std::sqrt(lengthSquared(edgeA) * lengthSquared(edgeB))) continue;
            axis /= axisLength;
            if (glm::dot(axis, p0 - centreA) < 0.0f) axis = -axis;
            const float separation = glm::dot(axis, q0 - p0);
            if (separation > query.separation) query = {separation, ea, eb, axis};
        }
    }
    return query;
}

struct ClipVertex {
    Vec3 point;
    std::uint32_t id;  // low byte: incident vertex; next byte: 1 + clip edge that made it
};
using ClipPolygon = std::array<ClipVertex, kMaxClipVertices>;

// World plane of one face and the side planes through its edges (pointing out of the face).
struct ReferenceFace {
    Vec3 normal{0.0f};
    float offset = 0.0f;
    std::array<Vec3, kMaxClipVertices> sideNormals;   // only the first sideCount are set
    std::array<float, kMaxClipVertices> sideOffsets;
    int sideCount = 0;
};

ReferenceFace referenceFace(const Polyhedron& poly, const Transform& t, int face) {
    ReferenceFace ref;
    ref.normal = t.rotate(poly.faceNormal(face));
    ref.offset = poly.faceOffset(face) + glm::dot(ref.normal, t.position);
    const int n = std::min(poly.faceVertexCount(face), kMaxClipVertices);
    for (int i = 0; i < n; ++i) {
        const Vec3 v0 = t.apply(poly.faceVertex(face, i));
        const Vec3 v1 = t.apply(poly.faceVertex(face, (i + 1) % n));
        const Vec3 side = glm::cross(v1 - v0, ref.normal);
        const float length = glm::length(side);
        if (length <= 1e-9f) continue;
        ref.sideNormals[ref.sideCount] = side / length;
        ref.sideOffsets[ref.sideCount] = glm::dot(side / length, v0);
        ++ref.sideCount;
    }
    return ref;
}

// Sutherland-Hodgman: clips `polygon` (any orientation) to the prism over the reference face.
int clipToSides(const ReferenceFace& ref, ClipPolygon& polygon, int count) {
    ClipPolygon scratch;
    ClipPolygon* in = &polygon;
    ClipPolygon* out = &scratch;
    for (int s = 0; s < ref.sideCount && count > 0; ++s) {
        int outCount = 0;
        for (int i = 0; i < count; ++i) {
            const ClipVertex& current = (*in)[i];
            const ClipVertex& next = (*in)[(i + 1) % count];
            const float dc = glm::dot(ref.sideNormals[s], current.point) - ref.sideOffsets[s];
            const float dn = glm::dot(ref.sideNormals[s], next.point) - ref.sideOffsets[s];
            if (dc <= 0.0f && outCount < kMaxClipVertices) (*out)[outCount++] = current;
            if (((dc < 0.0f && dn > 0.0f) || (dc > 0.0f && dn < 0.0f)) && outCount < kMaxClipVertices) {
                const float t = dc / (dc - dn);
                (*out)[outCount++] = {current.point + t * (next.point - current.point),
                                      (std::uint32_t(s + 1) << 8) | (current.id & 0xFFu)};
            }
        }
        std::swap(in, out);
        count = outCount;
    }
    if (in != &polygon) std::copy(in->begin(), in->begin() + count, polygon.begin());
    return count;
}

// Clips segment p0-p1 to the prism over the reference face; false when nothing is left.
bool clipSegmentToSides(const ReferenceFace& ref, Vec3& p0, Vec3& p1) {
    float t0 = 0.0f;
    float t1 = 1.0f;
    const Vec3 start = p0;
    const Vec3 delta = p1 - p0;
    for (int s = 0; s < ref.sideCount; ++s) {
        const float d0 = glm::dot(ref.sideNormals[s], start) - ref.sideOffsets[s];
        const float d1 = glm::dot(ref.sideNormals[s], start + delta) - ref.sideOffsets[s];
        if (d0 > 0.0f && d1 > 0.0f) return false;
        if (d0 > 0.0f) t0 = std::max(t0, d0 / (d0 - d1));
        if (d1 > 0.0f) t1 = std::min(t1, d0 / (d0 - d1));
    }
    if (t0 > t1) return false;
    p0 = start + t0 * delta;
    p1 = start + t1 * delta;
    return true;
}

// Turns clipped incident core points (inflated by `incidentRadius`) into contacts against the
// reference plane; the reference shape is A when `referenceIsA`.
void addFaceContacts(const ReferenceFace& ref, const ClipVertex* points, int count, float incidentRadius,
                     bool referenceIsA, std::uint32_t idBase, float spec, Contacts& contacts) {
    contacts.normal = referenceIsA ? ref.normal : -ref.normal;
    for (int i = 0; i < count; ++i) {
        const Vec3& p = points[i].point;
        const float height = glm::dot(ref.normal, p) - ref.offset;
        const float separation = height - incidentRadius;
        if (separation > spec) continue;
        const Vec3 onReference = p - height * ref.normal;
        const Vec3 onIncident = p - incidentRadius * ref.normal;
        const std::uint32_t id = idBase | points[i].id;
        if (referenceIsA) {
            contacts.add(onReference, onIncident, separation, id);
        } else {
            contacts.add(onIncident, onReference, separation, id);
        }
    }
}

// One point from GJK/EPA: the deepest (or closest) pair of points.
void collideGeneric(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, float spec,
                    Contacts& contacts) {
    const ContactQuery query = penetrationOrDistance(a, ta, b, tb);
    const float separation = query.signedDistance();
    if (!(separation <= spec) || !isFinite(query.normal) || !isFinite(query.pointA) || !isFinite(query.pointB)) return;
    const float length = glm::length(query.normal);
    if (length <= 0.0f) return;
    contacts.normal = query.normal / length;
    contacts.add(query.pointA, query.pointB, separation, 0);
}

// ---- Box-box: dedicated SAT -----------------------------------------------------------------------
//
// The same decisions as the polyhedron path (same axes, tolerances, reference/incident faces,
// clip order and feature ids), computed from the relative rotation matrix: the 6 face axes and 9
// edge-cross axes in closed form, the incident face straight from the reference normal, and the
// incident quad clipped against the reference face's 4 side planes in the reference box's frame,
// where those planes are axis-aligned.

// Corner i (0..3) of box face f (2k: +axis k, 2k+1: -axis k), CCW about the outward normal; the
// same order as Polyhedron::faceVertex.
inline Vec3 boxFaceVertex(const Vec3& h, int f, int i) {
    const int axis = f >> 1;
    const bool positive = (f & 1) == 0;
    const int corner = positive ? i : 3 - i;
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    Vec3 p;
    p[axis] = positive ? h[axis] : -h[axis];
    p[u] = (corner == 1 || corner == 2) ? h[u] : -h[u];
    p[v] = (corner >= 2) ? h[v] : -h[v];
    return p;
}

// Rotation matrix of a unit quaternion, columns = local axes in the world.
inline Mat3 rotationMatrix(const Quat& q) { return glm::mat3_cast(q); }

void collideBoxBox(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, float spec,
                   Contacts& contacts) {
    const Vec3& hA = a.halfExtents;
    const Vec3& hB = b.halfExtents;
    const Mat3 ra = rotationMatrix(ta.rotation);
    const Mat3 rb = rotationMatrix(tb.rotation);
    const Vec3 d = tb.position - ta.position;

    // c[i][j] = B's axis j along A's axis i; |c| with no epsilon (the parallel edge axes are skipped).
    float c[3][3], absC[3][3];
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            c[i][j] = glm::dot(ra[i], rb[j]);
            absC[i][j] = std::abs(c[i][j]);
        }
    }
    const Vec3 t(glm::dot(ra[0], d), glm::dot(ra[1], d), glm::dot(ra[2], d));     // B's centre in A's frame
    const Vec3 u(-glm::dot(rb[0], d), -glm::dot(rb[1], d), -glm::dot(rb[2], d));  // A's centre in B's frame

    // A's faces. Face 2i (+axis) wins the tie with face 2i+1.
    float faceASeparation = -std::numeric_limits<float>::max();
    int faceA = -1;
    for (int i = 0; i < 3; ++i) {
        const float reach = hA[i] + hB[0] * absC[i][0] + hB[1] * absC[i][1] + hB[2] * absC[i][2];
        const float positive = t[i] - reach;
        const float negative = -t[i] - reach;
        if (positive > faceASeparation) faceASeparation = positive, faceA = 2 * i;
        if (negative > faceASeparation) faceASeparation = negative, faceA = 2 * i + 1;
    }
    if (faceASeparation > spec) return;
    float faceBSeparation = -std::numeric_limits<float>::max();
    int faceB = -1;
    for (int j = 0; j < 3; ++j) {
        const float reach = hB[j] + hA[0] * absC[0][j] + hA[1] * absC[1][j] + hA[2] * absC[2][j];
        const float positive = u[j] - reach;
        const float negative = -u[j] - reach;
        if (positive > faceBSeparation) faceBSeparation = positive, faceB = 2 * j;
        if (negative > faceBSeparation) faceBSeparation = negative, faceB = 2 * j + 1;
    }
    if (faceBSeparation > spec) return;

    // Edge axes cross(A axis i, B axis j), in A's frame; nearly parallel edges are left to the faces.
    float edgeSeparation = -std::numeric_limits<float>::max();
    int edgeI = -1;
    int edgeJ = -1;
    Vec3 edgeAxis(0.0f);
    for (int j = 0; j < 3; ++j) {
        const Vec3 bj(c[0][j], c[1][j], c[2][j]);
        for (int i = 0; i < 3; ++i) {
            const int i1 = i == 2 ? 0 : i + 1;
            const int i2 = i == 0 ? 2 : i - 1;
            // cross(e_i, bj): zero along i, -bj[i2] along i1, bj[i1] along i2.
            Vec3 axis(0.0f);
            axis[i1] = -bj[i2];
            axis[i2] = bj[i1];
            const float length2 = axis[i1] * axis[i1] + axis[i2] * axis[i2];
            if (length2 < 0.005f * 0.005f) continue;
            const float reachA = hA[i1] * std::abs(axis[i1]) + hA[i2] * std::abs(axis[i2]);
            const int j1 = j == 2 ? 0 : j + 1;
            const int j2 = j == 0 ? 2 : j - 1;
            const Vec3 bj1(c[0][j1], c[1][j1], c[2][j1]);
            const Vec3 bj2(c[0][j2], c[1][j2], c[2][j2]);
            const float reachB = hB[j1] * std::abs(glm::dot(axis, bj1)) + hB[j2] * std::abs(glm::dot(axis, bj2));
            const float inverseLength = 1.0f / std::sqrt(length2);
            const float separation = (std::abs(glm::dot(axis, t)) - reachA - reachB) * inverseLength;
            if (separation > edgeSeparation) {
                edgeSeparation = separation;
                edgeI = i;
                edgeJ = j;
                edgeAxis = axis * inverseLength;
            }
        }
    }
    if (edgeI >= 0 && edgeSeparation > spec) return;

    const float bestFace = std::max(faceASeparation, faceBSeparation);
    const bool edgeWins = edgeI >= 0 &&
        edgeSeparation > bestFace + kEdgeRelativeTolerance * std::abs(bestFace) + kEdgeAbsoluteTolerance;
    const bool referenceIsA =
        !(faceBSeparation > faceASeparation + kFaceRelativeTolerance * std::abs(faceASeparation) + kFaceAbsoluteTolerance);
    // Incident box seen from the reference box: m[j] = incident axis j, p = incident centre.
    Mat3 m;
    Vec3 p;
    if (referenceIsA) {
        for (int j = 0; j < 3; ++j) m[j] = Vec3(c[0][j], c[1][j], c[2][j]);
        p = t;
    } else {
        for (int j = 0; j < 3; ++j) m[j] = Vec3(c[j][0], c[j][1], c[j][2]);
        p = u;
    }
    const Vec3& hRef = referenceIsA ? hA : hB;
    const Vec3& hInc = referenceIsA ? hB : hA;
    const Mat3& rRef = referenceIsA ? ra : rb;
    const Vec3& refPosition = referenceIsA ? ta.position : tb.position;
    const int refFace = referenceIsA ? faceA : faceB;
    const int k = refFace >> 1;
    const float sign = (refFace & 1) == 0 ? 1.0f : -1.0f;

    // Incident face: the most anti-parallel to the reference normal (first best in face order).
    int incFace = 0;
    float incidentAlignment = -std::numeric_limits<float>::max();
    for (int j = 0; j < 3; ++j) {
        const float along = -sign * m[j][k];  // incident axis j against the reference normal
        if (along > incidentAlignment) incidentAlignment = along, incFace = 2 * j;
        if (-along > incidentAlignment) incidentAlignment = -along, incFace = 2 * j + 1;
    }

    Contacts edge;  // the edge pair's point, when the edge axis wins
    if (edgeWins) {
        const Vec3 n = glm::dot(edgeAxis, t) >= 0.0f ? edgeAxis : -edgeAxis;  // A's frame, A to B
        // A's edge along axis i farthest along n; B's edge along axis j farthest along -n.
        const int i1 = (edgeI + 1) % 3, i2 = (edgeI + 2) % 3;
        const bool posU = n[i1] > 0.0f, posV = n[i2] > 0.0f;
        Vec3 p0;
        p0[i1] = posU ? hA[i1] : -hA[i1];
        p0[i2] = posV ? hA[i2] : -hA[i2];
        Vec3 p1 = p0;
        p0[edgeI] = -hA[edgeI];
        p1[edgeI] = hA[edgeI];
        const int j1 = (edgeJ + 1) % 3, j2 = (edgeJ + 2) % 3;
        const float nB1 = n.x * c[0][j1] + n.y * c[1][j1] + n.z * c[2][j1];
        const float nB2 = n.x * c[0][j2] + n.y * c[1][j2] + n.z * c[2][j2];
        const bool posUB = nB1 < 0.0f, posVB = nB2 < 0.0f;
        Vec3 q0;
        q0[j1] = posUB ? hB[j1] : -hB[j1];
        q0[j2] = posVB ? hB[j2] : -hB[j2];
        Vec3 q1 = q0;
        q0[edgeJ] = -hB[edgeJ];
        q1[edgeJ] = hB[edgeJ];
        Vec3 onA, onB;
        closestPointsOfSegments(ta.position + ra * p0, ta.position + ra * p1, tb.position + rb * q0,
                                tb.position + rb * q1, onA, onB);
        edge.normal = ra * n;
        const float separation = glm::dot(onB - onA, edge.normal);
        if (separation <= spec) {
            const std::uint32_t edgeA = std::uint32_t(4 * edgeI + (posU ? 1 : 0) + (posV ? 2 : 0));
            const std::uint32_t edgeB = std::uint32_t(4 * edgeJ + (posUB ? 1 : 0) + (posVB ? 2 : 0));
            edge.add(onA, onB, separation, 0x40000000u | (edgeA << 12) | edgeB);
        }
        if (incidentAlignment < kFlatPairAlignment) {
            contacts = edge;
            return;
        }
    }

    // The incident quad in the reference frame, clipped against the side planes of the reference
    // face, in Polyhedron order: positive face -v, +u, +v, -u; negative face +v, +u, -v, -u.
    // (A convex quad gains at most one vertex per plane; the bound only guards against round-off.)
    constexpr int kBoxClipCapacity = 32;
    ClipVertex bufferA[kBoxClipCapacity], bufferB[kBoxClipCapacity];
    for (int i = 0; i < 4; ++i) bufferA[i] = {p + m * boxFaceVertex(hInc, incFace, i), std::uint32_t(i)};
    const int ku = (k + 1) % 3, kv = (k + 2) % 3;
    const int sideAxis[4] = {kv, ku, kv, ku};
    const float sideSign[4] = {-sign, 1.0f, sign, -1.0f};
    ClipVertex* in = bufferA;
    ClipVertex* out = bufferB;
    int count = 4;
    for (int s = 0; s < 4 && count > 0; ++s) {
        const int axis = sideAxis[s];
        const float sgn = sideSign[s];
        const float limit = hRef[axis];
        int outCount = 0;
        for (int i = 0; i < count; ++i) {
            const ClipVertex& current = in[i];
            const ClipVertex& next = in[i + 1 == count ? 0 : i + 1];
            const float dc = sgn * current.point[axis] - limit;
            const float dn = sgn * next.point[axis] - limit;
            if (dc <= 0.0f && outCount < kBoxClipCapacity) out[outCount++] = current;
            if (((dc < 0.0f && dn > 0.0f) || (dc > 0.0f && dn < 0.0f)) && outCount < kBoxClipCapacity) {
                const float f = dc / (dc - dn);
                out[outCount++] = {current.point + f * (next.point - current.point),
                                   (std::uint32_t(s + 1) << 8) | (current.id & 0xFFu)};
            }
        }
        std::swap(in, out);
        count = outCount;
    }

    const Vec3 normalWorld = sign * rRef[k];
    contacts.normal = referenceIsA ? normalWorld : -normalWorld;
    const std::uint32_t idBase = (referenceIsA ? 0u : 0x80000000u) | (std::uint32_t(refFace & 0x7F) << 24) |
                                 (std::uint32_t(incFace & 0xFF) << 16);
    const float faceLevel = sign * hRef[k];
    for (int i = 0; i < count; ++i) {
        const Vec3& q = in[i].point;
        const float separation = sign * q[k] - hRef[k];
        if (separation > spec) continue;
        Vec3 onReference = q;
        onReference[k] = faceLevel;
        const Vec3 worldIncident = refPosition + rRef * q;
        const Vec3 worldReference = refPosition + rRef * onReference;
        if (referenceIsA) {
            contacts.add(worldReference, worldIncident, separation, idBase | in[i].id);
        } else {
            contacts.add(worldIncident, worldReference, separation, idBase | in[i].id);
        }
    }
    if (edgeWins) {
        if (!faceManifoldServes(incidentAlignment, contacts, edge)) contacts = edge;
        return;
    }
    if (contacts.count == 0) collideGeneric(a, ta, b, tb, spec, contacts);
}

void collidePolyhedra(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, float spec,
                      Contacts& contacts) {
    const Polyhedron polyA(a);
    const Polyhedron polyB(b);
    if (!polyA.valid() || !polyB.valid()) return collideGeneric(a, ta, b, tb, spec, contacts);

    const Transform bToA = relativeTransform(ta, tb);
    const FaceQuery faceA = queryFaces(polyA, polyB, bToA);
    if (faceA.separation > spec) return;
    const FaceQuery faceB = queryFaces(polyB, polyA, relativeTransform(tb, ta));
    if (faceB.separation > spec) return;
    const EdgeQuery edges = queryEdges(polyA, polyB, bToA);
    if (edges.separation > spec) return;

    const float bestFace = std::max(faceA.separation, faceB.separation);
    const bool edgeWins = edges.edgeA >= 0 &&
        edges.separation > bestFace + kEdgeRelativeTolerance * std::abs(bestFace) + kEdgeAbsoluteTolerance;
    const bool referenceIsA =
        !(faceB.separation > faceA.separation + kFaceRelativeTolerance * std::abs(faceA.separation) + kFaceAbsoluteTolerance);
    const Polyhedron& refPoly = referenceIsA ? polyA : polyB;
    const Polyhedron& incPoly = referenceIsA ? polyB : polyA;
    const Transform& refT = referenceIsA ? ta : tb;
    const Transform& incT = referenceIsA ? tb : ta;
    const int refFaceIndex = referenceIsA ? faceA.face : faceB.face;

    const ReferenceFace ref = referenceFace(refPoly, refT, refFaceIndex);
    const int incFace = incPoly.incidentFace(incT, ref.normal);

    const float incidentAlignment = -glm::dot(incT.rotate(incPoly.faceNormal(incFace)), ref.normal);
    Contacts edge;  // the edge pair's point, when the edge axis wins
    if (edgeWins) {
        Vec3 p0, p1, q0, q1;
        int unused0, unused1;
        polyA.edge(edges.edgeA, p0, p1, unused0, unused1);
        polyB.edge(edges.edgeB, q0, q1, unused0, unused1);
        Vec3 onA, onB;
        closestPointsOfSegments(ta.apply(p0), ta.apply(p1), tb.apply(q0), tb.apply(q1), onA, onB);
        edge.normal = ta.rotate(edges.normal);
        const float separation = glm::dot(onB - onA, edge.normal);
        if (separation <= spec) {
            edge.add(onA, onB, separation,
                         0x40000000u | (std::uint32_t(edges.edgeA & 0xFFF) << 12) | std::uint32_t(edges.edgeB & 0xFFF));
        }
        if (incidentAlignment < kFlatPairAlignment) {
            contacts = edge;
            return;
        }
    }

    ClipPolygon polygon;
    const int incCount = std::min(incPoly.faceVertexCount(incFace), kMaxClipVertices);
    for (int i = 0; i < incCount; ++i) polygon[i] = {incT.apply(incPoly.faceVertex(incFace, i)), std::uint32_t(i)};
    const int clipped = clipToSides(ref, polygon, incCount);

    const std::uint32_t idBase = (referenceIsA ? 0u : 0x80000000u) | (std::uint32_t(refFaceIndex & 0x7F) << 24) |
                                 (std::uint32_t(incFace & 0xFF) << 16);
    addFaceContacts(ref, polygon.data(), clipped, 0.0f, referenceIsA, idBase, spec, contacts);
    if (edgeWins) {
        if (!faceManifoldServes(incidentAlignment, contacts, edge)) contacts = edge;
        return;
    }
    // Clipping can lose everything when the pair only touches at a rim; GJK/EPA still has a point.
    // (In deep penetration the deepest incident vertex may lie outside the reference face and be
    // clipped away: the manifold is then shallower than the true depth, as with any face clipper.)
    if (contacts.count == 0) collideGeneric(a, ta, b, tb, spec, contacts);
}

// A line feature (capsule segment, cylinder side) lying flat on a face of polyhedron A gives two
// points; false when the configuration does not apply.
// `contacts` holds the GJK/EPA point; the two points replace it only if they are as deep.
bool addSegmentOnFace(const Polyhedron& poly, const Transform& ta, const Vec3& normal, Vec3 p0, Vec3 p1,
                      float radius, float spec, Contacts& contacts) {
    float alignment;
    const int face = poly.mostAlignedFace(ta, normal, alignment);
    if (alignment < kFaceAlignment) return false;
    const ReferenceFace ref = referenceFace(poly, ta, face);
    const float length = glm::length(p1 - p0);
    if (length <= kLinearSlop || std::abs(glm::dot(p1 - p0, ref.normal)) > kLineParallel * length) return false;
    if (!clipSegmentToSides(ref, p0, p1)) return false;
    const std::array<ClipVertex, 2> ends{ClipVertex{p0, 0}, ClipVertex{p1, 1}};
    Contacts lineContacts;
    addFaceContacts(ref, ends.data(), 2, radius, true, std::uint32_t(face & 0xFF) << 16, spec, lineContacts);
    if (lineContacts.count == 0 || lineContacts.deepestSeparation() > contacts.deepestSeparation() + kLinearSlop) {
        return false;
    }
    contacts = lineContacts;
    return true;
}

// A capsule tilted over a face of polyhedron A, its low end's GJK/EPA point in `contacts`: a second
// point where the capsule's side line nearest the face ends at the high end, if that is within the
// speculative margin and over the face. A fast turn then cannot swing the high end through the
// face within a step: a ragdoll's shin turning at 28 rad/s went 9 cm into the ground with the low
// end's point alone.
void addTiltedCapsuleEnd(const Polyhedron& poly, const Transform& ta, const Segment& segment, float radius, float spec,
                         Contacts& contacts) {
    if (contacts.count != 1) return;
    float alignment;
    const int face = poly.mostAlignedFace(ta, contacts.normal, alignment);
    if (alignment < kFaceAlignment) return;
    const ReferenceFace ref = referenceFace(poly, ta, face);
    const Vec3 along = segment.p1 - segment.p0;
    const float length = glm::length(along);
    if (length <= kLinearSlop) return;
    const Vec3 axis = along / length;
    const Vec3 sideward = -ref.normal + glm::dot(ref.normal, axis) * axis;  // towards the face, across the axis
    const float sidewardLength = glm::length(sideward);
    if (sidewardLength <= 1e-6f) return;  // standing on an end: the GJK/EPA point is the whole contact
    const bool p0High = glm::dot(ref.normal, segment.p0) > glm::dot(ref.normal, segment.p1);
    const Vec3 onCapsule = (p0High ? segment.p0 : segment.p1) + (radius / sidewardLength) * sideward;
    for (int s = 0; s < ref.sideCount; ++s)
        if (glm::dot(ref.sideNormals[s], onCapsule) > ref.sideOffsets[s]) return;
    const float height = glm::dot(ref.normal, onCapsule) - ref.offset;
    const float separation = height * glm::dot(ref.normal, contacts.normal);  // along the manifold's normal
    if (separation > spec) return;
    contacts.add(onCapsule - height * ref.normal, onCapsule, separation, (std::uint32_t(face & 0xFF) << 16) | 2u);
}

// A capsule (B) over a face of polyhedron A, its GJK/EPA point in `contacts`: both ends lying flat,
// else the high end's point beside the low end's.
void addCapsuleOnFace(const Polyhedron& poly, const Transform& ta, const Segment& segment, float radius, float spec,
                      Contacts& contacts) {
    if (!addSegmentOnFace(poly, ta, contacts.normal, segment.p0, segment.p1, radius, spec, contacts))
        addTiltedCapsuleEnd(poly, ta, segment, radius, spec, contacts);
}

// Box or hull (A) and capsule (B).
void collidePolyhedronCapsule(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, float spec,
                              Contacts& contacts) {
    collideGeneric(a, ta, b, tb, spec, contacts);
    const Polyhedron poly(a);
    if (contacts.count == 0 || !poly.valid()) return;
    addCapsuleOnFace(poly, ta, capsuleSegment(b, tb), b.radius, spec, contacts);
}

// Cylinder (A) and sphere (B), in closed form in the cylinder's frame: the closest point of the
// solid cylinder, or, with the centre inside, the nearer of the side and the cap it is under.
void collideCylinderSphere(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, float spec,
                           Contacts& contacts) {
    const Vec3 p = ta.applyInverse(tb.position);
    const float radial = std::sqrt(p.x * p.x + p.z * p.z);
    Vec3 onCylinder = p;
    if (radial > a.radius) {
        const float scale = a.radius / radial;
        onCylinder.x *= scale;
        onCylinder.z *= scale;
    }
    onCylinder.y = std::clamp(p.y, -a.halfHeight, a.halfHeight);
    const Vec3 outside = p - onCylinder;
    const float outsideDistance = glm::length(outside);
    Vec3 localNormal;
    float separation;
    if (outsideDistance > 1e-6f) {
        localNormal = outside / outsideDistance;
        separation = outsideDistance - b.radius;
    } else {
        // Inside: leave through the nearer of the cap and the side.
        const float toCap = a.halfHeight - std::abs(p.y);
        const float toSide = a.radius - radial;
        onCylinder = p;
        if (toCap <= toSide || radial <= 1e-6f) {
            const float sign = p.y >= 0.0f ? 1.0f : -1.0f;
            localNormal = Vec3(0.0f, sign, 0.0f);
            onCylinder.y = sign * a.halfHeight;
            separation = -toCap - b.radius;
        } else {
            localNormal = Vec3(p.x / radial, 0.0f, p.z / radial);
            onCylinder.x = localNormal.x * a.radius;
            onCylinder.z = localNormal.z * a.radius;
            separation = -toSide - b.radius;
        }
    }
    if (separation > spec) return;
    contacts.normal = ta.rotate(localNormal);
    contacts.add(ta.apply(onCylinder), tb.position - b.radius * contacts.normal, separation, 0);
}

// Closest points of a segment and a box (box frame) when the segment lies outside the box; false
// when it touches or crosses the box. The distance is attained at an end of the segment against
// the box or at the segment against one of the 12 edges (an interior point facing a face interior
// only happens with the segment parallel to the face, where an edge or an end attains it too).
bool closestSegmentBox(const Vec3& h, const Vec3& p0, const Vec3& p1, Vec3& onBox, Vec3& onSegment, float& distance2) {
    // Slab test: does the segment meet the box?
    {
        float t0 = 0.0f, t1 = 1.0f;
        const Vec3 delta = p1 - p0;
        bool meets = true;
        for (int i = 0; i < 3 && meets; ++i) {
            if (std::abs(delta[i]) < 1e-12f) {
                if (std::abs(p0[i]) > h[i]) meets = false;
            } else {
                const float inverse = 1.0f / delta[i];
                float enter = (-h[i] - p0[i]) * inverse;
                float leave = (h[i] - p0[i]) * inverse;
                if (enter > leave) std::swap(enter, leave);
                t0 = std::max(t0, enter);
                t1 = std::min(t1, leave);
                if (t0 > t1) meets = false;
            }
        }
        if (meets) return false;
    }
    const auto consider = [&](const Vec3& box, const Vec3& segment) {
        const float d2 = lengthSquared(segment - box);
        if (d2 < distance2) distance2 = d2, onBox = box, onSegment = segment;
    };
    distance2 = std::numeric_limits<float>::max();
    consider(glm::clamp(p0, -h, h), p0);
    consider(glm::clamp(p1, -h, h), p1);
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3;
        const int v = (axis + 2) % 3;
        for (int corner = 0; corner < 4; ++corner) {
            Vec3 e0;
            e0[u] = (corner & 1) ? h[u] : -h[u];
            e0[v] = (corner & 2) ? h[v] : -h[v];
            Vec3 e1 = e0;
            e0[axis] = -h[axis];
            e1[axis] = h[axis];
            Vec3 onSeg, onEdge;
            closestPointsOfSegments(p0, p1, e0, e1, onSeg, onEdge);
            consider(onEdge, onSeg);
        }
    }
    return distance2 > 1e-12f;
}

// Box (A) and capsule (B): closed-form closest points of the box and the capsule's segment while
// the segment is outside the box (the resting regime), GJK/EPA once it reaches into the box; then
// the segment clipped against the face when the capsule lies flat on it.
void collideBoxCapsule(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, float spec,
                       Contacts& contacts) {
    const Segment segment = capsuleSegment(b, tb);
    Vec3 onBox(0.0f), onSegment(0.0f);
    float distance2 = 0.0f;
    if (closestSegmentBox(a.halfExtents, ta.applyInverse(segment.p0), ta.applyInverse(segment.p1), onBox, onSegment,
                          distance2)) {
        const float distance = std::sqrt(distance2);
        const float separation = distance - b.radius;
        if (separation > spec) return;
        contacts.normal = ta.rotate((onSegment - onBox) / distance);
        contacts.add(ta.apply(onBox), ta.apply(onSegment) - b.radius * contacts.normal, separation, 0);
    } else {
        collideGeneric(a, ta, b, tb, spec, contacts);
    }
    if (contacts.count == 0) return;
    addCapsuleOnFace(Polyhedron(a), ta, segment, b.radius, spec, contacts);
}

// Box or hull (A) and cylinder (B). GJK/EPA finds the normal; a cap resting flat on a face is then
// an 8-gon on the rim clipped against the face (the rim points lie on the true surface, so their
// separations are exact), and a cylinder lying on its side contributes its lowest side line.
void collidePolyhedronCylinder(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, float spec,
                               Contacts& contacts) {
    collideGeneric(a, ta, b, tb, spec, contacts);
    const Polyhedron poly(a);
    if (contacts.count == 0 || !poly.valid()) return;
    const Vec3 n = contacts.normal;
    const Vec3 axis = tb.rotate(Vec3(0.0f, 1.0f, 0.0f));
    const float axisAlongNormal = glm::dot(axis, n);

    if (std::abs(axisAlongNormal) >= kFaceAlignment) {
        float alignment;
        const int face = poly.mostAlignedFace(ta, n, alignment);
        if (alignment < kFaceAlignment) return;
        const ReferenceFace ref = referenceFace(poly, ta, face);
        // The cap facing A is the one whose outward axis points against n.
        const float capY = axisAlongNormal > 0.0f ? -b.halfHeight : b.halfHeight;
        ClipPolygon polygon;
        for (int i = 0; i < kCylinderCapPoints; ++i) {
            const float angle = 2.0f * kPi * float(i) / float(kCylinderCapPoints);
            polygon[i] = {tb.apply(Vec3(b.radius * std::cos(angle), capY, b.radius * std::sin(angle))), std::uint32_t(i)};
        }
        const int clipped = clipToSides(ref, polygon, kCylinderCapPoints);
        Contacts capContacts;
        addFaceContacts(ref, polygon.data(), clipped, 0.0f, true, std::uint32_t(face & 0xFF) << 16, spec, capContacts);
        if (capContacts.count > 0 && capContacts.deepestSeparation() <= contacts.deepestSeparation() + kLinearSlop) {
            contacts = capContacts;
        }
    } else if (std::abs(axisAlongNormal) <= kLineParallel) {
        const Vec3 towardA = glm::normalize(-n + axisAlongNormal * axis);
        const Vec3 p0 = tb.apply(Vec3(0.0f, -b.halfHeight, 0.0f)) + b.radius * towardA;
        const Vec3 p1 = tb.apply(Vec3(0.0f, b.halfHeight, 0.0f)) + b.radius * towardA;
        addSegmentOnFace(poly, ta, n, p0, p1, 0.0f, spec, contacts);
    }
}

// Two cylinders stacked cap on cap: A's cap (a 16-gon on the rim) is the reference face and B's
// cap (an 8-gon) is clipped against it. Otherwise, one GJK/EPA point.
void collideCylinderCylinder(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, float spec,
                             Contacts& contacts) {
    collideGeneric(a, ta, b, tb, spec, contacts);
    if (contacts.count == 0) return;
    const Vec3 n = contacts.normal;
    const Vec3 axisA = ta.rotate(Vec3(0.0f, 1.0f, 0.0f));
    const Vec3 axisB = tb.rotate(Vec3(0.0f, 1.0f, 0.0f));
    const float alongA = glm::dot(axisA, n);
    const float alongB = glm::dot(axisB, n);
    if (std::abs(alongA) < kFaceAlignment || std::abs(alongB) < kFaceAlignment) return;

    constexpr int kReferenceRimPoints = 16;
    const float capA = alongA > 0.0f ? a.halfHeight : -a.halfHeight;  // A's cap facing B
    const float capB = alongB > 0.0f ? -b.halfHeight : b.halfHeight;  // B's cap facing A
    const Vec3 capCentreA = ta.apply(Vec3(0.0f, capA, 0.0f));
    ReferenceFace ref;
    ref.normal = alongA > 0.0f ? axisA : -axisA;
    ref.offset = glm::dot(ref.normal, capCentreA);
    const auto rimA = [&](int i) {
        const float angle = 2.0f * kPi * float(i % kReferenceRimPoints) / float(kReferenceRimPoints);
        return ta.apply(Vec3(a.radius * std::cos(angle), capA, a.radius * std::sin(angle)));
    };
    for (int i = 0; i < kReferenceRimPoints && a.radius > 0.0f; ++i) {
        const Vec3 v0 = rimA(i);
        Vec3 side = glm::normalize(glm::cross(rimA(i + 1) - v0, ref.normal));
        if (glm::dot(side, capCentreA - v0) > 0.0f) side = -side;  // point out of the cap
        ref.sideNormals[ref.sideCount] = side;
        ref.sideOffsets[ref.sideCount] = glm::dot(side, v0);
        ++ref.sideCount;
    }
    ClipPolygon polygon;
    for (int i = 0; i < kCylinderCapPoints; ++i) {
        const float angle = 2.0f * kPi * float(i) / float(kCylinderCapPoints);
        polygon[i] = {tb.apply(Vec3(b.radius * std::cos(angle), capB, b.radius * std::sin(angle))), std::uint32_t(i)};
    }
    const int clipped = clipToSides(ref, polygon, kCylinderCapPoints);
    Contacts capContacts;
    addFaceContacts(ref, polygon.data(), clipped, 0.0f, true, 0x00010000u, spec, capContacts);
    if (capContacts.count > 0 && capContacts.deepestSeparation() <= contacts.deepestSeparation() + kLinearSlop) {
        contacts = capContacts;
    }
}

// ---- Dispatch -------------------------------------------------------------------------------------

using Routine = void (*)(const Shape&, const Transform&, const Shape&, const Transform&, float, Contacts&);

struct Dispatch {
    Routine routine;
    bool swapped;  // the routine expects (B, A)
};

// Rows: A's type, columns: B's type, in ShapeType order (sphere, box, capsule, cylinder, hull).
constexpr Dispatch kDispatch[kShapeTypeCount][kShapeTypeCount] = {
    {{collideSphereSphere, false}, {collideBoxSphere, true}, {collideSphereCapsule, false},
     {collideCylinderSphere, true}, {collideGeneric, false}},
    {{collideBoxSphere, false}, {collideBoxBox, false}, {collideBoxCapsule, false},
     {collidePolyhedronCylinder, false}, {collidePolyhedra, false}},
    {{collideSphereCapsule, true}, {collideBoxCapsule, true}, {collideCapsuleCapsule, false},
     {collideGeneric, false}, {collidePolyhedronCapsule, true}},
    {{collideCylinderSphere, false}, {collidePolyhedronCylinder, true}, {collideGeneric, false},
     {collideCylinderCylinder, false}, {collidePolyhedronCylinder, true}},
    {{collideGeneric, false}, {collidePolyhedra, false}, {collidePolyhedronCapsule, false},
     {collidePolyhedronCylinder, false}, {collidePolyhedra, false}},
};

}  // namespace

bool collideShapes(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                   float speculativeDistance, ContactManifold& out) {
    out = ContactManifold{};
    const int rowA = int(a.type);
    const int columnB = int(b.type);
    if (rowA < 0 || rowA >= kShapeTypeCount || columnB < 0 || columnB >= kShapeTypeCount) return false;

    const Dispatch& entry = kDispatch[rowA][columnB];
    Contacts contacts;
    if (entry.swapped) {
        entry.routine(b, tb, a, ta, speculativeDistance, contacts);
        contacts.normal = -contacts.normal;
        for (int i = 0; i < contacts.count; ++i) std::swap(contacts.items[i].pointA, contacts.items[i].pointB);
    } else {
        entry.routine(a, ta, b, tb, speculativeDistance, contacts);
    }
    reduceToManifold(contacts.items, contacts.count, contacts.normal, out);
    return out.pointCount > 0;
}

}  // namespace simcore
