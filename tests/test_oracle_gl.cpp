// SPDX-License-Identifier: LGPL-3.0-or-later
// Image oracle against Mesa's off-screen OpenGL (OSMesa, llvmpipe; Debian libosmesa6-dev).
//
// Every scene is rendered twice: by exbsp (BSP order + painter's rasterizer, no z-buffer) and
// by Mesa with a 24-bit z-buffer (GL_LESS), unlit, flat colours, no blending, no dithering, no
// multisampling, the same background. Mesa gets the scene's triangles after the modelling
// transforms (the world-space soup of scene::load_geometry) and builds its own matrices from
// the scene's parameters: the gluLookAt matrix computed here, glFrustum (perspective as
// gluPerspective's equivalent frustum), glOrtho, and for oblique views glOrtho times the
// PHIGS shear of view/projection.h recomputed here. Per scene, at least 99.5% of all pixels
// and 99.5% of the drawn pixels (not background in either image) must be equal, exact RGB.
// Pixels may differ only where the renderers round differently: along intersection lines
// (z-buffer depth ties) and on edges passing within Mesa's 1/256-pixel vertex snapping of a
// pixel centre.
//
// Tie rule: for pixel centres exactly on an edge, Mesa (llvmpipe) owns left edges, as
// docs/contract.md "Pixels" does, but BOTTOM edges in GL window coordinates where exbsp owns TOP
// edges; the edge-aligned top view below checks that mirroring y makes the two identical.
//
// Coplanar faces that overlap (z-fighting) have no z-buffer answer: such meshes are marked as
// "tied" and Mesa renders the scene twice with glPolygonOffset pushing them towards and away
// from the viewer; where the two renderings differ, either colour is accepted from exbsp.
//
// Scenes: the built-in demo, every scenes/*.json without effects or with backface culling
// only (inside.json, with GL_CULL_FACE, and once more without culling; curves.json without
// its curves; the effects_*.json scenes are out of scope), and scenes built here as OFF files
// + scene JSON in a temporary directory: interpenetrating boxes, coplanar-touching boxes
// (perspective, and an axis-aligned orthographic top view with edges through pixel centres),
// triangles in cyclic overlap (3- and 4-cycles), and a grid of thin interpenetrating sticks.
// Smooth shading: a lit UV sphere with "smooth" lighting against Mesa's GL_SMOOTH with vertex
// colours computed here from the sphere's own vertex normals (99% of the drawn pixels within 2
// levels; the flat-shaded sphere is checked to fail that comparison).
// Textures: a perspective floor quad and a fin through it, both textured (split by the tree),
// against Mesa's GL_TEXTURE_2D with GL_NEAREST, GL_LINEAR, GL_CLAMP_TO_EDGE and, lit, GL_MODULATE
// (GL_PERSPECTIVE_CORRECTION_HINT GL_NICEST): 99% of the drawn pixels within 2 levels, as for
// smooth shading (measured: nearest all equal; linear about half equal, the rest within 2 levels).
//
// For a failing scene (or every scene when EXBSP_KEEP_TEST_OUTPUT is set) exbsp.png,
// mesa.png and mask.png (mismatches red, z-fighting pixels blue) are written to a directory
// under the system temp dir, whose path is printed; it is removed at exit when every test
// passed and output is not kept. Without OSMesa, or when it cannot create a context, the tests
// FAIL with a message naming the package.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include <exbsp/view/image.h>
#include <exbsp/view/matrix.h>
#include <exbsp/view/png_io.h>
#include "scene/demo_scene.h"
#include "scene/scene.h"
#include "view/effects.h"
#include "support/test_helpers.h"

#include "support/osmesa_zbuffer.h"

#if !EXBSP_HAVE_OSMESA

TEST(OracleGL, OSMesaIsAvailable) {
  FAIL() << "OSMesa (GL/osmesa.h, GL/gl.h, libOSMesa) was not found when configuring: install "
            "Debian's "
            "libosmesa6-dev (scripts/setup) and reconfigure; the Mesa z-buffer oracle cannot run";
}

#else

namespace {

using namespace exbsp;
using nlohmann::json;
namespace fs = std::filesystem;

constexpr double pi = 3.14159265358979323846;
/// Share of all pixels that must be equal (the criterion).
constexpr double required_agreement = 0.995;
/// Share of the drawn pixels (not background in either image) that must be equal, so that
/// scenes with much background cannot pass on the background alone (a depth sort of the BSP
/// fragments instead of the BSP order passes the 99.5% above on the demo and cyclic scenes
/// but fails this).
constexpr double required_drawn_agreement = 0.995;

// ---------------------------------------------------------------------------------------
// Output directory

bool keep_output() {
  const char* v = std::getenv("EXBSP_KEEP_TEST_OUTPUT");
  return v && *v && std::string(v) != "0";
}

const std::string& temp_dir() {
  static const std::string dir = exbsp_test::make_temp_dir("test_oracle_gl").string();
  return dir;
}

/// Removes the output directory at exit when every test passed (and output is not kept).
class output_cleanup : public ::testing::Environment {
 public:
  void TearDown() override {
    const ::testing::UnitTest* u = ::testing::UnitTest::GetInstance();
    if (u->Passed() && !keep_output()) {
      std::error_code ec;
      fs::remove_all(temp_dir(), ec);
    } else {
      std::cout << "oracle_gl: images kept in " << temp_dir() << "\n";
    }
  }
};
[[maybe_unused]] ::testing::Environment* const cleanup_env =
    ::testing::AddGlobalTestEnvironment(new output_cleanup);

// ---------------------------------------------------------------------------------------
// Small vector algebra on std::array, independent of view/matrix.h (the oracle builds its own
// matrices)

using v3 = std::array<double, 3>;
using exbsp_test::add;
using exbsp_test::cross;
using exbsp_test::dot;
using exbsp_test::scale;
using exbsp_test::sub;
using exbsp_test::unit;
v3 from(const view::point3& p) { return {p.x, p.y, p.z}; }
v3 from(const view::vector3& p) { return {p.x, p.y, p.z}; }

using osmesa::column_major;

/// gluLookAt's matrix, row-major: rows s, u, -f (f = unit gaze, s = unit f x up, u = s x f),
/// then the translation by -eye.
std::array<double, 16> look_at_rows(const v3& eye, const v3& center, const v3& up) {
  const v3 f = unit(sub(center, eye));
  const v3 s = unit(cross(f, up));
  const v3 u = cross(s, f);
  return {s[0],  s[1],  s[2],  -dot(s, eye),  //
          u[0],  u[1],  u[2],  -dot(u, eye),  //
          -f[0], -f[1], -f[2], dot(f, eye),   //
          0,     0,     0,     1};
}

// ---------------------------------------------------------------------------------------
// Rendering

/// Meshes whose faces overlap other faces in their plane (z-fighting): Mesa draws them once
/// pushed towards the viewer and once away (render_mesa), and exbsp may show either result.
using tied_meshes = std::set<std::size_t>;

/// exbsp's own image of a scene: the standard pipeline without the write stage.
view::image render_exbsp(const scene::scene& s, const scene::scene_geometry& g) {
  view::frame f;
  f.view = scene::make_view_setup(s);
  f.background = s.background;
  f.soup = g.soup;
  f.face_colors = g.face_colors;
  f.visibility = s.teaching.painter;  // "teaching": {"painter": "depth_sort"} (default: the BSP)
  view::standard_pipeline(s.effects, view::output_kind::png).run(f, nullptr);
  return f.picture;
}

using osmesa_context = osmesa::context;

/// GL_RENDERER of an OSMesa context ("llvmpipe (LLVM ...)", "softpipe"). Throws like
/// osmesa_context.
const std::string& mesa_renderer() {
  static const std::string name = [] {
    osmesa_context ctx(8, 8);
    const GLubyte* r = glGetString(GL_RENDERER);
    return std::string(r ? reinterpret_cast<const char*>(r) : "?");
  }();
  return name;
}

/// Loads GL_PROJECTION and GL_MODELVIEW for the scene from its parameters (not from exbsp's
/// matrices). `mirror_y`: y_ndc is negated (glScaled(1, -1, 1) before the projection).
void load_gl_view(const scene::scene& s, bool mirror_y) {
  const scene::projection_spec& p = s.projection;
  const v3 eye = from(s.camera.eye), center = from(s.camera.look_at), up = from(s.camera.up);
  const std::array<double, 16> mv_rows = look_at_rows(eye, center, up);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  if (mirror_y) glScaled(1, -1, 1);
  if (s.projection_matrix) {  // "type": "matrix": glLoadMatrix's counterpart
    const std::array<double, 16> raw = column_major(s.projection_matrix->m);
    glMultMatrixd(raw.data());
    glMatrixMode(GL_MODELVIEW);
    const std::array<double, 16> mv = column_major(mv_rows);
    glLoadMatrixd(mv.data());
    return;
  }
  switch (p.kind) {
    case view::projection_kind::perspective: {  // gluPerspective as a symmetric glFrustum
      const double top = p.near_dist * std::tan(p.fovy_deg * pi / 360);
      const double right = top * s.width / s.height;
      glFrustum(-right, right, -top, top, p.near_dist, p.far_dist);
      break;
    }
    case view::projection_kind::frustum:
      glFrustum(p.left, p.right, p.bottom, p.top, p.near_dist, p.far_dist);
      break;
    case view::projection_kind::orthographic:
      glOrtho(p.left, p.right, p.bottom, p.top, p.near_dist, p.far_dist);
      break;
    case view::projection_kind::oblique: {
      // Shear x' = x + shx (z - zp), y' = y + shy (z - zp) mapping the eye-space direction of
      // projection onto -z and fixing the view plane through look_at (z = zp).
      const v3 d = unit(from(p.direction));
      const v3 dop = {dot({mv_rows[0], mv_rows[1], mv_rows[2]}, d),
                      dot({mv_rows[4], mv_rows[5], mv_rows[6]}, d),
                      dot({mv_rows[8], mv_rows[9], mv_rows[10]}, d)};
      const double zp = -std::sqrt(dot(sub(center, eye), sub(center, eye)));
      const double shx = -dop[0] / dop[2], shy = -dop[1] / dop[2];
      glOrtho(p.left, p.right, p.bottom, p.top, p.near_dist, p.far_dist);
      const std::array<double, 16> shear = column_major({1, 0, shx, -shx * zp,  //
                                                         0, 1, shy, -shy * zp,  //
                                                         0, 0, 1, 0,            //
                                                         0, 0, 0, 1});
      glMultMatrixd(shear.data());
      break;
    }
  }
  glMatrixMode(GL_MODELVIEW);
  const std::array<double, 16> mv = column_major(mv_rows);
  glLoadMatrixd(mv.data());
}

/// How Mesa draws the tied meshes: not specially, pushed towards the viewer, or away.
enum class tie_pass { none, towards, away };

/// How the oracle renders and judges a scene.
struct oracle_options {
  tied_meshes tied;
  /// Mesa draws the scene upside down (y_ndc negated) and the image is flipped back. Mesa
  /// (llvmpipe) breaks ties of pixel centres exactly on a horizontal edge by owning BOTTOM
  /// edges in GL window coordinates (the top-left rule applied to its buffer, whose row 0 is
  /// the window's bottom row), whereas docs/contract.md "Pixels" owns TOP edges (y up); mirrored,
  /// Mesa's rule becomes exbsp's. Left edges are owned by both either way.
  bool mirror_y = false;
  double required = required_agreement;
  double required_drawn = required_drawn_agreement;
  /// false: only measure and print (a diagnostic rendering), expect nothing.
  bool check = true;
  /// When set, receives the share of the drawn pixels that equal Mesa's.
  double* drawn_agreement = nullptr;
};

/// Mesa's z-buffer image of a scene's world-space triangles. Throws std::runtime_error when
/// OSMesa cannot render.
view::image render_mesa(const scene::scene& s, const scene::scene_geometry& g, bool cull,
                        const oracle_options& opt, tie_pass pass) {
  const tied_meshes& tied = opt.tied;
  osmesa_context ctx(s.width, s.height);
  GLint depth_bits = 0, samples = 0;
  glGetIntegerv(GL_DEPTH_BITS, &depth_bits);
  glGetIntegerv(GL_SAMPLES, &samples);
  if (depth_bits < 24 || samples != 0)
    throw std::runtime_error("OSMesa context has " + std::to_string(depth_bits) +
                             " depth bits and " + std::to_string(samples) +
                             " samples (want >= 24 and 0)");

  glViewport(0, 0, s.width, s.height);
  glDepthRange(0, 1);
  // backface_culling: N = (b - a) x (c - a) facing away from the viewer is culled
  osmesa::begin_zbuffer_frame(s.background, cull, opt.mirror_y);
  load_gl_view(s, opt.mirror_y);

  // Draws the triangles of the untied meshes (mesh = npos) or of one tied mesh.
  constexpr std::size_t untied = static_cast<std::size_t>(-1);
  auto draw = [&](std::size_t mesh) {
    glBegin(GL_TRIANGLES);
    for (const soup_triangle& t : g.soup.triangles) {
      const std::size_t m = scene::mesh_of_face(g, t.face);
      if (mesh == untied ? tied.count(m) > 0 : m != mesh) continue;
      const view::rgb8 c =
          t.face < g.face_colors.size() ? g.face_colors[t.face] : view::rgb8{160, 160, 160};
      glColor3ub(c.r, c.g, c.b);
      for (std::uint32_t v : t.v)
        glVertex3d(g.soup.vertices[v][0], g.soup.vertices[v][1], g.soup.vertices[v][2]);
    }
    glEnd();
  };
  draw(untied);
  // Tied mesh of rank r (0-based, in mesh order) is offset by r + 1 steps: towards the viewer
  // (later ranks win their ties, and every tied mesh beats an untied face in its plane) or
  // away from it (earlier ranks win, untied faces beat tied ones).
  int rank = 0;
  for (std::size_t m : tied) {
    if (pass != tie_pass::none) {
      const GLfloat steps =
          static_cast<GLfloat>(rank + 1) * (pass == tie_pass::towards ? -1.0f : 1.0f);
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(2.0f * steps, 64.0f * steps);
    }
    draw(m);
    glDisable(GL_POLYGON_OFFSET_FILL);
    ++rank;
  }
  glFinish();
  const GLenum err = glGetError();
  if (err != GL_NO_ERROR)
    throw std::runtime_error("OpenGL error " + std::to_string(err) + " while rendering");
  return ctx.picture(opt.mirror_y);
}

// ---------------------------------------------------------------------------------------
// Comparison

struct comparison {
  std::size_t pixels = 0, equal = 0, tied = 0;
  std::size_t drawn = 0, drawn_equal = 0;  ///< pixels not background in either image
  double agreement() const { return pixels ? static_cast<double>(equal) / pixels : 0; }
  double drawn_agreement() const { return drawn ? static_cast<double>(drawn_equal) / drawn : 0; }
};

using exbsp_test::colours_of;

/// Renders `s` with exbsp and Mesa, compares, prints the agreement and (opt.check) expects
/// at least opt.required of all pixels and opt.required_drawn of the drawn pixels to be
/// equal; returns the agreement over all pixels (0 when Mesa failed). `name` names the
/// output subdirectory. Tied meshes: see the file comment.
double expect_matches_mesa(const std::string& name, const scene::scene& s,
                           const oracle_options& opt = {}) {
  const tied_meshes& tied = opt.tied;
  const scene::scene_geometry g = scene::load_geometry(s);
  const bool cull =
      std::find(s.effects.begin(), s.effects.end(), "backface_culling") != s.effects.end();
  for (const std::string& e : s.effects)
    if (e != "backface_culling") {
      ADD_FAILURE() << name << ": the oracle has no counterpart for effect " << e;
      return 0;
    }

  const view::image mine = render_exbsp(s, g);
  view::image mesa, mesa_alt;
  try {
    mesa = render_mesa(s, g, cull, opt, tied.empty() ? tie_pass::none : tie_pass::towards);
    if (!tied.empty()) mesa_alt = render_mesa(s, g, cull, opt, tie_pass::away);
  } catch (const std::exception& e) {
    ADD_FAILURE() << name << ": Mesa oracle failed: " << e.what();
    return 0;
  }
  if (mine.width() != mesa.width() || mine.height() != mesa.height()) {
    ADD_FAILURE() << name << ": exbsp's image is " << mine.width() << "x" << mine.height()
                  << ", Mesa's " << mesa.width() << "x" << mesa.height();
    return 0;
  }

  comparison cmp;
  view::image mask(mine.width(), mine.height(), {255, 255, 255});
  for (int r = 0; r < mine.height(); ++r)
    for (int k = 0; k < mine.width(); ++k) {
      const view::rgb8 a = mine.at_row(r, k), b = mesa.at_row(r, k);
      const bool is_tied = !tied.empty() && mesa_alt.at_row(r, k) != b;
      const bool ok = a == b || (is_tied && a == mesa_alt.at_row(r, k));
      ++cmp.pixels;
      cmp.equal += ok;
      cmp.tied += is_tied;
      if (a != s.background || b != s.background) {
        ++cmp.drawn;
        cmp.drawn_equal += ok;
      }
      // Mask: mismatches red, tied pixels light blue, the rest a faded copy of exbsp's image.
      const auto fade = [](std::uint8_t v) { return static_cast<std::uint8_t>(191 + v / 4); };
      mask.set_at_row(r, k,
                      !ok       ? view::rgb8{255, 0, 0}
                      : is_tied ? view::rgb8{150, 200, 255}
                                : view::rgb8{fade(a.r), fade(a.g), fade(a.b)});
    }

  const bool pass = !opt.check || (cmp.agreement() >= opt.required &&
                                   cmp.drawn_agreement() >= opt.required_drawn);
  const std::string dir = temp_dir() + "/" + name;
  std::ostringstream line;
  line << std::fixed << std::setprecision(3) << "oracle_gl " << name << ": "
       << 100 * cmp.agreement() << "% of " << cmp.pixels << " pixels equal ("
       << cmp.pixels - cmp.equal << " differ; " << 100 * cmp.drawn_agreement() << "% of "
       << cmp.drawn << " drawn pixels";
  if (!tied.empty()) line << ", " << cmp.tied << " z-fighting pixels accept either colour";
  line << ")";
  if (!pass || keep_output()) {
    fs::create_directories(dir);
    view::write_png(mine, dir + "/exbsp.png");
    view::write_png(mesa, dir + "/mesa.png");
    if (!tied.empty()) view::write_png(mesa_alt, dir + "/mesa_alt.png");
    view::write_png(mask, dir + "/mask.png");
    line << "; images in " << dir << " (mask.png: mismatches red)";
  }
  std::cout << line.str() << std::endl;
  if (opt.drawn_agreement) *opt.drawn_agreement = cmp.drawn_agreement();
  if (!opt.check) return cmp.agreement();
  // The oracle image must show the scene, not just the background.
  EXPECT_GT(colours_of(mesa).size(), 3u) << name;
  EXPECT_GT(cmp.drawn, cmp.pixels / 20) << name << ": less than 5% of the image is drawn";
  EXPECT_GE(cmp.agreement(), opt.required)
      << name << ": only " << 100 * cmp.agreement()
      << "% of pixels equal Mesa's z-buffer image; mismatch mask: " << dir << "/mask.png";
  EXPECT_GE(cmp.drawn_agreement(), opt.required_drawn)
      << name << ": only " << 100 * cmp.drawn_agreement()
      << "% of the drawn pixels equal Mesa's z-buffer image; mismatch mask: " << dir << "/mask.png";
  return cmp.agreement();
}

// ---------------------------------------------------------------------------------------
// Test scenes written as OFF files + scene JSON

/// One OFF file's worth of polygons.
struct off_mesh {
  std::vector<v3> vertices;
  std::vector<std::vector<std::uint32_t> > faces;

  void add_polygon(const std::vector<v3>& poly) {
    std::vector<std::uint32_t> f;
    for (const v3& p : poly) {
      f.push_back(static_cast<std::uint32_t>(vertices.size()));
      vertices.push_back(p);
    }
    faces.push_back(std::move(f));
  }
  void write(const std::string& path) const {
    std::ofstream out(path);
    out << std::setprecision(17) << "OFF\n" << vertices.size() << " " << faces.size() << " 0\n";
    for (const v3& p : vertices) out << p[0] << " " << p[1] << " " << p[2] << "\n";
    for (const auto& f : faces) {
      out << f.size();
      for (std::uint32_t i : f) out << " " << i;
      out << "\n";
    }
    if (!out) throw std::runtime_error("cannot write " + path);
  }
};

/// The six outward-facing quads of the box centre + sum of +-half[k] axis[k] (axes need not be
/// unit, but must be mutually orthogonal), indexed +a0, -a0, +a1, -a1, +a2, -a2.
std::array<std::vector<v3>, 6> box_quads(const v3& centre, const std::array<v3, 3>& axes,
                                         const v3& half) {
  std::array<std::vector<v3>, 6> quads;
  for (int k = 0; k < 3; ++k) {
    const v3 n = scale(half[k], axes[k]);
    const v3 e1 = scale(half[(k + 1) % 3], axes[(k + 1) % 3]),
             e2 = scale(half[(k + 2) % 3], axes[(k + 2) % 3]);
    for (int side = 0; side < 2; ++side) {
      const v3 c = side == 0 ? add(centre, n) : sub(centre, n);
      std::vector<v3> q = {sub(sub(c, e1), e2), add(sub(c, e2), e1), add(add(c, e1), e2),
                           sub(add(c, e2), e1)};
      const v3 outward = side == 0 ? n : scale(-1, n);
      if (dot(cross(sub(q[1], q[0]), sub(q[2], q[0])), outward) < 0) std::swap(q[1], q[3]);
      quads[2 * k + side] = std::move(q);
    }
  }
  return quads;
}

/// Axis-aligned box [lo, hi].
std::array<std::vector<v3>, 6> aabb_quads(const v3& lo, const v3& hi) {
  return box_quads(scale(0.5, add(lo, hi)), {v3{1, 0, 0}, v3{0, 1, 0}, v3{0, 0, 1}},
                   scale(0.5, sub(hi, lo)));
}

/// A base colour shaded for face direction k of box_quads (fixed "baked" shades).
view::rgb8 shade(view::rgb8 base, int k) {
  static const double f[6] = {1.0, 0.62, 0.88, 0.55, 0.76, 0.48};
  return {static_cast<std::uint8_t>(std::lround(base.r * f[k])),
          static_cast<std::uint8_t>(std::lround(base.g * f[k])),
          static_cast<std::uint8_t>(std::lround(base.b * f[k]))};
}

/// A scene under construction: meshes are written as OFF files next to the scene file.
class scene_writer {
 public:
  explicit scene_writer(std::string name) : name_(std::move(name)), dir_(temp_dir() + "/" + name_) {
    fs::create_directories(dir_ + "/meshes");
    doc_["meshes"] = json::array();
  }
  /// Adds a mesh (index returned) with an optional row-major transform.
  std::size_t add_mesh(const off_mesh& m, view::rgb8 c, const std::vector<double>& transform = {}) {
    const std::size_t index = doc_["meshes"].size();
    const std::string file = "meshes/m" + std::to_string(index) + ".off";
    m.write(dir_ + "/" + file);
    json e = {{"file", file}, {"color", {c.r, c.g, c.b}}};
    if (!transform.empty()) e["transform"] = transform;
    doc_["meshes"].push_back(e);
    return index;
  }
  /// Adds the six faces of a box as six meshes in shades of `base`.
  void add_box(const std::array<std::vector<v3>, 6>& quads, view::rgb8 base,
               const std::vector<double>& transform = {}) {
    for (int k = 0; k < 6; ++k) {
      off_mesh m;
      m.add_polygon(quads[k]);
      add_mesh(m, shade(base, k), transform);
    }
  }
  json& doc() { return doc_; }
  /// Writes the scene file and loads it back through scene::load_scene.
  scene::scene load() {
    const std::string path = dir_ + "/scene.json";
    std::ofstream(path) << doc_.dump(2);
    return scene::load_scene(path);
  }

 private:
  std::string name_, dir_;
  json doc_;
};

json perspective_view(const v3& eye, const v3& look_at, const v3& up, double fovy, int w, int h) {
  return {{"camera", {{"eye", eye}, {"look_at", look_at}, {"up", up}}},
          {"projection", {{"type", "perspective"}, {"fovy_deg", fovy}, {"near", 1}, {"far", 40}}},
          {"viewport", {{"width", w}, {"height", h}}},
          {"background", {242, 244, 248}}};
}

void set_view(json& doc, const json& view) {
  for (auto it = view.begin(); it != view.end(); ++it) doc[it.key()] = it.value();
}

/// Row-major 4x4 of translation * rotation(axis, degrees) * scale(s).
std::vector<double> trs(const v3& t, const v3& axis, double degrees, const v3& s) {
  const v3 a = unit(axis);
  const double c = std::cos(degrees * pi / 180), sn = std::sin(degrees * pi / 180), C = 1 - c;
  const double R[3][3] = {
      {c + a[0] * a[0] * C, a[0] * a[1] * C - a[2] * sn, a[0] * a[2] * C + a[1] * sn},
      {a[1] * a[0] * C + a[2] * sn, c + a[1] * a[1] * C, a[1] * a[2] * C - a[0] * sn},
      {a[2] * a[0] * C - a[1] * sn, a[2] * a[1] * C + a[0] * sn, c + a[2] * a[2] * C}};
  std::vector<double> m(16, 0.0);
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k) m[4 * r + k] = R[r][k] * s[k];
    m[4 * r + 3] = t[r];
  }
  m[15] = 1;
  return m;
}

scene::scene example(const std::string& name) {
  return scene::load_scene(std::string(EXBSP_SOURCE_DIR) + "/scenes/" + name + ".json");
}

// ---------------------------------------------------------------------------------------
// Tests

TEST(OracleGL, OSMesaCreatesA24BitDepthContextWithoutMultisampling) {
  try {
    osmesa_context ctx(64, 48);
    GLint depth_bits = 0, samples = -1;
    glGetIntegerv(GL_DEPTH_BITS, &depth_bits);
    glGetIntegerv(GL_SAMPLES, &samples);
    const GLubyte* renderer = glGetString(GL_RENDERER);
    const GLubyte* version = glGetString(GL_VERSION);
    std::cout << "oracle_gl: OSMesa renderer \""
              << (renderer ? reinterpret_cast<const char*>(renderer) : "?") << "\", OpenGL "
              << (version ? reinterpret_cast<const char*>(version) : "?") << ", " << depth_bits
              << " depth bits, " << samples << " samples; output in " << temp_dir() << std::endl;
    EXPECT_GE(depth_bits, 24);
    EXPECT_EQ(samples, 0);
    // A cleared buffer reads back exactly, with window row 0 at the bottom.
    glClearColor(10 / 255.0f, 20 / 255.0f, 30 / 255.0f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 64, 1);
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    const view::image img = ctx.picture();
    EXPECT_EQ(img.pixel(5, 0), (view::rgb8{255, 0, 0}));
    EXPECT_EQ(img.at_row(img.height() - 1, 5), (view::rgb8{255, 0, 0}));
    EXPECT_EQ(img.at_row(0, 5), (view::rgb8{10, 20, 30}));
  } catch (const std::exception& e) {
    FAIL() << e.what();
  }
}

TEST(OracleGL, BuiltInDemoMatchesMesaZBuffer) { expect_matches_mesa("demo", scene::demo_scene()); }

class OracleGLExample : public ::testing::TestWithParam<std::string> {};

TEST_P(OracleGLExample, MatchesMesaZBuffer) {
  expect_matches_mesa(GetParam(), example(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(ExampleScenes, OracleGLExample,
                         ::testing::Values("perspective", "orthographic", "oblique", "frustum",
                                           "inside", "cyclic"),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

TEST(OracleGL, InsideRoomWithoutCullingMatchesMesaZBuffer) {
  // The near plane cuts the walls around the eye; every face drawn.
  scene::scene s = example("inside");
  s.effects.clear();
  expect_matches_mesa("inside_no_culling", s);
}

TEST(OracleGL, CurvesSceneMeshesWithoutTheCurvesMatchMesaZBuffer) {
  // curves.json has no effects; its Bezier curves have no counterpart here, its meshes do.
  scene::scene s = example("curves");
  s.curves.clear();
  expect_matches_mesa("curves_meshes", s);
}

/// Four rotated boxes passing through each other (the first `count` of them), seen in
/// perspective from (4.5, -6, 3.5).
void add_interpenetrating_boxes(scene_writer& w, int count = 4) {
  const auto cube = aabb_quads({-1, -1, -1}, {1, 1, 1});
  const std::vector<std::pair<view::rgb8, std::vector<double> > > boxes = {
      {{210, 80, 60}, trs({0, 0, 0}, {0, 0, 1}, 20, {1.2, 1.2, 1.2})},
      {{70, 130, 220}, trs({0.3, -0.2, 0.4}, {1, 1, 0.3}, 35, {2.6, 0.45, 0.45})},
      {{90, 180, 90}, trs({-0.3, 0.3, 0.0}, {1, 0, 0}, 25, {0.4, 0.4, 2.2})},
      {{230, 190, 60}, trs({0.9, 0.8, -0.6}, {0.2, 1, 0.4}, 50, {0.9, 0.7, 0.5})}};
  for (int k = 0; k < count; ++k) w.add_box(cube, boxes[k].first, boxes[k].second);
  set_view(w.doc(), perspective_view({4.5, -6, 3.5}, {0, 0, 0}, {0, 0, 1}, 40, 640, 480));
}

// The depth-sort painter ("teaching": {"painter": "depth_sort"}, a teaching view): on the three
// planks in cyclic overlap of scenes/teaching_cyclic.json no order of whole triangles is right,
// so its picture must differ from Mesa's z-buffer (and from the BSP's), while the BSP's picture
// of the same scene matches Mesa. Both depth keys fail.
TEST(OracleGL, DepthSortPainterFailsOnCyclicPlanksWhereTheBspMatchesMesa) {
  scene::scene depth_sorted = example("teaching_cyclic");
  ASSERT_EQ(depth_sorted.teaching.painter, view::visibility_order::depth_sort_farthest);
  scene::scene by_tree = depth_sorted;
  by_tree.teaching.painter = view::visibility_order::bsp;
  expect_matches_mesa("teaching_cyclic_bsp", by_tree);
  const scene::scene_geometry g = scene::load_geometry(by_tree);
  const view::image bsp_picture = render_exbsp(by_tree, g);
  for (const view::visibility_order key :
       {view::visibility_order::depth_sort_farthest, view::visibility_order::depth_sort_centroid}) {
    depth_sorted.teaching.painter = key;
    oracle_options opt;
    opt.check = false;
    double drawn = 1;
    opt.drawn_agreement = &drawn;
    const std::string name = key == view::visibility_order::depth_sort_farthest
                                 ? "teaching_cyclic_depth_sort_farthest"
                                 : "teaching_cyclic_depth_sort_centroid";
    expect_matches_mesa(name, depth_sorted, opt);
    EXPECT_LT(drawn, 0.98) << name << ": the depth sort should get a cyclic overlap wrong";
    const view::image wrong = render_exbsp(depth_sorted, g);
    std::size_t differ = 0, drawn_pixels = 0;  // drawn: not background in the BSP's picture
    for (int r = 0; r < wrong.height(); ++r)
      for (int k = 0; k < wrong.width(); ++k) {
        differ += wrong.at_row(r, k) != bsp_picture.at_row(r, k);
        drawn_pixels += bsp_picture.at_row(r, k) != by_tree.background;
      }
    EXPECT_GT(differ * 100, drawn_pixels)
        << name << ": at least 1% of the drawn pixels should differ from the BSP's";
  }
}

TEST(OracleGL, InterpenetratingBoxesMatchMesaZBuffer) {
  scene_writer w("interpenetrating_boxes");
  add_interpenetrating_boxes(w);
  expect_matches_mesa("interpenetrating_boxes", w.load());
}

/// Boxes touching in shared planes: A's +x face and B's -x face overlap (hidden inside), the
/// top faces of A and B are coplanar and meet along an edge, C sits on A's top face, D touches
/// C's +x face with coplanar front faces meeting along an edge; a decal triangle lies in A's
/// top face and two triangles overlap in one plane in mid-air (both z-fighting: tied).
/// Coordinates are multiples of 1/8, exact in binary (see the top view test).
scene_writer coplanar_touching_boxes(const std::string& name, tied_meshes& tied) {
  scene_writer w(name);
  w.add_box(aabb_quads({-2, -1.5, -0.5}, {2, 1.5, 0}), {200, 200, 205});
  w.add_box(aabb_quads({2, -0.625, -0.5}, {3.25, 0.625, 0}), {210, 80, 60});
  w.add_box(aabb_quads({-1.5, -1, 0}, {-0.25, 0.25, 0.75}), {70, 130, 220});
  w.add_box(aabb_quads({-0.25, -1, 0}, {0.875, 0.25, 0.5}), {90, 180, 90});
  off_mesh decal;
  decal.add_polygon({{0.875, -1.25, 0}, {1.875, -0.875, 0}, {1.25, 1, 0}});
  tied.insert(w.add_mesh(decal, {230, 190, 60}));
  off_mesh pane1, pane2;
  pane1.add_polygon({{-1.75, 1.75, 0.25}, {-0.25, 1.75, 0.25}, {-1, 1.75, 1.5}});
  pane2.add_polygon({{-1.375, 1.75, 1.25}, {-0.625, 1.75, 1.25}, {-1, 1.75, 0.125}});
  tied.insert(w.add_mesh(pane1, {160, 90, 200}));
  tied.insert(w.add_mesh(pane2, {40, 160, 160}));
  return w;
}

TEST(OracleGL, ARawProjectionMatrixMatchesMesasGlLoadMatrix) {
  // An off-axis frustum with a shear, given as a matrix: its centre of projection is not the
  // camera's eye, so the tree must be ordered from the point the matrix makes (scene.cpp).
  scene_writer w("raw_matrix");
  add_interpenetrating_boxes(w, 3);
  // glFrustum(-0.45, 0.35, -0.3, 0.3, 1, 40) times a shear x += 0.25 z, y -= 0.1 z and a shift
  // of the centre of projection by (0.4, 0.2, 0) in eye coordinates.
  const double l = -0.45, r = 0.35, b = -0.3, t = 0.3, n = 1, f = 40;
  const std::array<double, 16> frustum{2 * n / (r - l),
                                       0,
                                       (r + l) / (r - l),
                                       0,  //
                                       0,
                                       2 * n / (t - b),
                                       (t + b) / (t - b),
                                       0,  //
                                       0,
                                       0,
                                       -(f + n) / (f - n),
                                       -2 * f * n / (f - n),  //
                                       0,
                                       0,
                                       -1,
                                       0};
  const view::mat4 shear =
      view::mat4::from_rows({1, 0, 0.25, -0.4, 0, 1, -0.1, -0.2, 0, 0, 1, 0, 0, 0, 0, 1});
  const view::mat4 raw = view::mat4::from_rows(frustum) * shear;
  w.doc()["projection"] = {{"type", "matrix"}, {"matrix", raw.m}};
  const scene::scene s = w.load();
  ASSERT_TRUE(s.projection_matrix.has_value());
  EXPECT_EQ(s.projection.kind, view::projection_kind::frustum);
  expect_matches_mesa("raw_matrix", s);
}

TEST(OracleGL, CoplanarTouchingFacesMatchMesaZBuffer) {
  oracle_options opt;
  scene_writer w = coplanar_touching_boxes("coplanar_touching", opt.tied);
  set_view(w.doc(), perspective_view({3, -6, 4.5}, {0.3, 0, 0}, {0, 0, 1}, 45, 640, 480));
  expect_matches_mesa("coplanar_touching", w.load(), opt);
}

TEST(OracleGL, CoplanarTouchingFacesFromAboveWithEdgesThroughPixelCentresMatchMesaZBuffer) {
  // Orthographic top view at 128 pixels per unit, shifted by half a pixel so that every box
  // edge (x = 2, x = -0.25, y = -0.625, ...) passes exactly through pixel centres; all numbers
  // are exact in binary, so both renderers compute the ties exactly and apply their tie rule.
  // On horizontal edges the rules differ (oracle_options::mirror_y): Mesa's image as it is
  // differs along them (Mesa 22.3: 0.37% of the pixels), Mesa's image rendered mirrored agrees
  // on every pixel. Whichever way a Mesa version breaks ties, one orientation must agree exactly.
  oracle_options opt;
  scene_writer w = coplanar_touching_boxes("coplanar_touching_top", opt.tied);
  w.doc()["camera"] = {{"eye", {0.0, 0.0, 10.0}}, {"look_at", {0.0, 0.0, 0.0}}, {"up", {0, 1, 0}}};
  const double half_pixel = 0.5 / 128;
  w.doc()["projection"] = {{"type", "orthographic"},
                           {"left", -4 - half_pixel},
                           {"right", 4 - half_pixel},
                           {"bottom", -2 - half_pixel},
                           {"top", 2 - half_pixel},
                           {"near", 1},
                           {"far", 40}};
  w.doc()["viewport"] = {{"width", 1024}, {"height", 512}};
  w.doc()["background"] = {242, 244, 248};
  const scene::scene s = w.load();
  opt.required_drawn = 0.99;  // the horizontal edges are 0.9% of the drawn pixels here
  const double as_is = expect_matches_mesa("coplanar_touching_top", s, opt);
  opt.mirror_y = true;
  opt.check = false;
  const double mirrored = expect_matches_mesa("coplanar_touching_top_mirrored", s, opt);
  // Tie rules are the rasterizer's choice; the exact agreement is known for llvmpipe (Mesa's
  // default). Other drivers (GALLIUM_DRIVER=softpipe) only have to pass the check above.
  if (mesa_renderer().rfind("llvmpipe", 0) == 0)
    EXPECT_EQ(std::max(as_is, mirrored), 1.0)
        << "with every edge exactly on pixel centres, exbsp's top-left rule (docs/contract.md "
           "\"Pixels\") should equal llvmpipe's tie rule in one orientation";
  else
    std::cout << "oracle_gl: renderer \"" << mesa_renderer()
              << "\" is not llvmpipe: its tie rule is not checked\n";
}

/// n thin triangles around the origin, each tilted along its length so that it passes over
/// the next one and under the previous one: a cycle no depth sort can order.
void add_cyclic_triangles(scene_writer& w, int n, const v3& centre, double length,
                          double half_width, const std::vector<view::rgb8>& colours) {
  for (int k = 0; k < n; ++k) {
    const double a = 2 * pi * k / n;
    const v3 ex = {std::cos(a), std::sin(a), 0}, ey = {-std::sin(a), std::cos(a), 0};
    // Local frame: the triangle runs along local x at local y = -1; z = 0.2 x.
    auto at = [&](double x, double y) {
      return add(centre, add(add(scale(x, ex), scale(y, ey)), v3{0, 0, 0.2 * x}));
    };
    off_mesh m;
    m.add_polygon({at(-length, -1 - half_width), at(length, -1), at(-length, -1 + half_width)});
    w.add_mesh(m, colours[k % colours.size()]);
  }
}

TEST(OracleGL, TrianglesInCyclicOverlapMatchMesaZBuffer) {
  scene_writer w("cyclic_triangles");
  add_cyclic_triangles(w, 3, {-3.3, 0, 0}, 3.0, 0.6,
                       {{240, 190, 60}, {235, 125, 45}, {150, 95, 200}});
  add_cyclic_triangles(w, 4, {3.3, 0, 0}, 2.5, 0.6,
                       {{70, 130, 220}, {90, 180, 90}, {210, 80, 60}, {40, 160, 160}});
  set_view(w.doc(), perspective_view({0, -1.5, 9}, {0, 0, 0}, {0, 1, 0}, 45, 640, 480));
  expect_matches_mesa("cyclic_triangles", w.load());
}

TEST(OracleGL, ThinSticksGridMatchesMesaZBuffer) {
  // 9 sticks along x and 9 along y in one layer (every crossing interpenetrates; the y sticks
  // are flatter, so no faces are coplanar), plus 5 diagonal sticks rising through the layer;
  // faces grouped by stick family and direction.
  scene_writer w("sticks_grid");
  const double h = 0.035;
  std::array<off_mesh, 6> xs, ys, ds;
  for (int i = 0; i < 9; ++i) {
    const double c = -2 + 0.5 * i;
    const auto qx = box_quads({0, c, 0}, {v3{1, 0, 0}, v3{0, 1, 0}, v3{0, 0, 1}}, {2.3, h, h});
    const auto qy =
        box_quads({c, 0, 0}, {v3{0, 1, 0}, v3{0, 0, 1}, v3{1, 0, 0}}, {2.3, 0.7 * h, h});
    for (int k = 0; k < 6; ++k) {
      xs[k].add_polygon(qx[k]);
      ys[k].add_polygon(qy[k]);
    }
  }
  for (int i = 0; i < 5; ++i) {
    const double c = -1.6 + 0.8 * i;
    const v3 a = unit({1, 1, 0.35}), u = unit(cross(a, {0, 0, 1})), v = cross(u, a);
    const auto q = box_quads({c, -c * 0.3, 0}, {a, u, v}, {2.0, h, h});
    for (int k = 0; k < 6; ++k) ds[k].add_polygon(q[k]);
  }
  for (int k = 0; k < 6; ++k) {
    w.add_mesh(xs[k], shade({70, 130, 220}, k));
    w.add_mesh(ys[k], shade({235, 125, 45}, k));
    w.add_mesh(ds[k], shade({90, 180, 90}, k));
  }
  set_view(w.doc(), perspective_view({3.5, -5, 4}, {0, 0, 0}, {0, 0, 1}, 35, 800, 600));
  expect_matches_mesa("sticks_grid", w.load());
}

// ---------------------------------------------------------------------------------------
// Smooth (Gouraud) shading against Mesa's GL_SMOOTH

/// Mesa's scene for frame f's matrices, viewport (the whole image), background, drawn mirrored
/// (Mesa's tie rule turned into exbsp's); the triangles are the caller's.
osmesa::zbuffer_scene mesa_scene_of(const view::frame& f) {
  osmesa::zbuffer_scene z;
  z.image_width = z.vp_width = f.view.vp.width;
  z.image_height = z.vp_height = f.view.vp.height;
  z.background = f.background;
  z.projection = f.view.projection.m;
  z.model_view = f.view.model_view.m;
  z.mirror_y = true;
  return z;
}

/// A UV sphere of radius 1: `slices` around z, `stacks` from pole to pole, shared vertices,
/// outward winding; one face per triangle.
triangle_soup uv_sphere(int slices, int stacks) {
  triangle_soup s;
  const auto at = [&](int i, int j) {
    return static_cast<std::uint32_t>(1 + (j - 1) * slices + (i % slices));
  };
  s.vertices.push_back({0, 0, 1});
  for (int j = 1; j < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      const double th = pi * j / stacks, ph = 2 * pi * i / slices;
      s.vertices.push_back(
          {std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)});
    }
  s.vertices.push_back({0, 0, -1});
  const auto south = static_cast<std::uint32_t>(s.vertices.size() - 1);
  const auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    s.triangles.push_back({{a, b, c}, static_cast<std::uint32_t>(s.triangles.size())});
  };
  for (int i = 0; i < slices; ++i) {
    add(0, at(i, 1), at(i + 1, 1));
    for (int j = 1; j + 1 < stacks; ++j) {
      add(at(i, j), at(i, j + 1), at(i + 1, j + 1));
      add(at(i, j), at(i + 1, j + 1), at(i + 1, j));
    }
    add(at(i, stacks - 1), south, at(i + 1, stacks - 1));
  }
  s.face_count = static_cast<std::uint32_t>(s.triangles.size());
  return s;
}

TEST(OracleGL, SmoothShadedSpheresMatchMesasGouraudShading) {
  // Two interpenetrating spheres: the tree splits their triangles where they meet, and the
  // pieces must interpolate their triangle's corners as Mesa interpolates the whole triangle.
  triangle_soup sphere = uv_sphere(28, 14);
  triangle_soup second = uv_sphere(22, 11);
  for (vec3d& v : second.vertices) v = {0.7 * v[0] + 0.8, 0.7 * v[1] - 0.3, 0.7 * v[2] + 0.25};
  const std::size_t first_count = sphere.triangles.size();
  sphere.append(second);
  std::vector<view::rgb8> colors(sphere.triangles.size(), view::rgb8{210, 160, 90});
  for (std::size_t t = first_count; t < colors.size(); ++t) colors[t] = {90, 170, 220};
  const int w = 200, h = 150;
  view::frame f = exbsp_test::perspective_frame(
      sphere, colors, {{1.2, -2.6, 2.2}, {0.3, 0, 0}, {0, 0, 1}}, w, h, 45, 0.5, 20);
  view::lighting_settings& l = f.settings.lighting;
  l.direction = {1, -0.5, 2};
  l.intensity = 0.75;
  l.ambient = 0.2;
  l.smooth = true;
  l.crease_deg = 30;
  view::standard_pipeline({"lighting"}, view::output_kind::png).run(f, nullptr);
  ASSERT_GT(f.tree->stats().splits, 0u);

  // The oracle's own vertex colours: the normal at a vertex of a UV sphere is the mean of the
  // area vectors of its triangles (every dihedral angle is under 30 degrees), Lambert's term.
  std::vector<v3> normal(sphere.vertices.size(), v3{0, 0, 0});
  for (const soup_triangle& t : sphere.triangles) {
    const v3 a = sphere.vertices[t.v[0]], b = sphere.vertices[t.v[1]], c = sphere.vertices[t.v[2]];
    const v3 m = scale(0.5, cross(sub(b, a), sub(c, a)));
    for (std::uint32_t v : t.v) normal[v] = add(normal[v], m);
  }
  const v3 light = unit({1, -0.5, 2});
  osmesa::zbuffer_scene z = mesa_scene_of(f);
  for (const soup_triangle& t : sphere.triangles) {
    std::array<std::array<double, 3>, 3> tri;
    std::array<view::rgb8, 3> colors;
    for (int k = 0; k < 3; ++k) {
      tri[k] = sphere.vertices[t.v[k]];
      const double lit = 0.2 + 0.75 * std::max(0.0, dot(unit(normal[t.v[k]]), light));
      const auto ch = [&](std::uint8_t c) {
        return static_cast<std::uint8_t>(std::lround(std::min(255.0, c * lit)));
      };
      const view::rgb8 base = f.face_colors[t.face];
      colors[k] = {ch(base.r), ch(base.g), ch(base.b)};
    }
    z.triangles.push_back(tri);
    z.corner_colors.push_back(colors);
  }
  view::image mesa;
  try {
    mesa = osmesa::render_zbuffer(z);
  } catch (const std::exception& e) {
    FAIL() << "OSMesa: " << e.what();
  }
  // Mesa interpolates the 8-bit corner colours in floating point; exbsp interpolates the same
  // corners and rounds once. Pixels on the silhouette may differ by the tie rule.
  std::size_t drawn = 0, close = 0, flat_close = 0;
  int worst = 0;
  for (int r = 0; r < h; ++r)
    for (int k = 0; k < w; ++k) {
      const view::rgb8 a = f.picture.at_row(r, k), b = mesa.at_row(r, k);
      if (a == f.background && b == f.background) continue;
      ++drawn;
      const int d = std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
      close += d <= 2;
      if (d <= 2) worst = std::max(worst, d);
    }
  ASSERT_GT(drawn, 8000u);
  EXPECT_GE(static_cast<double>(close) / drawn, 0.99) << close << " of " << drawn;
  // The same sphere shaded flat is far from Mesa's smooth image: the comparison can fail.
  view::frame g = f;
  g.settings.lighting.smooth = false;
  view::standard_pipeline({"lighting"}, view::output_kind::png).run(g, nullptr);
  for (int r = 0; r < h; ++r)
    for (int k = 0; k < w; ++k) {
      const view::rgb8 a = g.picture.at_row(r, k), b = mesa.at_row(r, k);
      if (a == g.background && b == g.background) continue;
      flat_close += std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}) <= 2;
    }
  EXPECT_LT(static_cast<double>(flat_close) / drawn, 0.8);
  if (keep_output()) {
    view::write_png(f.picture, temp_dir() + "/smooth_exbsp.png");
    view::write_png(mesa, temp_dir() + "/smooth_mesa.png");
  }
}

// ---------------------------------------------------------------------------------------
// Textures against Mesa's GL_TEXTURE_2D (GL_NEAREST / GL_LINEAR, GL_PERSPECTIVE_CORRECTION_HINT
// GL_NICEST, GL_MODULATE with white faces)

/// An 8 x 8 checkerboard whose squares differ in every channel (so that a wrong texel shows).
view::image checker_texture() {
  view::image t(8, 8, {0, 0, 0});
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      const bool dark = (i + j) % 2 != 0;
      t.set_pixel(i, j,
                  dark ? view::rgb8{static_cast<std::uint8_t>(20 + 20 * i),
                                    static_cast<std::uint8_t>(40 + 10 * j), 60}
                       : view::rgb8{230, static_cast<std::uint8_t>(250 - 20 * j),
                                    static_cast<std::uint8_t>(120 + 15 * i)});
    }
  return t;
}

/// A floor quad receding from the eye (UVs 0..3 x 0..2: the texture repeats) pierced by a
/// textured upright triangle (the tree splits both), one textured mesh each.
triangle_soup textured_floor_and_fin() {
  triangle_soup s;
  s.vertices = {{-3, 0, 0},      {3, 0, 0},      {3, 12, 0},     {-3, 12, 0},
                {-1.3, 2.5, -1}, {1.7, 5.5, -1}, {0.2, 4.1, 2.2}};
  s.add_polygon({0, 1, 2, 3}, {{0, 0}, {3, 0}, {3, 2}, {0, 2}}, 0);
  s.add_polygon({4, 5, 6}, {{0.1, 0.2}, {0.9, 0.3}, {0.4, 1.1}}, 1);
  return s;
}

/// exbsp's and Mesa's pictures of textured_floor_and_fin with `filter` and `wrap`; the share of
/// drawn pixels within 2 levels in every channel. `lit`: exbsp's flat "lighting" (one
/// directional light, two-sided), and Mesa's triangles coloured here with the Lambert term of
/// a white face (lighting.h), GL_MODULATE.
double textured_agreement(view::texture::filter_kind filter, view::texture::wrap_kind wrap,
                          const std::string& name, bool lit = false) {
  const triangle_soup soup = textured_floor_and_fin();
  const int w = 240, h = 180;
  view::frame f =
      exbsp_test::perspective_frame(soup, {view::rgb8{255, 255, 255}, view::rgb8{255, 255, 255}},
                                    {{0.4, -2.2, 1.6}, {0, 5, 0}, {0, 0, 1}}, w, h, 50, 0.5, 40);
  const auto tex = std::make_shared<const view::texture>(checker_texture(), filter, wrap);
  f.mesh_textures = {tex, tex};
  f.mesh_face_offsets = {0, 1, 2};
  view::lighting_settings& l = f.settings.lighting;
  l.direction = {1, -0.5, 2};
  l.intensity = 0.6;
  l.ambient = 0.3;
  l.two_sided = true;
  view::standard_pipeline(lit ? std::vector<std::string>{"lighting"} : std::vector<std::string>{},
                          view::output_kind::png)
      .run(f, nullptr);
  EXPECT_GT(f.tree->stats().splits, 0u);
  osmesa::zbuffer_scene z = mesa_scene_of(f);
  z.texture = tex->texels;
  z.texture_linear = filter == view::texture::filter_kind::linear;
  z.texture_clamp = wrap == view::texture::wrap_kind::clamp;
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    std::array<std::array<double, 3>, 3> tri;
    for (int k = 0; k < 3; ++k) tri[k] = soup.vertices[soup.triangles[t].v[k]];
    z.triangles.push_back(tri);
    std::uint8_t grey = 255;
    if (lit) {  // ambient + intensity max(0, n . l), n turned towards the eye
      v3 n = unit(cross(sub(tri[1], tri[0]), sub(tri[2], tri[0])));
      if (dot(n, sub(from(f.view.cam.eye), tri[0])) < 0) n = scale(-1.0, n);
      const double k = 0.3 + 0.6 * std::max(0.0, dot(n, unit({1, -0.5, 2})));
      grey = static_cast<std::uint8_t>(std::lround(std::min(255.0, 255 * k)));
    }
    z.colors.push_back({grey, grey, grey});
    z.corner_uvs.push_back(soup.triangle_uvs[t]);
  }
  view::image mesa;
  try {
    mesa = osmesa::render_zbuffer(z);
  } catch (const std::exception& e) {
    ADD_FAILURE() << "OSMesa: " << e.what();
    return 0;
  }
  std::size_t drawn = 0, close = 0, equal = 0;
  for (int r = 0; r < h; ++r)
    for (int k = 0; k < w; ++k) {
      const view::rgb8 a = f.picture.at_row(r, k), b = mesa.at_row(r, k);
      if (a == f.background && b == f.background) continue;
      ++drawn;
      equal += a == b;
      close += std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}) <= 2;
    }
  EXPECT_GT(drawn, 15000u);
  if (keep_output()) {
    view::write_png(f.picture, temp_dir() + "/" + name + "_exbsp.png");
    view::write_png(mesa, temp_dir() + "/" + name + "_mesa.png");
  }
  const double share = drawn ? static_cast<double>(close) / drawn : 0;
  std::cout << "oracle_gl: " << name << ": " << 100 * share
            << "% of the drawn pixels within 2 levels of Mesa's ("
            << 100.0 * static_cast<double>(equal) / std::max<std::size_t>(drawn, 1) << "% equal, "
            << drawn << " drawn)" << std::endl;
  return share;
}

// Mesa interpolates the texture coordinates in floating point and samples with its own
// weights; exbsp interpolates the exactly derived corner UVs of every fragment
// (texture_uvs.h). As for smooth shading, 99% of the drawn pixels must be within 2 levels:
// the rest lie on texel boundaries or the silhouette.
TEST(OracleGL, TexturedQuadNearestMatchesMesasGlNearest) {
  EXPECT_GE(textured_agreement(view::texture::filter_kind::nearest,
                               view::texture::wrap_kind::repeat, "texture_nearest"),
            0.99);
}

TEST(OracleGL, TexturedQuadBilinearMatchesMesasGlLinear) {
  EXPECT_GE(textured_agreement(view::texture::filter_kind::linear, view::texture::wrap_kind::repeat,
                               "texture_linear"),
            0.99);
}

TEST(OracleGL, TexturedQuadLitMatchesMesasGlModulate) {
  // Lighting scales the texel as it scales a white face's colour (GL_MODULATE).
  EXPECT_GE(textured_agreement(view::texture::filter_kind::linear, view::texture::wrap_kind::repeat,
                               "texture_lit", true),
            0.99);
}

TEST(OracleGL, TexturedQuadClampedMatchesMesasClampToEdge) {
  EXPECT_GE(textured_agreement(view::texture::filter_kind::linear, view::texture::wrap_kind::clamp,
                               "texture_clamp"),
            0.99);
}

}  // namespace

#endif  // EXBSP_HAVE_OSMESA
