#pragma once
// Draws a transform gizmo (gizmo.h) for the renderer's screen pass: each handle a stroke of
// constant width in widget pixels over a wider near-black one, so that it reads on the light sky,
// a pale floor and dark bodies alike; arrows end in heads, plane handles are filled squares, the
// far halves of the axis rings are thin and dim (they cannot be picked), and the hovered or
// dragged handle is drawn last and highlighted.

#include "app/viewport/camera.h"
#include "app/viewport/gizmo.h"
#include "app/viewport/renderer.h"

#include <vector>

namespace interplay {

// Triangles in widget pixels (x right, y down; z unused), three vertices each.
std::vector<OverlayVertex> gizmoTriangles(const gizmo::Placement& placement, gizmo::Mode mode,
                                          gizmo::Handle highlighted, const Camera& camera, float widthPixels,
                                          float heightPixels);

}  // namespace interplay
