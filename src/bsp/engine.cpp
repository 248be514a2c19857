// SPDX-License-Identifier: LGPL-3.0-or-later
// exbsp::bsp facade: kernel dispatch, names, and the kernel-independent helpers.
#include <exbsp/bsp/engine.h>
#include "bsp/parallel.h"

#include <cmath>

#include <exbsp/core/errors.h>
#include "bsp/bsp_impl.h"
#include "bsp/bsp_tree.h"
#include "bsp/exact_output.h"
#include "bsp/heuristic_table.h"
#include "bsp/heuristics.h"
#include "bsp/kernels.h"

namespace exbsp {

// Kernel names, parsing and exactness: kernels.cpp (the kernel table).

// Heuristic names and the choice of a chooser: heuristic_table.cpp.

unsigned max_build_threads() { return static_cast<unsigned>(detail::team_limit()); }

bsp bsp::build(const triangle_soup& soup, const build_options& options) {
  build_options scored;
  detail::heuristic_for(options, scored);  // fail fast on a bad name
  if (options.threads > max_build_threads())
    throw usage_error("threads: " + std::to_string(options.threads) +
                      " is out of range (0 for all cores, or 1.." +
                      std::to_string(max_build_threads()) + ")");
  return bsp(kernel_row_of(options.kernel).make(soup, options));
}

bsp bsp::inserted(const triangle_soup& added, const insert_options& options) const {
  return bsp(impl_->inserted(added, options));
}

void bsp::insert(const triangle_soup& added, const insert_options& options) {
  *this = inserted(added, options);
}

bsp::bsp(std::unique_ptr<bsp_impl> impl) : impl_(std::move(impl)) {}
bsp::bsp(const bsp&) noexcept = default;
bsp& bsp::operator=(const bsp&) noexcept = default;
bsp::bsp(bsp&&) noexcept = default;
bsp& bsp::operator=(bsp&&) noexcept = default;
bsp::~bsp() = default;

const build_stats& bsp::stats() const { return impl_->stats(); }
const triangle_soup& bsp::input() const { return impl_->input(); }
kernel_id bsp::kernel() const { return impl_->kernel(); }
std::size_t bsp::fragment_count() const { return impl_->fragment_count(); }
fragment_d bsp::fragment(std::size_t i) const { return impl_->fragment(i); }
std::uint32_t bsp::fragment_source(std::size_t i) const { return impl_->source(i); }

std::vector<fragment_d> bsp::fragments_double() const {
  std::vector<fragment_d> out;
  out.reserve(fragment_count());
  for (std::size_t i = 0; i < fragment_count(); ++i) out.push_back(impl_->fragment(i));
  return out;
}

exact_triangle bsp::fragment_exact(std::size_t i) const {
  return exact_text([&](const exact_visitor& visit) { impl_->visit_exact(i, visit); });
}

namespace detail {
void require_eye(const vec3d& eye, const char* function) {
  for (double x : eye)
    if (!std::isfinite(x)) throw usage_error(std::string(function) + ": the eye must be finite");
}

void require_direction(const vec3d& d, const char* function) {
  for (double x : d)
    if (!std::isfinite(x))
      throw usage_error(std::string(function) + ": the direction must be finite");
  if (d[0] == 0 && d[1] == 0 && d[2] == 0)
    throw usage_error(std::string(function) + ": the direction must not be zero");
}
}  // namespace detail

std::vector<std::uint32_t> bsp::order_from_eye(const vec3d& eye, bool back_to_front) const {
  detail::require_eye(eye, "order_from_eye");
  return impl_->order_from_eye(eye, back_to_front);
}

std::vector<std::uint32_t> bsp::order_for_direction(const vec3d& d, bool back_to_front) const {
  detail::require_direction(d, "order_for_direction");
  return impl_->order_for_direction(d, back_to_front);
}

std::vector<bsp::ancestor> bsp::ancestors(std::size_t i) const { return impl_->ancestors(i); }

}  // namespace exbsp
