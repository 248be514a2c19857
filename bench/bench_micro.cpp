// SPDX-License-Identifier: LGPL-3.0-or-later
// bench_micro: Google Benchmark micro-benchmarks of the exact core.
//
//   BM_orientation/<kind>   one orientation predicate on double input points:
//                           fast = exbsp's certified double filter (fast_orientation.h; the
//                           "undecided" answers are counted), double = Simple_cartesian<double>
//                           (inexact), epick, epeck (points built from doubles), gmpq.
//                           general: random points; coplanar: points exactly on the plane
//                           (every filter fails, the exact fallback decides).
//   BM_split_triangle/<K>   split_triangle of a straddling triangle (constructions included;
//                           Epeck also computes the exact points, as the build does).
//   BM_order_from_eye/<K>   back-to-front traversal of a built tree (random soup).
//   BM_build/<K>            a whole build of a small random soup (sampled heuristic).
// Never a timed test: the bench_smoke_micro test only runs it with --benchmark_min_time=0.01.
#include <benchmark/benchmark.h>

#include <array>
#include <vector>

#include "bsp/bsp_tree.h"
#include "bsp/geometry_cgal.h"
#include "bsp/fast_orientation.h"
#include "bsp/kernel_double.h"
#include "bsp/kernel_epeck.h"
#include "bsp/kernel_epick.h"
#include "bsp/kernel_gmpq.h"
#include "generators.h"

namespace {

using namespace exbsp;
using namespace exbsp::bench;

constexpr std::size_t point_sets = 1024;

/// point_sets sets of four double points (plane a, b, c and query p). general: uniform in the
/// unit cube; coplanar: p on the plane z = x + y with dyadic coordinates (exactly coplanar).
std::vector<std::array<vec3d, 4>> make_point_sets(bool coplanar) {
  split_mix rng(coplanar ? 7 : 3);
  std::vector<std::array<vec3d, 4>> sets(point_sets);
  for (auto& s : sets)
    for (auto& p : s) {
      if (coplanar) {
        const double x = static_cast<double>(rng.next() % 1024) / 64,
                     y = static_cast<double>(rng.next() % 1024) / 64;
        p = {x, y, x + y};
      } else {
        p = {rng.uniform(), rng.uniform(), rng.uniform()};
      }
    }
  return sets;
}

template <class K>
void bm_orientation_kernel(benchmark::State& state) {
  const auto sets = make_point_sets(state.range(0) != 0);
  std::vector<std::array<typename K::Point_3, 4>> pts(sets.size());
  for (std::size_t i = 0; i < sets.size(); ++i)
    for (int k = 0; k < 4; ++k)
      pts[i][k] = typename K::Point_3(sets[i][k][0], sets[i][k][1], sets[i][k][2]);
  const auto orientation = K().orientation_3_object();
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& p = pts[i++ % pts.size()];
    benchmark::DoNotOptimize(orientation(p[0], p[1], p[2], p[3]));
  }
  state.SetLabel(state.range(0) ? "coplanar" : "general");
}

void bm_orientation_fast(benchmark::State& state) {
  const auto sets = make_point_sets(state.range(0) != 0);
  std::vector<fast_plane> planes(sets.size());
  for (std::size_t i = 0; i < sets.size(); ++i)
    planes[i] = make_fast_plane(sets[i][0], sets[i][1], sets[i][2]);
  std::size_t i = 0, undecided = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % sets.size();
    const int s = fast_sign(planes[k], sets[k][3]);
    undecided += s == 2;
    benchmark::DoNotOptimize(s);
  }
  state.counters["undecided"] =
      benchmark::Counter(static_cast<double>(undecided), benchmark::Counter::kAvgIterations);
  state.SetLabel(state.range(0) ? "coplanar" : "general");
}

BENCHMARK(bm_orientation_fast)->Name("BM_orientation/fast")->Arg(0)->Arg(1);
BENCHMARK(bm_orientation_kernel<double_kernel>)->Name("BM_orientation/double")->Arg(0)->Arg(1);
BENCHMARK(bm_orientation_kernel<epick_kernel>)->Name("BM_orientation/epick")->Arg(0)->Arg(1);
BENCHMARK(bm_orientation_kernel<epeck_kernel>)->Name("BM_orientation/epeck")->Arg(0)->Arg(1);
BENCHMARK(bm_orientation_kernel<gmpq_kernel>)->Name("BM_orientation/gmpq")->Arg(0)->Arg(1);

/// A plane and a triangle that straddles it with no vertex on it (general position).
template <class K>
void bm_split_triangle(benchmark::State& state) {
  using P = typename K::Point_3;
  split_mix rng(11);
  struct item {
    std::array<P, 3> plane, t;
    std::array<int, 3> s;
  };
  std::vector<item> items;
  const auto orientation = K().orientation_3_object();
  while (items.size() < 256) {
    std::array<P, 3> plane, t;
    for (auto& p : plane) p = P(rng.uniform(), rng.uniform(), rng.uniform());
    for (auto& p : t) p = P(rng.uniform(), rng.uniform(), rng.uniform());
    std::array<int, 3> s;
    for (int k = 0; k < 3; ++k)
      s[k] = static_cast<int>(orientation(plane[0], plane[1], plane[2], t[k]));
    if (geom::classify_signs(s) == geom::classification::straddling && s[0] && s[1] && s[2])
      items.push_back({plane, t, s});
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const item& it = items[i++ % items.size()];
    benchmark::DoNotOptimize(split_triangle<K>(it.plane, it.t, it.s));
  }
}
BENCHMARK(bm_split_triangle<double_kernel>)->Name("BM_split_triangle/double");
BENCHMARK(bm_split_triangle<epick_kernel>)->Name("BM_split_triangle/epick");
BENCHMARK(bm_split_triangle<epeck_kernel>)->Name("BM_split_triangle/epeck");
BENCHMARK(bm_split_triangle<gmpq_kernel>)->Name("BM_split_triangle/gmpq");

build_options micro_build_options() {
  build_options o;
  o.heuristic = "sampled";
  o.threads = 1;
  return o;
}

template <class K>
void bm_order_from_eye(benchmark::State& state) {
  const triangle_soup soup = make_random_soup(static_cast<std::size_t>(state.range(0)), 1);
  const bsp_tree<K> tree(soup, micro_build_options());
  const bounds b = soup_bounds(soup);
  const vec3d c = b.centre();
  std::size_t i = 0;
  for (auto _ : state) {
    const double t = static_cast<double>(i++ % 16);
    const typename K::Point_3 eye(c[0] + 3 * b.diagonal(), c[1] + t, c[2] - t);
    benchmark::DoNotOptimize(tree.order_from_eye(eye));
  }
  state.counters["fragments"] = static_cast<double>(tree.fragments().size());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * tree.fragments().size()));
}
BENCHMARK(bm_order_from_eye<double_kernel>)->Name("BM_order_from_eye/double")->Arg(2000);
BENCHMARK(bm_order_from_eye<epeck_kernel>)->Name("BM_order_from_eye/epeck")->Arg(2000);

template <class K>
void bm_build(benchmark::State& state) {
  const triangle_soup soup = make_random_soup(static_cast<std::size_t>(state.range(0)), 2);
  std::size_t fragments = 0;
  for (auto _ : state) {
    const bsp_tree<K> tree(soup, micro_build_options());
    fragments = tree.fragments().size();
  }
  state.counters["fragments"] = static_cast<double>(fragments);
}
BENCHMARK(bm_build<double_kernel>)
    ->Name("BM_build/double")
    ->Arg(300)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(bm_build<epick_kernel>)->Name("BM_build/epick")->Arg(300)->Unit(benchmark::kMillisecond);
BENCHMARK(bm_build<epeck_kernel>)->Name("BM_build/epeck")->Arg(300)->Unit(benchmark::kMillisecond);
BENCHMARK(bm_build<gmpq_kernel>)->Name("BM_build/gmpq")->Arg(300)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
