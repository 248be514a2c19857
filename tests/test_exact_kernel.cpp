// SPDX-License-Identifier: LGPL-3.0-or-later
// exbsp's own exact kernel (`exact`, geometry_exact.h): its three ways of answering a side
// test each on points built to sit exactly on a plane and one ulp off it, and the contract
// that it gives the same tree and byte-identical orders as gmpq and epeck (docs/contract.md "The
// BSP") on every generator of the property suite and on the CGAL corpus.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "bsp/geometry_exact.h"
#include "bsp/packed_integers.h"
#include "support/generators.h"
#include "support/test_helpers.h"

namespace {

using namespace exbsp_test;
using exbsp::exact_geometry;
using exbsp::vec3d;

/// The geometry of `soup` with every triangle added as a source; fragments[i] for triangle i.
struct geometry_fixture {
  explicit geometry_fixture(const exbsp::triangle_soup& s) : soup(s), geom(soup) {
    for (std::uint32_t i = 0; i < soup.triangles.size(); ++i) {
      exact_geometry::fragment f{};
      EXPECT_TRUE(geom.add_source(soup, i, f));
      fragments.push_back(f);
    }
  }
  /// Splits fragment `f` by the plane of source `plane` (it must straddle it).
  std::vector<exact_geometry::fragment> split(const exact_geometry::fragment& f,
                                              std::uint32_t plane) {
    const std::array<int, 3> s{geom.sign(plane, f, 0), geom.sign(plane, f, 1),
                               geom.sign(plane, f, 2)};
    EXPECT_EQ(exbsp::geom::classify_signs(s), exbsp::geom::classification::straddling);
    const exbsp::geom::split_pattern pat = exbsp::geom::make_split_pattern(s);
    std::array<exact_geometry::fragment, 3> out;
    geom.split(plane, f, pat, out, scratch);
    return {out.begin(), out.begin() + pat.pieces};
  }
  exbsp::triangle_soup soup;
  exact_geometry geom;
  exact_geometry::scratch scratch;
  std::vector<exact_geometry::fragment> fragments;
};

/// Sign of orientation(plane triangle, point) computed with Gmpq from exact strings.
int reference_sign(const std::array<vec3d, 3>& plane, const std::array<std::string, 3>& point) {
  using GK = exbsp::gmpq_kernel;
  const auto P = [](const vec3d& v) { return GK::Point_3(v[0], v[1], v[2]); };
  const GK::Point_3 x{CGAL::Gmpq(point[0]), CGAL::Gmpq(point[1]), CGAL::Gmpq(point[2])};
  return static_cast<int>(CGAL::orientation(P(plane[0]), P(plane[1]), P(plane[2]), x));
}

// Triangle 0 (z = 0) is the fragment; triangle 1 (x = 1/4) splits it at (1/4, -1, 0) on edge
// [v0, v1] and at (1/4, 1/2, 0) on edge [v1, v2]; triangle 2 contains the edge
// [v1, v2] = [(1,-1,0), (0,1,0)] of triangle 0 but is tilted out of z = 0.
const std::array<vec3d, 3> fragment_triangle{{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}};
const std::array<vec3d, 3> cutter{{{0.25, -5, -5}, {0.25, 5, -5}, {0.25, 0, 5}}};
const std::array<vec3d, 3> through_edge{{{1, -1, 0}, {0, 1, 0}, {1, -1, 3}}};

/// The signs of the corners of `pieces` against plane 2 (the soup's third triangle, `plane`),
/// each checked against the Gmpq reference; returns how many are 0 and how many corners.
std::pair<int, int> checked_signs_on_plane_2(geometry_fixture& g,
                                             const std::vector<exact_geometry::fragment>& pieces,
                                             const std::array<vec3d, 3>& plane) {
  int zeros = 0, corners = 0;
  for (const auto& p : pieces)
    for (int k = 0; k < 3; ++k, ++corners) {
      const int s = g.geom.sign(2, p, k);
      EXPECT_EQ(s, reference_sign(plane, g.geom.to_exact(p)[static_cast<std::size_t>(k)]));
      zeros += s == 0;
    }
  return {zeros, corners};
}

/// The plane y = y0 (normal +y).
std::array<vec3d, 3> plane_y(double y0) { return {{{-5, y0, 5}, {5, y0, 5}, {0, y0, -5}}}; }

TEST(ExactKernel, a_split_point_on_its_own_plane_is_zero_without_arithmetic) {
  geometry_fixture g(soup_of({fragment_triangle, cutter}));
  const auto pieces = g.split(g.fragments[0], 1);
  int zeros = 0;
  for (const auto& p : pieces)
    for (int k = 0; k < 3; ++k) zeros += g.geom.sign(1, p, k) == 0;
  EXPECT_EQ(zeros, 5);  // A in three pieces, B in two
  EXPECT_EQ(g.geom.stats().exact.load(), 0u);
  EXPECT_GT(g.geom.stats().on_own_plane.load(), 0u);
}

TEST(ExactKernel, structural_zero_a_split_point_on_an_edge_the_plane_contains) {
  geometry_fixture g(soup_of({fragment_triangle, cutter, through_edge}));
  const auto pieces = g.split(g.fragments[0], 1);
  // The split point on the edge [(0,1,0), (-1,-1,0)] lies in plane 2: zero, and the answer came
  // from the endpoints' signs (both 0), not from arithmetic.
  EXPECT_GT(checked_signs_on_plane_2(g, pieces, through_edge).first, 0);
  EXPECT_GT(g.geom.stats().structural.load(), 0u);
  EXPECT_EQ(g.geom.stats().exact.load(), 0u);
}

TEST(ExactKernel, on_and_one_ulp_off_a_crossing_plane_the_exact_fallback_decides) {
  // The plane y = 1/2 crosses edge [v1, v2] exactly at the split point (1/4, 1/2, 0): the
  // endpoints are strictly on opposite sides, the centre is within its radius of the plane,
  // so only exact arithmetic can say 0. One ulp above or below, it must say -1 or +1.
  for (const double y0 : {0.5, std::nextafter(0.5, 1.0), std::nextafter(0.5, 0.0)}) {
    const auto plane = plane_y(y0);
    geometry_fixture g(soup_of({fragment_triangle, cutter, plane}));
    const auto pieces = g.split(g.fragments[0], 1);
    int checked = 0;
    for (const auto& p : pieces)
      for (int k = 0; k < 3; ++k) {
        const auto exact = g.geom.to_exact(p)[static_cast<std::size_t>(k)];
        if (exact[1] != "1/2") continue;  // the split point on [v1, v2]
        const int s = g.geom.sign(2, p, k);
        EXPECT_EQ(s, reference_sign(plane, exact)) << y0;
        EXPECT_EQ(s, y0 == 0.5 ? 0 : (y0 > 0.5 ? -1 : 1)) << y0;
        ++checked;
      }
    EXPECT_GT(checked, 0);
    EXPECT_GT(g.geom.stats().exact.load(), 0u) << y0;
  }
}

TEST(ExactKernel, a_split_next_to_an_endpoint_too_close_to_call_is_still_certified) {
  // One vertex of the fragment lies within the filter's error bound of the cutting plane
  // z = 0 (offsets from 1e-300 to 1e-12, above or below), the other two far on the other
  // side: the split points next to it are approximated without their exact values
  // (geometry_exact.cpp, approximate). Each split point's exact position (Gmpq) must lie
  // within its certified radius of its centre, in every coordinate, and its side of planes a
  // few ulps around it must be the exact one.
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> unit(0.05, 0.95), exponent(-300, -12);
  const std::array<vec3d, 3> z0{{{-9, -9, 0}, {9, -9, 0}, {0, 9, 0}}};
  int certified_points = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double sign = trial % 2 == 0 ? 1 : -1;
    const double near = sign * std::pow(10.0, exponent(rng));
    std::array<vec3d, 3> t{{{unit(rng), unit(rng), near},
                            {unit(rng), unit(rng), -sign * unit(rng)},
                            {unit(rng), unit(rng), -sign * unit(rng)}}};
    std::rotate(t.begin(), t.begin() + trial % 3, t.end());  // the near vertex anywhere
    const vec3d c = t[(3 - trial % 3) % 3];                  // where it went
    std::vector<std::array<vec3d, 3>> probes;
    for (int k = -2; k <= 2; ++k) {
      double x = c[0];
      for (int i = 0; i < std::abs(k); ++i) x = std::nextafter(x, k > 0 ? 2.0 : -2.0);
      probes.push_back({{{x, -5, -5}, {x, 5, -5}, {x, 0, 5}}});
    }
    for (const double z : {-1e-30, 1e-30}) probes.push_back({{{-9, -9, z}, {9, -9, z}, {0, 9, z}}});
    std::vector<std::array<vec3d, 3>> triangles{t, z0};
    triangles.insert(triangles.end(), probes.begin(), probes.end());
    geometry_fixture g(soup_of(triangles));
    for (const auto& piece : g.split(g.fragments[0], 1))
      for (int k = 0; k < 3; ++k) {
        const auto exact = g.geom.to_exact(piece)[static_cast<std::size_t>(k)];
        const std::uint32_t id = piece.v[static_cast<std::size_t>(k)];
        const vec3d& centre = g.geom.centre(id);
        const double radius = g.geom.radius(id);
        for (int i = 0; i < 3; ++i) {
          const CGAL::Gmpq off = CGAL::Gmpq(exact[static_cast<std::size_t>(i)]) -
                                 CGAL::Gmpq(centre[static_cast<std::size_t>(i)]);
          EXPECT_LE(CGAL::abs(off), CGAL::Gmpq(radius))
              << "trial " << trial << ", coordinate " << i << ": " << exact[i] << " vs centre "
              << centre[i] << " radius " << radius;
        }
        certified_points += exact[2] == "0" && radius < 1e-10;
        for (std::uint32_t j = 0; j < probes.size(); ++j)
          EXPECT_EQ(g.geom.sign(2 + j, piece, k), reference_sign(probes[j], exact))
              << "trial " << trial << ", probe " << j;
      }
  }
  EXPECT_GT(certified_points, 0);
}

TEST(ExactKernel, the_filter_answers_far_planes_without_fallback) {
  const std::array<vec3d, 3> far{{{-9, -9, 7}, {9, -9, 7}, {0, 9, 7}}};
  geometry_fixture g(soup_of({fragment_triangle, cutter, far}));
  const auto pieces = g.split(g.fragments[0], 1);
  for (const auto& p : pieces)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(g.geom.sign(2, p, k), -1);
  EXPECT_EQ(g.geom.stats().structural.load(), 0u);
  EXPECT_EQ(g.geom.stats().exact.load(), 0u);
}

TEST(ExactKernel, one_ulp_off_an_edge_the_sign_still_follows_from_the_endpoints) {
  // Plane 2 through v2 = (0,1,0) but one ulp off v1: the split point on [v1, v2] is off it
  // by about an ulp; v2 on the plane and v1 off it decide the sign with no arithmetic.
  std::array<vec3d, 3> off = through_edge;
  off[0][0] = std::nextafter(1.0, 2.0);
  off[2][0] = std::nextafter(1.0, 2.0);
  geometry_fixture g(soup_of({fragment_triangle, cutter, off}));
  const auto pieces = g.split(g.fragments[0], 1);
  const auto [zeros, corners] = checked_signs_on_plane_2(g, pieces, off);
  EXPECT_LT(zeros, corners);  // some corner is off the plane
  EXPECT_EQ(g.geom.stats().exact.load(), 0u);
}

TEST(ExactKernel, shared_split_points_are_made_once) {
  // Two triangles sharing the edge [(0,-1,0), (0,1,0)] crossed by the plane y = 0.
  // Vertex ids are shared, as in a mesh file.
  exbsp::triangle_soup s;
  s.vertices = {{0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0.5, 0}, {-5, 0, -5}, {5, 0, -5}, {0, 0, 5}};
  s.add_polygon({0, 1, 2}, 0);
  s.add_polygon({1, 0, 3}, 1);
  s.add_polygon({4, 5, 6}, 2);
  geometry_fixture g(s);
  const auto a = g.split(g.fragments[0], 2);
  const auto b = g.split(g.fragments[1], 2);
  std::set<std::uint32_t> ids_a, ids_b;
  for (const auto& f : a) ids_a.insert(f.v.begin(), f.v.end());
  for (const auto& f : b) ids_b.insert(f.v.begin(), f.v.end());
  std::vector<std::uint32_t> common;
  std::set_intersection(ids_a.begin(), ids_a.end(), ids_b.begin(), ids_b.end(),
                        std::back_inserter(common));
  EXPECT_EQ(common.size(), 3u);  // the two shared vertices and the one shared split point
}

// --- the compact representation: float radii, chunked points ---------------------------------

/// The triangles scaled by s (a power of two: exact).
std::array<vec3d, 3> scaled(std::array<vec3d, 3> t, double s) {
  for (auto& v : t)
    for (double& x : v) x *= s;
  return t;
}

TEST(ExactKernel, on_and_one_ulp_off_a_plane_at_scales_beyond_the_float_range) {
  // The same crossing as above at scales where a split point's radius underflows a float
  // (2^-140: rounded up to the smallest float), exceeds it (2^200: stored as infinity), and
  // where the input planes leave the filter's range (2^300: infinite coefficients). Every
  // sign must still be the exact one, for points and for view directions.
  for (const double scale : {std::ldexp(1.0, -140), std::ldexp(1.0, 200), std::ldexp(1.0, 300)})
    for (const double y0 : {0.5, std::nextafter(0.5, 1.0), std::nextafter(0.5, 0.0)}) {
      const auto plane = scaled(plane_y(y0), scale);
      geometry_fixture g(soup_of({scaled(fragment_triangle, scale), scaled(cutter, scale), plane,
                                  scaled(through_edge, scale)}));
      const auto pieces = g.split(g.fragments[0], 1);
      int checked = 0;
      for (const auto& p : pieces)
        for (int k = 0; k < 3; ++k) {
          const auto exact = g.geom.to_exact(p)[static_cast<std::size_t>(k)];
          const int s = g.geom.sign(2, p, k);
          EXPECT_EQ(s, reference_sign(plane, exact)) << scale << " " << y0;
          EXPECT_EQ(g.geom.sign(3, p, k), reference_sign(scaled(through_edge, scale), exact))
              << scale << " " << y0;
          checked += s == (y0 == 0.5 ? 0 : (y0 > 0.5 ? -1 : 1));
        }
      EXPECT_GT(checked, 0) << scale << " " << y0;
      // Plane 2's normal is +y (times scale^2): the direction (0, -1, 0) looks along it.
      EXPECT_EQ(g.geom.side_of_direction(2, {0, -1, 0}), 1) << scale;
      EXPECT_EQ(g.geom.side_of_direction(2, {1, 0, 0}), 0) << scale;
      EXPECT_EQ(g.geom.side_of_eye(2, {0, y0 * scale, 0}), 0) << scale;
    }
}

TEST(ExactKernel, nested_split_points_of_mixed_exponents_lie_exactly_on_their_planes) {
  // Exact values are homogeneous integers X / w with only common twos removed; an input
  // vertex whose coordinates have very different exponents (2^-1000 beside 3 and 2^900)
  // must enter exactly, and points split from split points (the diagonal pieces) must still
  // lie exactly on every plane that made them and on the fragment's own plane.
  const double tiny = std::ldexp(1.0, -1000), huge = std::ldexp(1.0, 900);
  const std::array<vec3d, 3> fragment{{{tiny, 3, -huge}, {-1, tiny, huge}, {2, -2, tiny}}};
  const std::array<vec3d, 3> cut_a{{{0.375, -5, -5}, {0.375, 5, -5}, {0.375, 0, 5}}};
  const std::array<vec3d, 3> cut_b{{{-5, 0.625, -5}, {5, 0.625, -5}, {0, 0.625, 5}}};
  const std::array<vec3d, 3> cut_c{{{-5, -5, 0.125}, {5, -5, 0.125}, {0, 5, 0.125}}};
  geometry_fixture g(soup_of({fragment, cut_a, cut_b, cut_c}));
  const std::array<std::array<vec3d, 3>, 4> planes{fragment, cut_a, cut_b, cut_c};
  std::vector<exact_geometry::fragment> pieces{g.fragments[0]};
  std::set<std::uint32_t> cut_by;  // planes that made some point of the pieces
  for (std::uint32_t plane = 1; plane <= 3; ++plane) {
    std::vector<exact_geometry::fragment> next;
    for (const auto& f : pieces) {
      const std::array<int, 3> s{g.geom.sign(plane, f, 0), g.geom.sign(plane, f, 1),
                                 g.geom.sign(plane, f, 2)};
      if (exbsp::geom::classify_signs(s) != exbsp::geom::classification::straddling) {
        next.push_back(f);
        continue;
      }
      cut_by.insert(plane);
      for (const auto& p : g.split(f, plane)) next.push_back(p);
    }
    pieces = next;
  }
  EXPECT_EQ(cut_by.size(), 3u);
  std::size_t on_cuts = 0;
  for (const auto& p : pieces)
    for (int k = 0; k < 3; ++k) {
      const auto exact = g.geom.to_exact(p)[static_cast<std::size_t>(k)];
      EXPECT_EQ(reference_sign(fragment, exact), 0) << exact[0] << " " << exact[1];
      for (std::uint32_t plane = 1; plane <= 3; ++plane) {
        const int s = reference_sign(planes[plane], exact);
        EXPECT_EQ(g.geom.sign(plane, p, k), s) << plane;
        on_cuts += s == 0;
      }
    }
  EXPECT_GT(on_cuts, 6u);
}

TEST(ExactKernel, quotient_to_double_rounds_like_the_reduced_rational) {
  // quotient_to_double(num, den) on unreduced fractions must give rational_to_double's
  // correctly rounded double: midpoints (ties to even), values near and below the smallest
  // normal double (where a double has fewer bits), signs, zero, and large common factors.
  std::vector<std::pair<mpz_class, mpz_class>> cases;
  const mpz_class two53 = mpz_class(1) << 53;
  cases.push_back({two53 + 1, 1});             // a midpoint: ties to even (down)
  cases.push_back({two53 + 3, 1});             // a midpoint: ties to even (up)
  cases.push_back({-(two53 + 1) * 6, 6});      // the same, negative and unreduced
  cases.push_back({0, 12345});                 // zero
  cases.push_back({1, mpz_class(1) << 1022});  // the smallest normal
  cases.push_back({3, mpz_class(1) << 1024});  // below it: subnormal
  cases.push_back({(mpz_class(1) << 52) + 1, mpz_class(1) << 1074});  // just below DBL_MIN
  cases.push_back({1, mpz_class(1) << 1075});  // half the smallest subnormal: ties to 0
  cases.push_back({3, mpz_class(1) << 1076});  // three quarters of it: rounds up
  cases.push_back({1, 3});
  std::mt19937_64 rng(20261124);
  for (int i = 0; i < 2000; ++i) {
    mpz_class num, den, common;
    const auto random_bits = [&](int bits) {
      mpz_class z = 0;
      for (int b = 0; b < bits; b += 64) z = (z << 64) + mpz_class(std::to_string(rng()));
      return z;
    };
    num = random_bits(64 + static_cast<int>(rng() % 2000));
    den = random_bits(64 + static_cast<int>(rng() % 2000)) + 1;
    common = random_bits(64 + static_cast<int>(rng() % 200)) + 1;
    if (rng() % 2) num = -num;
    cases.push_back({num * common, den * common});
  }
  for (const auto& [num, den] : cases) {
    mpq_class q(num, den);
    q.canonicalize();
    const double want = exbsp::geom::rational_to_double(q.get_mpq_t());
    const double got = exbsp::geom::quotient_to_double(num.get_mpz_t(), den.get_mpz_t());
    EXPECT_EQ(std::signbit(got), std::signbit(want)) << num << "/" << den;
    EXPECT_EQ(got, want) << num << "/" << den;
  }
}

TEST(ExactKernel, points_beyond_many_chunks_keep_their_values_as_the_table_grows) {
  // 8,000 separate triangles (24,000 vertices: chunks of 256 points, the chunk table
  // doubles from 16), each crossed by the plane x = 1/4: the split points fill further
  // chunks, and every earlier point keeps its exact value.
  std::vector<std::array<vec3d, 3>> tris;
  const int n = 8000;
  for (int i = 0; i < n; ++i) {
    std::array<vec3d, 3> t = fragment_triangle;
    for (auto& v : t) v[2] = i;
    tris.push_back(t);
  }
  tris.push_back(cutter);
  geometry_fixture g(soup_of(tris));
  std::vector<exact_geometry::fragment> pieces;
  for (int i = 0; i < n; ++i)
    for (const auto& p : g.split(g.fragments[static_cast<std::size_t>(i)], n)) pieces.push_back(p);
  for (std::size_t i = 0; i < pieces.size(); i += 97) {
    const auto exact = g.geom.to_exact(pieces[i]);
    for (int k = 0; k < 3; ++k) {
      const auto& x = exact[static_cast<std::size_t>(k)];
      EXPECT_EQ(x[2], std::to_string(pieces[i].source));
      EXPECT_EQ(g.geom.sign(static_cast<std::uint32_t>(n), pieces[i], k),
                reference_sign(cutter, x));
    }
  }
  EXPECT_GT(g.geom.points_memory(), std::size_t{24000 + 2 * n} * 40);
}

// --- exact = gmpq = epeck --------------------------------------------------------------------

void expect_exact_equals(exbsp::kernel_id other, const exbsp::triangle_soup& soup,
                         const std::string& h, std::uint64_t seed, const std::string& what) {
  exbsp::build_options a, b;
  a.heuristic = b.heuristic = h;
  a.seed = b.seed = seed;
  a.kernel = exbsp::kernel_id::exact;
  b.kernel = other;
  const auto eyes = eyes_for(soup);
  const std::string x = observable(exbsp::bsp::build(soup, a), eyes);
  const std::string y = observable(exbsp::bsp::build(soup, b), eyes);
  if (x == y) return;
  // Report the first line that differs, not megabytes of both.
  std::size_t line = 0, at = 0;
  while (at < x.size() && at < y.size() && x[at] == y[at]) line += x[at++] == '\n';
  const auto line_of = [&](const std::string& s) {
    const std::size_t begin = s.rfind('\n', at == 0 ? 0 : at - 1);
    const std::size_t from = begin == std::string::npos ? 0 : begin + 1;
    return s.substr(from, std::min<std::size_t>(400, s.find('\n', from) - from));
  };
  const std::string message = what + " / exact vs " + exbsp::to_string(other) + " / " + h +
                              ": line " + std::to_string(line) + "\n exact: " + line_of(x) +
                              "\n other: " + line_of(y);
  ADD_FAILURE() << message;
  RC_FAIL(message);
}

RC_GTEST_PROP(ExactKernel, equals_gmpq_and_epeck_on_every_generator_and_heuristic, ()) {
  const soup_case c =
      *rc::gen::oneOf(any_small_soup(), coplanar_stack(), vertex_on_plane(), near_coplanar(),
                      scale_disparity(), slivers(), mesh_like(), cyclic_sticks());
  const exbsp::triangle_soup soup = c.soup();
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  for (const std::string& h : exbsp::heuristic_names()) {
    expect_exact_equals(exbsp::kernel_id::gmpq, soup, h, seed, c.kind);
    expect_exact_equals(exbsp::kernel_id::epeck, soup, h, seed, c.kind);
  }
}

TEST(ExactKernel, equals_epeck_on_cad_subsets) {
  const auto files = present_cad_meshes();
  EXBSP_NEED_CORPUS(!files.empty(), "data/meshes/");
  EXPECT_TRUE(rc::check("exact equals epeck on CAD subsets", [&] {
    const soup_case c = *cad_subset(files, 150);
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    expect_exact_equals(exbsp::kernel_id::epeck, c.soup(),
                        *rc::gen::elementOf(exbsp::heuristic_names()), seed, c.kind);
  }));
}

TEST(ExactKernel, equals_epeck_and_gmpq_on_corpus_meshes) {
  // Every small corpus mesh against gmpq, larger ones against epeck (gmpq takes minutes).
  std::string missing;
  for (const char* name : {"cube.off", "tetrahedron.off", "cross.off", "pyramid.off", "joint.off",
                           "elephant.off", "fandisk.off", "cheese.off", "blade.off"}) {
    const soup_case* mesh = cad_mesh(name);
    if (!mesh) {
      missing += std::string(" data/meshes/") + name;
      continue;
    }
    const exbsp::triangle_soup soup = mesh->soup();
    if (soup.triangles.size() <= 3000)
      expect_exact_equals(exbsp::kernel_id::gmpq, soup, "sampled", 0, name);
    expect_exact_equals(exbsp::kernel_id::epeck, soup, "sampled", 0, name);
  }
  EXBSP_NEED_CORPUS(missing.empty(), missing);
}

// The memoised values and planes are kept packed (four integers in one block of limbs): each
// integer reads back as it was, whatever its sign and size, zeros and a single limb too, and
// the block holds exactly the limbs in use.
TEST(ExactKernel, packed_integers_read_back_as_they_were_stored) {
  std::mt19937_64 rng(20261127);
  gmp_randclass bits(gmp_randinit_default);
  bits.seed(20261127);
  for (int round = 0; round < 500; ++round) {
    std::array<mpz_class, 4> v;
    std::size_t limbs = 0;
    for (mpz_class& z : v) {
      switch (rng() % 5) {
        case 0:
          z = 0;
          break;
        case 1:
          z = static_cast<long>(rng() % 1000) - 500;
          break;
        default:
          z = bits.get_z_bits(static_cast<mp_bitcnt_t>(rng() % 2000));
          break;
      }
      if (rng() % 2) z = -z;
      limbs += mpz_size(z.get_mpz_t());
    }
    exbsp::detail::packed_integers packed(exbsp::detail::views_of(v[0], v[1], v[2], v[3]));
    EXPECT_EQ(packed.limb_bytes(), limbs * sizeof(mp_limb_t));
    const exbsp::detail::integer_views back = packed.views();
    for (int k = 0; k < 4; ++k) EXPECT_EQ(mpz_class(back[k]), v[static_cast<std::size_t>(k)]) << k;
    // A moved packing keeps its limbs where they were (the kernel's stores move values in).
    const exbsp::detail::packed_integers moved(std::move(packed));
    for (int k = 0; k < 4; ++k)
      EXPECT_EQ(mpz_cmp(moved.views()[k], v[static_cast<std::size_t>(k)].get_mpz_t()), 0);
  }
}

TEST(ExactKernel, is_the_default_and_identical_for_1_and_2_threads) {
  EXPECT_EQ(exbsp::build_options{}.kernel, exbsp::kernel_id::exact);
  const soup_case* mesh = cad_mesh("fandisk.off");
  EXBSP_NEED_CORPUS(mesh, "data/meshes/fandisk.off");
  exbsp::build_options o;
  o.threads = 1;
  const auto eyes = eyes_for(mesh->soup());
  const std::string one = observable(exbsp::bsp::build(mesh->soup(), o), eyes);
  o.threads = 2;
  EXPECT_EQ(one, observable(exbsp::bsp::build(mesh->soup(), o), eyes));
}

}  // namespace
