// SPDX-License-Identifier: LGPL-3.0-or-later
// Private: the type-erased tree behind exbsp::bsp, one implementation per kernel.
#pragma once
#include <memory>
#include <vector>

#include <exbsp/bsp/engine.h>
#include "bsp/exact_output.h"

namespace exbsp {
namespace tree_file {
class writer;
}

class bsp_impl {
 public:
  virtual ~bsp_impl() = default;
  virtual const build_stats& stats() const = 0;
  virtual kernel_id kernel() const = 0;
  virtual std::size_t fragment_count() const = 0;
  virtual fragment_d fragment(std::size_t i) const = 0;
  /// The input triangle fragment i lies in (usage_error out of range).
  virtual std::uint32_t source(std::size_t i) const = 0;
  /// Calls visit(k, axis, value) for the exact coordinates of fragment i (k, axis = 0..2).
  /// Throws usage_error for an index out of range or an inexact kernel.
  virtual void visit_exact(std::size_t i, const exact_visitor& visit) const = 0;
  virtual std::vector<std::uint32_t> order_from_eye(const vec3d& eye, bool back_to_front) const = 0;
  virtual std::vector<std::uint32_t> order_for_direction(const vec3d& d,
                                                         bool back_to_front) const = 0;
  virtual std::vector<bsp::ancestor> ancestors(std::size_t i) const = 0;
  /// Writes the body of a saved tree (tree_file.h): the common part, then the kernel's own;
  /// without `timings`, build_seconds and peak_rss_bytes are written as 0.
  virtual void write_tree(tree_file::writer& out, bool timings) const = 0;
  virtual std::size_t node_count() const = 0;
  virtual const triangle_soup& input() const = 0;
  virtual bsp_node node(std::size_t k) const = 0;
  /// bsp::inserted: a new tree, this one untouched (tree_insert.h).
  virtual std::unique_ptr<bsp_impl> inserted(const triangle_soup& added,
                                             const insert_options& options) const = 0;
  /// The traversal for an eye point (direction = false) or a direction of projection.
  virtual void traverse(const vec3d& at, bool direction, bsp_visitor& visitor,
                        bool back_to_front) const = 0;
};

/// The library's access to a bsp's implementation (bsp is its friend).
class bsp_access {
 public:
  static const bsp_impl& impl(const bsp& tree) { return *tree.impl_; }
};

namespace detail {
/// usage_error "<function>: the eye must be finite" (engine.cpp).
void require_eye(const vec3d& eye, const char* function);
/// usage_error unless d is finite and not zero.
void require_direction(const vec3d& d, const char* function);
}  // namespace detail

}  // namespace exbsp
