// SPDX-License-Identifier: LGPL-3.0-or-later
// Standard pipeline stages (notation in stages.h).
#include <exbsp/view/stages.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include <exbsp/core/errors.h>
#include "view/clip_stage.h"
#include "view/depth_sort.h"
#include "view/paint.h"
#include "view/svg_writer.h"
#include "view/texture_uvs.h"
#include "view/vector_pdf.h"

namespace exbsp::view {

namespace {

/// Bitwise key of a point (so that -0 and +0 stay distinct points: bit-identical transforms).
struct point_bits {
  std::uint64_t k[3];
  bool operator==(const point_bits& o) const {
    return k[0] == o.k[0] && k[1] == o.k[1] && k[2] == o.k[2];
  }
};
struct point_bits_hash {
  std::size_t operator()(const point_bits& p) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (std::uint64_t x : p.k) h = (h ^ x) * 0x100000001b3ull + (h >> 29);
    return static_cast<std::size_t>(h);
  }
};

/// f.points and f.fragment_points from f.fragments: each distinct corner (bitwise) once.
void index_points(frame& f) {
  f.points.clear();
  f.fragment_points.resize(f.fragments.size());
  std::unordered_map<point_bits, std::uint32_t, point_bits_hash> index;
  index.reserve(f.fragments.size());
  for (std::size_t i = 0; i < f.fragments.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const vec3d& p = f.fragments[i].v[k];
      point_bits key;
      std::memcpy(key.k, p.data(), sizeof key.k);
      const auto [at, fresh] = index.emplace(key, static_cast<std::uint32_t>(f.points.size()));
      if (fresh) f.points.push_back(p);
      f.fragment_points[i][k] = at->second;
    }
}

/// A world point after P Mv, as the fast path of transform+clip needs it (32 bytes: the
/// per-fragment loop reads three of these at random): `code` is its outcode
/// (view_volume_outcode), plus w_not_positive when it is inside but w <= 0, or just
/// not_finite; `win` is its window point when code == 0.
struct clipped_point {
  static constexpr unsigned w_not_positive = 64, not_finite = 128;
  window_point win;
  unsigned code = 0;
};

hpoint to_clip(const mat4& pm, const vec3d& p) { return pm * to_point(p); }

clipped_point transform_point(const mat4& pm, const viewport& vp, const vec3d& p) {
  clipped_point r;
  const hpoint c = to_clip(pm, p);
  if (!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(c.w))) {
    r.code = clipped_point::not_finite;
    return r;
  }
  r.code = view_volume_outcode(c);
  if (r.code == 0 && !(c.w > 0)) r.code = clipped_point::w_not_positive;
  if (r.code == 0) r.win = to_window(vp, c.x / c.w, c.y / c.w, c.z / c.w);
  return r;
}

}  // namespace

std::string build_stage(frame& f) {
  if (f.visibility != visibility_order::bsp) {  // a depth sort (teaching view): no tree
    f.tree.reset();
    f.fragments = soup_fragments(f.soup);
    index_points(f);
    texture_uvs(f);
    return std::to_string(f.fragments.size()) + " triangles for a depth sort (no BSP, no splits)";
  }
  if (f.soup.triangles.empty()) {  // nothing to draw: no tree, no fragments
    f.tree.reset();
    f.fragments.clear();
    f.points.clear();
    f.fragment_points.clear();
    return "empty scene";
  }
  f.tree.emplace(bsp::build(f.soup, f.build));
  f.fragments = f.tree->fragments_double();
  index_points(f);
  texture_uvs(f);
  const build_stats& s = f.tree->stats();
  return std::to_string(s.input_triangles) + " triangles, " + std::to_string(s.fragments) +
         " fragments, " + std::to_string(s.splits) + " splits, " + std::to_string(s.nodes) +
         " nodes, depth " + std::to_string(s.depth) + ", kernel " + s.kernel + ", heuristic " +
         s.heuristic;
}

std::string adopt_tree_stage(frame& f) {
  if (!f.tree) throw usage_error("adopt_tree_stage: the frame holds no tree");
  f.fragments = f.tree->fragments_double();
  index_points(f);
  texture_uvs(f);
  const build_stats& s = f.tree->stats();
  return std::to_string(s.input_triangles) + " triangles, " + std::to_string(s.fragments) +
         " fragments (a saved tree, not rebuilt), kernel " + s.kernel;
}

std::string order_stage(frame& f) {
  // A new view: the products of the effect and curve stages of the previous view are stale.
  f.fragment_colors.clear();
  f.corner_colors.clear();
  f.lines.clear();
  f.fog.reset();
  f.shader.reset();
  if (f.visibility != visibility_order::bsp) {
    f.order = depth_sorted_order(f.fragments, f.view, f.visibility);
    return std::to_string(f.order.size()) + " triangles, depth sort by " +
           (f.visibility == visibility_order::depth_sort_farthest ? "farthest corner"
                                                                  : "centroid") +
           " (not the BSP's order)";
  }
  if (!f.tree) {
    if (!f.fragments.empty()) throw usage_error("order_stage: the BSP has not been built");
    f.order.clear();
    return "empty scene";
  }
  if (f.view.is_parallel()) {
    const vector3& d = f.view.direction;
    f.order = f.tree->order_for_direction({d.x, d.y, d.z});
    return std::to_string(f.order.size()) + " fragments, direction";
  }
  f.order = f.tree->order_from_eye(to_vec3d(f.view.cam.eye));
  return std::to_string(f.order.size()) + " fragments, eye point";
}

std::string transform_clip_stage(frame& f) {
  // Each distinct point is transformed once (f.points; per corner when the index does not
  // match f.fragments). A fragment whose corners are all inside the view volume is what the
  // clipper would return unchanged, one with an outcode bit common to its corners what it
  // would return empty: only the others go through clip_to_view_volume. The window points are
  // the same doubles as the clipper's path computes.
  const mat4 pm = f.view.projection * f.view.model_view;
  const viewport& vp = f.view.vp;
  const bool indexed = f.fragment_points.size() == f.fragments.size() && !f.fragments.empty();
  std::vector<clipped_point> points;
  if (indexed) {
    points.reserve(f.points.size());
    for (const vec3d& p : f.points) points.push_back(transform_point(pm, vp, p));
  }
  std::size_t count = 0;  // f.polygons[0..count) are this frame's; the rest are reused storage
  f.polygons.reserve(f.order.size());
  f.fully_clipped = 0;
  f.non_finite = 0;
  f.near_dropped = 0;
  // near_plane_rule drop_*: a corner in front of the near plane (w + z < 0: bit 4 of the outcode,
  // clip/homogeneous.h) leaves the polygon out, or every polygon of its mesh.
  constexpr unsigned in_front_of_near = 1u << 4;
  const bool drop = f.near_plane != near_plane_rule::clip;
  std::vector<bool> dropped_mesh;
  const auto corners_of = [&](std::uint32_t idx, clipped_point* corner) {
    for (int k = 0; k < 3; ++k)
      corner[k] = indexed ? points[f.fragment_points[idx][k]]
                          : transform_point(pm, vp, f.fragments.at(idx).v[k]);
  };
  if (f.near_plane == near_plane_rule::drop_mesh)
    for (std::uint32_t idx : f.order) {
      const fragment_d& fr = f.fragments.at(idx);
      if (!fr.finite()) continue;
      clipped_point corner[3];
      corners_of(idx, corner);
      if (((corner[0].code | corner[1].code | corner[2].code) & in_front_of_near) == 0) continue;
      const std::uint32_t mesh = f.mesh_of(fr.face);
      if (mesh >= dropped_mesh.size()) dropped_mesh.resize(mesh + 1, false);
      dropped_mesh[mesh] = true;
    }
  // A mesh stays whole unless a fragment of it meets the near plane or worse (pipeline.h).
  const std::size_t meshes = mesh_count(f.mesh_face_offsets);
  f.meshes_whole.assign(meshes, 1);
  const auto cut = [&](std::uint32_t face) {
    const std::uint32_t mesh = f.mesh_of(face);
    if (mesh < meshes) f.meshes_whole[mesh] = 0;
  };
  constexpr unsigned not_whole =
      in_front_of_near | clipped_point::w_not_positive | clipped_point::not_finite;
  std::vector<hpoint> in(3), out;
  for (std::uint32_t idx : f.order) {
    const fragment_d& fr = f.fragments.at(idx);
    // An inexact kernel's rounded split point can be NaN or infinite: such a fragment has no
    // place in the picture; it is counted (the caller reports it), never passed on.
    if (!fr.finite()) {
      ++f.non_finite;
      cut(fr.face);
      continue;
    }
    clipped_point corner[3];
    corners_of(idx, corner);
    const unsigned any = corner[0].code | corner[1].code | corner[2].code;
    if ((any & not_whole) != 0) cut(fr.face);
    const unsigned all = corner[0].code & corner[1].code & corner[2].code;
    if (drop && (any & clipped_point::not_finite) == 0 && (all & 63) == 0) {
      const std::uint32_t mesh = f.mesh_of(fr.face);
      if ((any & in_front_of_near) != 0 || (mesh < dropped_mesh.size() && dropped_mesh[mesh])) {
        ++f.near_dropped;
        continue;
      }
    }
    const bool inside = any == 0;  // the clipper returns it unchanged, every w > 0
    bool ok = inside;
    if (!inside && (any & clipped_point::not_finite) == 0 && (all & 63) != 0) {
      ok = false;          // outside one plane: the clipper returns it empty
    } else if (!inside) {  // crosses a plane, has w <= 0 or a non-finite coordinate (throws)
      for (int k = 0; k < 3; ++k) in[k] = to_clip(pm, fr.v[k]);
      clip_to_view_volume(in, out);
      ok = !out.empty();
      for (const hpoint& c : out)
        if (!(c.w > 0)) ok = false;  // cannot happen after near-plane clipping; guards the divide
    }
    if (!ok) {
      ++f.fully_clipped;
      continue;
    }
    if (count == f.polygons.size()) f.polygons.emplace_back();
    screen_polygon& poly = f.polygons[count++];
    poly.fragment = idx;
    poly.face = fr.face;
    poly.color = f.fragment_colors.empty() ? f.color_of(fr.face) : f.fragment_colors.at(idx);
    poly.v.clear();
    if (inside) {
      poly.v.assign({corner[0].win, corner[1].win, corner[2].win});
    } else {
      poly.v.reserve(out.size());
      for (const hpoint& c : out) poly.v.push_back(to_window(vp, c.x / c.w, c.y / c.w, c.z / c.w));
    }
  }
  f.polygons.resize(count);
  return std::to_string(f.polygons.size()) + " polygons, " + std::to_string(f.fully_clipped) +
         " fully clipped" +
         (drop ? ", " + std::to_string(f.near_dropped) + " dropped at the near plane (not cut)"
               : std::string()) +
         (f.non_finite ? ", " + std::to_string(f.non_finite) + " with a non-finite corner left out"
                       : std::string());
}

std::string raster_stage(frame& f) {
  const viewport& vp = f.view.vp;
  f.picture = paint_frame(f, 1);
  std::string note =
      std::to_string(vp.width) + "x" + std::to_string(vp.height) + ", " +
      std::to_string(f.polygons.size()) + " polygons painted " +
      (effective_paint_order(f) == paint_order::front_to_back ? "front to back" : "back to front");
  if (!f.lines.empty())
    note += ", " + std::to_string(f.lines.size()) + " curve lines in their slots";
  return note;
}

namespace {

std::string drawing_note(const vector_drawing& d, std::size_t bytes) {
  const drawing_counts c = count_paths(d);
  return std::to_string(c.regions) + " regions (" + std::to_string(c.rings) + " rings), " +
         std::to_string(c.visible_edges) + " visible and " + std::to_string(c.hidden_edges) +
         " hidden edge pieces, " + std::to_string(c.curves) + " curve paths, " +
         std::to_string(bytes) + " bytes" +
         (d.back_faces_left_out ? ", " + std::to_string(d.back_faces_left_out) +
                                      " back faces of closed meshes left out"
                                : std::string());
}

}  // namespace

std::string svg_stage(frame& f) {
  if (f.vector.mode == vector_options::mode_kind::visible) {
    const vector_drawing d = visible_drawing(f);
    f.vector_seconds = d.seconds;
    f.svg = svg_document(d);
    return "visible regions: " + drawing_note(d, f.svg.size());
  }
  f.svg = f.lines.empty() && !f.shader ? svg_document(f.view.vp, f.background, f.polygons)
                                       : svg_document(f.view.vp, f.background, f.polygons, f.lines,
                                                      f.shader ? &*f.shader : nullptr);
  if (f.view.needs_placement()) f.svg = place_svg(f.svg, f.view.vp.height, placement_of(f));
  return "painter: " + std::to_string(f.polygons.size()) + " paths, " +
         std::to_string(f.lines.size()) + " curve pieces, " + std::to_string(f.svg.size()) +
         " bytes";
}

std::string pdf_stage(frame& f) {
  const bool visible = f.vector.mode == vector_options::mode_kind::visible;
  const vector_drawing d = visible ? visible_drawing(f) : painter_drawing(f);
  f.vector_seconds = d.seconds;
  f.pdf = pdf_document(d);
  return std::string(visible ? "visible regions: " : "painter: ") + drawing_note(d, f.pdf.size());
}

}  // namespace exbsp::view
