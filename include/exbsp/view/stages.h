// SPDX-License-Identifier: LGPL-3.0-or-later
// The standard stages of the viewing pipeline (pipeline.h). Each takes the frame, fills its
// products and returns a short note for the verbose log.
//
// Notation: fragment vertices are world-space points p (w = 1); clip coordinates
// c = P Mv p; after clip_to_view_volume, ndc = c.xyz / c.w; window = viewport(ndc).
#pragma once
#include <string>

#include <exbsp/core/export.h>
#include <exbsp/view/pipeline.h>

namespace exbsp::view {

/// "build": one BSP of f.soup with f.build, then f.fragments = fragments_double() (converted
/// once) and their distinct corners f.points / f.fragment_points (each transformed once per
/// view). Throws usage_error / limit_error from bsp::build. With f.visibility a depth sort (a
/// teaching view) no tree is built: f.fragments are the soup's triangles, unsplit.
EXBSP_EXPORT std::string build_stage(frame& f);

/// "build" for a tree made elsewhere (a saved tree, bsp::load): f.tree is set; fills the
/// products build_stage would (fragments, points) without building. Throws usage_error when
/// f.tree is empty.
EXBSP_EXPORT std::string adopt_tree_stage(frame& f);

/// "order": f.order = back-to-front fragment indices: order_from_eye(camera eye) for
/// perspective and frustum, order_for_direction(f.view.direction) for orthographic and oblique.
/// With f.visibility a depth sort: the triangles sorted by depth instead (depth_sort.h).
/// Clears the per-view products of effect and curve stages (fragment_colors, lines, fog).
/// Precondition: build_stage ran.
EXBSP_EXPORT std::string order_stage(frame& f);

/// "transform+clip": for each fragment in f.order, c = P Mv p per vertex, homogeneous clip
/// (clip_stage.h), divide, viewport; fills f.polygons in the same order and counts the
/// fragments that are entirely outside in f.fully_clipped, and those with a NaN or infinite
/// corner (an inexact kernel's split points), which are left out, in f.non_finite. Each distinct
/// point is transformed once; fragments entirely inside (or outside one plane) skip the clipper,
/// with the same doubles as its path. Polygon colours: the face colour, or
/// f.fragment_colors[fragment] when the lighting stage filled it.
/// With f.near_plane drop_polygon (drop_mesh), a fragment with a corner in front of the near
/// plane (w + z < 0; or any fragment of a mesh that has one) is left out instead of being cut,
/// and counted in f.near_dropped (a teaching view; fragments outside another plane entirely
/// are counted as fully clipped).
EXBSP_EXPORT std::string transform_clip_stage(frame& f);

/// "raster": painter's algorithm, no z-buffer: f.picture = background, then every polygon of
/// f.polygons in order with the top-left-rule rasterizer, with the curve lines of f.lines in
/// their slots and per-pixel fog when the fog stage ran (paint.h). The image of that
/// back-to-front walk; computed front to back with a coverage mask unless f.painter says
/// otherwise or there are lines (effective_paint_order).
EXBSP_EXPORT std::string raster_stage(frame& f);

/// "edges" (PNG, after the raster and its effects, before "place"): the feature edges of
/// f.raster_edges drawn over f.picture, the same paths as the SVG's (edge_paths.h: exact
/// visibility, visible solid, hidden dashed, the SVG's widths and colours), stroked
/// anti-aliased by cairo. With f.wireframe the picture is first cleared to the background and
/// hidden edges are drawn solid. Throws usage_error when crease_deg is outside (0, 180] or cairo
/// fails.
EXBSP_EXPORT std::string raster_edges_stage(frame& f);

/// "svg": f.svg = the SVG document: the visible-region drawing of the frame (vector_drawing.h),
/// or, with f.vector.mode painter, the painter's stack of f.polygons and f.lines (svg_writer.h).
EXBSP_EXPORT std::string svg_stage(frame& f);

/// "pdf": f.pdf = the PDF document (vector_pdf.h) of the same drawing as svg_stage (painter's
/// stack: painter_drawing). Throws usage_error when cairo fails.
EXBSP_EXPORT std::string pdf_stage(frame& f);

}  // namespace exbsp::view
