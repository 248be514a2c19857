// SPDX-License-Identifier: LGPL-3.0-or-later
// Saved trees (bsp::save / load, docs/tree-file.md): round trips give the same tree (stats,
// fragments, exact coordinates, ancestors, byte-identical orders and a byte-identical re-save)
// for every kernel; every damaged or forged file is an input_error naming the file, never a
// crash or a huge allocation; the command line's build --save and order/build of a .exbsp.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <boost/crc.hpp>
#include <nlohmann/json.hpp>

#include <cstring>
#include <filesystem>
#include <cmath>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/core/errors.h>
#include <exbsp/mesh/mesh_io.h>
#include "support/cli_support.h"
#include "support/generators.h"
#include "support/inputs.h"
#include "support/test_helpers.h"

namespace {

using exbsp::bsp;
using exbsp::kernel_id;
using exbsp_test::soup_case;
using exbsp_test::tri_d;

const std::vector<kernel_id> all_kernels{kernel_id::exact, kernel_id::epeck, kernel_id::gmpq,
                                         kernel_id::epick, kernel_id::double_};

bsp build(const exbsp::triangle_soup& soup, kernel_id k, const std::string& heuristic = "sampled",
          std::uint64_t seed = 0) {
  exbsp::build_options o;
  o.kernel = k;
  o.heuristic = heuristic;
  o.seed = seed;
  o.threads = 1;
  return bsp::build(soup, o);
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Everything observable of two trees is equal: stats, fragments (bit for bit), exact
/// coordinates, ancestors, orders for a few eyes and directions.
void expect_same_tree(const bsp& a, const bsp& b, const std::string& what) {
  SCOPED_TRACE(what);
  const exbsp::build_stats &s = a.stats(), &t = b.stats();
  EXPECT_EQ(s.input_triangles, t.input_triangles);
  EXPECT_EQ(s.degenerate_input, t.degenerate_input);
  EXPECT_EQ(s.fragments, t.fragments);
  EXPECT_EQ(s.splits, t.splits);
  EXPECT_EQ(s.nodes, t.nodes);
  EXPECT_EQ(s.depth, t.depth);
  EXPECT_TRUE(same_bits(s.build_seconds, t.build_seconds));
  EXPECT_EQ(s.peak_rss_bytes, t.peak_rss_bytes);
  EXPECT_EQ(s.kernel, t.kernel);
  EXPECT_EQ(s.heuristic, t.heuristic);
  EXPECT_EQ(s.seed, t.seed);
  EXPECT_EQ(a.kernel(), b.kernel());
  ASSERT_EQ(a.fragment_count(), b.fragment_count());
  const auto fa = a.fragments_double(), fb = b.fragments_double();
  for (std::size_t i = 0; i < fa.size(); ++i) {
    EXPECT_EQ(fa[i].face, fb[i].face) << "fragment " << i;
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j)
        EXPECT_TRUE(same_bits(fa[i].v[k][j], fb[i].v[k][j])) << "fragment " << i;
    if (exbsp::is_exact(a.kernel())) {
      EXPECT_EQ(a.fragment_exact(i), b.fragment_exact(i)) << "fragment " << i;
    }
    const auto aa = a.ancestors(i), ab = b.ancestors(i);
    ASSERT_EQ(aa.size(), ab.size()) << "fragment " << i;
    for (std::size_t k = 0; k < aa.size(); ++k) {
      EXPECT_EQ(aa[k].plane_face, ab[k].plane_face);
      EXPECT_EQ(aa[k].side, ab[k].side);
    }
  }
  for (const exbsp::vec3d& e :
       {exbsp::vec3d{3, 4, 5}, exbsp::vec3d{-2, 0.5, 1}, exbsp::vec3d{0, 0, 0}}) {
    EXPECT_EQ(a.order_from_eye(e), b.order_from_eye(e));
    EXPECT_EQ(a.order_from_eye(e, false), b.order_from_eye(e, false));
    EXPECT_EQ(a.order_for_direction(e == exbsp::vec3d{0, 0, 0} ? exbsp::vec3d{0, 0, 1} : e),
              b.order_for_direction(e == exbsp::vec3d{0, 0, 0} ? exbsp::vec3d{0, 0, 1} : e));
  }
}

/// Round trip in memory: the loaded tree equals the built one and saves to the same bytes.
void check_round_trip(const bsp& tree, const std::string& what) {
  const std::string bytes = tree.serialize();
  const bsp back = bsp::deserialize(bytes, "memory.exbsp");
  expect_same_tree(tree, back, what);
  EXPECT_EQ(back.serialize(), bytes) << what << ": a loaded tree saves to the same bytes";
}

std::uint32_t crc32_of(const std::string& bytes, std::size_t n) {
  boost::crc_32_type crc;
  crc.process_bytes(bytes.data(), n);
  return crc.checksum();
}

/// Recomputes the trailing CRC-32, as a forger would (tests the checks behind the checksum).
void fix_crc(std::string& bytes) {
  const std::uint32_t c = crc32_of(bytes, bytes.size() - 4);
  for (int i = 0; i < 4; ++i)
    bytes[bytes.size() - 4 + i] = static_cast<char>((c >> (8 * i)) & 0xff);
}

void put_u32(std::string& bytes, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<char>((v >> (8 * i)) & 0xff);
}
void put_u64(std::string& bytes, std::size_t at, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) bytes[at + i] = static_cast<char>((v >> (8 * i)) & 0xff);
}
std::uint64_t get_u64(const std::string& bytes, std::size_t at) {
  std::uint64_t v = 0;
  for (int i = 0; i < 8; ++i)
    v |= std::uint64_t{static_cast<unsigned char>(bytes[at + i])} << (8 * i);
  return v;
}

/// Offsets of the count fields of an exact-kernel file (docs/tree-file.md).
struct exact_layout {
  std::size_t vertices, triangles, points, fragments, nodes;
  std::size_t first_point, first_node;
};
exact_layout layout_of(const std::string& b) {
  exact_layout l{};
  const std::size_t heuristic = 24 + 8 * 9;
  const std::size_t name_length = static_cast<std::size_t>(get_u64(b, heuristic) & 0xffffffffu);
  l.vertices = heuristic + 4 + name_length + 16;
  l.triangles = l.vertices + 8 + 24 * get_u64(b, l.vertices);
  l.points = l.triangles + 8 + 16 * get_u64(b, l.triangles);
  l.first_point = l.points + 8;
  l.fragments = l.first_point + 12 * get_u64(b, l.points);
  l.nodes = l.fragments + 8 + 16 * get_u64(b, l.fragments);
  l.first_node = l.nodes + 8;
  return l;
}

/// The load must fail with an input_error naming the file and containing `needle`.
void expect_rejected(const std::string& bytes, const std::string& needle, const std::string& what) {
  try {
    (void)bsp::deserialize(bytes, "bad.exbsp");
    ADD_FAILURE() << what << ": accepted";
  } catch (const exbsp::input_error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("bad.exbsp: ", 0), 0u) << what << ": " << message;
    EXPECT_NE(message.find(needle), std::string::npos) << what << ": " << message;
  }
}

/// Uses every query of a tree that loaded from a mutated file: none may crash.
void exercise(const bsp& t) {
  (void)t.fragments_double();
  for (std::size_t i = 0; i < t.fragment_count(); ++i) {
    if (exbsp::is_exact(t.kernel())) (void)t.fragment_exact(i);
    (void)t.ancestors(i);
  }
  (void)t.order_from_eye({3, 4, 5});
  (void)t.order_for_direction({1, -1, 2});
  (void)t.serialize();
}

/// A small soup whose trees have splits: two crossing quads and a slanted triangle.
exbsp::triangle_soup crossing_soup() {
  exbsp::triangle_soup s;
  s.add_triangle({-1, -1, 0}, {1, -1, 0}, {1, 1, 0});
  s.add_triangle({-1, -1, 0}, {1, 1, 0}, {-1, 1, 0});
  s.add_triangle({0, -1, -1}, {0, 1, -1}, {0, 1, 1});
  s.add_triangle({0, -1, -1}, {0, 1, 1}, {0, -1, 1});
  s.add_triangle({-1, 0, -1}, {1, 0.25, 1}, {0.5, 0, 0.75});
  s.add_triangle({0, 0, 0}, {1, 1, 1}, {2, 2, 2});  // degenerate: skipped and counted
  return s;
}

// ---- Degenerate trees first ------------------------------------------------------------------

TEST(TreeFile, an_empty_soup_round_trips_for_every_kernel) {
  for (kernel_id k : all_kernels) {
    const bsp tree = build(exbsp::triangle_soup{}, k);
    check_round_trip(tree, exbsp::to_string(k));
    EXPECT_EQ(bsp::deserialize(tree.serialize(), "e.exbsp").fragment_count(), 0u);
  }
}

TEST(TreeFile, a_soup_of_degenerate_triangles_keeps_its_count) {
  exbsp::triangle_soup s;
  s.add_triangle({0, 0, 0}, {1, 1, 1}, {2, 2, 2});
  s.add_triangle({0, 0, 0}, {0, 0, 0}, {0, 0, 0});
  for (kernel_id k : all_kernels) {
    const bsp back = bsp::deserialize(build(s, k).serialize(), "d.exbsp");
    EXPECT_EQ(back.stats().degenerate_input, 2u);
    EXPECT_EQ(back.fragment_count(), 0u);
  }
}

TEST(TreeFile, one_triangle_round_trips_for_every_kernel) {
  exbsp::triangle_soup s;
  s.add_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  for (kernel_id k : all_kernels) check_round_trip(build(s, k), exbsp::to_string(k));
}

TEST(TreeFile, a_soup_with_splits_round_trips_for_every_kernel_heuristic_and_seed) {
  for (kernel_id k : all_kernels)
    for (const std::string& h : exbsp::heuristic_names())
      for (std::uint64_t seed : {0u, 7u}) {
        const bsp tree = build(crossing_soup(), k, h, seed);
        ASSERT_GT(tree.stats().splits, 0u);
        check_round_trip(tree, exbsp::to_string(k) + " " + h + " seed " + std::to_string(seed));
      }
}

TEST(TreeFile, a_tree_built_without_keep_input_is_the_same_tree_but_cannot_be_saved) {
  for (kernel_id k : all_kernels) {
    SCOPED_TRACE(exbsp::to_string(k));
    exbsp::build_options with, without;
    with.kernel = without.kernel = k;
    without.keep_input = false;
    const bsp a = bsp::build(crossing_soup(), with), b = bsp::build(crossing_soup(), without);
    ASSERT_EQ(a.fragment_count(), b.fragment_count());
    for (std::size_t i = 0; i < a.fragment_count(); ++i) {
      EXPECT_EQ(a.fragment(i).face, b.fragment(i).face);
      EXPECT_EQ(a.fragment(i).v, b.fragment(i).v);
    }
    EXPECT_EQ(a.order_from_eye({3, -5, 7}), b.order_from_eye({3, -5, 7}));
    EXPECT_EQ(a.node_count(), b.node_count());
    EXPECT_THROW(b.serialize(), exbsp::usage_error);
    EXPECT_THROW(b.input(), exbsp::usage_error);
    const std::string path = (std::filesystem::temp_directory_path() / "keep_input.exbsp").string();
    std::filesystem::remove(path);
    EXPECT_THROW(b.save(path), exbsp::usage_error);
    EXPECT_FALSE(std::filesystem::exists(path)) << "no partial file";
    EXPECT_NO_THROW(a.serialize());
    EXPECT_EQ(a.input().triangles.size(), crossing_soup().triangles.size());
  }
}

TEST(TreeFile, the_sampled_parameters_and_the_seed_are_kept) {
  exbsp::build_options o;
  o.heuristic = "random";
  o.seed = 123456789012345ULL;
  o.sampled_candidates = 3;
  const bsp tree = bsp::build(crossing_soup(), o);
  const std::string bytes = tree.serialize();
  EXPECT_EQ(bsp::deserialize(bytes, "s.exbsp").stats().seed, 123456789012345ULL);
  EXPECT_EQ(bsp::deserialize(bytes, "s.exbsp").serialize(), bytes);
}

// ---- Round trips on generated soups and the corpus --------------------------------------------

RC_GTEST_PROP(TreeFile, generated_soups_round_trip_for_every_kernel, ()) {
  const soup_case c = *rc::gen::oneOf(exbsp_test::any_small_soup(), exbsp_test::cyclic_sticks());
  const kernel_id k = *rc::gen::element(kernel_id::exact, kernel_id::epeck, kernel_id::gmpq,
                                        kernel_id::epick, kernel_id::double_);
  const std::string h = *rc::gen::elementOf(exbsp::heuristic_names());
  const bsp tree = build(c.soup(), k, h, *rc::gen::inRange<std::uint64_t>(0, 1000));
  const std::string bytes = tree.serialize();
  const bsp back = bsp::deserialize(bytes, "g.exbsp");
  RC_ASSERT(back.serialize() == bytes);
  RC_ASSERT(back.fragment_count() == tree.fragment_count());
  for (const exbsp::vec3d& e : {exbsp::vec3d{3, 4, 5}, exbsp::vec3d{-7, 1, 0.5}}) {
    RC_ASSERT(back.order_from_eye(e) == tree.order_from_eye(e));
    RC_ASSERT(back.order_for_direction(e) == tree.order_for_direction(e));
  }
  const auto fa = tree.fragments_double(), fb = back.fragments_double();
  for (std::size_t i = 0; i < fa.size(); ++i) {
    RC_ASSERT(fa[i].face == fb[i].face);
    for (int v = 0; v < 3; ++v)
      for (int j = 0; j < 3; ++j) RC_ASSERT(same_bits(fa[i].v[v][j], fb[i].v[v][j]));
    if (exbsp::is_exact(k)) RC_ASSERT(tree.fragment_exact(i) == back.fragment_exact(i));
  }
}

/// A saved tree without the two measurements of its build (stats.peak_rss_bytes at bytes
/// 72..79, stats.build_seconds at 88..95: docs/tree-file.md) and the CRC that covers them.
std::string without_measurements(const std::string& bytes) {
  return bytes.substr(0, 72) + bytes.substr(80, 8) + bytes.substr(96, bytes.size() - 4 - 96);
}

TEST(TreeFile, the_same_tree_saves_to_the_same_bytes_for_any_thread_count) {
  // Threads claim point ids in blocks, in an order that depends on timing; the file numbers
  // constructed points by first use, so it must not depend on it.
  const exbsp::triangle_soup soup = exbsp_test::make_random_soup(600, 7);
  std::string one;
  for (unsigned threads : {1u, 2u, 4u, 2u, 4u}) {
    exbsp::build_options o;
    o.threads = threads;
    o.parallel_min_fragments = 0;  // the subtrees in parallel even for this small input
    const std::string bytes = without_measurements(bsp::build(soup, o).serialize());
    if (one.empty()) {
      one = bytes;
      ASSERT_GT(bsp::build(soup, o).stats().splits, 100u) << "the soup must make split points";
    } else {
      EXPECT_EQ(bytes, one) << threads << " threads";
    }
  }
}

TEST(TreeFile, corpus_meshes_round_trip_with_the_exact_kernel) {
  for (const char* name : {"fandisk.off", "anchor.off", "couplingdown.off", "cross.off"}) {
    const std::string path = exbsp_test::corpus_dir() + name;
    EXBSP_NEED_CORPUS(std::filesystem::exists(path), path);
    check_round_trip(build(exbsp::read_mesh(path), kernel_id::exact), name);
  }
}

TEST(TreeFile, a_corpus_mesh_round_trips_with_the_cgal_kernels) {
  const std::string path = exbsp_test::corpus_dir() + "cross.off";
  EXBSP_NEED_CORPUS(std::filesystem::exists(path), path);
  const exbsp::triangle_soup soup = exbsp::read_mesh(path);
  for (kernel_id k : all_kernels) check_round_trip(build(soup, k), exbsp::to_string(k));
}

// ---- Damaged files ----------------------------------------------------------------------------

TEST(TreeFile, every_truncation_is_an_input_error_naming_the_file) {
  for (kernel_id k : {kernel_id::exact, kernel_id::epeck}) {
    const std::string bytes = build(crossing_soup(), k).serialize();
    for (std::size_t n = 0; n < bytes.size(); ++n) {
      try {
        (void)bsp::deserialize(bytes.substr(0, n), "cut.exbsp");
        ADD_FAILURE() << "accepted the first " << n << " bytes";
      } catch (const exbsp::input_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("cut.exbsp: ", 0), 0u) << e.what();
      }
    }
  }
}

TEST(TreeFile, every_single_bit_flip_is_caught_by_the_checksum_or_the_header_checks) {
  const std::string bytes = build(crossing_soup(), kernel_id::exact).serialize();
  for (std::size_t i = 0; i < bytes.size(); ++i)
    for (int bit = 0; bit < 8; ++bit) {
      std::string bad = bytes;
      bad[i] = static_cast<char>(bad[i] ^ (1 << bit));
      EXPECT_THROW((void)bsp::deserialize(bad, "flip.exbsp"), exbsp::input_error)
          << "byte " << i << " bit " << bit;
    }
}

TEST(TreeFile, bit_flips_behind_a_forged_checksum_are_rejected_or_load_a_well_formed_tree) {
  for (kernel_id k : {kernel_id::exact, kernel_id::epeck, kernel_id::double_}) {
    const std::string bytes = build(crossing_soup(), k).serialize();
    std::size_t rejected = 0, loaded = 0;
    for (std::size_t i = 24; i + 4 < bytes.size(); ++i)
      for (int bit : {0, 3, 6, 7}) {  // half the bits: the test also runs under ASan
        std::string bad = bytes;
        bad[i] = static_cast<char>(bad[i] ^ (1 << bit));
        fix_crc(bad);
        try {
          const bsp t = bsp::deserialize(bad, "forged.exbsp");
          exercise(t);
          ++loaded;
        } catch (const exbsp::input_error&) {
          ++rejected;
        }
      }
    EXPECT_GT(rejected, 0u);
    EXPECT_GT(loaded, 0u);  // e.g. a changed coordinate or build_seconds: still a well-formed tree
  }
}

TEST(TreeFile, header_damage_names_what_is_wrong) {
  const std::string bytes = build(crossing_soup(), kernel_id::exact).serialize();
  std::string b = bytes;
  b[0] = 'X';
  expect_rejected(b, "not an exbsp saved tree", "wrong magic");
  expect_rejected("OFF\n3 1 0\n", "not an exbsp saved tree", "a mesh file");
  b = bytes;
  b.replace(5, 2, "\n");  // CR LF -> LF, as a text-mode transfer does
  expect_rejected(b, "text mode", "text-mode damage");
  b = bytes;
  put_u32(b, 8, 2);
  expect_rejected(b, "format version 2 is not supported", "a newer version");
  b = bytes;
  put_u32(b, 8, 0);
  expect_rejected(b, "byte 8: version", "version 0");
  b = bytes;
  put_u32(b, 12, 9);
  expect_rejected(b, "unknown kernel code 9", "kernel code");
  expect_rejected(bytes + "x", "1 bytes of trailing data", "trailing garbage");
  expect_rejected(bytes + std::string(1000, '\0'), "trailing data", "trailing zeros");
  expect_rejected(bytes.substr(0, bytes.size() - 1), "truncated", "one byte short");
  b = bytes;
  b[100] = static_cast<char>(b[100] ^ 0x10);
  expect_rejected(b, "checksum", "a flipped bit");
  expect_rejected(std::string(), "not an exbsp saved tree", "an empty file");
}

TEST(TreeFile, forged_huge_counts_are_rejected_before_any_allocation) {
  const std::string bytes = build(crossing_soup(), kernel_id::exact).serialize();
  const exact_layout l = layout_of(bytes);
  ASSERT_EQ(get_u64(bytes, l.nodes), build(crossing_soup(), kernel_id::exact).stats().nodes);
  const std::pair<std::size_t, const char*> fields[] = {{l.vertices, "soup.vertices"},
                                                        {l.triangles, "soup.triangles"},
                                                        {l.points, "points"},
                                                        {l.fragments, "fragments"},
                                                        {l.nodes, "nodes"}};
  for (const auto& [at, name] : fields)
    for (std::uint64_t n : {std::uint64_t{1} << 62, ~std::uint64_t{0}, std::uint64_t{0xffffffff},
                            std::uint64_t{100000}}) {
      std::string b = bytes;
      put_u64(b, at, n);
      fix_crc(b);
      expect_rejected(b, name, std::string(name) + " = " + std::to_string(n));
    }
  std::string b = bytes;
  put_u32(b, 24 + 8 * 9, 0x7fffffff);  // the heuristic name's length
  fix_crc(b);
  expect_rejected(b, "stats.heuristic", "a huge name");
}

TEST(TreeFile, forged_structure_is_rejected_naming_the_field) {
  const bsp tree = build(crossing_soup(), kernel_id::exact, "naive");
  const std::string bytes = tree.serialize();
  const exact_layout l = layout_of(bytes);
  ASSERT_GE(get_u64(bytes, l.points), 1u);
  ASSERT_GE(tree.stats().nodes, 3u);
  const auto forged = [&](std::size_t at, std::uint32_t v) {
    std::string b = bytes;
    put_u32(b, at, v);
    fix_crc(b);
    return b;
  };
  const std::size_t vertices = get_u64(bytes, l.vertices);
  // Point V (the first constructed one): p, q, plane.
  expect_rejected(forged(l.first_point, static_cast<std::uint32_t>(vertices)),
                  "is not an earlier point", "self");
  expect_rejected(forged(l.first_point + 4, 0xffffffffu), "is not an earlier point",
                  "endpoint range");
  expect_rejected(forged(l.first_point + 8, 5), "degenerate triangle", "a degenerate plane");
  expect_rejected(forged(l.first_point + 8, 999), "out of range", "plane range");
  {
    std::string b = bytes;  // p = q: the segment cannot cross the plane
    std::memcpy(&b[l.first_point + 4], &b[l.first_point], 4);
    fix_crc(b);
    expect_rejected(b, "does not cross the plane", "p = q");
  }
  // Fragment 0: a point id and the source.
  expect_rejected(forged(l.fragments + 8, 1u << 30), "out of range", "fragment point");
  expect_rejected(forged(l.fragments + 8 + 12, 5), "degenerate", "fragment source");
  // Node 0 (plane, count, negative, positive) and the nodes' tree structure.
  expect_rejected(forged(l.first_node + 4, 0), "fragment count 0", "an empty node");
  expect_rejected(forged(l.first_node + 4, 1000), "fragment count", "too many fragments");
  expect_rejected(forged(l.first_node + 8, 0), "neither -1 nor a later node",
                  "the root as its own child");
  expect_rejected(forged(l.first_node + 12, 0x7fffffff), "neither -1 nor a later node",
                  "child out of range");
  {
    std::string b = bytes;  // both children the same node
    const std::int32_t negative =
        static_cast<std::int32_t>(get_u64(b, l.first_node + 8) & 0xffffffffu);
    const std::int32_t positive =
        static_cast<std::int32_t>(get_u64(b, l.first_node + 12) & 0xffffffffu);
    put_u32(b, l.first_node + 8, static_cast<std::uint32_t>(negative >= 0 ? negative : positive));
    put_u32(b, l.first_node + 12, static_cast<std::uint32_t>(negative >= 0 ? negative : positive));
    fix_crc(b);
    expect_rejected(b, "two parents", "shared child");
  }
  {
    std::string b = bytes;  // a node no one points to
    put_u32(b, l.first_node + 8, 0xffffffffu);
    put_u32(b, l.first_node + 12, 0xffffffffu);
    fix_crc(b);
    expect_rejected(b, "not a child of an earlier node", "orphans");
  }
  // The stats must describe the tree.
  {
    std::string b = bytes;
    put_u64(b, 24 + 8 * 2, get_u64(b, 24 + 8 * 2) + 1);
    fix_crc(b);
    expect_rejected(b, "stats.fragments", "fragment count");
    b = bytes;
    put_u64(b, 24 + 8 * 5, 1);
    fix_crc(b);
    expect_rejected(b, "stats.depth", "depth");
  }
}

TEST(TreeFile, forged_rationals_must_be_canonical) {
  const std::string bytes = build(crossing_soup(), kernel_id::gmpq).serialize();
  // The first coordinate of fragment 0: after the fragments count and the source.
  const exact_layout l = layout_of(bytes);  // valid up to the points field, which gmpq files lack
  const std::size_t first = l.points + 8 + 4;
  const auto numerator = static_cast<std::uint32_t>(get_u64(bytes, first) & 0xffffffffu);
  ASSERT_LT(numerator & 0x7fffffffu, 64u);
  const std::size_t denominator = first + 4 + (numerator & 0x7fffffffu);
  std::string b = bytes;
  put_u32(b, denominator, 0);  // a zero denominator (length 0)
  b.erase(denominator + 4, get_u64(bytes, denominator) & 0xffffffffu);
  put_u64(b, 16, b.size() - 28);
  fix_crc(b);
  expect_rejected(b, "zero denominator", "q = 0");
}

TEST(TreeFile, forged_nested_split_points_cost_time_and_memory_bounded_by_the_file) {
  // Small slanted triangles whose planes cross the x axis near x = t_k, far apart from each
  // other's planes (the tree splits nothing, so its file has no constructed point), then a
  // forged chain of points on the x axis: c_0 and c_1 input vertices at x = -1 and x = 1,
  // c_k = SEG(c_{k-1}, c_{k-2}, plane of triangle k), t_k the midpoint of t_{k-1} and t_{k-2}.
  // Every check of the loader passes (each segment crosses its plane, the file is canonical),
  // but each exact value is about twice the size of the one before (the planes' coefficients
  // are not powers of two): 40 levels ask for 2^40 times a point's size. The loaded tree must
  // refuse, quickly, once its exact values outgrow the budget of a file of its size.
  constexpr int levels = 40;
  exbsp::triangle_soup s;
  const double tiny = 1.0 / 1024;
  s.add_triangle({-1, 0, 0}, {-1, tiny, 0}, {-1, 0, tiny});  // c_0: vertex 0
  s.add_triangle({1, 0, 0}, {1, tiny, 0}, {1, 0, tiny});     // c_1: vertex 3
  std::vector<double> t{-1, 1};
  for (int k = 2; k < levels + 2; ++k) {
    t.push_back((t[k - 1] + t[k - 2]) / 2);
    const double e = std::ldexp(1.0, -(k + 3));  // far below the spacing 2^-(k-2) of the t's
    // Triangle k: the plane x = t_k + y / 2 + (z - e) / 10.
    s.add_triangle({t[k], 0, e}, {t[k] + 0.3 * e, e, -e}, {t[k] - 0.7 * e, -e, -e});
  }
  std::string b = build(s, kernel_id::exact, "naive").serialize();
  const exact_layout l = layout_of(b);
  ASSERT_EQ(get_u64(b, l.points), 0u) << "parallel triangles: no split point";
  const auto vertices = static_cast<std::uint32_t>(get_u64(b, l.vertices));
  const auto id_of = [&](int k) {
    return k == 0 ? 0u : k == 1 ? 3u : vertices + static_cast<std::uint32_t>(k - 2);
  };
  std::string points(12 * levels, '\0');
  for (int k = 2; k < levels + 2; ++k) {
    const std::size_t at = 12 * static_cast<std::size_t>(k - 2);
    put_u32(points, at, id_of(k - 1));
    put_u32(points, at + 4, id_of(k - 2));
    put_u32(points, at + 8, static_cast<std::uint32_t>(k));
  }
  b.insert(l.first_point, points);
  put_u64(b, l.points, levels);
  put_u32(b, l.fragments + points.size() + 8, id_of(levels + 1));  // fragment 0's first corner
  put_u64(b, 16, b.size() - 28);
  fix_crc(b);
  try {
    // Refused while loading (the loader's exact checks) or when the value is asked for.
    const bsp loaded = bsp::deserialize(b, "nested.exbsp");
    (void)loaded.fragment_exact(0);
    ADD_FAILURE() << "the nested point's exact value was made";
  } catch (const exbsp::input_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("nested.exbsp: ", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("nest so deeply"), std::string::npos) << e.what();
  }
}

// ---- Files -------------------------------------------------------------------------------------

class TreeFileCli : public exbsp_test::cli_fixture {};

TEST_F(TreeFileCli, save_and_load_through_files) {
  const bsp tree = build(crossing_soup(), kernel_id::exact);
  const std::string path = (dir / "t.exbsp").string();
  tree.save(path);
  EXPECT_TRUE(bsp::is_saved_tree(path));
  const std::string renamed = (dir / "t.bin").string();
  std::filesystem::rename(path, renamed);
  EXPECT_TRUE(bsp::is_saved_tree(renamed)) << "by its magic";
  EXPECT_FALSE(bsp::is_saved_tree((dir / "missing.off").string()));
  expect_same_tree(tree, bsp::load(renamed), "file");
  EXPECT_THROW((void)bsp::load((dir / "missing.exbsp").string()), exbsp::input_error);
  EXPECT_THROW(tree.save((dir / "no/such/dir/t.exbsp").string()), exbsp::output_error);
}

TEST_F(TreeFileCli, build_save_then_order_and_build_of_the_tree_match_the_mesh) {
  write("m.off", exbsp_test::off_text(crossing_soup()));
  auto r = run("build m.off --heuristic min-split --seed 3 --save t.exbsp --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto built = nlohmann::json::parse(r.out);
  r = run("build t.exbsp --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto loaded = nlohmann::json::parse(r.out);
  for (const char* key : {"input_triangles", "degenerate_input", "fragments", "splits", "nodes",
                          "depth", "build_seconds", "kernel", "heuristic", "seed"})
    EXPECT_EQ(built[key], loaded[key]) << key;
  EXPECT_TRUE(loaded.contains("load_seconds"));
  for (const char* view : {"--eye 3,4,5", "--eye 0,0,0", "--direction 1,-2,0.5"}) {
    const auto a = run(std::string("order m.off --heuristic min-split --seed 3 ") + view);
    const auto b = run(std::string("order t.exbsp ") + view);
    ASSERT_EQ(b.status, 0) << b.err;
    EXPECT_EQ(a.out, b.out) << view << ": byte-identical order";
  }
  // Options that repeat the saved tree's are accepted; others cannot change it.
  EXPECT_EQ(run("order t.exbsp --kernel exact --heuristic min-split --seed 3 --eye 1,1,1").status,
            0);
  r = run("order t.exbsp --kernel epeck --eye 1,1,1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("t.exbsp is a saved tree built with --kernel exact"), std::string::npos)
      << r.err;
  r = run("build t.exbsp --seed 4");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--seed"), std::string::npos) << r.err;
  // A saved tree saves again to the same bytes.
  ASSERT_EQ(run("build t.exbsp --save u.exbsp").status, 0);
  EXPECT_EQ(exbsp_test::read_file(dir / "t.exbsp"), exbsp_test::read_file(dir / "u.exbsp"));
}

TEST_F(TreeFileCli, a_damaged_tree_exits_2_naming_the_file_and_writes_nothing) {
  write("m.off", exbsp_test::off_text(crossing_soup()));
  ASSERT_EQ(run("build m.off --save t.exbsp").status, 0);
  std::string bytes = exbsp_test::read_file(dir / "t.exbsp");
  write("cut.exbsp", bytes.substr(0, bytes.size() / 2));
  bytes[bytes.size() / 2] ^= 0x20;
  write("flip.exbsp", bytes);
  for (const char* name : {"cut.exbsp", "flip.exbsp"}) {
    const auto r = run(std::string("order ") + name + " --eye 1,2,3 -o out.json");
    EXPECT_EQ(r.status, 2) << name;
    EXPECT_NE(r.err.find(std::string("exbsp: error: ") + name + ": "), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.json"));
  }
  const auto r = run("build m.off --save no/such/dir/t.exbsp");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("no/such/dir/t.exbsp"), std::string::npos) << r.err;
}

}  // namespace
