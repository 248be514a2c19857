// SPDX-License-Identifier: LGPL-3.0-or-later
// Checks of the exbsp command line (docs/contract.md "Input" and "Command line"), run as a separate
// process (EXBSP_CLI) in a fresh temporary directory: bad input exits 2 naming file and line and
// writes nothing; `build --json` has every documented key; `order` JSON has the eye or the
// direction, faces, 17-digit doubles and reduced exact rationals whose nearest double is the
// printed one, in the library's order; --max-fragments exits 3 with no output; bad option
// values exit 2; two runs write byte-identical orders.
#include <gmp.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/core/errors.h>
#include <exbsp/core/version.h>
#include <exbsp/mesh/mesh_io.h>
#include <exbsp/view/png_io.h>
#include "support/cli_support.h"
#include "app/cli_parse.h"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

using exbsp_test::quoted;
using exbsp_test::read_file;
using exbsp_test::write_file;
using result = exbsp_test::cli_result;

/// A fresh temporary directory per test; the CLI runs inside it.
class Cli : public exbsp_test::cli_fixture {
 protected:
  /// The painter's failure case (tests/test_bsp.cpp) as an OFF file: it needs splits.
  fs::path write_cyclic_triple() {
    std::string off = "OFF\n9 3 0\n";
    char buf[256];
    for (int i = 0; i < 3; ++i) {
      const double ang = i * 2.0943951023931957, cx = std::cos(ang), cy = std::sin(ang), px = -cy,
                   py = cx;
      std::snprintf(buf, sizeof buf, "%.17g %.17g 0\n%.17g %.17g 0\n%.17g %.17g 1\n",
                    -3 * cx + 0.3 * px, -3 * cy + 0.3 * py, -3 * cx - 0.3 * px, -3 * cy - 0.3 * py,
                    3 * cx, 3 * cy);
      off += buf;
    }
    off += "3 0 1 2\n3 3 4 5\n3 6 7 8\n";
    const fs::path p = dir / "cyclic.off";
    write_file(p, off);
    return p;
  }
};

const std::string data_dir = EXBSP_TEST_DATA;

// --- (1) bad input ----------------------------------------------------------------------------

TEST_F(Cli, every_bad_input_file_exits_2_naming_file_and_line_and_writes_no_output) {
  const auto manifest = exbsp_test::bad_input_manifest();
  ASSERT_GE(manifest.size(), 50u) << "tests/data/bad/EXPECTED.tsv";
  for (const exbsp_test::bad_input& b : manifest) {
    SCOPED_TRACE(b.file);
    const std::string path = data_dir + "/bad/" + b.file;
    const result r = run("build " + quoted(path));
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err.rfind("exbsp: error: ", 0), 0u) << r.err;
    const std::string where = b.line ? path + ":" + std::to_string(b.line) + ":" : path;
    EXPECT_NE(r.err.find(where), std::string::npos) << "expected '" << where << "' in: " << r.err;
    EXPECT_NE(r.err.find(b.message), std::string::npos)
        << "expected '" << b.message << "' in: " << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;

    const result o = run("order " + quoted(path) + " --eye 0,0,10 -o OUT.json");
    EXPECT_EQ(o.status, 2);
    EXPECT_EQ(o.err.rfind("exbsp: error: ", 0), 0u) << o.err;
    EXPECT_FALSE(fs::exists(dir / "OUT.json")) << "partial output";
    EXPECT_TRUE(file_names().empty()) << "left behind: " << file_names().front();
  }
}

TEST_F(Cli, failed_order_leaves_an_existing_output_file_untouched) {
  write_file(dir / "OUT.json", "previous\n");
  const result r =
      run("order " + quoted(data_dir + "/bad/off_nan.off") + " --eye 0,0,10 -o OUT.json");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(read_file(dir / "OUT.json"), "previous\n");
  EXPECT_EQ(file_names(), std::vector<std::string>{"OUT.json"});
}

TEST_F(Cli, a_missing_mesh_file_exits_2_naming_it) {
  const result r = run("build no_such_mesh.off");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("exbsp: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("no_such_mesh.off"), std::string::npos) << r.err;
}

// --- (2) build --json ---------------------------------------------------------------------------

TEST_F(Cli, build_json_has_every_key_of_design_section_4_and_matches_the_library) {
  const fs::path cyclic = write_cyclic_triple();
  for (const std::string& mesh : {data_dir + "/cube.off", data_dir + "/fan.off", cyclic.string()}) {
    for (const char* kernel : {"exact", "epeck", "gmpq", "epick", "double"}) {
      SCOPED_TRACE(mesh + " " + kernel);
      const result r =
          run("build " + quoted(mesh) + " --kernel " + kernel + " --heuristic min-split --json");
      ASSERT_EQ(r.status, 0) << r.err;
      const json j = json::parse(r.out);
      ASSERT_TRUE(j.is_object());
      for (const char* key :
           {"input_triangles", "degenerate_input", "fragments", "splits", "nodes", "depth"}) {
        ASSERT_TRUE(j.contains(key)) << key;
        EXPECT_TRUE(j[key].is_number_unsigned()) << key;
      }
      ASSERT_TRUE(j.contains("build_seconds") && j["build_seconds"].is_number());
      EXPECT_GE(j["build_seconds"].get<double>(), 0.0);
      ASSERT_TRUE(j.contains("kernel") && j["kernel"].is_string());
      ASSERT_TRUE(j.contains("heuristic") && j["heuristic"].is_string());
      EXPECT_EQ(j["kernel"], kernel);
      EXPECT_EQ(j["heuristic"], "min-split");
      // The same numbers as the library's.
      exbsp::build_options o;
      o.kernel = exbsp::parse_kernel(kernel);
      o.heuristic = "min-split";
      const auto s = exbsp::bsp::build(exbsp::read_mesh(mesh), o).stats();
      EXPECT_EQ(j["input_triangles"].get<std::size_t>(), s.input_triangles);
      EXPECT_EQ(j["degenerate_input"].get<std::size_t>(), s.degenerate_input);
      EXPECT_EQ(j["fragments"].get<std::size_t>(), s.fragments);
      EXPECT_EQ(j["splits"].get<std::size_t>(), s.splits);
      EXPECT_EQ(j["nodes"].get<std::size_t>(), s.nodes);
      EXPECT_EQ(j["depth"].get<std::size_t>(), s.depth);
    }
  }
  // Defaults: kernel exact, the default heuristic.
  const result d = run("build " + quoted(cyclic.string()) + " --json");
  ASSERT_EQ(d.status, 0) << d.err;
  const json j = json::parse(d.out);
  EXPECT_EQ(j["kernel"], "exact");
  EXPECT_EQ(j["heuristic"], exbsp::default_heuristic());
  EXPECT_GE(j["splits"].get<std::size_t>(), 1u);
}

// --- (3) order JSON
// -------------------------------------------------------------------------------

/// True when `text` is a canonical rational: "p" or "p/q", q > 1, no sign on q, no leading
/// zeros, gcd(p, q) = 1, and no "-0".
bool canonical_rational(const std::string& text, mpq_t q) {
  static const std::regex form("-?(0|[1-9][0-9]*)(/[1-9][0-9]*)?");
  if (!std::regex_match(text, form) || text == "-0") return false;
  if (mpq_set_str(q, text.c_str(), 10) != 0) return false;
  mpq_t c;
  mpq_init(c);
  mpq_set(c, q);
  mpq_canonicalize(c);
  const bool same = mpq_equal(c, q) && mpz_cmp(mpq_numref(c), mpq_numref(q)) == 0 &&
                    mpz_cmp(mpq_denref(c), mpq_denref(q)) == 0;
  char* s = mpq_get_str(nullptr, 10, c);
  const bool same_text = text == s;
  void (*free_fn)(void*, size_t);
  mp_get_memory_functions(nullptr, nullptr, &free_fn);
  free_fn(s, std::char_traits<char>::length(s) + 1);
  mpq_clear(c);
  return same && same_text;
}

/// True when x is the double nearest to q (ties to even), checked exactly against both
/// neighbours of x.
bool nearest_double(const mpq_t q, double x) {
  if (!std::isfinite(x)) return false;
  mpq_t d, diff, best;
  mpq_inits(d, diff, best, nullptr);
  mpq_set_d(d, x);
  mpq_sub(best, q, d);
  mpq_abs(best, best);
  bool ok = true;
  for (double n : {std::nextafter(x, HUGE_VAL), std::nextafter(x, -HUGE_VAL)}) {
    if (!std::isfinite(n)) continue;
    mpq_set_d(d, n);
    mpq_sub(diff, q, d);
    mpq_abs(diff, diff);
    const int c = mpq_cmp(diff, best);
    if (c < 0) ok = false;
    if (c == 0) {  // a tie: x must have an even last mantissa bit
      int e;
      const double m = std::frexp(x, &e);
      const double last = std::ldexp(m, 53);
      if (std::fmod(last, 2.0) != 0) ok = false;
    }
  }
  mpq_clears(d, diff, best, nullptr);
  return ok;
}

/// The raw text of the numbers in each "v" array, in file order (one fragment per line).
std::vector<std::vector<std::string>> raw_v_numbers(const std::string& text) {
  std::vector<std::vector<std::string>> out;
  static const std::regex v_array(R"("v": \[\[([^\]]*)\], \[([^\]]*)\], \[([^\]]*)\]\])");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), v_array);
       it != std::sregex_iterator(); ++it) {
    std::vector<std::string> numbers;
    for (int g = 1; g <= 3; ++g) {
      std::stringstream ss((*it)[g].str());
      std::string tok;
      while (std::getline(ss, tok, ',')) numbers.push_back(tok.substr(tok.find_first_not_of(' ')));
    }
    out.push_back(numbers);
  }
  return out;
}

std::string g17(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

TEST_F(Cli, order_json_has_eye_or_direction_faces_17_digit_doubles_and_reduced_exact_rationals) {
  const fs::path cyclic = write_cyclic_triple();
  const std::string exact_decimal = data_dir + "/exact_decimal.off";
  struct view_case {
    std::string mesh, option, key;
    exbsp::vec3d where;
  };
  const std::vector<view_case> cases{
      {cyclic.string(), "--eye 0.1,0.2,10", "eye", {0.1, 0.2, 10}},
      {cyclic.string(), "--direction 0,0.5,-1", "direction", {0, 0.5, -1}},
      {exact_decimal, "--eye 1,2,3", "eye", {1, 2, 3}},
      {data_dir + "/cube.off", "--eye 0.5,0.5,5", "eye", {0.5, 0.5, 5}}};
  for (const view_case& vc : cases) {
    for (const char* kernel : {"exact", "epeck", "gmpq"}) {
      SCOPED_TRACE(vc.mesh + " " + vc.option + " " + kernel);
      const result r = run("order " + quoted(vc.mesh) + " " + vc.option + " --kernel " + kernel +
                           " --heuristic naive -o OUT.json");
      ASSERT_EQ(r.status, 0) << r.err;
      const std::string text = read_file(dir / "OUT.json");
      const json j = json::parse(text);
      ASSERT_TRUE(j.contains(vc.key));
      EXPECT_FALSE(j.contains(vc.key == "eye" ? "direction" : "eye"));
      ASSERT_EQ(j[vc.key].size(), 3u);
      for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(j[vc.key][k].get<double>(), vc.where[k]);
      ASSERT_TRUE(j.contains("fragments") && j["fragments"].is_array());
      const auto raw = raw_v_numbers(text);
      ASSERT_EQ(raw.size(), j["fragments"].size()) << "one fragment per line";

      // The library's order for the same input and viewpoint.
      exbsp::build_options o;
      o.kernel = exbsp::parse_kernel(kernel);
      o.heuristic = "naive";
      const exbsp::bsp tree = exbsp::bsp::build(exbsp::read_mesh(vc.mesh), o);
      const auto order =
          vc.key == "eye" ? tree.order_from_eye(vc.where) : tree.order_for_direction(vc.where);
      ASSERT_EQ(order.size(), j["fragments"].size());

      mpq_t q;
      mpq_init(q);
      for (std::size_t n = 0; n < order.size(); ++n) {
        const json& f = j["fragments"][n];
        ASSERT_TRUE(f["face"].is_number_unsigned());
        EXPECT_EQ(f["face"].get<std::uint32_t>(), tree.fragment(order[n]).face);
        ASSERT_EQ(f["v"].size(), 3u);
        ASSERT_EQ(f["exact"].size(), 3u);
        const exbsp::exact_triangle e = tree.fragment_exact(order[n]);
        for (std::size_t i = 0; i < 3; ++i)
          for (std::size_t k = 0; k < 3; ++k) {
            const std::string ex = f["exact"][i][k].get<std::string>();
            EXPECT_EQ(ex, e[i][k]);
            ASSERT_TRUE(canonical_rational(ex, q)) << "not a reduced rational: " << ex;
            const double v = f["v"][i][k].get<double>();
            EXPECT_TRUE(nearest_double(q, v)) << v << " is not the nearest double to " << ex;
            EXPECT_EQ(raw[n][3 * i + k], g17(v)) << "not printed with 17 significant digits";
          }
      }
      mpq_clear(q);
    }
  }
}

TEST_F(Cli, order_with_an_inexact_kernel_has_no_exact_coordinates) {
  const fs::path cyclic = write_cyclic_triple();
  const result r = run("order " + quoted(cyclic.string()) + " --eye 0,0,10 --kernel double");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_FALSE(j["fragments"].empty());
  for (const json& f : j["fragments"]) EXPECT_FALSE(f.contains("exact"));
}

TEST_F(Cli, two_runs_write_byte_identical_orders_whatever_the_thread_count) {
  // The small cyclic scene, and a real mesh big enough for the parallel build.
  std::vector<std::string> meshes{write_cyclic_triple().string()};
  const std::string anchor = std::string(EXBSP_SOURCE_DIR) + "/data/meshes/anchor.off";
  if (fs::exists(anchor)) meshes.push_back(anchor);
  for (const std::string& mesh : meshes)
    for (const char* h : {"naive", "min-split", "sampled", "random"}) {
      const std::string base =
          "order " + quoted(mesh) + " --eye 0.3,0.2,7 --heuristic " + h + " --seed 5";
      ASSERT_EQ(run(base + " --threads 1 -o A.json").status, 0);
      ASSERT_EQ(run(base + " --threads 2 -o B.json").status, 0);
      ASSERT_EQ(run(base + " -o C.json").status, 0);
      const std::string a = read_file(dir / "A.json");
      EXPECT_EQ(a, read_file(dir / "B.json")) << mesh << " " << h;
      EXPECT_EQ(a, read_file(dir / "C.json")) << mesh << " " << h;
    }
  EXBSP_NEED_CORPUS(fs::exists(anchor), anchor);  // after the cyclic scene's checks
}

// --- (4) --max-fragments ------------------------------------------------------------------------

TEST_F(Cli, max_fragments_below_what_the_splits_need_exits_3_and_writes_nothing) {
  const fs::path cyclic = write_cyclic_triple();
  const result b =
      run("build " + quoted(cyclic.string()) + " --heuristic naive --max-fragments 3 --json");
  EXPECT_EQ(b.status, 3);
  EXPECT_EQ(b.err.rfind("exbsp: error: ", 0), 0u) << b.err;
  EXPECT_TRUE(b.out.empty()) << b.out;
  const result o = run("order " + quoted(cyclic.string()) +
                       " --eye 0,0,10 --heuristic naive --max-fragments 3 -o OUT.json");
  EXPECT_EQ(o.status, 3);
  EXPECT_EQ(o.err.rfind("exbsp: error: ", 0), 0u) << o.err;
  EXPECT_EQ(file_names(), std::vector<std::string>{"cyclic.off"})
      << "no OUT.json, no temporary file";
  const result s =
      run("order " + quoted(cyclic.string()) + " --eye 0,0,10 --heuristic naive --max-fragments 3");
  EXPECT_EQ(s.status, 3);
  EXPECT_TRUE(s.out.empty()) << "nothing on standard output either";
  // A limit the tree fits in is fine.
  EXPECT_EQ(
      run("build " + quoted(cyclic.string()) + " --heuristic naive --max-fragments 1000").status,
      0);
}

// --- (5) bad option values
// ------------------------------------------------------------------------

TEST_F(Cli, bad_option_values_exit_2_with_a_message_and_write_nothing) {
  const std::string mesh = quoted(data_dir + "/cube.off");
  const std::vector<std::string> bad{
      "order " + mesh + " --eye 1,2 -o OUT.json",
      "order " + mesh + " --eye 1,2,3,4 -o OUT.json",
      "order " + mesh + " --eye a,b,c -o OUT.json",
      "order " + mesh + " --eye 1,,3 -o OUT.json",
      "order " + mesh + " --eye nan,0,0 -o OUT.json",
      "order " + mesh + " --eye inf,0,0 -o OUT.json",
      "order " + mesh + " --eye 1e999,0,0 -o OUT.json",
      "order " + mesh + " --direction 0,0,0 -o OUT.json",
      "order " + mesh + " --eye 0,0,5 --direction 0,0,-1 -o OUT.json",
      "order " + mesh + " -o OUT.json",
      "order " + mesh + " --eye 0,0,5 --kernel foo -o OUT.json",
      "order " + mesh + " --eye 0,0,5 --heuristic foo -o OUT.json",
      "build " + mesh + " --kernel foo",
      "build " + mesh + " --heuristic best",
      "build " + mesh + " --seed -1x",
      "build " + mesh + " --max-fragments many",
      "build",
      "frobnicate " + mesh};
  for (const std::string& args : bad) {
    SCOPED_TRACE(args);
    const result r = run(args);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.err.rfind("exbsp: error: ", 0), 0u) << r.err;
    EXPECT_FALSE(fs::exists(dir / "OUT.json"));
  }
}

// --- (6) a friendlier command line: version, suggestions, standard input, render MESH ---------

TEST_F(Cli, version_prints_the_library_version_and_no_command_is_a_clear_error) {
  const result v = run("--version");
  EXPECT_EQ(v.status, 0) << v.err;
  EXPECT_EQ(v.out, std::string("exbsp ") + exbsp::version_string + "\n");
  const result none = run("");
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find(
                "a command is required: build, order, render, section, clip, drawing or matrices"),
            std::string::npos)
      << none.err;
}

TEST_F(Cli, misspelled_commands_and_options_get_the_closest_valid_name) {
  const std::string mesh = quoted(data_dir + "/cube.off");
  const std::vector<std::pair<std::string, std::string>> cases{
      {"bild " + mesh, "unknown command 'bild'; did you mean 'build'?"},
      {"rendr", "unknown command 'rendr'; did you mean 'render'?"},
      {"build " + mesh + " --kernal epeck",
       "unknown option '--kernal' for 'build'; did you mean '--kernel'?"},
      {"order " + mesh + " --ey 1,2,3", "unknown option '--ey' for 'order'; did you mean '--eye'?"},
      {"render --veiw top", "unknown option '--veiw' for 'render'; did you mean '--view'?"},
      {"build " + mesh + " --heuristic=naive --jsno",
       "unknown option '--jsno' for 'build'; did you mean '--json'?"},
      {"--verison", "unknown option '--verison'; did you mean '--version'?"},
      {"xyzzy", "unknown command 'xyzzy'"}};
  for (const auto& [args, message] : cases) {
    SCOPED_TRACE(args);
    const result r = run(args);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err.rfind("exbsp: error: " + message, 0), 0u) << r.err;
  }
  // Far from every name: no suggestion.
  EXPECT_EQ(run("xyzzy").err.find("did you mean"), std::string::npos);
}

TEST_F(Cli, negative_numbers_for_unsigned_options_are_refused) {
  const std::string mesh = quoted(data_dir + "/cube.off");
  for (const std::string& args :
       {"build " + mesh + " --seed -1", "build " + mesh + " --max-fragments -5",
        "build " + mesh + " --threads -2",
        std::string("render -o OUT.png --orbit-drag 1,2:3,4 --frames -3")}) {
    SCOPED_TRACE(args);
    const result r = run(args);
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_EQ(r.err.rfind("exbsp: error: ", 0), 0u) << r.err;
    EXPECT_FALSE(fs::exists(dir / "OUT.png"));
    EXPECT_FALSE(fs::exists(dir / "OUT_0000.png"));
  }
}

TEST_F(Cli, a_mesh_on_standard_input_needs_format_and_builds_the_same_tree_as_the_file) {
  const std::string mesh = data_dir + "/cube.off";
  const result no_format = run_with_input("build - --json", mesh);
  EXPECT_EQ(no_format.status, 2);
  EXPECT_NE(no_format.err.find("needs --format"), std::string::npos) << no_format.err;
  const result piped = run_with_input("order - --format off --eye 3,4,5", mesh);
  const result file = run("order " + quoted(mesh) + " --eye 3,4,5");
  ASSERT_EQ(piped.status, 0) << piped.err;
  EXPECT_EQ(piped.out, file.out);
  const result stats = run_with_input("build - --format off --json", mesh);
  ASSERT_EQ(stats.status, 0) << stats.err;
  EXPECT_EQ(json::parse(stats.out)["mesh"], "<stdin>");
  // --format also overrides a file's extension; a wrong format is an error naming the input.
  write("cube.txt", read_file(mesh));
  EXPECT_EQ(run("build cube.txt --format off").status, 0);
  EXPECT_EQ(run("build cube.txt").status, 2);
  const result wrong = run_with_input("build - --format stl", mesh);
  EXPECT_EQ(wrong.status, 2);
  EXPECT_NE(wrong.err.find("<stdin>"), std::string::npos) << wrong.err;
  const result bad_format = run_with_input("build - --format dxf", mesh);
  EXPECT_EQ(bad_format.status, 2);
  const result section = run_with_input("section - --format off --plane 0,0,1,0", mesh);
  EXPECT_EQ(section.status, 0) << section.err;
}

/// Bounding box of the pixels that differ from the corner pixel (the background).
std::array<int, 4> drawn_box(const exbsp::view::image& img) {
  const auto bg = img.at_row(0, 0);
  std::array<int, 4> box{img.width(), img.height(), -1, -1};
  for (int row = 0; row < img.height(); ++row)
    for (int col = 0; col < img.width(); ++col) {
      const auto c = img.at_row(row, col);
      if (c.r == bg.r && c.g == bg.g && c.b == bg.b) continue;
      box = {std::min(box[0], col), std::min(box[1], row), std::max(box[2], col),
             std::max(box[3], row)};
    }
  return box;
}

TEST_F(Cli, render_of_a_mesh_fits_every_named_view_and_prints_a_summary) {
  const std::string mesh = quoted(data_dir + "/cube.off");
  for (const std::string view : {"iso", "front", "back", "left", "right", "top", "bottom"}) {
    SCOPED_TRACE(view);
    const result r =
        run("render " + mesh + " --view " + view + " --size 320x200 -o " + view + ".png");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("exbsp: wrote " + view + ".png: 12 triangles -> "), std::string::npos)
        << r.err;
    const exbsp::view::image img = exbsp::view::read_png((dir / (view + ".png")).string());
    ASSERT_EQ(img.width(), 320);
    ASSERT_EQ(img.height(), 200);
    // The whole cube is inside the picture, away from its borders, and fills a fair part of it.
    const auto box = drawn_box(img);
    EXPECT_GT(box[0], 0);
    EXPECT_GT(box[1], 0);
    EXPECT_LT(box[2], 319);
    EXPECT_LT(box[3], 199);
    EXPECT_GT(box[3] - box[1], 200 / 4);
  }
  // Lighting makes the faces of the iso view distinguishable: at least three shades.
  const exbsp::view::image iso = exbsp::view::read_png((dir / "iso.png").string());
  std::set<std::tuple<int, int, int>> shades;
  for (int row = 0; row < iso.height(); ++row)
    for (int col = 0; col < iso.width(); ++col) {
      const auto c = iso.at_row(row, col);
      shades.insert({c.r, c.g, c.b});
    }
  EXPECT_GE(shades.size(), 4u);  // background + three faces
  const result quiet = run("render " + mesh + " -q -o quiet.svg");
  ASSERT_EQ(quiet.status, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  const std::string svg = read_file(dir / "quiet.svg");
  EXPECT_NE(svg.find("<g id=\"mesh-0\""), std::string::npos);
  EXPECT_NE(svg.find("<g id=\"visible-edges\""), std::string::npos) << "visible edges by default";
}

TEST_F(Cli, render_of_a_bad_mesh_or_bad_mesh_options_exits_2_and_writes_nothing) {
  write("empty.off", "OFF\n0 0 0\n");
  write("point.off", "OFF\n3 1 0\n1 1 1\n1 1 1\n1 1 1\n3 0 1 2\n");
  write("huge.off", "OFF\n3 1 0\n-1.7e308 0 0\n1.7e308 0 0\n0 1.7e308 0\n3 0 1 2\n");
  const std::string cube = quoted(data_dir + "/cube.off");
  for (const std::string& args :
       {std::string("render empty.off -o OUT.png"), std::string("render huge.off -o OUT.png"),
        "render " + cube + " --view diagonal -o OUT.png",
        "render " + cube + " --size 0x10 -o OUT.png", "render " + cube + " --size 800 -o OUT.png",
        "render " + cube + " --edges some -o OUT.svg", std::string("render - -o OUT.png"),
        std::string("render --format off -o OUT.png"), std::string("render missing.off -o OUT.png"),
        "render " + cube + " -o OUT.tiff"}) {
    SCOPED_TRACE(args);
    const result r = run(args);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.err.rfind("exbsp: error: ", 0), 0u) << r.err;
    EXPECT_EQ(file_names(), (std::vector<std::string>{"empty.off", "huge.off", "point.off"}));
  }
  // All triangles degenerate at one point: nothing to draw, but a picture of the empty view.
  const result point = run("render point.off -o point.png");
  EXPECT_EQ(point.status, 0) << point.err;
  EXPECT_NE(point.err.find("1 triangles -> 0 fragments"), std::string::npos) << point.err;
}

// Every render flag acts or is refused (issue 25): a saved tree is drawn as it was built, the
// flags of a mesh's fitted view are refused on a scene, --edges overrides a scene's (SVG and
// PDF: its "svg" edges; PNG: its "raster" edges), --frames needs an orbit and at least one frame.
TEST_F(Cli, render_of_a_saved_tree_gives_the_bytes_of_the_mesh_without_a_build) {
  const std::string mesh = quoted(data_dir + "/nonmanifold.off");
  ASSERT_EQ(run("build " + mesh + " --save t.exbsp").status, 0);
  for (const std::string& ext : {std::string("png"), std::string("svg")}) {
    SCOPED_TRACE(ext);
    const result a = run("render " + mesh + " --view front --size 200x150 -o mesh." + ext);
    ASSERT_EQ(a.status, 0) << a.err;
    const result b = run("render t.exbsp --view front --size 200x150 -v -o tree." + ext);
    ASSERT_EQ(b.status, 0) << b.err;
    EXPECT_EQ(read_file(dir / ("mesh." + ext)), read_file(dir / ("tree." + ext)));
    EXPECT_NE(b.err.find("stage adopt:"), std::string::npos) << b.err;
    EXPECT_EQ(b.err.find("stage build:"), std::string::npos) << "a saved tree is not rebuilt";
  }
  for (const char* steer : {"--threads 1", "--max-fragments 10"}) {
    const result r = run(std::string("order t.exbsp --eye 1,2,3 -o o.json ") + steer);
    EXPECT_EQ(r.status, 2) << steer;
    EXPECT_NE(r.err.find("steers a build; t.exbsp is a saved tree"), std::string::npos) << r.err;
  }
  const result kernel = run("render t.exbsp --kernel epeck -o k.png");
  EXPECT_EQ(kernel.status, 2);
  EXPECT_NE(kernel.err.find("saved tree built with --kernel exact"), std::string::npos)
      << kernel.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "k.png"));
}

TEST_F(Cli, render_flags_act_on_a_scene_or_are_refused_with_the_reason) {
  const std::string scene = quoted(std::string(EXBSP_SOURCE_DIR) + "/scenes/perspective.json");
  const struct {
    std::string args, reason;
  } refused[] = {
      {"render " + scene + " --view front -o a.png", "has its own \"camera\""},
      {"render " + scene + " --size 100x100 -o a.png", "sets it in \"viewport\""},
      {"render --size 100x100 -o a.png", "the demo scene"},
      {"render " + scene + " --edges all -o a.png", "--edges: all not in"},
      {"render " + scene + " --wireframe -o a.svg", "--wireframe applies to PNG output"},
      {"render " + scene + " --wireframe --edges none -o a.png", "--wireframe needs edges"},
      {"render " + scene + " --frames 3 -o a.png", "needs --orbit-drag"},
      {"render " + scene + " --frames 0 -o a.png", "needs --orbit-drag"},
      {"render " + scene + " --orbit-drag 1,2:3,4 --frames 0 -o a.png", "at least 1"},
  };
  for (const auto& c : refused) {
    SCOPED_TRACE(c.args);
    const result r = run(c.args);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find(c.reason), std::string::npos) << r.err;
    EXPECT_TRUE(file_names().empty());
  }
  // --edges on a scene's SVG overrides its "svg" "edges" (none in perspective.json).
  ASSERT_EQ(run("render " + scene + " -q -o plain.svg").status, 0);
  ASSERT_EQ(run("render " + scene + " -q --edges visible+hidden -o edges.svg").status, 0);
  EXPECT_EQ(read_file(dir / "plain.svg").find("hidden-edges"), std::string::npos);
  EXPECT_NE(read_file(dir / "edges.svg").find("<g id=\"visible-edges\""), std::string::npos);
  EXPECT_NE(read_file(dir / "edges.svg").find("<g id=\"hidden-edges\""), std::string::npos);
  // On a PNG it draws the same edges over the picture; without it the PNG is the scene's.
  ASSERT_EQ(run("render " + scene + " -q -o plain.png").status, 0);
  const result edges = run("render " + scene + " -v --edges visible+hidden -o edges.png");
  ASSERT_EQ(edges.status, 0) << edges.err;
  EXPECT_NE(edges.err.find("stage edges:"), std::string::npos) << edges.err;
  EXPECT_NE(read_file(dir / "plain.png"), read_file(dir / "edges.png"));
  const result none = run("render " + scene + " -v --edges none -o none.png");
  EXPECT_EQ(none.err.find("stage edges:"), std::string::npos) << "no stage when none is asked";
  EXPECT_EQ(read_file(dir / "plain.png"), read_file(dir / "none.png"));
  const result wire = run("render " + scene + " -v --wireframe -o wire.png");
  ASSERT_EQ(wire.status, 0) << wire.err;
  EXPECT_NE(wire.err.find("a wireframe of"), std::string::npos) << wire.err;
}

// The progress line on a terminal (issue 25): every stage over a second shows, the line is
// redrawn at most ~10 times a second, the build's share never goes backwards, and the line is
// cleared at the end. A pseudo-terminal from util-linux's `script`.
TEST_F(Cli, the_progress_line_shows_long_stages_ten_times_a_second_and_never_goes_back) {
  const std::string mesh = std::string(EXBSP_SOURCE_DIR) + "/data/meshes/refined_elephant.off";
  if (!std::filesystem::exists(mesh)) GTEST_SKIP() << "the CGAL corpus is missing: " << mesh;
  if (std::system("command -v script >/dev/null") != 0) GTEST_SKIP() << "no script(1)";
  // Under the sanitizers the render takes 110 s of the run's budget for what is a terminal
  // line's timing; the render path runs instrumented in the other render tests.
  if (std::getenv("EXBSP_SANITIZED"))
    GTEST_SKIP() << "a terminal line's timing: not a sanitizer check";
  const std::string command = quoted(EXBSP_CLI) + " render " + quoted(mesh) +
                              " --kernel epeck -o " + quoted((dir / "e.svg").string());
  const auto t0 = std::chrono::steady_clock::now();
  const std::string cmd = "script -qec " + quoted(command) + " /dev/null > " +
                          quoted((dir / "tty.txt").string()) + " 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::string tty = read_file(dir / "tty.txt");
  // Redraws: "\r\033[Kexbsp: STAGE: ..." each; the last one clears the line.
  std::vector<std::string> lines;
  for (std::size_t at = tty.find("\r\033[K"); at != std::string::npos;
       at = tty.find("\r\033[K", at + 1)) {
    const std::size_t end = tty.find('\r', at + 1);
    lines.push_back(tty.substr(at + 4, end == std::string::npos ? end : end - at - 4));
  }
  ASSERT_GE(lines.size(), 5u) << tty.substr(0, 2000);
  EXPECT_LE(static_cast<double>(lines.size()), 10.5 * seconds + 2) << seconds << " s";
  double share = -1;
  bool building = false;
  // Only the lines with a share: "exbsp: building: 1.9 s", drawn before the build's first
  // report (over a second under the sanitizers), is not one (sscanf's "%d%%" would read its 1).
  const std::regex with_share(R"(^exbsp: building: +(\d+)% \(\d+ of \d+ fragments placed\))");
  for (const std::string& l : lines) {
    std::smatch m;
    if (std::regex_search(l, m, with_share)) {
      const int percent = std::stoi(m[1].str());
      building = true;
      EXPECT_GE(percent, share) << l;
      share = percent;
    }
  }
  EXPECT_TRUE(building) << "the build (several seconds with epeck) shows its share";
  // The line is cleared before the summary.
  EXPECT_NE(tty.find("\r\033[Kexbsp: wrote"), std::string::npos) << tty.substr(tty.size() - 300);
}

// The man page and bash completion come from the CLI11 definitions (src/app/cli_docs.h): every
// command and every option of `--help` is in them, groff reads the page without a warning,
// and bash completes commands, options and option values.
TEST_F(Cli, the_man_page_and_bash_completion_list_every_command_and_option) {
  const result man = run("--man");
  ASSERT_EQ(man.status, 0) << man.err;
  EXPECT_EQ(man.out.rfind(".TH EXBSP 1", 0), 0u);
  const result completion = run("--bash-completion");
  ASSERT_EQ(completion.status, 0) << completion.err;
  for (const char* command : {"build", "order", "render", "section", "clip", "drawing"}) {
    SCOPED_TRACE(command);
    EXPECT_NE(man.out.find(std::string(".SH \"exbsp ") + command + "\""), std::string::npos);
    // Every long option --help shows for the command is in both.
    const result help = run(std::string(command) + " --help");
    const std::regex long_option(R"(\n  (?:-\w,)?--([a-z][a-z-]*))");
    std::size_t seen = 0;
    for (std::sregex_iterator it(help.out.begin(), help.out.end(), long_option), end; it != end;
         ++it, ++seen) {
      const std::string name = (*it)[1].str();
      std::string escaped;
      for (char c : name) escaped += c == '-' ? std::string("\\-") : std::string(1, c);
      EXPECT_NE(man.out.find("\\-\\-" + escaped), std::string::npos) << name;
      EXPECT_NE(completion.out.find("--" + name), std::string::npos) << name;
    }
    EXPECT_GT(seen, 2u);
  }
  write("exbsp.1", man.out);
  if (std::system("command -v groff >/dev/null") == 0) {
    const std::string cmd =
        "cd " + quoted(dir.string()) + " && groff -man -Tutf8 -ww -z exbsp.1 > groff.txt 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0);
    EXPECT_EQ(read_file(dir / "groff.txt"), "") << "groff warnings";
  }
  write("exbsp.bash", completion.out);
  const auto complete = [&](const std::string& words, int cword) {
    const std::string script = "source exbsp.bash; COMP_WORDS=(" + words +
                               "); COMP_CWORD=" + std::to_string(cword) +
                               "; _exbsp; echo \"${COMPREPLY[*]}\"";
    const std::filesystem::path out = dir / "completed.txt";
    const std::string cmd = "cd " + quoted(dir.string()) + " && bash -c " + quoted(script) + " > " +
                            quoted(out.string());
    EXPECT_EQ(std::system(cmd.c_str()), 0);
    return read_file(out);
  };
  EXPECT_EQ(complete("exbsp dr", 1), "drawing\n");
  EXPECT_EQ(complete("exbsp render --ker", 2), "--kernel\n");
  EXPECT_EQ(complete("exbsp build --kernel e", 3), "exact epeck epick\n");
  EXPECT_EQ(complete("exbsp render --view f", 3), "front\n");
}

TEST(CliParse, values_sizes_drag_paths_and_suggestions) {
  using namespace exbsp::cli;
  EXPECT_EQ(parse_triple("1,2.5,-3", "--eye"), (exbsp::vec3d{1, 2.5, -3}));
  EXPECT_EQ(parse_size("800x600"), (std::array<int, 2>{800, 600}));
  for (const char* bad :
       {"", "800", "x600", "800x", "0x5", "5x0", "-5x5", "16385x1", "8a0x600", "800x600x2"})
    EXPECT_THROW(parse_size(bad), exbsp::usage_error) << bad;
  EXPECT_EQ(parse_drag_path("10,20:30.5,-4"),
            (std::vector<std::array<double, 2>>{{10, 20}, {30.5, -4}}));
  EXPECT_EQ(parse_drag_path("7,8").size(), 1u);
  for (const char* bad : {"", "1", "1,2:", "1,2;3,4", "a,b", "1,2,3", "1,nan", "1,2:3", ":1,2"})
    EXPECT_THROW(parse_drag_path(bad), exbsp::usage_error) << bad;
  EXPECT_THROW(parse_plane("0,0,0,1"), exbsp::usage_error);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("same", "same"), 0u);
  EXPECT_EQ(closest("--kernal", {"--kernel", "--heuristic", "--seed"}), "--kernel");
  EXPECT_EQ(closest("--zzzzzz", {"--kernel", "--heuristic", "--seed"}), "");
  EXPECT_EQ(closest("bild", {"build", "order", "render"}), "build");
}

}  // namespace
