// SPDX-License-Identifier: LGPL-3.0-or-later
// Exact defect counts of a built tree; definitions at the top of defects.h. The checks are
// tests/support/tree_checker.h's; this file picks the large-tree options (no pairwise overlap
// test, sampled rays, fixed eyes) and turns the checker's report into counts.
#include "defects.h"

#include <algorithm>
#include <chrono>

#include "generators.h"
#include "support/tree_checker.h"

namespace exbsp::bench {
namespace {

/// Fixed eye directions (not unit: the eye is a double point, exact as it is).
constexpr double eye_directions[8][3] = {{1, 0.6, 0.3},    {-0.4, 1, -0.7},  {0.2, -0.5, 1},
                                         {-1, -0.8, -0.6}, {0.7, -1, 0.1},   {-0.3, 0.2, -1},
                                         {0.9, 0.9, -0.8}, {-0.6, -0.1, 0.9}};

}  // namespace

template <class K>
defect_report check_defects(const bsp_tree<K>& tree, const triangle_soup& soup,
                            const defect_options& options) {
  using E = exbsp_test::exact_kernel_of<K>;
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  auto last = start;
  const auto lap = [&last](double& into) {
    const auto now = clock::now();
    into = std::chrono::duration<double>(now - last).count();
    last = now;
  };
  const exbsp_test::tree_view<E> v = exbsp_test::view_of<E>(tree, soup);
  defect_report d;
  d.fragments = v.fragments.size();
  d.non_finite = v.nonfinite;
  exbsp_test::check_report r;

  exbsp_test::check_source_planes(v, r);
  d.off_plane = r.count("source_plane");
  lap(d.seconds_plane);

  std::vector<std::uint32_t> per_source(v.sources.size(), 0);
  for (std::uint32_t s : v.source) ++per_source[s];
  for (std::uint32_t n : per_source) d.split_sources += n >= 2 ? 1 : 0;
  exbsp_test::check_tiling(v, r, /*pairwise=*/false);
  d.not_tiling = r.count("tiling_area");
  lap(d.seconds_tiling);

  exbsp_test::check_node_planes(v, r);
  d.misclassified = r.count("ancestor_side");
  for (std::size_t i = 0; i < v.fragments.size(); ++i)
    if (v.finite[i]) d.ancestor_tests += v.nodes[v.node_of[i]].depth - 1;
  lap(d.seconds_classification);

  if (options.order && !v.fragments.empty()) {
    const bounds b = soup_bounds(soup);
    const std::size_t samples = kernel_traits<K>::exact ? options.exact_samples : options.samples;
    const std::size_t eyes = std::min<std::size_t>(options.eyes, 8);
    for (std::size_t k = 0; k < eyes; ++k) {
      const vec3d c = b.centre();
      const double* dir = eye_directions[k];
      const double far = 2 * b.diagonal();
      const vec3d eye{c[0] + far * dir[0], c[1] + far * dir[1], c[2] + far * dir[2]};
      const exbsp_test::viewpoint<E> vp{
          true, exbsp_test::exact_point<E>(eye), {}, "eye " + std::to_string(k)};
      const auto tally =
          exbsp_test::check_order_along_rays(v, vp, exbsp_test::tree_order(tree, vp), samples, r);
      ++d.eyes;
      d.order_samples += tally.rays;
      d.occluding_pairs += tally.pairs;
      d.order_errors += tally.misordered;
    }
  }
  lap(d.seconds_order);
  d.seconds = std::chrono::duration<double>(clock::now() - start).count();
  return d;
}

template defect_report check_defects<double_kernel>(const bsp_tree<double_kernel>&,
                                                    const triangle_soup&, const defect_options&);
template defect_report check_defects<epick_kernel>(const bsp_tree<epick_kernel>&,
                                                   const triangle_soup&, const defect_options&);
template defect_report check_defects<epeck_kernel>(const bsp_tree<epeck_kernel>&,
                                                   const triangle_soup&, const defect_options&);

}  // namespace exbsp::bench
