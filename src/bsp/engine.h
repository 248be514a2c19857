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
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "../mesh/soup.h"

namespace exbsp {

/// The number type behind classification and splitting.
enum class kernel_id {
  exact,   ///< exbsp's own exact points (filter, structural signs, GMP on demand). Default.
  epeck,   ///< CGAL Epeck: lazy exact (filtered intervals, GMP rationals on demand).
  epick,   ///< CGAL Epick: exact predicates, rounded (double) constructions.
  double_, ///< Simple_cartesian<double>: plain double, no filter, no epsilon.
  gmpq     ///< Simple_cartesian<CGAL::Gmpq>: exact rationals, no filter.
};

/// "exact", "epeck", "epick", "double", "gmpq".
std::string to_string(kernel_id k);
/// Parses a kernel name; throws usage_error for an unknown name.
kernel_id parse_kernel(const std::string& name);
/// True for kernels whose constructions are exact (exact, epeck, gmpq).
bool is_exact(kernel_id k);

/// Names of the splitter heuristics: "naive", "min-split", "sampled", "random".
const std::vector<std::string>& heuristic_names();
/// The default heuristic (the best one the benchmarks found; see bench/RESULTS.md).
const char* default_heuristic();

/// Progress of a running build, reported to build_options::progress.
struct build_progress {
  std::size_t fragments_placed;  ///< fragments already stored at nodes
  std::size_t fragments_total;   ///< current total (grows with splits)
  std::size_t nodes;
  double seconds;
};

struct build_options {
  kernel_id kernel = kernel_id::exact;
  std::string heuristic = default_heuristic();
  std::uint64_t seed = 0;          ///< for randomised heuristics; same seed, same tree
  std::size_t max_fragments = 0;   ///< 0: no limit; otherwise throw limit_error beyond it
  unsigned threads = 0;            ///< worker threads for candidate evaluation (0: all cores)
  /// The sampled heuristic: up to `sampled_candidates` seeded candidates per node, each scored
  /// on an evenly spaced sample of at most `sampled_samples` fragments by
  /// sampled_split_weight * splits + |positive - negative|; lowest score wins.
  unsigned sampled_candidates = 16;
  unsigned sampled_samples = 512;
  unsigned sampled_split_weight = 8;
  /// Called about every 256 nodes and once when the tree is complete; may be empty. Calls
  /// never overlap (one at a time) but may come from the build's worker threads.
  /// Cancellation: to cancel a build, throw from `progress` (exbsp::build_cancelled is meant
  /// for it; any exception works). It is not called again; the exception propagates out of
  /// bsp::build unchanged once every worker thread has stopped (each finishes at most the
  /// node it is splitting); no tree is returned and everything the build allocated is freed.
  std::function<void(const build_progress&)> progress;
};

/// Statistics of a build (names follow `exbsp build --json`).
struct build_stats {
  std::size_t input_triangles = 0;   ///< triangles after fan triangulation, degenerate ones included
  std::size_t degenerate_input = 0;  ///< exactly collinear triangles skipped (no plane)
  std::size_t fragments = 0;         ///< triangles stored in the tree
  std::size_t splits = 0;            ///< split events (one per straddling triangle split)
  std::size_t nodes = 0;
  std::size_t depth = 0;             ///< nodes on the longest root-to-leaf path (root alone: 1)
  double build_seconds = 0;
  std::size_t peak_rss_bytes = 0;    ///< process peak resident set after the build (Linux), 0 if unknown
  std::string kernel, heuristic;
  std::uint64_t seed = 0;            ///< build_options::seed of the build
};

/// A fragment converted to doubles (each coordinate correctly rounded from its exact value).
struct fragment_d {
  std::uint32_t face;
  std::array<vec3d, 3> v;
};

/// Exact coordinates of a fragment as reduced rationals "p/q" (or "p").
using exact_triangle = std::array<std::array<std::string, 3>, 3>;

class bsp_impl;
class bsp_access;  // private: the library's own access to the implementation (bsp_impl.h)

/// A built BSP tree. Movable, not copyable. Thread-safe for concurrent const use.
class bsp {
public:
  /// Builds the tree of `soup`. Throws usage_error for an unknown heuristic,
  /// limit_error when options.max_fragments is exceeded, and whatever options.progress throws
  /// (cancellation, see build_options::progress). Degenerate triangles are skipped
  /// and counted in stats().degenerate_input.
  static bsp build(const triangle_soup& soup, const build_options& options = {});

  bsp(bsp&&) noexcept;
  bsp& operator=(bsp&&) noexcept;
  ~bsp();

  const build_stats& stats() const;
  kernel_id kernel() const;

  /// Fragments in storage order (node by node); indices below refer to this order.
  std::size_t fragment_count() const;
  fragment_d fragment(std::size_t i) const;
  std::vector<fragment_d> fragments_double() const;
  /// Exact coordinates; throws usage_error on an inexact kernel.
  exact_triangle fragment_exact(std::size_t i) const;

  /// Fragment indices back to front (or front to back) for a perspective eye point
  /// (DESIGN.md section 3).
  std::vector<std::uint32_t> order_from_eye(const vec3d& eye, bool back_to_front = true) const;
  /// Same for a parallel projection with direction of projection d (eye into the scene).
  /// Throws usage_error for a zero or non-finite d.
  std::vector<std::uint32_t> order_for_direction(const vec3d& d, bool back_to_front = true) const;

  /// Structure for checks and point location: for fragment i, each ancestor node's plane
  /// (plane_face = index of the input triangle in soup.triangles whose plane it is) and the
  /// side (+1 / -1) of it that fragment i lies on, root first. Empty for fragments at the root.
  struct ancestor { std::uint32_t plane_face; int side; };
  std::vector<ancestor> ancestors(std::size_t i) const;

  /// Saved trees (docs/tree-file.md): a versioned, checksummed binary file holding the input
  /// soup and the tree's exact representation, so that a loaded tree has the same stats,
  /// fragments, ancestors and byte-identical orders, without a build. Every kernel is saved.
  /// save writes through write_file_atomically (throws output_error naming `path`).
  void save(const std::string& path) const;
  /// The bytes save writes.
  std::string serialize() const;
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
  std::unique_ptr<bsp_impl> impl_;
};

}  // namespace exbsp
