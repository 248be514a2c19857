// SPDX-License-Identifier: LGPL-3.0-or-later
// The exact build's batched side tests (src/bsp/batch_classify.h, fast_orientation.h): the
// static plane filter and the box filter on points built to sit exactly on a plane and one ulp
// off it (they may only say "not known" there, never a wrong sign), the learnt coplanar
// classes, and the tree they build on a stack where whole blocks move at once.
#include <gtest/gtest.h>

#include <array>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include <exbsp/bsp/engine.h>
#include "bsp/batch_classify.h"
#include "bsp/kernel_gmpq.h"

namespace {

using exbsp::vec3d;

/// Exact orientation of d against the plane (a, b, c), in rationals.
int exact_orientation(const vec3d& a, const vec3d& b, const vec3d& c, const vec3d& d) {
  using GK = exbsp::gmpq_kernel;
  const auto P = [](const vec3d& v) { return GK::Point_3(v[0], v[1], v[2]); };
  return static_cast<int>(CGAL::orientation(P(a), P(b), P(c), P(d)));
}

// A tilted plane through three points with inexact coordinates, and points on a line across
// it: exactly on it (a vertex and a dyadic point of the plane), and one ulp either side.
const vec3d pa{0.1, 0.2, 0.3}, pb{1.7, -0.4, 0.9}, pc{-0.6, 1.3, 2.1};

TEST(BatchClassify, static_filter_is_silent_on_the_plane_and_right_one_ulp_off) {
  const exbsp::fast_plane plane = exbsp::make_fast_plane(pa, pb, pc);
  const exbsp::static_plane sp = exbsp::make_static_plane(plane, {-2, -2, -2}, {3, 3, 3});
  ASSERT_TRUE(sp.valid);
  // On the plane: the vertices; must not be certified as either side.
  for (const vec3d& v : {pa, pb, pc}) EXPECT_EQ(exbsp::static_sign(sp, v, 0), 0);
  int certified = 0;
  for (const vec3d& base : {pa, pb, pc, vec3d{0.5, 0.5, 1.0}, vec3d{-1.5, 2.5, -0.25}})
    for (int k = 0; k < 3; ++k)
      for (const double toward : {-1e300, 1e300})
        for (int steps : {1, 2, 1000, 1000000}) {
          vec3d p = base;
          for (int s = 0; s < steps && s < 4; ++s) p[k] = std::nextafter(p[k], toward);
          if (steps > 4) p[k] += (toward > 0 ? 1 : -1) * steps * 1e-12;
          const int exact = exact_orientation(pa, pb, pc, p);
          const int s = exbsp::static_sign(sp, p, 0);
          if (s != 0) {
            EXPECT_EQ(s, exact) << k << " " << steps;
            ++certified;
          }
        }
  EXPECT_GT(certified, 0);  // far enough off, the filter answers
  // A point far off: certified, also with a radius, which must widen the bound.
  const vec3d far{2.5, 2.5, 2.5};
  const int exact = exact_orientation(pa, pb, pc, far);
  EXPECT_EQ(exbsp::static_sign(sp, far, 0), exact);
  EXPECT_EQ(exbsp::static_sign(sp, far, 1e3), 0);
}

TEST(BatchClassify, box_filter_never_certifies_a_box_that_touches_or_crosses_the_plane) {
  const exbsp::fast_plane plane = exbsp::make_fast_plane(pa, pb, pc);
  // A box around a vertex of the plane, one as thin as a point, one just beside it.
  EXPECT_EQ(exbsp::fast_box_sign(plane, pa, pa, 0), 0);
  EXPECT_EQ(exbsp::fast_box_sign(plane, {0, 0, 0}, {0.2, 0.4, 0.6}, 0), 0);
  // A box off the plane: its sign is every corner's exact sign.
  const vec3d lo{2, 2, 2}, hi{2.5, 2.25, 3};
  const int s = exbsp::fast_box_sign(plane, lo, hi, 0);
  ASSERT_NE(s, 0);
  for (int corner = 0; corner < 8; ++corner) {
    const vec3d p{corner & 1 ? hi[0] : lo[0], corner & 2 ? hi[1] : lo[1],
                  corner & 4 ? hi[2] : lo[2]};
    EXPECT_EQ(exact_orientation(pa, pb, pc, p), s) << corner;
  }
  // A radius that reaches the plane makes it unknown.
  EXPECT_EQ(exbsp::fast_box_sign(plane, lo, hi, 10), 0);
}

TEST(BatchClassify, coplanar_classes_join_transitively_and_start_empty) {
  exbsp::detail::coplanar_sources classes;
  EXPECT_FALSE(classes.same(1, 2));
  EXPECT_NE(classes.root(1), classes.root(2));  // every source its own class
  const std::uint32_t root_of_1_before = classes.root(1);
  classes.join(1, 2, 6);
  classes.join(4, 2, 6);
  EXPECT_TRUE(classes.same(1, 4));
  EXPECT_TRUE(classes.same(4, 4));
  EXPECT_FALSE(classes.same(0, 1));
  EXPECT_FALSE(classes.same(3, 5));
  // Roots name the classes, and a root read before a join still names a member's class.
  EXPECT_EQ(classes.root(1), classes.root(4));
  EXPECT_EQ(classes.root(2), classes.root(4));
  EXPECT_NE(classes.root(0), classes.root(1));
  EXPECT_NE(classes.root(3), classes.root(5));
  EXPECT_TRUE(classes.same(root_of_1_before, 4));
}

TEST(BatchClassify, sign_cache_answers_right_or_unknown_and_starts_empty) {
  exbsp::detail::sign_cache cache;
  constexpr int unknown = exbsp::detail::sign_cache::unknown;
  EXPECT_EQ(cache.find(0, 0), unknown);
  EXPECT_EQ(cache.memory(), 0u);  // nothing allocated until the first answer
  // Keys that differ only in the point or only in the plane, with every sign.
  cache.insert(0, 0, -1);
  cache.insert(1, 0, 0);
  cache.insert(0, 1, 1);
  EXPECT_EQ(cache.find(0, 0), -1);
  EXPECT_EQ(cache.find(1, 0), 0);
  EXPECT_EQ(cache.find(0, 1), 1);
  EXPECT_EQ(cache.find(1, 1), unknown);
  // Ids beyond what a word packs, and the largest plane id, are never confused.
  cache.insert(1u << 29, 0, 1);
  EXPECT_EQ(cache.find(1u << 29, 0), unknown);
  cache.insert(5, ~0u, -1);
  EXPECT_EQ(cache.find(5, ~0u), -1);
  EXPECT_EQ(cache.find(5, 0), unknown);
  // Many more answers than the table holds at most: every answer it still gives is the
  // one inserted, and the most recent ones are still there.
  const auto sign_of = [](std::uint32_t id, std::uint32_t plane) {
    return static_cast<int>((std::uint64_t{id} * 2654435761u + plane) % 3) - 1;
  };
  std::size_t kept = 0;
  for (std::uint32_t id = 10; id < 40010; ++id) cache.insert(id, id % 97, sign_of(id, id % 97));
  for (std::uint32_t id = 10; id < 40010; ++id) {
    const int s = cache.find(id, id % 97);
    if (s == unknown) continue;
    EXPECT_EQ(s, sign_of(id, id % 97)) << id;
    ++kept;
  }
  EXPECT_GT(kept, 8000u);
  EXPECT_LT(kept, 40000u);  // bounded: it forgot some
  EXPECT_NE(cache.find(40009, 40009 % 97), unknown);
  EXPECT_LE(cache.memory(), 256u << 10);
}

TEST(BatchClassify, lane_masks_mark_exactly_the_all_known_fragments_and_their_side) {
  using exbsp::detail::lane_masks;
  // Every code the sampled count uses: -1, +1 known; 0 not known; 2 exactly in the plane.
  const std::int8_t codes[4] = {-1, 0, 1, 2};
  // What a fragment with codes (x, y, z) is, written out.
  const auto expect = [](int x, int y, int z, unsigned& known, unsigned& pos, unsigned& neg,
                         int j) {
    const auto is_known = [](int v) { return v == 1 || v == -1; };
    if (!is_known(x) || !is_known(y) || !is_known(z)) return;
    known |= 1u << j;
    if (x == 1 && y == 1 && z == 1) pos |= 1u << j;
    if (x == -1 && y == -1 && z == -1) neg |= 1u << j;
  };
  // All 64 code triples, 16 lanes at a time, and every length 0..16 of a partial group, with
  // the lanes beyond the length filled with known codes that must be ignored.
  std::vector<std::array<std::int8_t, 3>> triples;
  for (std::int8_t x : codes)
    for (std::int8_t y : codes)
      for (std::int8_t z : codes) triples.push_back({x, y, z});
  for (std::size_t start = 0; start < triples.size(); start += 16)
    for (std::size_t len = 0; len <= 16; ++len) {
      alignas(16) std::int8_t a[16], b[16], c[16];
      unsigned known = 0, pos = 0, neg = 0;
      for (std::size_t j = 0; j < 16; ++j) {
        const auto& t = triples[(start + j) % triples.size()];
        a[j] = j < len ? t[0] : 1;
        b[j] = j < len ? t[1] : 1;
        c[j] = j < len ? t[2] : 1;
        if (j < len) expect(t[0], t[1], t[2], known, pos, neg, static_cast<int>(j));
      }
      const lane_masks s = exbsp::detail::classify_lanes_scalar(a, b, c, len);
      EXPECT_EQ(s.known, known) << start << " " << len;
      EXPECT_EQ(s.positive, pos) << start << " " << len;
      EXPECT_EQ(s.negative, neg) << start << " " << len;
      const lane_masks v = exbsp::detail::classify_lanes(a, b, c, len);
      EXPECT_EQ(v.known, known) << start << " " << len;
      EXPECT_EQ(v.positive, pos) << start << " " << len;
      EXPECT_EQ(v.negative, neg) << start << " " << len;
      EXPECT_EQ(exbsp::detail::popcount16(known), __builtin_popcount(known));
    }
}

// A stand-in geometry for sample_batch: points of a small integer lattice (so a plane's exact
// sign is an integer determinant), each with a radius that makes the filter unsure near the
// plane, and input triangles on those points, many in the lattice's layers z = const (so
// fragments share points and lie in one another's planes).
struct lattice_geometry {
  static constexpr bool has_centres = true;
  struct fragment {
    std::array<std::uint32_t, 3> v;
    std::uint32_t source;
  };
  std::vector<vec3d> points;
  std::vector<double> radii;
  std::vector<std::array<std::uint32_t, 3>> sources;
  const vec3d& centre(std::uint32_t id) const { return points[id]; }
  double radius(std::uint32_t id) const { return radii[id]; }
  exbsp::fast_plane_core filter(std::uint32_t plane) const {
    const auto& s = sources[plane];
    return exbsp::make_fast_plane(points[s[0]], points[s[1]], points[s[2]]);
  }
  bool is_vertex_of(std::uint32_t plane, std::uint32_t id) const {
    const auto& s = sources[plane];
    return id == s[0] || id == s[1] || id == s[2];
  }
  /// The exact sign, in integers (the lattice's coordinates are small integers).
  int exact(std::uint32_t plane, std::uint32_t id) const {
    const auto& s = sources[plane];
    std::array<long long, 3> e1{}, e2{}, q{};
    for (int k = 0; k < 3; ++k) {
      e1[k] = std::llround(points[s[1]][k] - points[s[0]][k]);
      e2[k] = std::llround(points[s[2]][k] - points[s[0]][k]);
      q[k] = std::llround(points[id][k] - points[s[0]][k]);
    }
    const long long v = (e1[1] * e2[2] - e1[2] * e2[1]) * q[0] +
                        (e1[2] * e2[0] - e1[0] * e2[2]) * q[1] +
                        (e1[0] * e2[1] - e1[1] * e2[0]) * q[2];
    return (v > 0) - (v < 0);
  }
  int point_sign_of(std::uint32_t plane, const exbsp::fast_plane_core&, std::uint32_t id) const {
    return exact(plane, id);
  }
};

TEST(BatchClassify, sampled_counts_and_kept_signs_equal_the_exact_signs_point_by_point) {
  // sample_batch gathers each point once and keeps signs per point; against every candidate it
  // must count what the exact signs of each fragment's three points say, for chunks of 16
  // with the early stop of choose_sampled_counts, and the winner's kept signs must be exact.
  using G = lattice_geometry;
  std::mt19937 rng(7);
  std::size_t counted = 0, kept = 0;
  for (int round = 0; round < 300; ++round) {
    G g;
    constexpr int R = 2;  // the lattice [-2, 2]^3
    for (int x = -R; x <= R; ++x)
      for (int y = -R; y <= R; ++y)
        for (int z = -R; z <= R; ++z) {
          g.points.push_back({double(x), double(y), double(z)});
          const unsigned r = rng() % 3;  // exact, a little unsure, very unsure
          g.radii.push_back(r == 0 ? 0.0 : r == 1 ? 0.3 : 2.5);
        }
    const auto lattice = [&](int x, int y, int z) {
      return static_cast<std::uint32_t>(((x + R) * (2 * R + 1) + (y + R)) * (2 * R + 1) + (z + R));
    };
    const std::size_t wanted = 5 + rng() % 60;
    while (g.sources.size() < wanted) {
      std::array<std::uint32_t, 3> t{};
      const bool layer = rng() % 2 == 0;  // in a plane z = const, shared by many sources
      const int z = static_cast<int>(rng() % 3) - 1;
      for (auto& v : t)
        v = layer ? lattice(static_cast<int>(rng() % 5) - R, static_cast<int>(rng() % 5) - R, z)
                  : static_cast<std::uint32_t>(rng() % g.points.size());
      const vec3d &a = g.points[t[0]], &b = g.points[t[1]], &c = g.points[t[2]];
      const vec3d e1{b[0] - a[0], b[1] - a[1], b[2] - a[2]},
          e2{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
      if (e1[1] * e2[2] - e1[2] * e2[1] == 0 && e1[2] * e2[0] - e1[0] * e2[2] == 0 &&
          e1[0] * e2[1] - e1[1] * e2[0] == 0)
        continue;  // collinear: not a source
      g.sources.push_back(t);
    }
    std::vector<G::fragment> list;
    for (std::uint32_t s = 0; s < g.sources.size(); ++s) list.push_back({g.sources[s], s});
    std::shuffle(list.begin(), list.end(), rng);
    const std::size_t n = list.size();
    const std::size_t m = rng() % 3 == 0 ? n : 1 + rng() % n;  // the whole list, or a sample
    const auto entry = [&](std::size_t k) -> const G::fragment& {
      return list[k * n / m];  // heuristics.h's sample_position
    };
    exbsp::detail::sample_batch<G> sample;
    exbsp::detail::coplanar_sources classes;
    sample.gather(g, m, entry);
    const vec3d lo{-R, -R, -R}, hi{R, R, R};
    const long long weight = rng() % 10;
    long long best_score = std::numeric_limits<long long>::max();
    std::uint32_t best_plane = ~0u;
    const std::size_t candidates = 1 + rng() % std::min<std::size_t>(n, 20);
    for (std::size_t i = 0; i < candidates; ++i) {
      const std::uint32_t plane = list[i].source;
      const exbsp::fast_plane_core fp = g.filter(plane);
      const exbsp::static_plane sp = exbsp::make_static_plane(fp, lo, hi);
      exbsp::detail::side_counts got, want;
      std::size_t end = 0;
      for (std::size_t k = 0; k < m && weight * got.splits < best_score; k += 16) {
        end = std::min(m, k + 16);
        sample.count(g, plane, sp, fp, k, end, got, classes, g.sources.size());
      }
      for (std::size_t k = 0; k < end; ++k) {
        const G::fragment& f = entry(k);
        std::array<int, 3> s{};
        for (int t = 0; t < 3; ++t) s[t] = f.source == plane ? 0 : g.exact(plane, f.v[t]);
        want.add(exbsp::geom::classify_signs(s));
      }
      ASSERT_EQ(got.splits, want.splits) << round << " " << i;
      ASSERT_EQ(got.positive, want.positive) << round << " " << i;
      ASSERT_EQ(got.negative, want.negative) << round << " " << i;
      ++counted;
      const long long score = weight * got.splits + std::llabs(got.positive - got.negative);
      if (score < best_score) {
        ASSERT_EQ(end, m);  // a new best was counted over the whole sample
        best_score = score;
        best_plane = plane;
        sample.keep_best();
      }
    }
    for (std::size_t k = 0; k < m; ++k)
      for (int t = 0; t < 3; ++t) {
        const int kept_sign = sample.best_sign(k, t);
        if (kept_sign == exbsp::detail::sample_batch<G>::unknown_code) continue;
        const G::fragment& f = entry(k);
        ASSERT_EQ(kept_sign, f.source == best_plane ? 0 : g.exact(best_plane, f.v[t]))
            << round << " " << k << " " << t;
        ++kept;
      }
  }
  EXPECT_GT(counted, 1000u);
  EXPECT_GT(kept, 10000u);
}

TEST(BatchClassify, naive_on_a_stack_of_coplanar_layers_matches_gmpq) {
  // Layers of parallel triangles, several per plane (coplanar classes), in an order that
  // mixes layers so that blocks hold fragments on both sides of most planes.
  exbsp::triangle_soup soup;
  for (int i = 0; i < 300; ++i) {
    const double z = static_cast<double>((i * 37) % 50) * 0.1;
    const double x = static_cast<double>(i % 3);
    soup.add_triangle({x, 0, z}, {x + 1, 0, z + 0.01 * (i % 2)}, {x, 1, z});
  }
  for (const char* h : {"naive", "sampled"}) {
    exbsp::build_options exact, gmpq;
    exact.heuristic = gmpq.heuristic = h;
    gmpq.kernel = exbsp::kernel_id::gmpq;
    const exbsp::bsp a = exbsp::bsp::build(soup, exact);
    const exbsp::bsp b = exbsp::bsp::build(soup, gmpq);
    EXPECT_EQ(a.stats().fragments, b.stats().fragments) << h;
    EXPECT_EQ(a.stats().splits, b.stats().splits) << h;
    EXPECT_EQ(a.stats().nodes, b.stats().nodes) << h;
    EXPECT_EQ(a.stats().depth, b.stats().depth) << h;
    EXPECT_EQ(a.order_from_eye({0.3, 0.2, -2}), b.order_from_eye({0.3, 0.2, -2})) << h;
  }
}

}  // namespace
