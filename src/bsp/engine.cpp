// SPDX-License-Identifier: LGPL-3.0-or-later
// exbsp::bsp facade: kernel dispatch, names, and the kernel-independent helpers.
#include "bsp/engine.h"
#include "bsp/parallel.h"

#include <cmath>

#include "bsp/bsp_impl.h"
#include "bsp/bsp_tree.h"
#include "bsp/exact_output.h"
#include "bsp/heuristics.h"
#include "core/errors.h"

namespace exbsp {

std::string to_string(kernel_id k) {
  switch (k) {
    case kernel_id::exact:
      return "exact";
    case kernel_id::epeck:
      return "epeck";
    case kernel_id::epick:
      return "epick";
    case kernel_id::double_:
      return "double";
    case kernel_id::gmpq:
      return "gmpq";
  }
  return "unknown";
}

namespace {
constexpr kernel_id all_kernels[] = {kernel_id::exact, kernel_id::epeck, kernel_id::gmpq,
                                     kernel_id::epick, kernel_id::double_};
}  // namespace

const std::vector<std::string>& kernel_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (kernel_id k : all_kernels) out.push_back(to_string(k));
    return out;
  }();
  return names;
}

kernel_id parse_kernel(const std::string& name) {
  for (kernel_id k : all_kernels)
    if (to_string(k) == name) return k;
  throw usage_error("unknown kernel '" + name + "' (expected exact, epeck, gmpq, epick or double)");
}

bool is_exact(kernel_id k) {
  return k == kernel_id::exact || k == kernel_id::epeck || k == kernel_id::gmpq;
}

const std::vector<std::string>& heuristic_names() {
  static const std::vector<std::string> names{"naive", "min-split", "sampled", "random"};
  return names;
}

const char* default_heuristic() { return "sampled"; }

namespace detail {
heuristic_id heuristic_for(const build_options& options) {
  const auto& names = heuristic_names();
  const std::string& name = options.heuristic;
  if (name == "custom") {
    if (!options.score)
      throw usage_error("heuristic 'custom' needs a score callback (build_options::score)");
    return heuristic_custom;
  }
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) {
      if (options.score)
        throw usage_error("a score callback is set but the heuristic is '" + name +
                          "': use heuristic 'custom'");
      return static_cast<heuristic_id>(i);
    }
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  throw usage_error("unknown heuristic '" + name + "' (expected one of: " + list +
                    ", or custom with a score callback)");
}
}  // namespace detail

unsigned max_build_threads() { return static_cast<unsigned>(detail::team_limit()); }

bsp bsp::build(const triangle_soup& soup, const build_options& options) {
  detail::heuristic_for(options);  // fail fast on a bad name
  if (options.threads > max_build_threads())
    throw usage_error("threads: " + std::to_string(options.threads) +
                      " is out of range (0 for all cores, or 1.." +
                      std::to_string(max_build_threads()) + ")");
  switch (options.kernel) {
    case kernel_id::exact:
      return bsp(make_bsp_exact(soup, options));
    case kernel_id::epeck:
      return bsp(make_bsp_epeck(soup, options));
    case kernel_id::epick:
      return bsp(make_bsp_epick(soup, options));
    case kernel_id::double_:
      return bsp(make_bsp_double(soup, options));
    case kernel_id::gmpq:
      return bsp(make_bsp_gmpq(soup, options));
  }
  throw usage_error("unknown kernel");
}

bsp::bsp(std::unique_ptr<bsp_impl> impl) : impl_(std::move(impl)) {}
bsp::bsp(bsp&&) noexcept = default;
bsp& bsp::operator=(bsp&&) noexcept = default;
bsp::~bsp() = default;

const build_stats& bsp::stats() const { return impl_->stats(); }
const triangle_soup& bsp::input() const { return impl_->input(); }
kernel_id bsp::kernel() const { return impl_->kernel(); }
std::size_t bsp::fragment_count() const { return impl_->fragment_count(); }
fragment_d bsp::fragment(std::size_t i) const { return impl_->fragment(i); }

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
