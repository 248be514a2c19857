// SPDX-License-Identifier: LGPL-3.0-or-later
// The edge paths of the hidden-line drawing: the runs of edge_visibility.h projected to the
// drawing grid (vector_drawing.h), one visible and one hidden path per mesh.
//
// Chains: the pieces of each path are joined end to end where exactly two meet (grid points),
// so each chain is one polyline and a dash pattern runs on along it.
//
// Coincidence: where a hidden run and a visible run lie on one line of the drawing, their
// images coincide and only the visible one is drawn: the hidden run loses the part that a
// nearly parallel visible run covers within 4 grid units (0.04 pixel). This is a decision about
// strokes on the drawing's grid, made after visibility, which is exact (edge_visibility.h):
// in a standard view whose direction was rounded (an isometric eye placed by a normalised
// vector) the images of two edges can coincide to within 1e-12 pixel without being exactly
// collinear.
#pragma once

namespace exbsp::view {

struct frame;
struct vector_drawing;
struct vector_options;

/// Appends the frame's hidden edge paths (when opt.edges asks for them) and then its visible
/// edge paths to `d`, creases over opt.crease_deg: the SVG's options (f.vector) or a PNG's
/// (f.raster_edges). Precondition: 0 < opt.crease_deg <= 180 (the callers check it).
void add_edge_paths(const frame& f, const vector_options& opt, vector_drawing& d);

}  // namespace exbsp::view
