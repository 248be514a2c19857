// SPDX-License-Identifier: LGPL-3.0-or-later
// The kernel-specific implementation behind exbsp::bsp (bsp_kernel_impl<G>): the facade's
// queries, orders and saving over one basic_bsp_tree<G>, and the tree's traversals. Part of
// bsp_tree_impl.h; notation: bsp_tree.h.
#pragma once
#include "bsp/tree_build.h"  // its includes, build_context and classify

namespace exbsp {

template <class G>
std::size_t basic_bsp_tree<G>::node_of_fragment(std::size_t i) const {
  // Nodes are created in build order and append their fragments as they are created,
  // so node.first is non-decreasing with the node index.
  if (i >= fragments_.size()) throw usage_error("node_of_fragment: index out of range");
  const auto it = std::upper_bound(nodes_.begin(), nodes_.end(), i,
                                   [](std::size_t v, const node& nd) { return v < nd.first; });
  return static_cast<std::size_t>(std::prev(it) - nodes_.begin());
}

template <class G>
std::vector<std::uint32_t> basic_bsp_tree<G>::order_from_eye(const vec3d& eye,
                                                             bool back_to_front) const {
  return traverse([&](std::uint32_t plane) { return geom_.side_of_eye(plane, eye); },
                  back_to_front);
}

template <class G>
std::vector<std::uint32_t> basic_bsp_tree<G>::order_for_direction(const vec3d& d,
                                                                  bool back_to_front) const {
  return traverse([&](std::uint32_t plane) { return geom_.side_of_direction(plane, d); },
                  back_to_front);
}

/// The kernel-specific implementation behind exbsp::bsp.
template <class G>
class bsp_kernel_impl final : public bsp_impl {
 public:
  bsp_kernel_impl(const triangle_soup& soup, const build_options& options)
      : input_{{},
               0,
               options.sampled_candidates,
               options.sampled_samples,
               options.sampled_split_weight,
               options.keep_input ? soup : triangle_soup{}},
        has_input_(options.keep_input),
        tree_(soup, options) {}
  /// A saved tree (tree_file.h).
  bsp_kernel_impl(tree_file::reader& in, tree_file::common_part&& common)
      : input_(std::move(common)), tree_(input_, in) {}
  /// An insert into `old` (bsp::inserted): `soup` is old's input followed by the new
  /// triangles.
  bsp_kernel_impl(const bsp_kernel_impl& old, triangle_soup&& soup, const insert_options& options)
      : input_{{},
               0,
               old.input_.sampled_candidates,
               old.input_.sampled_samples,
               old.input_.sampled_split_weight,
               std::move(soup)},
        tree_(old.tree_, input_.soup, options, typename basic_bsp_tree<G>::inserting{}) {}
  std::unique_ptr<bsp_impl> inserted(const triangle_soup& added,
                                     const insert_options& options) const override {
    require_input("insert");
    if (tree_.stats().heuristic != "naive")
      throw usage_error("insert: the tree was built with the '" + tree_.stats().heuristic +
                        "' heuristic; only a naive tree can take new triangles (the naive "
                        "splitter, a node's first fragment, is the only one that new triangles "
                        "after the old ones cannot change: with another heuristic the result "
                        "would not be the heuristic's tree of the whole input; build it again)");
    for (std::size_t i = 0; i < added.vertices.size(); ++i)
      for (double x : added.vertices[i])
        if (!std::isfinite(x))
          throw usage_error("insert: vertex " + std::to_string(i) + " has a non-finite coordinate");
    for (std::size_t i = 0; i < added.triangles.size(); ++i)
      for (std::uint32_t v : added.triangles[i].v)
        if (v >= added.vertices.size())
          throw usage_error("insert: triangle " + std::to_string(i) + " uses vertex " +
                            std::to_string(v) + " (" + std::to_string(added.vertices.size()) +
                            " vertices)");
    triangle_soup soup = input_.soup;
    soup.append(added);
    return std::make_unique<bsp_kernel_impl<G>>(*this, std::move(soup), options);
  }
  const build_stats& stats() const override { return tree_.stats(); }
  kernel_id kernel() const override { return G::id; }
  std::size_t fragment_count() const override { return tree_.fragments().size(); }
  fragment_d fragment(std::size_t i) const override {
    if (i >= tree_.fragments().size()) throw usage_error("fragment: index out of range");
    tree_.geometry().prepare_output(tree_.fragments());
    return tree_.geometry().to_double(tree_.fragments()[i]);
  }
  std::uint32_t source(std::size_t i) const override {
    if (i >= tree_.fragments().size()) throw usage_error("fragment_source: index out of range");
    return tree_.fragments()[i].source;
  }
  void visit_exact(std::size_t i, const exact_visitor& visit) const override {
    if (i >= tree_.fragments().size()) throw usage_error("fragment_exact: index out of range");
    tree_.geometry().visit_exact(tree_.fragments()[i], visit);
  }
  std::vector<std::uint32_t> order_from_eye(const vec3d& e, bool back_to_front) const override {
    return tree_.order_from_eye(e, back_to_front);
  }
  std::vector<std::uint32_t> order_for_direction(const vec3d& d,
                                                 bool back_to_front) const override {
    return tree_.order_for_direction(d, back_to_front);
  }
  std::vector<bsp::ancestor> ancestors(std::size_t i) const override {
    std::vector<bsp::ancestor> out;
    const auto& nodes = tree_.nodes();
    std::int32_t at = static_cast<std::int32_t>(tree_.node_of_fragment(i));
    while (nodes[at].parent >= 0) {
      out.push_back({nodes[nodes[at].parent].plane_source, nodes[at].side_in_parent});
      at = nodes[at].parent;
    }
    std::reverse(out.begin(), out.end());
    return out;
  }
  void write_tree(tree_file::writer& out, bool timings) const override {
    require_input("save");
    build_stats stats = tree_.stats();
    if (!timings) {
      stats.build_seconds = 0;
      stats.peak_rss_bytes = 0;
    }
    tree_file::write_common(out, stats, input_);
    tree_.write_tree(out);
  }

  std::size_t node_count() const override { return tree_.nodes().size(); }
  const triangle_soup& input() const override {
    require_input("input");
    return input_.soup;
  }
  bsp_node node(std::size_t k) const override {
    if (k >= tree_.nodes().size()) throw usage_error("node: index out of range");
    const auto& nd = tree_.nodes()[k];
    return {static_cast<std::uint32_t>(k),
            nd.plane_source,
            tree_.geometry().source_points(nd.plane_source),
            nd.first,
            nd.count,
            nd.negative,
            nd.positive,
            nd.parent,
            nd.side_in_parent};
  }
  void traverse(const vec3d& at, bool direction, bsp_visitor& visitor,
                bool back_to_front) const override {
    const auto& geom = tree_.geometry();
    const auto side_of = [&](std::uint32_t plane) {
      return direction ? geom.side_of_direction(plane, at) : geom.side_of_eye(plane, at);
    };
    tree_.walk(
        side_of, back_to_front,
        [&](std::int32_t k, int s) { visitor.enter(node(static_cast<std::size_t>(k)), s); },
        [&](std::int32_t k) { visitor.fragments(node(static_cast<std::size_t>(k))); },
        [&](std::int32_t k, int side) { visitor.cell(node(static_cast<std::size_t>(k)), side); });
  }

 private:
  /// usage_error unless the tree kept its input (build_options::keep_input).
  void require_input(const char* function) const {
    if (!has_input_)
      throw usage_error(std::string(function) +
                        ": the tree was built with build_options::keep_input = false and holds "
                        "no copy of its input (build it with keep_input to save it)");
  }

  tree_file::common_part input_;  ///< the soup and options, for saving (its stats are unused)
  bool has_input_ = true;         ///< input_.soup is the input (build_options::keep_input)
  basic_bsp_tree<G> tree_;
};

}  // namespace exbsp
