// Checks of the exbsp command line (DESIGN.md sections 2 and 4), run as a separate process
// (EXBSP_CLI) in a fresh temporary directory: bad input exits 2 naming file and line and
// writes nothing; `build --json` has every documented key; `order` JSON has the eye or the
// direction, faces, 17-digit doubles and reduced exact rationals whose nearest double is the
// printed one, in the library's order; --max-fragments exits 3 with no output; bad option
// values exit 2; two runs write byte-identical orders.
#include <gmp.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "bsp/engine.h"
#include "support/cli_support.h"
#include "mesh/mesh_io.h"

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
      const double ang = i * 2.0943951023931957, cx = std::cos(ang), cy = std::sin(ang), px = -cy, py = cx;
      std::snprintf(buf, sizeof buf, "%.17g %.17g 0\n%.17g %.17g 0\n%.17g %.17g 1\n", -3 * cx + 0.3 * px,
                    -3 * cy + 0.3 * py, -3 * cx - 0.3 * px, -3 * cy - 0.3 * py, 3 * cx, 3 * cy);
      off += buf;
    }
    off += "3 0 1 2\n3 3 4 5\n3 6 7 8\n";
    const fs::path p = dir / "cyclic.off";
    write_file(p, off);
    return p;
  }
};

const std::string data_dir = EXBSP_TEST_DATA;

struct bad_file {
  std::string file;
  std::size_t line;
  std::string message;
};

std::vector<bad_file> bad_manifest() {
  std::vector<bad_file> out;
  std::ifstream in(data_dir + "/bad/EXPECTED.tsv");
  std::string row;
  while (std::getline(in, row)) {
    if (row.empty() || row[0] == '#') continue;
    const auto t1 = row.find('\t'), t2 = row.find('\t', t1 + 1);
    if (t1 == std::string::npos || t2 == std::string::npos) continue;
    out.push_back({row.substr(0, t1), std::stoul(row.substr(t1 + 1, t2 - t1 - 1)), row.substr(t2 + 1)});
  }
  return out;
}

// --- (1) bad input ----------------------------------------------------------------------------

TEST_F(Cli, every_bad_input_file_exits_2_naming_file_and_line_and_writes_no_output) {
  const auto manifest = bad_manifest();
  ASSERT_GE(manifest.size(), 50u) << "tests/data/bad/EXPECTED.tsv";
  for (const bad_file& b : manifest) {
    SCOPED_TRACE(b.file);
    const std::string path = data_dir + "/bad/" + b.file;
    const result r = run("build " + quoted(path));
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err.rfind("exbsp: error: ", 0), 0u) << r.err;
    const std::string where = b.line ? path + ":" + std::to_string(b.line) + ":" : path;
    EXPECT_NE(r.err.find(where), std::string::npos) << "expected '" << where << "' in: " << r.err;
    EXPECT_NE(r.err.find(b.message), std::string::npos) << "expected '" << b.message << "' in: " << r.err;
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
  const result r = run("order " + quoted(data_dir + "/bad/off_nan.off") + " --eye 0,0,10 -o OUT.json");
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
      const result r = run("build " + quoted(mesh) + " --kernel " + kernel + " --heuristic min-split --json");
      ASSERT_EQ(r.status, 0) << r.err;
      const json j = json::parse(r.out);
      ASSERT_TRUE(j.is_object());
      for (const char* key : {"input_triangles", "degenerate_input", "fragments", "splits", "nodes", "depth"}) {
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

// --- (3) order JSON -------------------------------------------------------------------------------

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
  const bool same = mpq_equal(c, q) && mpz_cmp(mpq_numref(c), mpq_numref(q)) == 0 && mpz_cmp(mpq_denref(c), mpq_denref(q)) == 0;
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
  for (auto it = std::sregex_iterator(text.begin(), text.end(), v_array); it != std::sregex_iterator(); ++it) {
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
  const std::vector<view_case> cases{{cyclic.string(), "--eye 0.1,0.2,10", "eye", {0.1, 0.2, 10}},
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
      const auto order = vc.key == "eye" ? tree.order_from_eye(vc.where) : tree.order_for_direction(vc.where);
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
      const std::string base = "order " + quoted(mesh) + " --eye 0.3,0.2,7 --heuristic " + h + " --seed 5";
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
  const result b = run("build " + quoted(cyclic.string()) + " --heuristic naive --max-fragments 3 --json");
  EXPECT_EQ(b.status, 3);
  EXPECT_EQ(b.err.rfind("exbsp: error: ", 0), 0u) << b.err;
  EXPECT_TRUE(b.out.empty()) << b.out;
  const result o = run("order " + quoted(cyclic.string()) + " --eye 0,0,10 --heuristic naive --max-fragments 3 -o OUT.json");
  EXPECT_EQ(o.status, 3);
  EXPECT_EQ(o.err.rfind("exbsp: error: ", 0), 0u) << o.err;
  EXPECT_EQ(file_names(), std::vector<std::string>{"cyclic.off"}) << "no OUT.json, no temporary file";
  const result s = run("order " + quoted(cyclic.string()) + " --eye 0,0,10 --heuristic naive --max-fragments 3");
  EXPECT_EQ(s.status, 3);
  EXPECT_TRUE(s.out.empty()) << "nothing on standard output either";
  // A limit the tree fits in is fine.
  EXPECT_EQ(run("build " + quoted(cyclic.string()) + " --heuristic naive --max-fragments 1000").status, 0);
}

// --- (5) bad option values ------------------------------------------------------------------------

TEST_F(Cli, bad_option_values_exit_2_with_a_message_and_write_nothing) {
  const std::string mesh = quoted(data_dir + "/cube.off");
  const std::vector<std::string> bad{"order " + mesh + " --eye 1,2 -o OUT.json",
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

}  // namespace
