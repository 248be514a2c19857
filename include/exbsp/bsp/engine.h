// SPDX-License-Identifier: LGPL-3.0-or-later
// exbsp public API: build an exact BSP tree of a triangle soup and read back-to-front orders.
//
// This header hides CGAL: the kernel is chosen at run time and the tree is one of five
// explicit instantiations (src/bsp/bsp_<kernel>.cpp). Fragments are the triangles stored in
// the tree (input triangles and the pieces of split ones); each keeps its source face id.
//
// Typical use (a CAD viewer):
//   exbsp::triangle_soup soup = exbsp::read_mesh("part.off");
//   exbsp::bsp tree = exbsp::bsp::build(soup, {});          // exact kernel, default heuristic
//   auto frags = tree.fragments_double();                    // convert once
//   for (auto i : tree.order_from_eye({0, 0, 10})) draw(frags[i]);
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <exbsp/bsp/traversal.h>
#include <exbsp/core/export.h>
#include <exbsp/mesh/soup.h>

namespace exbsp {

/// The number type behind classification and splitting.
enum class kernel_id {
  exact,    ///< exbsp's own exact points (filter, structural signs, GMP on demand). Default.
  epeck,    ///< CGAL Epeck: lazy exact (filtered intervals, GMP rationals on demand).
  epick,    ///< CGAL Epick: exact predicates, rounded (double) constructions.
  double_,  ///< Simple_cartesian<double>: plain double, no filter, no epsilon.
  gmpq      ///< Simple_cartesian<CGAL::Gmpq>: exact rationals, no filter.
};

/// "exact", "epeck", "epick", "double", "gmpq".
EXBSP_EXPORT std::string to_string(kernel_id k);
/// Every kernel's name, the default first: "exact", "epeck", "gmpq", "epick", "double".
EXBSP_EXPORT const std::vector<std::string>& kernel_names();
/// Parses a kernel name; throws usage_error for an unknown name.
EXBSP_EXPORT kernel_id parse_kernel(const std::string& name);
/// True for kernels whose constructions are exact (exact, epeck, gmpq).
EXBSP_EXPORT bool is_exact(kernel_id k);

/// Names of the built-in splitter heuristics: "naive", "min-split", "sampled", "random".
/// bsp::build also accepts "custom", which needs build_options::score (see there).
EXBSP_EXPORT const std::vector<std::string>& heuristic_names();
/// The default heuristic (the best one the benchmarks found; see bench/RESULTS.md).
EXBSP_EXPORT const char* default_heuristic();

/// The most threads a build uses and build_options::threads accepts: 4 per hardware thread,
/// at most 1024. (threads = 0, all cores, also stays within it whatever OMP_NUM_THREADS says.)
EXBSP_EXPORT unsigned max_build_threads();

/// Progress of a running build, reported to build_options::progress.
struct build_progress {
  std::size_t fragments_placed;  ///< fragments already stored at nodes
  std::size_t fragments_total;   ///< current total (grows with splits)
  std::size_t nodes;
  double seconds;
};

/// What a scoring callback (build_options::score) sees for one candidate splitter at one
/// node. The counts classify fragments exactly against the candidate's plane, over the
/// candidate set's fragments other than the candidate itself; a fragment of the same input
/// triangle is coplanar. They are the same for every exact kernel.
struct candidate_score_input {
  std::size_t candidate = 0;  ///< position of the candidate in the node's list (list order)
  std::uint32_t face = 0;     ///< its face id
  std::uint32_t source = 0;   ///< its input triangle (index in soup.triangles), whose plane it is
  std::size_t positive = 0, negative = 0;  ///< fragments entirely on one side (touching allowed)
  std::size_t straddling = 0;              ///< fragments the plane would split
  std::size_t coplanar = 0;                ///< fragments in the plane (either orientation)
  std::size_t list_size = 0;               ///< fragments in the node's list (>= 2)
  std::uint32_t depth = 1;                 ///< the node's depth (root: 1)
};

/// Which candidates the "custom" heuristic scores, counted over which fragments.
/// `all` costs n^2 exact side tests per node of n fragments: min-split's work without the
/// bound that lets min-split stop early (hand.off, 2 390 triangles: 82 s against 12 s), so
/// use `sampled` on large meshes; sampled_candidates >= n there scores every fragment on the
/// sample.
enum class candidate_set {
  all,     ///< every fragment of the list, counted over the whole list
  sampled  ///< the sampled heuristic's seeded candidates, counted over its sample
};

struct build_options {
  kernel_id kernel = kernel_id::exact;
  std::string heuristic = default_heuristic();
  std::uint64_t seed = 0;         ///< for randomised heuristics; same seed, same tree
  std::size_t max_fragments = 0;  ///< 0: no limit; otherwise throw limit_error beyond it
  unsigned threads = 0;  ///< worker threads for candidate evaluation (0: all cores); at most
                         ///< max_build_threads() (usage_error beyond)
  /// Fewer fragments than this pending below the top levels: the subtrees are built on the
  /// calling thread (threads only slow a build of milliseconds). 0: always in parallel.
  /// Never changes the tree.
  std::size_t parallel_min_fragments = 20000;
  /// The sampled heuristic: up to `sampled_candidates` seeded candidates per node, each scored
  /// on an evenly spaced sample of at most `sampled_samples` fragments by
  /// sampled_split_weight * splits + |positive - negative|; lowest score wins.
  unsigned sampled_candidates = 16;
  unsigned sampled_samples = 512;
  unsigned sampled_split_weight = 8;
  /// The "custom" heuristic (heuristic = "custom", and only then): score(in) for each
  /// candidate of `score_candidates`; the lowest score wins, ties to the earliest candidate in
  /// list order (so `return in.straddling;` over candidate_set::all is min-split exactly).
  /// Called only at nodes whose list holds >= 2 fragments. It is called CONCURRENTLY from the
  /// build's threads (`threads`; set threads = 1 for a callback that is not thread-safe) and
  /// must depend only on its input: then the tree is the same for every thread count and every
  /// exact kernel. A NaN score is a usage_error. An exception it throws stops the build and
  /// propagates out of bsp::build (the first one thrown, when several threads throw); no tree
  /// is returned.
  std::function<double(const candidate_score_input&)> score;
  candidate_set score_candidates = candidate_set::all;
  /// Called about every 256 nodes and once when the tree is complete; may be empty. Calls
  /// never overlap (one at a time) but may come from the build's worker threads.
  /// Cancellation: to cancel a build, throw from `progress` (exbsp::build_cancelled is meant
  /// for it; any exception works). It is not called again; the exception propagates out of
  /// bsp::build unchanged once every worker thread has stopped (each finishes at most the
  /// node it is splitting); no tree is returned and everything the build allocated is freed.
  std::function<void(const build_progress&)> progress;
  /// True: the tree keeps a copy of the input soup (24 bytes per vertex, 16 per triangle), for
  /// input(), save() and serialize(). False: it keeps none, and those throw usage_error; the
  /// tree, its orders and fragments are the same. The command line keeps it only when it saves.
  bool keep_input = true;
};

/// What bsp::inserted and bsp::insert take of a build's options (the kernel, heuristic and
/// seed are the tree's own).
struct insert_options {
  /// 0: no limit; otherwise limit_error when the tree after the insert would hold more
  /// fragments than this (the tree is left as it was).
  std::size_t max_fragments = 0;
  /// As build_options::progress: called about every 256 nodes the new triangles reach and once
  /// at the end, on the calling thread; throw from it to cancel (the exception propagates and
  /// the tree is left as it was).
  std::function<void(const build_progress&)> progress;
};

/// Statistics of a build (names follow `exbsp build --json`).
struct build_stats {
  std::size_t input_triangles = 0;  ///< triangles after fan triangulation, degenerate ones included
  std::size_t degenerate_input = 0;  ///< exactly collinear triangles skipped (no plane)
  std::size_t fragments = 0;         ///< triangles stored in the tree
  std::size_t splits = 0;            ///< split events (one per straddling triangle split)
  std::size_t nodes = 0;
  std::size_t depth = 0;  ///< nodes on the longest root-to-leaf path (root alone: 1)
  double build_seconds = 0;
  std::size_t peak_rss_bytes =
      0;  ///< process peak resident set after the build (Linux), 0 if unknown
  std::string kernel, heuristic;
  std::uint64_t seed = 0;  ///< build_options::seed of the build
};

/// The counts of `s`, each as visit(name, value) with the name `exbsp build --json` and
/// Python's stats dict give it: input_triangles, degenerate_input, fragments, splits, nodes,
/// depth. One list for every serialisation (the command line, Python, the benchmarks).
template <class Visit>
void for_each_stat_count(const build_stats& s, Visit&& visit) {
  visit("input_triangles", s.input_triangles);
  visit("degenerate_input", s.degenerate_input);
  visit("fragments", s.fragments);
  visit("splits", s.splits);
  visit("nodes", s.nodes);
  visit("depth", s.depth);
}

/// Every field of `s` as visit(name, value): the counts (for_each_stat_count), then
/// build_seconds, peak_rss_bytes, kernel, heuristic and seed.
template <class Visit>
void for_each_stat(const build_stats& s, Visit&& visit) {
  for_each_stat_count(s, visit);
  visit("build_seconds", s.build_seconds);
  visit("peak_rss_bytes", s.peak_rss_bytes);
  visit("kernel", s.kernel);
  visit("heuristic", s.heuristic);
  visit("seed", s.seed);
}

/// A fragment converted to doubles (each coordinate correctly rounded from its exact value).
struct fragment_d {
  std::uint32_t face;
  std::array<vec3d, 3> v;

  /// False when a corner has a NaN or infinite coordinate (an inexact kernel's rounded split
  /// point; never with the exact kernels).
  bool finite() const {
    for (const vec3d& p : v)
      for (double c : p)
        if (!std::isfinite(c)) return false;
    return true;
  }
};

/// Exact coordinates of a fragment as reduced rationals "p/q" (or "p").
using exact_triangle = std::array<std::array<std::string, 3>, 3>;

class bsp_impl;
class bsp_access;  // private: the library's own access to the implementation (bsp_impl.h)

/// A built BSP tree. Movable, not copyable. Thread-safe for concurrent const use.
class EXBSP_EXPORT bsp {
 public:
  /// Builds the tree of `soup`. Throws usage_error for an unknown heuristic (or "custom"
  /// without options.score, or options.score with another heuristic), limit_error when
  /// options.max_fragments is exceeded, and whatever options.score or options.progress throw
  /// (cancellation, see build_options::progress). Degenerate triangles are skipped and counted
  /// in stats().degenerate_input.
  static bsp build(const triangle_soup& soup, const build_options& options = {});

  /// Incremental insertion (the course notes' add(root, T)), for trees built with the naive
  /// heuristic: the tree that bsp::build(c, {same kernel, "naive"}) makes for the
  /// concatenation c = input() followed by `added` (c.append(added): vertex indices shifted
  /// by input().vertices.size(), face ids by input().face_count, so the new faces' ids
  /// continue after the existing ones), exactly: the same nodes, fragments in the same
  /// storage order, the same stats (but build_seconds: the build's plus the inserts'; and
  /// peak_rss_bytes), byte-identical serialize_reproducible() and orders, for every kernel.
  /// Each new triangle walks down from the root as in the build: classified exactly against
  /// each node's plane, coplanar -> appended to that node's list, positive / negative -> that
  /// child, straddling -> split by the build's split into ordered pieces; reaching an empty
  /// child, the new triangles there become a new subtree, its first fragment the splitter.
  /// Degenerate triangles are skipped and counted in stats().degenerate_input.
  /// This tree and its copies are left untouched (the result is a new tree): the work is the
  /// new triangles' walk and splits, plus a copy of this tree and a re-layout of its nodes and
  /// fragments in build order, linear in the tree's size (no side test of an old fragment).
  /// Measured on fandisk (12 946 triangles, naive tree of 506 688 fragments, exact kernel, 2
  /// busy cores): naive build of the whole 1.03 s; its last 129 triangles inserted into the
  /// tree of the others 35 ms; its second half into the first half's tree 0.57 s.
  /// Throws usage_error for a tree built with another heuristic (the result would not be that
  /// heuristic's tree: a node's splitter depends on the whole list), for a tree without its
  /// input (build_options::keep_input = false), a vertex index out of range or a non-finite
  /// coordinate in `added`; limit_error beyond options.max_fragments; whatever
  /// options.progress throws.
  bsp inserted(const triangle_soup& added, const insert_options& options = {}) const;
  /// The same in place: *this = inserted(added, options). Copies made before keep the old
  /// tree; on an exception *this is unchanged.
  void insert(const triangle_soup& added, const insert_options& options = {});

  /// A copy shares the built tree, which is immutable: it costs a reference count, not a
  /// tree (a renderer can hold the tree its caller holds).
  bsp(const bsp&) noexcept;
  bsp& operator=(const bsp&) noexcept;
  bsp(bsp&&) noexcept;
  bsp& operator=(bsp&&) noexcept;
  ~bsp();

  const build_stats& stats() const;
  kernel_id kernel() const;
  /// The soup the tree was built from (a loaded tree: the soup its file holds), its face ids
  /// those of the fragments.
  const triangle_soup& input() const;

  /// Fragments in storage order (node by node); indices below refer to this order.
  std::size_t fragment_count() const;
  fragment_d fragment(std::size_t i) const;
  std::vector<fragment_d> fragments_double() const;
  /// Exact coordinates; throws usage_error on an inexact kernel.
  exact_triangle fragment_exact(std::size_t i) const;
  /// The input triangle (index in the soup's triangles) fragment i lies in: the triangle
  /// itself or the one it was split from. Throws usage_error for i out of range.
  std::uint32_t fragment_source(std::size_t i) const;

  /// Fragment indices back to front (or front to back) for a perspective eye point
  /// (docs/contract.md "The BSP").
  /// Per frame: the tree does not depend on the viewpoint, so build once and call this (or
  /// order_for_direction) for every new camera; no rebuild. Cost: one exact side test of the
  /// eye per node and one visit per fragment, O(nodes + fragments), allocating only the
  /// result. Measured on fandisk (12 946 triangles; 29 123 fragments, 15 653 nodes; exact
  /// kernel, default heuristic, 2 busy cores): build 0.91 s, order 0.58 ms median (0.43 ms
  /// best), about 1/1500 of the build; Epeck: 3.2 s and 1.5 ms. Concurrent calls are safe.
  std::vector<std::uint32_t> order_from_eye(const vec3d& eye, bool back_to_front = true) const;
  /// Same for a parallel projection with direction of projection d (eye into the scene).
  /// Throws usage_error for a zero or non-finite d.
  std::vector<std::uint32_t> order_for_direction(const vec3d& d, bool back_to_front = true) const;

  /// The tree's nodes and cells (traversal.h). node(k) for k < node_count(); throws
  /// usage_error for k out of range.
  std::size_t node_count() const;
  bsp_node node(std::size_t k) const;
  /// Walks the tree for an eye point (a direction of projection d) calling `visitor` in the
  /// order of traversal.h; the fragments it visits are exactly order_from_eye(eye)
  /// (order_for_direction(d)). Same errors as order_from_eye (order_for_direction).
  void traverse_from_eye(const vec3d& eye, bsp_visitor& visitor, bool back_to_front = true) const;
  void traverse_for_direction(const vec3d& d, bsp_visitor& visitor,
                              bool back_to_front = true) const;

  // For checks (tests): the tree's structure seen from one fragment. Walking the tree is
  // traverse_from_eye's job; this is the independent path the tests compare against.

  /// For fragment i, each ancestor node's plane (plane_face = index of the input triangle in
  /// soup.triangles whose plane it is) and the side (+1 / -1) of it that fragment i lies on,
  /// root first. Empty for fragments at the root.
  struct ancestor {
    std::uint32_t plane_face;
    int side;
  };
  std::vector<ancestor> ancestors(std::size_t i) const;

  /// Saved trees (docs/tree-file.md): a versioned, checksummed binary file holding the input
  /// soup and the tree's exact representation, so that a loaded tree has the same stats,
  /// fragments, ancestors and byte-identical orders, without a build. Every kernel is saved.
  /// save writes through write_file_atomically (throws output_error naming `path`).
  void save(const std::string& path) const;
  /// The bytes save writes.
  std::string serialize() const;
  /// The same with the two measured stats (build_seconds, peak_rss_bytes) written as 0: equal
  /// trees give equal bytes, whichever run, machine or distributed build made them. A valid
  /// saved tree (load and deserialize read it).
  std::string serialize_reproducible() const;
  /// Loads a tree saved by save. Throws input_error naming the file (and, for a malformed
  /// file, the byte offset and field) for an unreadable, truncated, corrupted, wrong-version
  /// or inconsistent file; never returns a tree that fails the checks of docs/tree-file.md.
  static bsp load(const std::string& path);
  /// load for bytes already in memory; `name` names them in messages.
  static bsp deserialize(std::string_view bytes, const std::string& name);
  /// True when `path` ends in .exbsp (any case) or is a readable file starting with the magic.
  static bool is_saved_tree(const std::string& path);

 private:
  friend class bsp_access;
  explicit bsp(std::unique_ptr<bsp_impl> impl);
  std::shared_ptr<const bsp_impl> impl_;
};

}  // namespace exbsp
