// SPDX-License-Identifier: LGPL-3.0-or-later
// libFuzzer target: the scene parser (scene/scene.h, docs/contract.md "Scenes"). One input = the
// text of a scene file. Nothing is rendered.
//
// Per input:
//   1. parse_scene_text(text, <tmp>/scene.json, &warnings): exbsp::error or a scene;
//   2. for an accepted scene: the invariants its validation promises (ranges of the
//      viewport, near/far, fovy, window, finite numbers, known effects, mesh keys);
//   3. make_view_setup(scene) must not throw for a validated scene (scene.h) and its
//      matrices must be finite (a scene that passed validation must not turn into Inf/NaN);
//   4. load_geometry(scene), when every mesh path is relative and stays inside the fixture
//      directory (no "..": the fuzzer must not read arbitrary files of the machine), and at
//      most max_loaded_meshes meshes: exbsp::error or a geometry whose soup, face offsets,
//      colours and mesh_of_face agree.
// The fixture directory (created once, removed at exit) holds small meshes the scene can
// name, valid and invalid (listed in fixture_files below and in dict/scene.dict).
//
// Environment: EXBSP_FUZZ_ALLOW, a comma-separated list of known, reported findings to let
// pass, so that a run can get past them until they are fixed (README.md, "Findings"):
//   json-number-overflow   nlohmann's out_of_range 406 (a number beyond double, e.g. 1e400)
//                          escaping parse_scene_text instead of a scene_error
//   nonfinite-view         step 3's finiteness check of the view matrices
#include <stdlib.h>  // mkdtemp (POSIX)

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <exbsp/view/matrix.h>
#include "fuzz_check.h"
#include "scene/scene.h"
#include "view/effects.h"

namespace {

namespace fs = std::filesystem;
using exbsp::fuzz::require;

constexpr std::size_t max_loaded_meshes = 32;

struct fixture_file {
  const char* name;
  const char* text;
};

// Valid meshes in every format, an empty one, invalid ones; "folder.off" is a directory.
constexpr fixture_file fixture_files[] = {
    {"cube.off",
     "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
     "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n"},
    {"empty.off", "OFF\n0 0 0\n"},
    {"bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"},
    {"huge.off", "OFF\n3 1 0\n1e308 0 0\n0 1e308 0\n0 0 1e308\n3 0 1 2\n"},
    {"meshes/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
    {"meshes/tri.ply",
     "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float "
     "z\n"
     "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 "
     "1 2\n"},
    {"meshes/tri.stl",
     "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
     "endfacet\nendsolid t\n"},
    {"meshes/empty.stl", ""},
};

class fixture {
 public:
  fixture() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/exbsp-fuzz-scene-XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    if (!::mkdtemp(buffer.data())) {
      std::perror("exbsp fuzz: mkdtemp");
      std::abort();
    }
    dir_ = buffer.data();
    fs::create_directories(dir_ / "meshes");
    fs::create_directories(dir_ / "folder.off");
    for (const fixture_file& f : fixture_files) {
      std::ofstream out(dir_ / f.name, std::ios::binary);
      out << f.text;
      if (!out) {
        std::fprintf(stderr, "exbsp fuzz: cannot write the fixture %s\n", f.name);
        std::abort();
      }
    }
    scene_path_ = (dir_ / "scene.json").string();
  }
  ~fixture() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  fixture(const fixture&) = delete;
  fixture& operator=(const fixture&) = delete;

  const std::string& scene_path() const { return scene_path_; }

 private:
  fs::path dir_;
  std::string scene_path_;
};

const fixture& the_fixture() {
  static const fixture f;  // destroyed at exit, which removes the directory
  return f;
}

// Whether `finding` is listed in EXBSP_FUZZ_ALLOW.
bool allowed(const std::string& finding) {
  const char* list = std::getenv("EXBSP_FUZZ_ALLOW");
  if (!list) return false;
  const std::string text = std::string(",") + list + ",";
  return text.find("," + finding + ",") != std::string::npos;
}

bool allow_json_number_overflow() {
  static const bool allow = allowed("json-number-overflow");
  return allow;
}

bool allow_nonfinite_view() {
  static const bool allow = allowed("nonfinite-view");
  return allow;
}

bool finite(double x) { return std::isfinite(x); }
bool finite(const exbsp::view::vector3& v) { return finite(v.x) && finite(v.y) && finite(v.z); }
bool finite(const exbsp::view::point3& p) { return finite(p.x) && finite(p.y) && finite(p.z); }

bool enabled(const exbsp::scene::scene& s, const char* effect) {
  for (const std::string& e : s.effects)
    if (e == effect) return true;
  return false;
}

// The documented ranges of the parameters of the enabled effects (scene.h).
void check_effect_settings(const exbsp::scene::scene& s) {
  const exbsp::view::effect_settings& es = s.effect_settings;
  if (enabled(s, "lighting")) {
    const exbsp::view::lighting_settings& l = es.lighting;
    require(finite(l.direction) && exbsp::view::length(l.direction) > 0,
            "light direction finite, not zero");
    require(finite(l.intensity) && l.intensity >= 0, "light intensity finite, >= 0");
    require(finite(l.ambient) && l.ambient >= 0, "ambient finite, >= 0");
    require(finite(l.specular) && l.specular >= 0 && finite(l.shininess) && l.shininess >= 0,
            "specular and shininess finite, >= 0");
    require(l.lights.size() < exbsp::view::max_lights, "at most max_lights lights in all");
    for (const exbsp::view::light_source& light : l.lights)
      require(finite(light.where) && finite(light.intensity) && light.intensity >= 0,
              "each light finite, intensity >= 0");
  }
  if (enabled(s, "fog")) {
    const exbsp::view::fog_settings& f = es.fog;
    if (f.mode == exbsp::view::fog_mode::linear)
      require(finite(f.start) && finite(f.end) && f.start >= 0 && f.end > f.start,
              "linear fog: 0 <= start < end");
    else
      require(finite(f.density) && f.density > 0, "exp fog: density finite, > 0");
  }
  if (enabled(s, "depth_of_field")) {
    const exbsp::view::depth_of_field_settings& d = es.depth_of_field;
    require(finite(d.focal_length) && d.focal_length > 0, "focal_length finite, > 0");
    require(finite(d.aperture) && d.aperture > 0, "aperture finite, > 0");
    require(finite(d.focus_distance) && d.focus_distance > d.focal_length,
            "focus_distance > focal_length");
    require(d.samples >= 2 && d.samples <= 1024, "depth_of_field samples in 2..1024");
  }
  if (enabled(s, "antialias")) {
    const int n = es.antialias.samples;
    require(n >= 1 && n <= 8, "antialias samples in 1..8");
    require(
        static_cast<long long>(std::max(s.width, s.height)) * n <= exbsp::scene::max_viewport_side,
        "the supersampled image fits max_viewport_side");
  }
}

void check_scene(const exbsp::scene::scene& s) {
  using exbsp::view::projection_kind;
  require(s.path == the_fixture().scene_path(), "scene.path is the scene file");
  require(s.width >= 1 && s.width <= exbsp::scene::max_viewport_side, "viewport width in range");
  require(s.height >= 1 && s.height <= exbsp::scene::max_viewport_side, "viewport height in range");
  require(finite(s.camera.eye) && finite(s.camera.look_at) && finite(s.camera.up),
          "camera is finite");
  require(!(s.camera.eye.x == s.camera.look_at.x && s.camera.eye.y == s.camera.look_at.y &&
            s.camera.eye.z == s.camera.look_at.z),
          "eye differs from look_at");
  const exbsp::scene::projection_spec& p = s.projection;
  require(finite(p.near_dist) && finite(p.far_dist) && p.near_dist > 0 && p.far_dist > p.near_dist,
          "0 < near < far, finite");
  if (p.kind == projection_kind::perspective) {
    require(p.fovy_deg > 0 && p.fovy_deg < 180, "fovy in (0, 180)");
  } else {
    require(finite(p.left) && finite(p.right) && finite(p.bottom) && finite(p.top),
            "window is finite");
    require(p.right > p.left && p.top > p.bottom, "window is not empty");
  }
  if (p.kind == projection_kind::oblique)
    require(finite(p.direction), "oblique direction is finite");
  std::set<std::string> effects;
  for (const std::string& e : s.effects) {
    const exbsp::view::effect_description* d = exbsp::view::find_effect(e);
    require(d && d->available, "every enabled effect is known and available");
    require(effects.insert(e).second, "no effect enabled twice");
  }
  for (const exbsp::view::curve_spec& c : s.curves) {
    require(!c.control_points.empty() &&
                c.control_points.size() <= exbsp::scene::max_curve_control_points,
            "a curve has 1..max_curve_control_points control points");
    for (const exbsp::vec3d& q : c.control_points)
      require(finite(q[0]) && finite(q[1]) && finite(q[2]), "curve control points are finite");
  }
  check_effect_settings(s);
  for (std::size_t i = 0; i < s.meshes.size(); ++i) {
    const exbsp::scene::mesh_spec& m = s.meshes[i];
    require(m.key == "/meshes/" + std::to_string(i), "mesh key is its JSON pointer");
    require(!m.file.empty() && !m.path.empty(), "mesh file named");
    require(!m.soup, "a parsed mesh has no inline soup");
    for (double x : m.transform.m) require(finite(x), "mesh transform is finite");
  }
}

void check_view_setup(const exbsp::scene::scene& s) {
  exbsp::view::view_setup v;
  try {
    v = exbsp::scene::make_view_setup(s);
  } catch (const exbsp::error& e) {
    std::fprintf(stderr, "exbsp fuzz: make_view_setup rejected a validated scene: %s\n", e.what());
    std::abort();
  }
  require(v.kind == s.projection.kind, "view_setup has the scene's projection type");
  require(v.vp.width == s.width && v.vp.height == s.height, "view_setup has the scene's viewport");
  if (allow_nonfinite_view()) return;
  require(exbsp::view::is_finite(v.model_view),
          "the model-view matrix of a validated scene is finite");
  require(exbsp::view::is_finite(v.projection),
          "the projection matrix of a validated scene is finite");
  if (v.is_parallel()) require(finite(v.direction), "the direction of projection is finite");
}

// Relative, without "..": the path stays inside the fixture directory.
bool stays_inside_fixture(const std::string& file) {
  const fs::path p(file);
  if (p.is_absolute() || p.has_root_name() || p.has_root_directory()) return false;
  for (const fs::path& part : p)
    if (part == "..") return false;
  return true;
}

void check_geometry(const exbsp::scene::scene& s, const exbsp::scene::scene_geometry& g) {
  const exbsp::triangle_soup& soup = g.soup;
  require(g.face_offsets.size() == s.meshes.size() + 1, "one face offset per mesh, plus the end");
  require(g.face_offsets.front() == 0, "face offsets start at 0");
  for (std::size_t k = 0; k + 1 < g.face_offsets.size(); ++k)
    require(g.face_offsets[k] <= g.face_offsets[k + 1], "face offsets do not decrease");
  require(g.face_offsets.back() == soup.face_count, "face offsets end at the face count");
  require(g.face_colors.size() == soup.face_count, "one colour per face");
  for (const exbsp::vec3d& p : soup.vertices)
    require(finite(p[0]) && finite(p[1]) && finite(p[2]), "every transformed vertex is finite");
  for (const exbsp::soup_triangle& t : soup.triangles) {
    for (std::uint32_t v : t.v) require(v < soup.vertices.size(), "vertex index in range");
    require(t.face < soup.face_count, "face id in range");
  }
  for (std::uint32_t f = 0; f < soup.face_count; ++f) {
    const std::size_t k = exbsp::scene::mesh_of_face(g, f);
    require(k < s.meshes.size(), "mesh_of_face finds a mesh for every face");
    require(g.face_offsets[k] <= f && f < g.face_offsets[k + 1],
            "mesh_of_face agrees with face_offsets");
    require(g.face_colors[f] == s.meshes[k].color, "a face has its mesh's colour");
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  (void)the_fixture();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const fixture& fx = the_fixture();
  const std::string text(reinterpret_cast<const char*>(data), size);
  exbsp::fuzz::run_guarded([&] {
    std::ostringstream warnings;
    exbsp::scene::scene s;
    try {
      s = exbsp::scene::parse_scene_text(text, fx.scene_path(), &warnings);
    } catch (const nlohmann::json::out_of_range& e) {
      if (e.id == 406 && allow_json_number_overflow()) return;
      throw;
    }
    check_scene(s);
    check_view_setup(s);
    if (s.meshes.size() > max_loaded_meshes) return;
    for (const exbsp::scene::mesh_spec& m : s.meshes)
      if (!stays_inside_fixture(m.file)) return;
    const exbsp::scene::scene_geometry g = exbsp::scene::load_geometry(s);
    check_geometry(s, g);
  });
  return 0;
}
