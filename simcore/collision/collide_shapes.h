#pragma once
// Narrow phase: contact manifolds for one pair of placed shapes.
//
// A dispatch table over (ShapeType, ShapeType) picks a routine per pair; pairs with only the
// reverse routine run swapped and have their normal and points flipped back.
//   - sphere, capsule among themselves: closest points of the cores (point / segment), closed form;
//     parallel capsules give two points over the overlap of their segments.
//   - box-sphere: closest point on the box, or the nearest face when the centre is inside.
//   - cylinder-sphere: the same in closed form against the solid cylinder (cap or side when inside).
//   - box-box: dedicated SAT from the relative rotation matrix (6 face + 9 edge axes), incident
//     face straight from the reference normal, its quad clipped in the reference box's frame; same
//     decisions, tolerances and feature ids as the polyhedron path below.
//   - box-capsule: closed-form closest points of box and segment while the segment is outside the
//     box (GJK/EPA once it reaches in), plus the segment clipped against the face when lying flat.
//   - box/hull among themselves (other than box-box): SAT (faces of both, edge pairs pruned by the Gauss-map test), then
//     reference/incident face clipping, or one edge-edge point.
//   - hull with capsule: GJK/EPA for the normal, plus the capsule segment clipped against the
//     face when the capsule lies flat on it (two points).
//   - box/hull with cylinder: GJK/EPA, plus an 8-point cap polygon (cap flat on a face) or the side
//     line (cylinder lying on a face) clipped against the face.
//   - cylinder-cylinder: GJK/EPA, plus cap-on-cap clipping (B's 8-gon against A's 16-gon cap).
//   - everything else (sphere-hull, cylinder-capsule): one point from GJK/EPA.
// Manifolds with more than four candidates are reduced to the four spanning the largest area.

#include "simcore/collision/contact_manifold.h"
#include "simcore/math/math.h"
#include "simcore/shapes/shape.h"

namespace simcore {

// Convex shapes only: a compound collides child pair by child pair through the contact manager's
// mid-phase (contact_manager.h); given one, this reports no contact.
//
// Fills `out` with the contact points of A and B whose separation is <= speculativeDistance
// (normal unit, from A to B; at most kMaxManifoldPoints) and returns true when there is at least
// one. `out` is reset on every call. Allocates nothing.
bool collideShapes(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                   float speculativeDistance, ContactManifold& out);

}  // namespace simcore
