// The edge paths of the hidden-line drawing: the runs of edge_visibility.h projected to the
// drawing grid (vector_drawing.h), one visible and one hidden path per mesh.
//
// Chains: the pieces of each path are joined end to end where exactly two meet (grid points),
// so each chain is one polyline and a dash pattern runs on along it.
//
// Coincidence: where a hidden run and a visible run lie on one line through the viewer (exact
// test: both ends of the visible run's edge in the plane through E and the hidden run's edge,
// geom/homogeneous_det.h), their images coincide and only the visible one is drawn: the hidden
// run loses the part that the visible one covers (measured along it on the grid).
#pragma once

namespace exbsp::view {

struct frame;
struct vector_drawing;

/// Appends the frame's hidden edge paths (when f.vector.edges asks for them) and then its
/// visible edge paths to `d`. Precondition: 0 < f.vector.crease_deg <= 180 (visible_drawing
/// checks it).
void add_edge_paths(const frame& f, vector_drawing& d);

}  // namespace exbsp::view
