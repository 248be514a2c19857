// SPDX-License-Identifier: LGPL-3.0-or-later
// The plug-in tables (issue 26). Kernels (src/bsp/kernels.h): every row is wired through
// names, parsing, exactness, the build, saved trees and the command line's help and memory
// budget, and a kernel added here, in a test-only file, by one new instantiation and one row,
// works end to end with nothing else changed. Heuristics (src/bsp/heuristic_table.h): every
// row builds, names its tree and shows in --help, and one added here by a score and a row
// works the same way. Output formats (src/scene/output_formats.h): every row renders, and a
// format added here (PPM) by a writer and a row renders the same pixels as PNG.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>

#include <exbsp/bsp/engine.h>
#include <exbsp/core/errors.h>
#include <exbsp/scene/procedural.h>
#include <exbsp/view/png_io.h>
#include "app/commands/common.h"
#include "app/resources.h"
#include "bsp/heuristic_table.h"
#include "bsp/bsp_tree_impl.h"
#include "bsp/geometry_cgal.h"
#include "bsp/kernel_double.h"
#include "bsp/kernels.h"
#include "core/atomic_file.h"
#include "scene/output_formats.h"
#include "scene/render.h"

namespace exbsp {

/// The test's kernel: the plain double geometry under another id (a new kernel needs nothing
/// more than a geometry with its own id).
struct test_double_geometry : cgal_geometry<double_kernel> {
  using cgal_geometry<double_kernel>::cgal_geometry;
  static constexpr kernel_id id = static_cast<kernel_id>(100);
};

}  // namespace exbsp

EXBSP_INSTANTIATE_BSP(exbsp::test_double_geometry, test_double)

namespace {

using namespace exbsp;

/// Two boxes that cross, so that a build splits.
triangle_soup crossing_boxes() {
  triangle_soup a = scene::make_box({0, 0, 0}, {2, 1, 1});
  const triangle_soup b = scene::make_box({0.5, -0.5, -0.5}, {1.5, 1.5, 1.5});
  const auto offset = static_cast<std::uint32_t>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (soup_triangle t : b.triangles) {
    for (auto& v : t.v) v += offset;
    t.face += a.face_count;
    a.triangles.push_back(t);
  }
  a.face_count += b.face_count;
  return a;
}

/// Everything a row promises, checked through the public API and the command line's policy.
void expect_wired(const kernel_row& row) {
  SCOPED_TRACE(row.name);
  EXPECT_EQ(parse_kernel(row.name), row.id);
  EXPECT_EQ(to_string(row.id), row.name);
  EXPECT_EQ(is_exact(row.id), row.exact);
  bool named = false;
  for (const std::string& n : kernel_names()) named = named || n == row.name;
  EXPECT_TRUE(named) << "kernel_names() lacks it";
  EXPECT_GT(row.bytes_per_fragment, 0u);
  // A build alone needs at most what a command that also draws or writes the tree needs.
  EXPECT_GT(row.build_bytes_per_fragment, 0u);
  EXPECT_LE(row.build_bytes_per_fragment, row.bytes_per_fragment);
  EXPECT_FALSE(row.description.empty());
  EXPECT_NE(cli::kernel_help().find(row.name + " (" + row.description + ")"), std::string::npos);
  EXPECT_NE(cli::max_fragments_help().find(row.name), std::string::npos);
  EXPECT_NE(cli::max_fragments_help(cli::fragment_use::build).find(row.name), std::string::npos);

  build_options options;
  options.kernel = row.id;
  const bsp tree = bsp::build(crossing_boxes(), options);
  EXPECT_EQ(tree.kernel(), row.id);
  EXPECT_EQ(tree.stats().kernel, row.name);
  EXPECT_GT(tree.stats().splits, 0u);
  if (row.exact) {
    EXPECT_NO_THROW(tree.fragment_exact(0));
  } else {
    EXPECT_THROW(tree.fragment_exact(0), usage_error);
  }
  // Saved trees: the row's file code at byte 12, loaded back by the row's loader.
  const std::string bytes = tree.serialize();
  std::uint32_t code = 0;
  for (int i = 0; i < 4; ++i)
    code |= std::uint32_t{static_cast<unsigned char>(bytes[12 + i])} << (8 * i);
  EXPECT_EQ(code, row.file_code);
  const bsp loaded = bsp::deserialize(bytes, "t.exbsp");
  EXPECT_EQ(loaded.kernel(), row.id);
  EXPECT_EQ(loaded.serialize(), bytes);
  EXPECT_EQ(loaded.order_from_eye({5, -7, 3}), tree.order_from_eye({5, -7, 3}));
}

TEST(KernelTable, the_default_comes_first_and_ids_names_and_file_codes_are_unique) {
  const auto& rows = kernel_table();
  ASSERT_GE(rows.size(), 5u);
  EXPECT_EQ(rows.front().id, build_options{}.kernel);
  std::set<int> ids;
  std::set<std::string> names;
  std::set<std::uint32_t> codes;
  for (const kernel_row& r : rows) {
    EXPECT_TRUE(ids.insert(static_cast<int>(r.id)).second) << r.name;
    EXPECT_TRUE(names.insert(r.name).second) << r.name;
    EXPECT_TRUE(codes.insert(r.file_code).second) << r.name;
  }
  EXPECT_EQ(kernel_names().size(), rows.size());
}

TEST(KernelTable, every_row_is_wired_end_to_end) {
  for (const kernel_row& r : kernel_table()) expect_wired(r);
}

TEST(KernelTable, saved_trees_keep_their_published_kernel_codes) {
  // docs/tree-file.md: the codes are part of the file format and never change.
  EXPECT_EQ(kernel_row_of(kernel_id::exact).file_code, 1u);
  EXPECT_EQ(kernel_row_of(kernel_id::epeck).file_code, 2u);
  EXPECT_EQ(kernel_row_of(kernel_id::gmpq).file_code, 3u);
  EXPECT_EQ(kernel_row_of(kernel_id::epick).file_code, 4u);
  EXPECT_EQ(kernel_row_of(kernel_id::double_).file_code, 5u);
}

TEST(KernelTable, a_kernel_added_in_a_test_file_works_end_to_end) {
  add_kernel({static_cast<kernel_id>(100), "test-double", false, 100, 640, 512,
              "the double geometry under another id", make_bsp_test_double,
              tree_file::load_test_double});
  const kernel_row& row = kernel_row_of(static_cast<kernel_id>(100));
  expect_wired(row);
  // The same geometry as "double": the same tree.
  build_options a, b;
  a.kernel = kernel_id::double_;
  b.kernel = row.id;
  const bsp plain = bsp::build(crossing_boxes(), a), test = bsp::build(crossing_boxes(), b);
  EXPECT_EQ(plain.fragment_count(), test.fragment_count());
  EXPECT_EQ(plain.order_for_direction({1, 2, 3}), test.order_for_direction({1, 2, 3}));
  // A second kernel with a taken name, id or file code is refused.
  kernel_row again = row;
  again.id = static_cast<kernel_id>(101);
  EXPECT_THROW(add_kernel(again), usage_error);
  again.name = "test-double-2";
  EXPECT_THROW(add_kernel(again), usage_error);  // file code 100 is taken
  // Without its bytes per fragment the default --max-fragments would divide by zero.
  again.file_code = 102;
  again.build_bytes_per_fragment = 0;
  EXPECT_THROW(add_kernel(again), usage_error);
  again.build_bytes_per_fragment = 512;
  again.bytes_per_fragment = 0;
  EXPECT_THROW(add_kernel(again), usage_error);
}

TEST(KernelTable, unknown_kernels_are_usage_errors) {
  EXPECT_THROW(parse_kernel("quad"), usage_error);
  EXPECT_THROW(kernel_row_of(static_cast<kernel_id>(77)), usage_error);
  EXPECT_EQ(kernel_row_of_file_code(77), nullptr);
  build_options o;
  o.kernel = static_cast<kernel_id>(77);
  EXPECT_THROW(bsp::build(crossing_boxes(), o), usage_error);
}

}  // namespace

namespace {

using namespace exbsp;

void expect_heuristic_wired(const heuristic_row& row) {
  SCOPED_TRACE(row.name);
  bool named = false;
  for (const std::string& n : heuristic_names()) named = named || n == row.name;
  EXPECT_TRUE(named) << "heuristic_names() lacks it";
  EXPECT_FALSE(row.description.empty());
  EXPECT_NE(cli::heuristic_help().find(row.name + " (" + row.description + ")"), std::string::npos);
  const std::set<std::string> fields{"seed", "sampled_candidates", "sampled_samples",
                                     "sampled_split_weight", "threads"};
  for (const std::string& p : row.parameters) EXPECT_TRUE(fields.count(p)) << p;
  build_options options;
  options.heuristic = row.name;
  const bsp tree = bsp::build(crossing_boxes(), options);
  EXPECT_EQ(tree.stats().heuristic, row.name);
  EXPECT_GT(tree.stats().splits, 0u);
  // Deterministic: the same options give the same tree.
  const bsp again = bsp::build(crossing_boxes(), options);
  EXPECT_EQ(again.fragment_count(), tree.fragment_count());
  EXPECT_EQ(again.order_from_eye({5, -7, 3}), tree.order_from_eye({5, -7, 3}));
  // A score callback belongs to "custom" only.
  options.score = [](const candidate_score_input& in) { return double(in.straddling); };
  EXPECT_THROW(bsp::build(crossing_boxes(), options), usage_error);
}

TEST(HeuristicTable, every_row_is_wired_and_the_default_is_a_row) {
  const auto& rows = heuristic_table();
  ASSERT_GE(rows.size(), 4u);
  EXPECT_EQ(heuristic_names().size(), rows.size());
  bool default_found = false;
  std::set<std::string> names;
  for (const heuristic_row& r : rows) {
    EXPECT_TRUE(names.insert(r.name).second) << r.name;
    default_found = default_found || r.name == default_heuristic();
    expect_heuristic_wired(r);
  }
  EXPECT_TRUE(default_found);
}

TEST(HeuristicTable, a_heuristic_added_by_a_score_and_a_row_works_end_to_end) {
  // The fewest straddlers over every candidate, ties to the earliest: min-split exactly
  // (build_options::score's contract), so its trees must equal min-split's.
  add_heuristic({"test-fewest-straddlers",
                 "min-split by a score",
                 {"threads"},
                 detail::heuristic_custom,
                 [](const candidate_score_input& in) { return double(in.straddling); },
                 candidate_set::all});
  const heuristic_row& row = heuristic_table().back();
  ASSERT_EQ(row.name, "test-fewest-straddlers");
  expect_heuristic_wired(row);
  build_options a, b;
  a.heuristic = "min-split";
  b.heuristic = row.name;
  for (const kernel_id k : {kernel_id::exact, kernel_id::epeck}) {
    a.kernel = b.kernel = k;
    const bsp x = bsp::build(crossing_boxes(), a), y = bsp::build(crossing_boxes(), b);
    EXPECT_EQ(x.fragment_count(), y.fragment_count());
    EXPECT_EQ(x.order_from_eye({3, -4, 5}), y.order_from_eye({3, -4, 5}));
    EXPECT_EQ(y.stats().heuristic, row.name);
  }
  EXPECT_THROW(add_heuristic(row), usage_error);  // the name is taken
  heuristic_row unnamed = row;
  unnamed.name = "custom";
  EXPECT_THROW(add_heuristic(unnamed), usage_error);
  heuristic_row no_score = row;
  no_score.name = "test-no-score";
  no_score.score = nullptr;
  EXPECT_THROW(add_heuristic(no_score), usage_error);
}

}  // namespace

namespace {

using namespace exbsp;

/// The test's output format: binary PPM (P6) of the raster picture.
void write_ppm(const view::frame& f, const std::string& path) {
  const view::image& img = f.picture;
  std::string text =
      "P6\n" + std::to_string(img.width()) + " " + std::to_string(img.height()) + "\n255\n";
  text.append(reinterpret_cast<const char*>(img.data().data()), img.data().size());
  write_file_atomically(path, text);
}

/// A render of the built-in demo scene to `path`.
render_summary render_demo(const std::string& path) {
  std::ostringstream log;
  render_request request{"", path, false};
  return render_command(request, log);
}

TEST(OutputFormatTable, every_row_renders_the_demo_and_names_itself_in_help_and_errors) {
  const std::string dir = testing::TempDir();
  for (const output_format_row& r : output_format_table()) {
    SCOPED_TRACE(r.extension);
    EXPECT_EQ(&output_format_for("x" + r.extension), &r);
    EXPECT_NE(output_extensions().find(r.extension), std::string::npos);
    const std::string path = dir + "/table_demo" + r.extension;
    std::remove(path.c_str());
    render_demo(path);
    EXPECT_TRUE(std::filesystem::file_size(path) > 100);
    std::remove(path.c_str());
  }
  EXPECT_EQ(&output_format_for("-"), &output_format_table().front());
  try {
    output_format_for("x.tiff");
    ADD_FAILURE() << "no error for .tiff";
  } catch (const usage_error& e) {
    EXPECT_NE(std::string(e.what()).find(output_extensions()), std::string::npos) << e.what();
  }
}

TEST(OutputFormatTable, a_format_added_by_a_writer_and_a_row_works_end_to_end) {
  add_output_format({".ppm", "binary PPM of the picture", view::output_kind::png, write_ppm});
  EXPECT_NE(output_extensions().find(".ppm"), std::string::npos);
  const std::string dir = testing::TempDir();
  const std::string ppm = dir + "/table_demo.PPM", png = dir + "/table_demo_ref.png";
  render_demo(ppm);
  render_demo(png);
  // The PPM holds the PNG's pixels exactly.
  const view::image ref = view::read_png(png);
  std::ifstream in(ppm, std::ios::binary);
  std::string magic;
  int w = 0, h = 0, max = 0;
  in >> magic >> w >> h >> max;
  in.get();
  EXPECT_EQ(magic, "P6");
  EXPECT_EQ(w, ref.width());
  EXPECT_EQ(h, ref.height());
  EXPECT_EQ(max, 255);
  std::string pixels((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_EQ(pixels.size(), ref.data().size());
  EXPECT_TRUE(std::equal(pixels.begin(), pixels.end(), ref.data().begin(),
                         [](char a, std::uint8_t b) { return static_cast<std::uint8_t>(a) == b; }));
  // An orbit writes one file per frame in the new format too.
  render_request orbit{"", dir + "/table_orbit.ppm", false};
  orbit.orbit_drag = {{400, 300}, {420, 300}};
  std::ostringstream log;
  const render_summary s = render_command(orbit, log);
  ASSERT_EQ(s.outputs.size(), 2u);
  for (const std::string& p : s.outputs) {
    EXPECT_TRUE(std::filesystem::exists(p)) << p;
    std::remove(p.c_str());
  }
  EXPECT_THROW(add_output_format({".ppm", "again", view::output_kind::png, write_ppm}),
               usage_error);
  EXPECT_THROW(add_output_format({"ppm2", "no dot", view::output_kind::png, write_ppm}),
               usage_error);
  std::remove(ppm.c_str());
  std::remove(png.c_str());
}

}  // namespace
