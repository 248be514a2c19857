// SPDX-License-Identifier: LGPL-3.0-or-later
// Scene files (docs/contract.md "Scenes"): parsing, validation, view setup and geometry loading.
//
// Notation: every error names the scene file and the offending key as a JSON pointer
// ("/meshes/0/color/1", "/projection/near"); see scene_error in core/errors.h. Mesh paths are
// relative to the scene file's directory. A mesh transform is 16 numbers, row-major, acting on
// column vectors (view/matrix.h); it is applied in double and the results are the exact input
// of the BSP.
//
// Projection keys:
//   perspective   fovy_deg or fovx_deg (in (0, 180)), near, far   gluPerspective; "aspect"
//                 (width / height of the window, default the viewport's); fovx_deg, the
//                 width angle, gives fovy = 2 atan(tan(fovx / 2) / aspect)
//   frustum       left, right, bottom, top, near, far              glFrustum (window on near plane)
//   orthographic  left, right, bottom, top, near, far              glOrtho
//   oblique       left, right, bottom, top, near, far, direction   direction = world-space
//                 direction of projection (eye into the scene, positive component along the
//                 gaze); the window lies in the view plane through look_at (view/projection.h)
//   ortho2d       left, right, bottom, top                         gluOrtho2D (near -1, far 1)
// near and far are distances in front of the eye with 0 < near < far, except orthographic
// (glOrtho: any two distinct numbers; negative = behind the eye).
//
// Modelling: "meshes" and nested "groups" ({"transforms", "meshes", "groups"}) are read in
// document order (a group's meshes, then its groups, depth first; face ids follow that order)
// with a view::matrix_stack: a group pushes, applies its "transforms" list, and pops when done;
// a mesh's matrix is the stack's top times its own "transform" or "transforms". Each list
// entry post-multiplies like glTranslated / glRotated / glScaled / glMultMatrixd:
// {"translate": [x,y,z]}, {"rotate": [deg, ax, ay, az]}, {"scale": [sx,sy,sz]},
// {"matrix": [16 numbers], "order": "row-major" | "column-major"} (order required). Nesting
// deeper than max_group_depth is refused. Parsed iteratively (scene_parts.cpp).
//
// Cameras (one form): {"eye","look_at","up"}; {"position","look","up"}; {"polar": {"distance",
// "twist_deg","elevation_deg","azimuth_deg","look_at"}}; {"pilot": {"position","roll_deg",
// "pitch_deg","heading_deg"}}; {"phigs": {"vrp","vpn","vup","prp","window","front","back",
// "projection"}} (view/camera.h, view/phigs.h). A phigs camera defines the projection: the
// scene then has no "projection". "ortho2d" (left, right, bottom, top; gluOrtho2D) needs no
// camera (default: eye at the origin looking down -z, up +y). Orthographic near and far may
// be any distinct numbers.
// Viewport: "viewport": {"width","height","x","y"} inside "image": {"width","height"}, and
// "aspect": "stretch" | "fit" (letterbox: the viewport shrinks, centred, to the aspect of the
// projection's window; perspective views already use the viewport's aspect).
// Lines: "lines": [{"points": [[x,y,z], ...] (2 .. max_line_points), "color" (default black),
// "clipper": "cohen-sutherland" | "liang-barsky" (default)}]: polylines in world space drawn
// like curves (view/curves.h), each segment clipped in clip space by the named algorithm.
// Trackball: "trackball": "arcball" (default) | "virtual" for orbit drags (render.h).
//
// Curves: "curves": [{"bezier": [[x,y,z], ...], "color": [r,g,b], "control_polygon": true |
// {"color"} (the polyline through the control points, grey by default, drawn like a line)}]: at
// least one and at most max_curve_control_points finite control points (world space, no transform),
// colour default black. Drawn as described in view/curves.h.
//
// Sections: "clip_planes": [[A,B,C,D], ...] (at most max_clip_planes; finite, (A,B,C) not zero;
// world coordinates) keep A*x+B*y+C*z+D >= 0 of every mesh, cut exactly after its transform
// and before the BSP (clip/section.h, clip_soup); "caps": {"color": [r,g,b]} (default
// [200,60,50]) adds, for each closed mesh and each plane, the exact cap of the cut as one new
// face of that mesh in the cap colour; caps of earlier planes are cut by later ones. The cut
// pieces enter the BSP as the nearest doubles of their exact points, like every other input.
//
// Effects: "effects": {NAME: true | false | {PARAM: value, ...}}; NAME from
// view::effect_catalog() (backface_culling, lighting, fog, depth_of_field, antialias), whose
// entry also reads the parameters: each effect's parameters and defaults are documented once,
// at its reader in view/<effect>.h. `true` or {} takes every default; an unknown NAME or
// PARAM, or a bad value, is a scene_error naming /effects/NAME or /effects/NAME/PARAM.
//
// Teaching views (the course's; none is ever a default, docs/contract.md "Scenes"):
// "teaching": {"painter": "bsp" (default) | "depth_sort", "depth_key": "farthest" (default) |
// "centroid", "near_plane": "clip" (default) | "drop" | "drop_mesh", "view_volume": {"camera",
// "projection", "color", "axes", "axis_length"}}. depth_sort paints the input triangles sorted
// by depth instead of the BSP order (view/depth_sort.h; refused with curves, lines, a view
// volume or smooth lighting, which need the tree). drop leaves out every polygon with a corner
// in front of the near plane instead of cutting it, drop_mesh every polygon of a mesh that has
// such a corner (stages.h, transform+clip). view_volume draws the view volume of a second,
// observed camera (any camera form and projection, the scene's viewport aspect) as lines: its
// near and far rectangles, the four side edges, the edges from its centre of projection to the
// near corners (perspective), and its reference frame: the origin of its eye coordinates (the
// eye; PHIGS: the VRP) with its x, y, z (u, v, n) axes in red, green and blue (teaching.cpp).
// Its "space": "world" (default) | "vrc" | "sheared" | "opening_45" | "normalised" draws the
// whole scene (meshes, curves, lines, the view volume and frames) after the observed PHIGS
// camera's normalisation up to that step (view::phigs_normalisation; teaching.cpp).
//
// Vector output: "svg": {"mode": "visible" | "painter", "edges": "none" | "visible" |
// "visible+hidden", "crease_deg": (0, 180]} (view/vector_drawing.h; SVG and PDF), default
// visible regions without edges.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <exbsp/mesh/soup.h>
#include <exbsp/view/camera.h>
#include <exbsp/view/image.h>
#include <exbsp/view/matrix.h>
#include <exbsp/view/phigs.h>
#include <exbsp/view/pipeline.h>
#include "drawing/drawing.h"

namespace exbsp::scene {

/// Largest accepted viewport side in pixels.
constexpr int max_viewport_side = 16384;
/// Deepest accepted nesting of "groups" (a group inside a group inside ... counts each level).
constexpr std::size_t max_group_depth = 64;
/// Largest accepted number of points of one "lines" polyline.
constexpr std::size_t max_line_points = 1u << 20;
/// Largest accepted number of control points of one curve.
/// (Flattening splits a curve with de Casteljau, O(degree^2) per split, up to 2^16 pieces.)
constexpr std::size_t max_curve_control_points = 128;

/// Largest number of "clip_planes" (glClipPlane's GL_MAX_CLIP_PLANES minimum).
constexpr std::size_t max_clip_planes = 6;

/// A mesh's "texture": {"png": path, "filter": "nearest" (default) | "linear", "wrap":
/// "repeat" (default) | "clamp", "transforms": [...]} (view/texture.h). The mesh file must give
/// texture coordinates (OBJ vt, PLY u/v or s/t); the raster samples the PNG per pixel
/// (GL_MODULATE with the lit colour of a white face: the texel replaces "color"); SVG and PDF
/// fill the mesh's regions flat in the texture's mean colour (lit like a face colour).
/// "transforms" is the texture matrix (glMatrixMode(GL_TEXTURE)): a list as a mesh's, applied
/// to (s, t, 0, 1) of every corner in double when the mesh is loaded (the results are the
/// texture coordinates the exact interpolation starts from); it must leave q = 1 (bottom row
/// 0 0 0 1: no projective texturing).
struct texture_spec {
  std::string png;   ///< as written in the scene
  std::string path;  ///< resolved against the scene file's directory
  view::texture::filter_kind filter = view::texture::filter_kind::nearest;
  view::texture::wrap_kind wrap = view::texture::wrap_kind::repeat;
  std::optional<view::mat4> matrix;  ///< "transforms" (absent: identity)
};

/// One entry of "meshes".
struct mesh_spec {
  std::string file;           ///< as written in the scene
  std::string path;           ///< resolved against the scene file's directory
  std::string key;            ///< JSON pointer of the entry, e.g. "/meshes/0"
  std::string transform_key;  ///< key named when the transform fails (default key + "/transform")
  view::rgb8 color{160, 160, 160};  ///< default grey
  view::mat4 transform = view::mat4::identity();
  std::shared_ptr<const triangle_soup> soup;  ///< inline geometry (built-in demo): file not read
  std::optional<texture_spec> texture;        ///< "texture" (absent: none)
};

/// "projection".
struct projection_spec {
  view::projection_kind kind = view::projection_kind::perspective;
  double fovy_deg = 0;  ///< perspective (0: fovx_deg gives it)
  double fovx_deg = 0;  ///< perspective: the width angle, or 0
  double aspect = 0;    ///< perspective: the window's width / height (0: the viewport's)
  double left = 0, right = 0, bottom = 0, top = 0;  ///< frustum, orthographic, oblique
  double near_dist = 0, far_dist = 0;
  view::vector3 direction;  ///< oblique: world-space direction of projection
  bool ortho2d = false;     ///< "ortho2d": orthographic with near -1, far 1
};

/// How the view volume's window meets a viewport of another aspect ratio ("aspect").
enum class aspect_policy {
  stretch,  ///< OpenGL: the window fills the viewport, distorted when the aspects differ
  fit       ///< letterbox: the largest centred part of the viewport with the window's aspect
};

/// "teaching": the views the course notes draw to teach (never defaults; notation at the top).
struct teaching_spec {
  view::visibility_order painter = view::visibility_order::bsp;    ///< "painter", "depth_key"
  view::near_plane_rule near_plane = view::near_plane_rule::clip;  ///< "near_plane"
  std::size_t view_volume_lines = 0;  ///< "view_volume": its lines, the last ones of `curves`
  /// "view_volume" "space" other than "world": its name, the product of the observed PHIGS
  /// camera's normalisation steps up to it (view::phigs_normalisation), applied to every mesh
  /// after its own transform, and, for the perspective "normalised" space (a projective map),
  /// the world half-space A x + B y + C z + D >= 0 each mesh is cut to first (the side of the
  /// plane halfway between the centre of projection and the front plane that holds the scene).
  std::string space = "world";
  std::optional<view::mat4> space_matrix;
  std::optional<std::array<double, 4>> space_keep;
};

/// The camera forms of docs/contract.md "Scenes" ("camera").
enum class camera_form { look_at, look, polar, pilot, phigs };

/// A validated scene.
struct scene {
  std::string path;  ///< scene file, or "(built-in demo)"
  std::vector<mesh_spec> meshes;
  view::camera camera;
  projection_spec projection;
  int width = 0, height = 0;
  view::rgb8 background{255, 255, 255};
  std::vector<std::string> effects;       ///< enabled effects (names from view::effect_catalog())
  view::effect_settings effect_settings;  ///< parameters of the enabled effects, defaults filled in
  std::vector<view::curve_spec> curves;   ///< "curves", then "lines" (empty when absent)
  std::size_t line_count = 0;             ///< the last line_count entries of curves are "lines"

  camera_form form = camera_form::look_at;
  /// Viewing matrix of the polar, pilot and phigs forms (absent: look_at(camera)). `camera` is
  /// then the equivalent gluLookAt camera (view::camera_of): its eye orders the BSP.
  std::optional<view::mat4> view_matrix;
  std::optional<view::phigs_matrices> phigs;  ///< phigs form: its projection replaces "projection"
  std::optional<view::phigs_view> phigs_parameters;  ///< phigs form: the parameters as given
  /// "projection": {"type": "matrix"} (glLoadMatrix): the given eye-to-clip matrix; `projection`
  /// then holds the kind it amounts to (frustum when its centre of projection is a point,
  /// orthographic when it is at infinity) and its window and near and far distances.
  std::optional<view::mat4> projection_matrix;
  int viewport_x = 0, viewport_y = 0;     ///< glViewport x, y (from the image's lower left)
  double depth_near = 0, depth_far = 1;   ///< "viewport" "depth_range" (glDepthRange)
  int image_width = 0, image_height = 0;  ///< "image" (default: the viewport's size)
  aspect_policy aspect = aspect_policy::stretch;
  std::string trackball = "arcball";  ///< "arcball" or "virtual" (orbit drags)
  view::vector_options vector;        ///< "svg": vector output options (SVG and PDF)
  /// "raster": the feature edges drawn over a PNG ("edges", "crease_deg"; default none) and
  /// "wireframe" (true: those edges alone, hidden ones solid; edges default visible+hidden).
  bool wireframe = false;
  view::vector_options raster_edges{view::vector_options::mode_kind::visible,
                                    view::vector_options::edges_kind::none, 30};
  std::vector<std::array<double, 4>> clip_planes;  ///< "clip_planes" (A, B, C, D), keep >= 0
  bool caps = false;                               ///< "caps" present: draw the cut faces
  view::rgb8 cap_color{200, 60, 50};               ///< "caps": {"color"}
  /// "drawing": the options of `exbsp drawing` for this scene (title block values, views,
  /// sheet, scale, units, projection, sections, lines_only, line_widths, crease_deg), and the
  /// names of the keys it gave (flags of the command override those).
  drawing::drawing_options drawing;
  std::vector<std::string> drawing_keys;
  teaching_spec teaching;  ///< "teaching" (default: none of its views)
};

/// Validates a parsed JSON document. `path` names the file in messages and anchors relative
/// mesh paths. Unknown keys (outside effect parameters) produce warnings naming the expected
/// keys on `warnings` (may be null), or with `strict` a scene_error naming the key.
/// Throws scene_error naming the key for every missing, wrongly typed or impossible
/// value (including up parallel to the view direction, unknown and not-yet-supported effects,
/// unknown or bad effect parameters and bad curves).
scene parse_scene(const nlohmann::json& doc, const std::string& path,
                  std::ostream* warnings = nullptr, bool strict = false);

/// The JSON document of a scene's text, not yet validated: nesting deeper than max_json_depth
/// (mesh/json_limits.h) is an input_error naming the line, before parsing; a syntax error a
/// scene_error with an empty key.
nlohmann::json parse_scene_json(const std::string& text, const std::string& path);

/// parse_scene on JSON text (parse_scene_json, same errors).
scene parse_scene_text(const std::string& text, const std::string& path,
                       std::ostream* warnings = nullptr, bool strict = false);

/// Reads and validates a scene file. Throws input_error when the file cannot be read or is not
/// a regular file (mesh_io.h read_input_file), scene_error as parse_scene.
scene load_scene(const std::string& path, std::ostream* warnings = nullptr, bool strict = false);

/// Camera, projection and viewport of a validated scene as the pipeline's view_setup.
/// Throws scene_error naming the key if the scene was not validated and is impossible.
view::view_setup make_view_setup(const scene& s);

/// A perspective projection's lens: its height angle and aspect (notation at the top: the
/// projection's "aspect" or the viewport's, "fovy_deg" or the one "fovx_deg" gives).
struct perspective_lens {
  double fovy_deg = 0, aspect = 1;
};
perspective_lens lens_of(const projection_spec& p, int viewport_width, int viewport_height);

/// All meshes of a scene, transformed to world space, cut by the clip planes (with their caps
/// as extra faces of each mesh) and appended into one soup.
struct scene_geometry {
  triangle_soup soup;
  std::vector<view::rgb8> face_colors;  ///< colour by face id of `soup`
  /// The texture of mesh k ("texture": its PNG read; null: none). A textured mesh's faces have
  /// the texture's mean colour in face_colors (make_frame makes them white for the raster).
  std::vector<std::shared_ptr<const view::texture>> textures;
  std::vector<std::uint32_t> face_offsets;  ///< first face id of mesh k (size = meshes + 1)
};

/// Reads every mesh (read_mesh: input_error for bad files), applies its transform and appends
/// it. Throws scene_error naming /meshes/K/file for a missing file and /meshes/K/transform when
/// the transform sends a vertex to infinity or so far that the scene's view of it overflows
/// (/meshes/K/file when the mesh has no transform and its own coordinates do), and
/// /meshes/K/texture/png for a texture PNG that is missing or unreadable, /meshes/K/texture for
/// a textured mesh whose file has no texture coordinates (or with clip_planes, whose cut
/// pieces carry none).
scene_geometry load_geometry(const scene& s);

/// The pipeline frame of a scene: its view (make_view_setup), background, effect settings,
/// curves and vector options, and all its meshes as one soup with their face colours and
/// offsets (load_geometry; same errors), and its textures (frame::mesh_textures; the faces of a
/// textured mesh white, so that the raster's texel is the colour; use_texture_means undoes
/// that for vector output). Build options stay at their defaults.
view::frame make_frame(const scene& s);

/// For SVG / PDF output: every textured mesh's faces take its texture's mean colour and the
/// frame's textures are dropped (vector output fills regions flat).
void use_texture_means(view::frame& f);

/// The mesh index of a face id (upper bound in face_offsets); meshes.size() if out of range.
std::size_t mesh_of_face(const scene_geometry& g, std::uint32_t face);

}  // namespace exbsp::scene
