#pragma once
// Narrow phase against static surfaces: the contact manifold of one convex shape against one
// triangle of a TriangleMesh or HeightField (shapes/triangle_mesh.h, shapes/height_field.h). The
// surface's midphase (forEachTriangleOverlapping) proposes the triangles under a shape's bounds;
// this makes each one's manifold, so the contact manager can keep one manifold per triangle.
//
// How:
//   - The shape is seen as its core plus a radius (gjk.h's PlacedCore). A sphere is closed form:
//     the closest point of the triangle to its centre. Every other shape is tested by SAT on its
//     support function: the triangle's normal; box and hull face normals; triangle edges crossed
//     with box, hull and capsule edges and the cylinder's axis; the closest-point direction of a
//     capsule's segment; the direction from a cylinder's axis to each triangle vertex. The
//     triangle's normal wins near-ties (kTriangleFacePreference), so resting contacts stay on it.
//   - The manifold: on the triangle's normal, the shape's lowest feature (a face of a box or hull
//     within ~11 degrees of flat, a flat-lying box or hull edge, capsule segment or cylinder side
//     line, a cylinder cap as 8 points, else one vertex) clipped to the prism over the triangle;
//     on a box or hull face, the triangle clipped to the prism over that face; on an edge pair or
//     closest-point axis, one point. More than four are reduced to the four spanning the largest
//     area.
//   - Internal edges: when the winning axis is not the triangle's normal, the triangle's feature
//     touching the shape (a vertex, or an edge when two vertices tie) is looked up in the
//     triangle's active-edge flags. An inactive edge or vertex (a flat or concave seam) gives the
//     contact the triangle's face normal instead, so a body crossing the seam between two
//     coplanar triangles sees one flat surface.
//   - One-sided: a shape whose centre (of its local bounds) is behind the triangle's plane gets no
//     contact, and the triangle's normal is only tested pointing out of its front. A body that
//     reached behind a wall (it should not: contacts are speculative and fast bodies are swept)
//     leaves through the back freely rather than being shot across the wall.
//   - Limitation: a cylinder's rim against a triangle edge is covered by the listed axes only
//     approximately; in such configurations the separation may be reported up to a few millimetres
//     too small (a contact a little early), never a missed penetration of a face.
//
// The normal runs from the triangle (A) to the shape (B); separation = dot(pointB - pointA, normal).

#include "simcore/collision/contact_manifold.h"
#include "simcore/math/math.h"
#include "simcore/shapes/shape.h"
#include "simcore/shapes/triangle_mesh.h"

namespace simcore {

// Metres by which another axis must separate more than the triangle's normal to win over it.
constexpr float kTriangleFacePreference = 1e-3f;

// Fills `out` with the contact points of `triangle` (world frame) and `shape` placed by `transform`
// whose separation is <= speculativeDistance, and returns true when there is at least one. `out`
// is reset on every call. Allocates nothing.
bool collideTriangleConvex(const Triangle& triangle, const Shape& shape, const Transform& transform,
                           float speculativeDistance, ContactManifold& out);

}  // namespace simcore
