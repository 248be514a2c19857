// SPDX-License-Identifier: LGPL-3.0-or-later
// exbsp's own exact geometry (`--kernel exact`): the same tree and order as gmpq and epeck,
// at close to double speed.
//
// Notation: a point is an input vertex (exact double coordinates) or SEG(p, q, P), the point
// where the plane P of an input triangle meets the segment between points p and q (which
// lie strictly on opposite sides of P). Points live in one table shared by all fragments; a
// fragment is three point ids, its source triangle and its face id (20 bytes). Each point
// (40 bytes) caches a double centre c and a certified radius r, a float rounded up: the exact
// point lies within r of c in the max norm (r = 0 for input vertices). Side of point x
// against plane Q, in order:
//   1. filter: the double orientation of c with an error bound that covers r (fast_sign);
//   2. structure: x = SEG(p, q, Q) lies on Q; otherwise, when p and q are not strictly on
//      opposite sides of Q, x (strictly between them) takes their sign (both 0: 0) — the
//      structural zeros (a split point on an edge that Q contains) cost no arithmetic;
//   3. exact: the point's exact value against Q's exact plane, in integers (GMP): a point is
//      X / w in homogeneous integer coordinates, unreduced but for common twos, computed once
//      and memoised, iteratively over the points it depends on.
// Reduced "p/q" strings and correctly rounded doubles are produced once per point, at output.
// Hand-written rather than a CGAL kernel because no CGAL kernel offers (2): the structure of
// the construction is what makes most exact answers free.
#pragma once
#include <array>
#include <cmath>
#include <atomic>
#include <cstdint>
#include <deque>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include <exbsp/bsp/engine.h>
#include "bsp/exact_output.h"
#include "bsp/fast_orientation.h"
#include "geom/split_pattern.h"

namespace exbsp {
namespace tree_file {
class writer;
class reader;
}  // namespace tree_file
namespace detail {
struct integer_views;  // bsp/packed_integers.h
}  // namespace detail

class exact_geometry {
 public:
  static constexpr kernel_id id = kernel_id::exact;
  static constexpr bool exact = true;
  static constexpr std::uint32_t none = ~0u;

  struct fragment {
    std::array<std::uint32_t, 3> v;  ///< point ids
    std::uint32_t source;
    std::uint32_t face;
  };
  /// A run of point ids owned by one subtree builder (ids are claimed in blocks, so builders
  /// on other threads never touch the same slots), and the split points made at the current
  /// node, for sharing: the point SEG(p, q, P) of two neighbouring fragments is made once.
  struct scratch {
    std::uint32_t next = 0, end = 0;
    std::uint32_t plane = none;
    std::unordered_map<std::uint64_t, std::uint32_t> made;
  };

  explicit exact_geometry(const triangle_soup& soup);
  ~exact_geometry();
  exact_geometry(const exact_geometry&) = delete;
  exact_geometry& operator=(const exact_geometry&) = delete;

  bool add_source(const triangle_soup& soup, std::uint32_t i, fragment& out);

  /// For batched side tests (bsp/batch_classify.h): a point's certified centre and radius
  /// (its exact position lies within the radius, max norm) and a plane's filter.
  static constexpr bool has_centres = true;
  const vec3d& centre(std::uint32_t id) const { return at(id).c; }
  double radius(std::uint32_t id) const { return at(id).r; }
  /// The filter of input triangle `plane` (fast_orientation.h), made from its vertices when
  /// asked rather than stored: 48 bytes per input triangle were up to a third of the peak
  /// heap, and making it costs a cross product. The build makes it once per node plane and
  /// candidate, in a direct-mapped cache of 32 per subtree (bsp_tree_impl.h, static_filter_of).
  /// Measured side by side: peak heap per fragment pinion 152 -> 128, anchor_dense 154 -> 117,
  /// blade 141 -> 93; build time within noise to 4% slower (pinion, part, fandisk).
  fast_plane_core filter(std::uint32_t plane) const {
    const std::array<std::uint32_t, 3>& s = sources_[plane];
    return make_fast_plane(at(s[0]).c, at(s[1]).c, at(s[2]).c);
  }

  int sign(std::uint32_t plane, const fragment& f, int k) const {
    return point_sign_of(plane, f.v[k]);
  }
  /// The same, with the plane's filter(plane) made by the caller (who asks many points
  /// against one plane: the filter is made from the vertices, not stored).
  int sign(std::uint32_t plane, const fast_plane_core& fp, const fragment& f, int k) const {
    return point_sign_of(plane, fp, f.v[k]);
  }
  /// The three input points of triangle `plane` (its vertices' doubles).
  std::array<vec3d, 3> source_points(std::uint32_t plane) const {
    const std::array<std::uint32_t, 3>& s = sources_[plane];
    return {at(s[0]).c, at(s[1]).c, at(s[2]).c};
  }
  /// Whether point `id` is one of the vertices of input triangle `plane` (so lies in its
  /// plane): one 12-byte load.
  bool is_vertex_of(std::uint32_t plane, std::uint32_t id) const {
    const std::array<std::uint32_t, 3>& s = sources_[plane];
    return id == s[0] || id == s[1] || id == s[2];
  }
  /// The exact sign of point `id` against the plane of input triangle `plane`.
  int point_sign_of(std::uint32_t plane, std::uint32_t id) const {
    return point_sign_of(plane, filter(plane), id);
  }
  /// The same, with fp = filter(plane).
  int point_sign_of(std::uint32_t plane, const fast_plane_core& fp, std::uint32_t id) const {
    int budget = 32;
    return point_sign(plane, fp, id, budget);
  }
  void split(std::uint32_t plane, const fragment& f, const geom::split_pattern& pat,
             std::array<fragment, 3>& out, scratch& sc);

  int side_of_eye(std::uint32_t plane, const vec3d& eye) const;
  int side_of_direction(std::uint32_t plane, const vec3d& d) const;

  /// Computes the correctly rounded doubles of the fragments' points (once; thread-safe).
  /// Precondition of to_double.
  void prepare_output(const std::vector<fragment>& fragments) const;
  fragment_d to_double(const fragment& f) const;
  void visit_exact(const fragment& f, const exact_visitor& visit) const;
  /// The same as text (bsp::fragment_exact's form).
  exact_triangle to_exact(const fragment& f) const {
    return exact_text([&](const exact_visitor& visit) { visit_exact(f, visit); });
  }
  /// Saved trees (geometry_exact_file.cpp, docs/tree-file.md): writes the constructed points
  /// the fragments use, renumbered densely, then the fragments; read_fragments reads them back
  /// into a geometry made from the same soup, in which `usable[i]` says whether add_source
  /// accepted triangle i. It checks every id and that each constructed point's segment
  /// crosses its plane strictly (so every exact value is well defined), and restores each
  /// point's certified approximation. Throws input_error through `in`.
  void write_fragments(tree_file::writer& out, const std::vector<fragment>& fragments) const {
    write_fragments(out, fragments, inputs_, nullptr);
  }
  void read_fragments(tree_file::reader& in, const triangle_soup& soup,
                      const std::vector<char>& usable, std::vector<fragment>& fragments);
  /// The same for the cells and parts of a distributed build (bsp/tree_distributed.h), whose
  /// fragments use points already known to the reader. write: the point ids below `known_end`
  /// (at least the input vertices) are written as they are, not as constructed points; the
  /// ids of the constructed points written, in file order, go to `written` when not null.
  /// read: file ids below V are input vertices, the next known.size() name known[...] (points
  /// of this geometry), the constructed points of the file get new ids. Unlike a saved
  /// tree's read, it sets no budget on the exact values (the build's own data).
  void write_fragments(tree_file::writer& out, const std::vector<fragment>& fragments,
                       std::uint32_t known_end, std::vector<std::uint32_t>* written) const;
  void read_fragments(tree_file::reader& in, const triangle_soup& soup,
                      const std::vector<char>& usable, std::vector<fragment>& fragments,
                      const std::vector<std::uint32_t>& known);
  /// Incremental insertion (tree_insert.h): copies the constructed points of `old`, the
  /// geometry of a soup whose vertices are the first ones of this geometry's soup (same ids),
  /// behind this geometry's input vertices, and renumbers `fragments` (point ids of `old`)
  /// into this geometry. Precondition: nothing constructed here yet. Exact values are not
  /// copied (made again when asked).
  void import_points(const exact_geometry& old, std::vector<fragment>& fragments);
  /// Point ids in use: ids below this are input vertices or claimed constructed points.
  std::uint32_t point_id_end();
  /// Frees the exact values and planes memoised so far (the build calls it once its side
  /// tests are done, before its peak step: output makes the values it needs again).
  /// Precondition: no other thread uses the geometry.
  void forget_exact_values();
  /// Bytes held by the point table (for the memory benchmark).
  std::size_t points_memory() const;

  /// Counters of how side tests of constructed points were answered (for tests and bench).
  struct counters {
    std::atomic<std::uint64_t> on_own_plane{0}, structural{0}, exact{0};
  };
  const counters& stats() const { return counters_; }

 private:
  struct exact_value;
  struct exact_plane;
  struct point {
    vec3d c{};
    float r = 0;                                     ///< rounded up (round_up_to_float)
    std::uint32_t p = none, q = none, plane = none;  ///< SEG(p, q, plane); none: input vertex
  };
  /// fast_eval against the plane of input triangle `plane`.
  bool filter(std::uint32_t plane, const vec3d& x, double radius, double& v, double& bound) const {
    return fast_eval(filter(plane), x, radius, v, bound);
  }
  /// Points live in chunks of chunk_size, found through a table of chunk pointers that
  /// doubles when full; a table once published is never changed in the slots in use nor
  /// freed before the geometry, so other threads may read through any table they loaded.
  static constexpr unsigned chunk_bits = 8;       ///< 10 KB per chunk
  static constexpr unsigned max_point_bits = 28;  ///< 2^28 points (10 GB) at most
  static constexpr std::uint32_t chunk_size = 1u << chunk_bits;
  static constexpr std::uint32_t block = 16;

  const point& at(std::uint32_t id) const {
    return chunk_table_.load(std::memory_order_acquire)[id >> chunk_bits][id & (chunk_size - 1)];
  }
  point& at(std::uint32_t id) {
    return chunk_table_.load(std::memory_order_acquire)[id >> chunk_bits][id & (chunk_size - 1)];
  }
  std::uint32_t allocate(scratch& sc);
  void claim_block(scratch& sc);
  /// Makes the chunks of ids below end (caller holds claim_mutex_).
  void grow_chunks(std::uint32_t end);

  int point_sign(std::uint32_t plane, const fast_plane_core& fp, std::uint32_t x,
                 int& budget) const {
    const point& pt = at(x);
    double v, bound;  // the core filter (fast_sign without the shared-vertex test)
    if (fast_eval(fp, pt.c, pt.r, v, bound)) {
      if (v > bound) return 1;
      if (v < -bound) return -1;
    }
    return point_sign_slow(plane, fp, x, budget);
  }
  int point_sign_slow(std::uint32_t plane, const fast_plane_core& fp, std::uint32_t x,
                      int& budget) const;
  int exact_sign(std::uint32_t plane, std::uint32_t x) const;
  /// The memoised exact value of constructed point x (made on first use).
  const exact_value& exact_of(std::uint32_t x) const;
  /// Working integers for an input vertex's exact value (reused from call to call).
  struct vertex_value;
  /// Views of point id's exact value into `out`: an input vertex's, written into `vertex`, or a
  /// constructed point's memoised one (false until made).
  bool value_of(std::uint32_t id, vertex_value& vertex, detail::integer_views& out) const;
  const exact_plane& plane_of(std::uint32_t plane) const;
  std::uint32_t construct(std::uint32_t plane, std::uint32_t p, std::uint32_t q, scratch& sc);
  /// Sets the certified centre and radius of constructed point id from its p, q and plane.
  void approximate(std::uint32_t id);

  std::vector<std::array<std::uint32_t, 3>> sources_;  ///< input vertex ids (= point ids)
  /// Exact values of the few points that needed one (and of output points), by point id, and
  /// exact planes of the triangles that needed one: rare during a build, so locked maps
  /// rather than 8 bytes in every point and triangle.
  const exact_value* find_exact(std::uint32_t id) const;
  mutable std::mutex exact_mutex_;
  /// Values in a deque (a value's address never changes, so references to it stay valid),
  /// found by point id in exact_slot_ (1 + the value's index; 0: none), each value's four
  /// integers packed in one block of limbs (packed_integers.h). A node-based map cost about 40
  /// bytes more per value, four mpz_class about 100 more, and a 1M-triangle assembly memoises
  /// hundreds of thousands.
  mutable std::deque<exact_value> exact_store_;
  mutable std::vector<std::uint32_t> exact_slot_;
  /// A tree loaded from a file (read_fragments) may make exact values of at most this many
  /// bits in all, a budget from the file's size: nested split points double their values' size
  /// at each level, so a small forged file could otherwise ask for unbounded time and memory.
  /// Built trees have no budget (their input bounds them).
  std::uint64_t exact_budget_bits_ = std::numeric_limits<std::uint64_t>::max();
  std::string exact_budget_file_;
  mutable std::atomic<std::uint64_t> exact_bits_{0};
  mutable std::deque<exact_plane> plane_store_;    ///< as exact_store_, by triangle id:
  mutable std::vector<std::uint32_t> plane_slot_;  ///< 1 + index into plane_store_; 0: none
  std::atomic<point**> chunk_table_{nullptr};
  std::vector<std::unique_ptr<point*[]>> chunk_tables_;  ///< every table made (the last in use)
  std::vector<std::unique_ptr<point[]>> chunks_;         ///< guarded by claim_mutex_
  std::size_t table_size_ = 0;                           ///< guarded by claim_mutex_
  std::mutex claim_mutex_;
  std::uint32_t claimed_ = 0;  ///< ids below this are claimed (guarded by claim_mutex_)
  std::uint32_t inputs_ = 0;
  mutable std::once_flag output_once_;
  mutable std::vector<vec3d>
      rounded_;  ///< correctly rounded doubles per point, after prepare_output
  mutable counters counters_;
};

}  // namespace exbsp
