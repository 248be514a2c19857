// Standard pipeline stages (notation in stages.h).
#include "view/stages.h"

#include "mesh/errors.h"
#include "view/clip_stage.h"
#include "view/paint.h"
#include "view/svg_writer.h"
#include "view/vector_pdf.h"

namespace exbsp::view {

std::string build_stage(frame& f) {
  if (f.soup.triangles.empty()) {  // nothing to draw: no tree, no fragments
    f.tree.reset();
    f.cells.reset();
    f.fragments.clear();
    return "empty scene";
  }
  f.cells.reset();  // the curves stage's copy of the old tree's shape
  f.tree.emplace(bsp::build(f.soup, f.build));
  f.fragments = f.tree->fragments_double();
  const build_stats& s = f.tree->stats();
  return std::to_string(s.input_triangles) + " triangles, " + std::to_string(s.fragments) + " fragments, " +
         std::to_string(s.splits) + " splits, " + std::to_string(s.nodes) + " nodes, depth " +
         std::to_string(s.depth) + ", kernel " + s.kernel + ", heuristic " + s.heuristic;
}

std::string order_stage(frame& f) {
  // A new view: the products of the effect and curve stages of the previous view are stale.
  f.fragment_colors.clear();
  f.lines.clear();
  f.fog.reset();
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
  const mat4 pm = f.view.projection * f.view.model_view;
  const viewport& vp = f.view.vp;
  f.polygons.clear();
  f.polygons.reserve(f.order.size());
  f.fully_clipped = 0;
  std::vector<hpoint> in(3), out;
  for (std::uint32_t idx : f.order) {
    const fragment_d& fr = f.fragments.at(idx);
    for (int k = 0; k < 3; ++k) in[k] = pm * to_point(fr.v[k]);
    clip_to_view_volume(in, out);
    bool ok = !out.empty();
    for (const hpoint& c : out)
      if (!(c.w > 0)) ok = false;  // cannot happen after near-plane clipping; guards the divide
    if (!ok) {
      ++f.fully_clipped;
      continue;
    }
    screen_polygon poly;
    poly.fragment = idx;
    poly.face = fr.face;
    poly.color = f.fragment_colors.empty() ? f.color_of(fr.face) : f.fragment_colors.at(idx);
    poly.v.reserve(out.size());
    for (const hpoint& c : out) poly.v.push_back(to_window(vp, c.x / c.w, c.y / c.w, c.z / c.w));
    f.polygons.push_back(std::move(poly));
  }
  return std::to_string(f.polygons.size()) + " polygons, " + std::to_string(f.fully_clipped) + " fully clipped";
}

std::string raster_stage(frame& f) {
  const viewport& vp = f.view.vp;
  f.picture = paint_frame(f, 1);
  std::string note = std::to_string(vp.width) + "x" + std::to_string(vp.height) + ", " +
                     std::to_string(f.polygons.size()) + " polygons painted back to front";
  if (!f.lines.empty()) note += ", " + std::to_string(f.lines.size()) + " curve lines in their slots";
  return note;
}

namespace {

std::string drawing_note(const vector_drawing& d, std::size_t bytes) {
  const drawing_counts c = count_paths(d);
  return std::to_string(c.regions) + " regions (" + std::to_string(c.rings) + " rings), " +
         std::to_string(c.visible_edges) + " visible and " + std::to_string(c.hidden_edges) + " hidden edge pieces, " +
         std::to_string(c.curves) + " curve paths, " + std::to_string(bytes) + " bytes";
}

}  // namespace

std::string svg_stage(frame& f) {
  if (f.vector.mode == vector_options::mode_kind::visible) {
    const vector_drawing d = visible_drawing(f);
    f.svg = svg_document(d);
    return "visible regions: " + drawing_note(d, f.svg.size());
  }
  f.svg = f.lines.empty() && !f.fog ? svg_document(f.view.vp, f.background, f.polygons)
                                     : svg_document(f.view.vp, f.background, f.polygons, f.lines,
                                                    f.fog ? &*f.fog : nullptr);
  return "painter: " + std::to_string(f.polygons.size()) + " paths, " + std::to_string(f.lines.size()) +
         " curve pieces, " + std::to_string(f.svg.size()) + " bytes";
}

std::string pdf_stage(frame& f) {
  const bool visible = f.vector.mode == vector_options::mode_kind::visible;
  const vector_drawing d = visible ? visible_drawing(f) : painter_drawing(f);
  f.pdf = pdf_document(d);
  return std::string(visible ? "visible regions: " : "painter: ") + drawing_note(d, f.pdf.size());
}

}  // namespace exbsp::view
