// SPDX-License-Identifier: LGPL-3.0-or-later
// The viewing pipeline as an explicit list of named stages over one `frame`.
//
// Data flow (docs/architecture.md): world-space soup -> BSP build -> fragments converted once to
// double -> back-to-front order for the view -> [world-space effects: backface_culling,
// lighting] -> modelview, projection, homogeneous clip, divide, viewport -> [curves] ->
// [screen effects: fog, a sample shader] -> rasterizer (painter's algorithm; antialias replaces it)
// or SVG -> [image effects: depth_of_field] -> write. Only the stages a scene asks for are in the
// list, so an effect that is not named costs nothing, and the curves stage exists only when the
// scene has curves. Effects plug in at four hooks (effects.h); the render command adds the write
// stage.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/core/export.h>
#include <exbsp/mesh/soup.h>
#include <exbsp/view/camera.h>
#include <exbsp/view/effect_settings.h>
#include <exbsp/view/image.h>
#include <exbsp/view/matrix.h>
#include <exbsp/view/sample_shader.h>
#include <exbsp/view/screen_line.h>
#include <exbsp/view/screen_polygon.h>
#include <exbsp/view/texture.h>
#include <exbsp/view/vector_drawing.h>
#include <exbsp/view/view_setup.h>
#include <exbsp/view/viewport.h>

namespace exbsp::geom {
class soup_cache;  // src/geom/soup_cache.h
}  // namespace exbsp::geom

namespace exbsp::view {

/// A new, empty cache of what the views of one soup share (frame::soup_products).
EXBSP_EXPORT std::shared_ptr<geom::soup_cache> new_soup_cache();

/// How the painter (paint.h) walks the polygons: the reference back-to-front walk, or
/// front-to-back with a coverage mask. Both give the same image.
enum class paint_order { back_to_front, front_to_back };

/// Which order the painter draws in. `bsp` (the default) is the tree's back-to-front order, which
/// is always right. The others are teaching views (docs/contract.md "Scenes", "teaching"): the
/// depth-sort painter of the course notes, which sorts the input triangles (never split) by one
/// depth per triangle and is wrong wherever triangles overlap cyclically or intersect.
enum class visibility_order {
  bsp,
  depth_sort_farthest,  ///< by the depth of the triangle's farthest corner, farthest first
  depth_sort_centroid   ///< by the mean depth of its corners, farthest first
};

/// What transform+clip does with a polygon that has a corner in front of the near plane
/// (clip coordinates w + z < 0). `clip` (the default) cuts it at the plane; the others are the
/// course's cheap alternative (a teaching view): the polygon, or its whole mesh, is left out.
enum class near_plane_rule { clip, drop_polygon, drop_mesh };

/// The data flowing through the stages. Inputs are set by the caller; each stage fills the
/// products it is responsible for.
struct frame {
  // Inputs.
  triangle_soup soup;             ///< all meshes, transformed to world space, appended
  build_options build;            ///< BSP options (default: the exact kernel, default heuristic)
  std::vector<rgb8> face_colors;  ///< colour by face id of `soup`
  rgb8 default_color{160, 160, 160};  ///< the colour of a face id beyond face_colors
  view_setup view;
  rgb8 background{255, 255, 255};
  effect_settings settings;        ///< parameters of the named effects (the others are ignored)
  std::vector<curve_spec> curves;  ///< world-space Bézier curves and polylines ("curves" stage)
  std::vector<std::uint32_t>
      mesh_face_offsets;  ///< first face id of mesh k (size meshes + 1; "reject")
  /// The texture of mesh k (texture.h; null or beyond the end: none). A textured mesh needs
  /// soup.triangle_uvs; its faces' colours should be white: the raster multiplies each texel by
  /// the face's (lit) colour, OpenGL's GL_MODULATE. Default: none, and no cost.
  std::vector<std::shared_ptr<const texture>> mesh_textures;
  paint_order painter = paint_order::front_to_back;  ///< walk of "raster" and "antialias" (paint.h)
  /// Front-to-back bands painted in parallel (0: one per core). Default 1: on the shared 2-core
  /// machine of bench/RESULTS.md section 3, two bands were slower than one.
  unsigned raster_threads = 1;
  vector_options vector;  ///< SVG / PDF: visible regions or painter's stack, edges
  /// PNG: the feature edges the "edges" stage draws over the picture (raster_edges_stage in
  /// stages.h): `edges` and `crease_deg` as for SVG, the same exact visibility; `mode` unused.
  /// Default: none, and no stage.
  vector_options raster_edges{vector_options::mode_kind::visible, vector_options::edges_kind::none,
                              30};
  /// PNG: the "edges" stage draws its edges on the background alone, hidden ones solid like
  /// the visible ones: a wireframe (CAD's display mode: every feature edge, no faces).
  bool wireframe = false;
  /// "build" and "order": the BSP's order (default), or a teaching view's depth sort (no tree is
  /// built: f.fragments are the soup's triangles, unsplit; smooth shading and curves, which need
  /// the tree's cells, are then unavailable).
  visibility_order visibility = visibility_order::bsp;
  /// "transform+clip": cut polygons at the near plane (default) or drop them (teaching view).
  near_plane_rule near_plane = near_plane_rule::clip;
  vector_phase_seconds vector_seconds;  ///< svg / pdf stage (visible regions): phase times
  /// What does not depend on the view, kept across views by the svg, pdf and edges stages: the
  /// feature edges' graph (the soup's edges and the triangles around each) and which meshes are
  /// outward closed (the vector drawing then leaves out their back faces, which no viewer
  /// outside them sees). Each is made again only when the soup or its own parameter (crease
  /// angle, mesh_face_offsets) is not the one it was made from. Copies of a frame share it
  /// (thread-safe).
  std::shared_ptr<geom::soup_cache> soup_products = new_soup_cache();
  /// Called with each stage's name as it starts (pipeline::run), e.g. for a progress line;
  /// may be empty.
  std::function<void(const std::string&)> on_stage;

  // Products.
  std::optional<bsp> tree;            ///< "build"
  std::vector<fragment_d> fragments;  ///< "build": fragments_double(), converted once
  std::vector<vec3d> points;          ///< "build": the distinct vertices of `fragments` (bitwise)
  std::vector<std::array<std::uint32_t, 3>>
      fragment_points;  ///< "build": corner k of fragment i is points[fragment_points[i][k]]
  std::vector<std::uint32_t> order;      ///< "order": fragment indices, back to front
  std::vector<screen_polygon> polygons;  ///< "transform+clip": visible polygons, back to front
  /// "transform+clip": per mesh (mesh_of), 1 when no fragment of it had a corner in front of
  /// the near plane, at w <= 0 or not finite: nothing of it was cut or left out there.
  std::vector<std::uint8_t> meshes_whole;
  image picture;    ///< "raster"
  std::string svg;  ///< "svg": the SVG document
  std::string pdf;  ///< "pdf": the PDF document
  std::vector<rgb8>
      fragment_colors;  ///< "lighting": colour by fragment index (empty: face colours)
  /// "lighting" with smooth shading: the colours at the three corners of fragment i (empty:
  /// flat); the raster interpolates them (fragment_colors keeps the flat colour for vector
  /// output).
  std::vector<std::array<rgb8, 3>> corner_colors;
  /// "build" (and "adopt"), when a mesh is textured: the texture coordinates at the three
  /// corners of fragment i (view/texture_uvs.h: exact barycentric interpolation in the
  /// source triangle, rounded once); empty otherwise.
  std::vector<std::array<vec2d, 3>> fragment_uvs;
  std::vector<screen_line> lines;  ///< "curves": clipped curve pieces in painter's slots
  std::optional<fog_shading> fog;  ///< "fog": its parameters for this view
  std::optional<sample_shader>
      shader;  ///< screen effects ("fog"): the painters' per-sample colour change

  // Counters for --verbose.
  std::size_t culled = 0;         ///< fragments removed by backface_culling
  std::size_t fully_clipped = 0;  ///< fragments entirely outside the view volume
  std::size_t near_dropped = 0;   ///< fragments left out by near_plane_rule drop_*
  std::size_t non_finite =
      0;  ///< fragments with a NaN or infinite corner (inexact kernels), left out
  std::vector<std::size_t> rejected_meshes;  ///< "reject": meshes dropped by their bounding boxes

  /// Colour of a face id (default_color when the id has no colour).
  rgb8 color_of(std::uint32_t face) const {
    return face < face_colors.size() ? face_colors[face] : default_color;
  }
  /// The texture of a face id's mesh, or null.
  const texture* texture_of(std::uint32_t face) const {
    if (mesh_textures.empty()) return nullptr;
    const std::uint32_t mesh = mesh_of(face);
    return mesh < mesh_textures.size() ? mesh_textures[mesh].get() : nullptr;
  }
  /// True when some mesh has a texture.
  bool textured() const {
    return std::any_of(mesh_textures.begin(), mesh_textures.end(),
                       [](const std::shared_ptr<const texture>& t) { return t != nullptr; });
  }
  /// Mesh index of a face id (mesh_face_offsets: first face of mesh k; mesh 0 when empty).
  std::uint32_t mesh_of(std::uint32_t face) const { return mesh_of_face(mesh_face_offsets, face); }
};

/// One stage: a name and a function that updates the frame and returns a short note
/// (counts) for the verbose log.
struct stage {
  std::string name;
  std::function<std::string(frame&)> run;
};

/// An ordered list of stages.
class EXBSP_EXPORT pipeline {
 public:
  /// Appends a stage.
  void add(std::string name, std::function<std::string(frame&)> run);
  /// Inserts a stage right after the first stage called `after`; throws usage_error when
  /// there is none.
  void insert_after(const std::string& after, std::string name,
                    std::function<std::string(frame&)> run);
  const std::vector<stage>& stages() const { return stages_; }
  /// Stage names in order.
  std::vector<std::string> names() const;
  /// Runs every stage in order. With a log, prints one line per stage:
  /// "stage NAME: SECONDS s (NOTE)". Exceptions from a stage propagate unchanged.
  void run(frame& f, std::ostream* log) const;

 private:
  std::vector<stage> stages_;
};

}  // namespace exbsp::view
