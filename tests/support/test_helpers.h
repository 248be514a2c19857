// SPDX-License-Identifier: LGPL-3.0-or-later
// Small helpers of the test files, one copy each: whole-file reads and writes, temporary
// directories, RapidCheck's fixed seed, soups from triangles, the key of a scene_error, the
// colours of an image, quads and perspective frames, a z-buffer oracle of a frame, matrices from
// GLM, vector arithmetic on std::array<T, 3>, and the CGAL corpus (data/meshes) check.
//
// The corpus: tests that need data/meshes/ (extracted by scripts/setup) skip with a visible
// message when it is missing, unless EXBSP_REQUIRE_CORPUS=1 (scripts/test and CI set it):
// then they fail, so a CI machine without the corpus cannot pass silently.
#pragma once
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <exbsp/core/errors.h>
#include <exbsp/mesh/mesh_io.h>
#include <exbsp/mesh/soup.h>
#include <exbsp/view/camera.h>
#include <exbsp/view/image.h>
#include <exbsp/view/matrix.h>
#include <exbsp/view/pipeline.h>

namespace exbsp_test {

// --- files -------------------------------------------------------------------------------------

/// The bytes of file `p` (empty when it cannot be read).
std::string read_file(const std::filesystem::path& p);

/// Writes `text` to file `p` (created or truncated).
void write_file(const std::filesystem::path& p, const std::string& text);

/// A new, empty directory /tmp/exbsp_NAME_XXXXXX (mkdtemp); throws std::runtime_error.
std::filesystem::path make_temp_dir(const std::string& name);

/// Sets RC_PARAMS to a fixed RapidCheck seed (docs/contract.md "Input") unless the environment
/// already sets it; for a namespace-scope initialiser: `const bool seeded = fixed_rc_seed();`.
bool fixed_rc_seed();

/// A soup of the given triangles, one face each (face id = index).
exbsp::triangle_soup soup_of(const std::vector<std::array<exbsp::vec3d, 3>>& tris);

/// One row of tests/data/bad/EXPECTED.tsv: a malformed file of tests/data/bad/, the line its
/// error must name (0: none) and a part of the message.
struct bad_input {
  std::string file;
  std::size_t line = 0;
  std::string message;
};

/// The rows of tests/data/bad/EXPECTED.tsv (blank lines and # comments skipped); a row without
/// its two tabs, or a file that cannot be read, is a test failure.
std::vector<bad_input> bad_input_manifest();

// --- errors ------------------------------------------------------------------------------------

/// The input_error that reading `data` as `format` (file name `name`) throws; a test failure,
/// and an error naming "none", when it throws none.
exbsp::input_error mesh_data_error(const std::string& data, exbsp::mesh_format format,
                                   const std::string& name = "mem");

/// The key named by the scene_error that `parse()` throws (e.g. "/camera/eye/1"), or
/// "(no error)" when it throws none; the error's message goes to `message` if given.
template <class Parse>
std::string error_key(Parse&& parse, std::string* message = nullptr) {
  try {
    parse();
  } catch (const exbsp::scene_error& e) {
    if (message) *message = e.what();
    return e.key();
  }
  return "(no error)";
}

// --- images ------------------------------------------------------------------------------------

/// The distinct colours of an image, as (r, g, b).
std::set<std::tuple<int, int, int>> colours_of(const exbsp::view::image& img);

/// Appends quad (a, b, c, d) as one face with the next face id; returns the id.
std::uint32_t add_quad(exbsp::triangle_soup& s, const exbsp::vec3d& a, const exbsp::vec3d& b,
                       const exbsp::vec3d& c, const exbsp::vec3d& d);

/// Appends box [lo, hi] as six quads (add_quad) turned outward ((b - a) x (c - a) of each
/// points away from the box: -z, +z, -y, +y, -x, +x in that order).
void add_box(exbsp::triangle_soup& s, const exbsp::vec3d& lo, const exbsp::vec3d& hi);

/// A frame of `soup` (colours by face id, white background) seen from `cam` through
/// gluPerspective(fovy, width / height, near_dist, far_dist) on a width x height viewport.
exbsp::view::frame perspective_frame(exbsp::triangle_soup soup,
                                     std::vector<exbsp::view::rgb8> colors,
                                     const exbsp::view::camera& cam, int width, int height,
                                     double fovy = 45, double near_dist = 0.5,
                                     double far_dist = 100);

/// Z-buffer rendering of the frame's unsplit soup with the painter's coverage rule (the
/// oracle of the BSP order): triangles clipped to the view volume, depth interpolated
/// affinely in window coordinates; `cull` drops back faces as backface_culling does.
exbsp::view::image zbuffer_render(const exbsp::view::frame& f, bool cull = false);

// --- matrices --------------------------------------------------------------------------------

/// Our row-major matrix from a column-major one indexed g[column][row] (GLM's dmat4).
template <class ColumnMajor>
exbsp::view::mat4 from_column_major(const ColumnMajor& g) {
  exbsp::view::mat4 r;
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) r(row, col) = g[col][row];
  return r;
}

/// Max over elements of |a - b| / max(1, max |b|): "within 1e-12 relative" for a matrix.
double relative_difference(const exbsp::view::mat4& a, const exbsp::view::mat4& b);

// --- vectors -----------------------------------------------------------------------------------

template <class T>
std::array<T, 3> add(const std::array<T, 3>& a, const std::array<T, 3>& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
template <class T>
std::array<T, 3> sub(const std::array<T, 3>& a, const std::array<T, 3>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <class S, class T>
std::array<T, 3> scale(const S& s, const std::array<T, 3>& a) {
  return {s * a[0], s * a[1], s * a[2]};
}
template <class T>
T dot(const std::array<T, 3>& a, const std::array<T, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class T>
std::array<T, 3> cross(const std::array<T, 3>& a, const std::array<T, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const std::array<double, 3>& a) { return std::sqrt(dot(a, a)); }
inline double dist(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return norm(sub(a, b));
}
/// a / |a|.
inline std::array<double, 3> unit(const std::array<double, 3>& a) { return scale(1 / norm(a), a); }

// --- vector drawings ---------------------------------------------------------------------------

/// Nonzero winding number of `rings` (grid points of a vector drawing) at grid point (x, y):
/// crossings of the horizontal ray to the right, half-open in y.
int winding_number(const std::vector<std::vector<exbsp::view::grid_point>>& rings, double x,
                   double y);

// --- the CGAL corpus ---------------------------------------------------------------------------

/// data/meshes/ of the source tree (with a trailing slash).
std::string corpus_dir();
/// True when EXBSP_REQUIRE_CORPUS=1: a missing corpus mesh fails the test instead of skipping it.
bool corpus_required();

}  // namespace exbsp_test

/// In a test body: unless `present`, fails (EXBSP_REQUIRE_CORPUS=1) or skips the test with a
/// message naming `what` is missing.
#define EXBSP_NEED_CORPUS(present, what)                                                 \
  do {                                                                                   \
    if (!(present)) {                                                                    \
      if (::exbsp_test::corpus_required())                                               \
        FAIL() << (what) << " is missing and EXBSP_REQUIRE_CORPUS=1: run scripts/setup"; \
      GTEST_SKIP() << "SKIPPED: " << (what)                                              \
                   << " is missing (run scripts/setup to extract the corpus)";           \
    }                                                                                    \
  } while (false)
