// SPDX-License-Identifier: LGPL-3.0-or-later
// Batched side tests for geometries whose points carry a certified double centre and radius
// (G::has_centres: exbsp's exact geometry). Private to src/bsp (used by bsp_tree_impl.h).
//
// Notation: a point x has centre c and radius r (x lies within r of c, max norm); a plane's
// static filter (fast_orientation.h, static_plane) certifies sign f(x) with one dot product
// and one comparison. Two uses:
//   - the sampled heuristic's sample: its fragments' centres gathered once per node into flat
//     arrays (sample_batch), then each candidate plane sweeps them in a tight loop;
//   - list blocks: a node's list is cut into runs of at most block_size fragments, each with
//     the bounding box of its points (point_box); a run whose box is certified strictly on one
//     side of the plane moves to that child whole, without a test per fragment.
// Whatever the filters cannot certify goes to G::sign, the exact predicate, so every answer is
// the exact one: the tree is the same as without batching.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <exbsp/core/errors.h>
#include "bsp/fast_orientation.h"
#include "geom/split_pattern.h"

namespace exbsp {
namespace detail {

/// Whether geometry G offers centre(id), radius(id) and filter(plane).
template <class G, class = void>
struct has_centres : std::false_type {};
template <class G>
struct has_centres<G, std::enable_if_t<G::has_centres>> : std::true_type {};

/// Bounding box of a set of points: centres within [lo, hi], radii at most r, so every exact
/// point lies within [lo - r, hi + r]. Empty: lo > hi.
struct point_box {
  vec3d lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  double r = 0;
  void add(const vec3d& c, double radius) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], c[k]);
      hi[k] = std::max(hi[k], c[k]);
    }
    r = std::max(r, radius);
  }
  void add(const point_box& b) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], b.lo[k]);
      hi[k] = std::max(hi[k], b.hi[k]);
    }
    r = std::max(r, b.r);
  }
};

/// The box of fragment f's three points.
template <class G>
point_box fragment_box(const G& geom, const typename G::fragment& f) {
  point_box b;
  for (std::uint32_t id : f.v) b.add(geom.centre(id), geom.radius(id));
  return b;
}

/// Side of a whole box against plane p: -1 or +1 when every point in it is certified strictly
/// on that side, 0 otherwise.
inline int box_sign(const fast_plane_core& p, const point_box& b) {
  return fast_box_sign(p, b.lo, b.hi, b.r);
}

/// A run of a node's list: positions [begin, begin + count) and the box of their points.
struct list_block {
  std::uint32_t begin = 0, count = 0;
  point_box box;
};
/// The longest run (a block's box grows with it, so longer runs are certified less often).
constexpr std::uint32_t block_size = 64;

/// A child list under construction: fragment refs, and its blocks. Fragments added one by one
/// join an open block; a whole block of the parent joins as a block of its own.
class block_list_builder {
 public:
  /// Appends one fragment ref with its box.
  void add(std::uint32_t ref, const point_box& box) {
    if (!open_) {
      open_block_ = {static_cast<std::uint32_t>(list.size()), 0, box};
      open_ = true;
    } else {
      open_block_.box.add(box);
    }
    list.push_back(ref);
    if (++open_block_.count == block_size) close();
  }
  /// Appends a whole block: `count` refs and their box.
  void add_block(const std::uint32_t* refs, const list_block& b) {
    close();
    list_block nb = b;
    nb.begin = static_cast<std::uint32_t>(list.size());
    list.insert(list.end(), refs, refs + b.count);
    blocks.push_back(nb);
  }
  void close() {
    if (open_) blocks.push_back(open_block_);
    open_ = false;
  }
  std::vector<std::uint32_t> list;
  std::vector<list_block> blocks;

 private:
  list_block open_block_;
  bool open_ = false;
};

/// Blocks for a list of refs in order, boxes from `box_of(ref)`.
template <class BoxOf>
std::vector<list_block> make_blocks(const std::vector<std::uint32_t>& list, const BoxOf& box_of) {
  std::vector<list_block> blocks;
  for (std::size_t b = 0; b < list.size(); b += block_size) {
    list_block blk;
    blk.begin = static_cast<std::uint32_t>(b);
    blk.count = static_cast<std::uint32_t>(std::min<std::size_t>(block_size, list.size() - b));
    for (std::size_t j = b; j < b + blk.count; ++j) blk.box.add(box_of(list[j]));
    blocks.push_back(blk);
  }
  return blocks;
}

/// Input triangles found to lie in one plane, as classes (union-find over source ids): a
/// fragment whose source is in the class of the node plane's source lies in that plane, so it
/// is coplanar without a side test. Classes are learnt during the build from side tests that
/// found a fragment exactly in a plane (mostly on CAD meshes, whose flat faces are made of
/// many triangles: every such test is an exact zero, the slowest kind). Empty until the
/// first one is learnt.
class coplanar_sources {
 public:
  /// Whether sources a and b are known to lie in one plane (read only: safe in parallel).
  bool same(std::uint32_t a, std::uint32_t b) const { return root(a) == root(b); }
  /// The class of source a, named by one of its members (a itself until a is joined). Two
  /// sources with the same root lie in one plane (read only: safe in parallel). Roots only
  /// merge, so equal roots read at different times still mean one plane.
  std::uint32_t root(std::uint32_t a) const {
    if (parent_.empty()) return a;
    while (parent_[a] != a) a = parent_[a];
    return a;
  }
  /// Records that sources a and b (of `sources` in all) lie in one plane.
  void join(std::uint32_t a, std::uint32_t b, std::size_t sources) {
    if (parent_.empty()) {
      parent_.resize(sources);
      for (std::size_t i = 0; i < sources; ++i) parent_[i] = static_cast<std::uint32_t>(i);
    }
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::uint32_t find(std::uint32_t a) {
    while (parent_[a] != a) {
      parent_[a] = parent_[parent_[a]];  // path halving
      a = parent_[a];
    }
    return a;
  }
  std::vector<std::uint32_t> parent_;
};

/// Set bits of a 16-bit mask (by hand: __builtin_popcount is a library call without -mpopcnt,
/// and C++17 has no std::popcount).
inline int popcount16(unsigned x) {
  x = x - ((x >> 1) & 0x5555u);
  x = (x & 0x3333u) + ((x >> 2) & 0x3333u);
  x = (x + (x >> 4)) & 0x0f0fu;
  return static_cast<int>((x + (x >> 8)) & 0x1fu);
}
/// Index of the lowest set bit of x != 0.
inline int lowest_bit(unsigned x) { return __builtin_ctz(x); }

/// Of up to 16 fragments (lanes j < len) with point codes a[j], b[j], c[j] (+1 / -1 known,
/// anything else not): bit j set in `known` when all three are +-1, and then in `positive` or
/// `negative` when all three are +1 or all -1.
struct lane_masks {
  unsigned known = 0, positive = 0, negative = 0;
};
inline lane_masks classify_lanes_scalar(const std::int8_t* a, const std::int8_t* b,
                                        const std::int8_t* c, std::size_t len) {
  lane_masks m;
  for (std::size_t j = 0; j < len; ++j) {
    if (!(a[j] & b[j] & c[j] & 1)) continue;
    const int sum = a[j] + b[j] + c[j];
    m.known |= 1u << j;
    m.positive |= static_cast<unsigned>(sum == 3) << j;
    m.negative |= static_cast<unsigned>(sum == -3) << j;
  }
  return m;
}
#if defined(__SSE2__)
/// classify_lanes_scalar without a branch per lane (hand-written SSE2: the scalar loop's
/// branch mispredicted on the 5-15% of fragments not all known). a, b, c: 16 bytes each,
/// 16-byte aligned (lanes from len on are ignored).
inline lane_masks classify_lanes_sse2(const std::int8_t* a, const std::int8_t* b,
                                      const std::int8_t* c, std::size_t len) {
  const __m128i va = _mm_load_si128(reinterpret_cast<const __m128i*>(a));
  const __m128i vb = _mm_load_si128(reinterpret_cast<const __m128i*>(b));
  const __m128i vc = _mm_load_si128(reinterpret_cast<const __m128i*>(c));
  const __m128i one = _mm_set1_epi8(1);
  const __m128i known =
      _mm_cmpeq_epi8(_mm_and_si128(_mm_and_si128(va, vb), _mm_and_si128(vc, one)), one);
  const __m128i sum = _mm_add_epi8(_mm_add_epi8(va, vb), vc);
  const auto mask = [](__m128i v) { return static_cast<unsigned>(_mm_movemask_epi8(v)); };
  const unsigned lanes = (1u << len) - 1;
  lane_masks m;
  m.known = mask(known) & lanes;
  m.positive = mask(_mm_and_si128(known, _mm_cmpeq_epi8(sum, _mm_set1_epi8(3)))) & lanes;
  m.negative = mask(_mm_and_si128(known, _mm_cmpeq_epi8(sum, _mm_set1_epi8(-3)))) & lanes;
  return m;
}
#endif
/// classify_lanes_sse2 where the target has SSE2 (every x86-64), else the scalar loop.
inline lane_masks classify_lanes(const std::int8_t* a, const std::int8_t* b, const std::int8_t* c,
                                 std::size_t len) {
#if defined(__SSE2__)
  return classify_lanes_sse2(a, b, c, len);
#else
  return classify_lanes_scalar(a, b, c, len);
#endif
}

/// Counts of a candidate plane over part of a sample.
struct side_counts {
  long long splits = 0, positive = 0, negative = 0;
  /// Counts one fragment classified c (a coplanar one counts nowhere).
  void add(geom::classification c) {
    splits += c == geom::classification::straddling;
    positive += c == geom::classification::positive;
    negative += c == geom::classification::negative;
  }
};

/// Exact signs of (point, plane) pairs already asked, in a set-associative table of 64-bit
/// words (point id, plane id and sign packed in one word; a set is `ways` consecutive words,
/// newest first). Hand-written rather than a std::unordered_map: the map allocated a node per
/// entry and held about 200 KB per subtree builder even on tiny meshes; this costs 8 bytes a
/// slot, starts empty and doubles while it holds more entries than slots, up to max_slots;
/// then the oldest entry of a full set makes room. A forgotten answer is merely asked again,
/// so eviction never changes a result. (Measured, pinion / anchor_dense / fandisk: 5%, 3%, 5%
/// more exact questions than a table that never forgets, where the map asked 0%, 3%, 4% more
/// and 2 ways up to 9%; build time 3-7% lower than with the map.)
class sign_cache {
 public:
  static constexpr int unknown = 2;
  /// The sign remembered for point `id` against `plane`, or `unknown`.
  int find(std::uint32_t id, std::uint32_t plane) const {
    if (slots_.empty()) return unknown;
    const std::uint64_t key = key_of(id, plane);
    const std::uint64_t* set = &slots_[set_of(key)];
    for (std::size_t k = 0; k < ways; ++k)
      if ((set[k] >> 2) == key) return static_cast<int>(set[k] & 3) - 1;
    return unknown;
  }
  /// Remembers sign s (-1, 0 or +1) of point `id` against `plane` (not known to be held).
  void insert(std::uint32_t id, std::uint32_t plane, int s) {
    if (id >= max_id) return;  // not representable: not remembered
    if (slots_.empty()) slots_.assign(initial_slots, empty);
    place(key_of(id, plane) << 2 | static_cast<std::uint64_t>(s + 1));
    if (++entries_ > slots_.size() && slots_.size() < max_slots) grow();
  }
  /// Bytes held.
  std::size_t memory() const { return slots_.capacity() * sizeof(std::uint64_t); }

 private:
  static constexpr std::uint64_t empty = ~std::uint64_t{0};  ///< its id bits are >= max_id
  static constexpr std::uint32_t max_id = 1u << 29;
  static constexpr std::size_t ways = 8;              ///< one 64-byte cache line a set
  static constexpr std::size_t initial_slots = 256;   ///< 2 KB
  static constexpr std::size_t max_slots = 1u << 14;  ///< 128 KB
  static std::uint64_t key_of(std::uint32_t id, std::uint32_t plane) {
    return std::uint64_t{id} << 32 | plane;
  }
  /// First slot of key's set (slots_.size() is a power of two, at least `ways`).
  std::size_t set_of(std::uint64_t key) const {
    const std::uint64_t h = (key ^ key >> 29) * 0x9e3779b97f4a7c15ULL;
    return static_cast<std::size_t>(h >> 32) & (slots_.size() - ways);
  }
  /// Puts word first in its set; the set's oldest entry, if any, is forgotten.
  void place(std::uint64_t word) {
    std::uint64_t* set = &slots_[set_of(word >> 2)];
    for (std::size_t k = ways - 1; k > 0; --k) set[k] = set[k - 1];
    set[0] = word;
  }
  void grow() {
    std::vector<std::uint64_t> old(slots_.size() * 2, empty);
    old.swap(slots_);
    // Each set's oldest first, so that the newest stay in front.
    for (std::size_t k = 0; k < old.size(); k += ways)
      for (std::size_t j = k + ways; j-- > k;)
        if (old[j] != empty) place(old[j]);
  }
  std::vector<std::uint64_t> slots_;
  std::size_t entries_ = 0;  ///< inserted so far (at least the entries held)
};

/// The sampled heuristic's sample of one node, gathered: per sample fragment its source and
/// its three points, each point once (neighbouring fragments share most of their points) with
/// its centre and radius in flat arrays. Points get local indices in order of first use, so
/// the points of sample fragments [0, k) are the local points [0, upto(k)), and a candidate
/// counted in chunks from k = 0 filters each point once, when its first fragment is reached.
/// (Measured against one entry per fragment corner, side by side: builds 6-22% faster, e.g.
/// anchor_dense 28.2 -> 25.2 ms, fandisk 86 -> 71 ms; the sample's arrays 3 times smaller.)
template <class G>
class sample_batch {
 public:
  using fragment = typename G::fragment;
  /// Gathers fragments fragment_at(k), k = 0..m-1.
  template <class FragmentAt>
  void gather(const G& geom, std::size_t m, const FragmentAt& fragment_at) {
    // Local index of a point id: open addressing on a table of at least 4m slots (the 3m
    // corners' points fill at most three quarters), hand-written because it is cleared at
    // every node and holds only indices into ids_ (4 bytes a slot).
    std::size_t size = 16;
    while (size < 4 * m) size *= 2;
    table_.assign(size, empty);
    const std::size_t mask = size - 1;
    ids_.clear();
    slot_.resize(3 * m);
    source_.resize(m);
    upto_.resize(m + 1);
    upto_[0] = 0;
    for (std::size_t k = 0; k < m; ++k) {
      const fragment& f = fragment_at(k);
      source_[k] = f.source;
      for (int t = 0; t < 3; ++t) {
        const std::uint32_t id = f.v[t];
        std::size_t h =
            static_cast<std::size_t>((std::uint64_t{id} * 0x9e3779b97f4a7c15ULL) >> 32) & mask;
        while (table_[h] != empty && ids_[table_[h]] != id) h = (h + 1) & mask;
        if (table_[h] == empty) {
          table_[h] = static_cast<std::uint32_t>(ids_.size());
          ids_.push_back(id);
        }
        slot_[3 * k + t] = table_[h];
      }
      upto_[k + 1] = static_cast<std::uint32_t>(ids_.size());
    }
    // Sized once the points are known (no growth slack: the root's sample is the largest).
    const std::size_t u = ids_.size();
    x_.resize(u);
    y_.resize(u);
    z_.resize(u);
    r_.resize(u);
    for (std::size_t p = 0; p < u; ++p) {
      const vec3d& c = geom.centre(ids_[p]);
      x_[p] = c[0];
      y_[p] = c[1];
      z_[p] = c[2];
      r_[p] = geom.radius(ids_[p]);
    }
    code_.resize(ids_.size());
    best_code_.resize(ids_.size());
  }
  /// Adds the classifications of sample fragments [k0, k1) against plane `plane` (static
  /// filter sp, made from G::filter fp) to `out`; a fragment of the plane's own source is coplanar.
  /// Call for one candidate with consecutive ranges from k0 = 0: the points first used in the range
  /// get their codes here, and exact signs found are kept in the codes for the fragments after.
  void count(const G& geom, std::uint32_t plane, const static_plane& sp, const fast_plane_core& fp,
             std::size_t k0, std::size_t k1, side_counts& out, coplanar_sources& classes,
             std::size_t sources) {
    // The codes of points before upto(k0) must be this candidate's: checked, since a caller
    // that skipped or reordered ranges would silently read another plane's codes.
    if (k0 != 0 && (k0 != next_k_ || plane != counting_plane_)) out_of_order();
    next_k_ = k1;
    counting_plane_ = plane;
    const std::size_t p0 = upto_[k0], p1 = upto_[k1];
    std::int8_t* __restrict code = code_.data();
    if (sp.valid) {
      const double a0 = sp.a[0], a1 = sp.a[1], a2 = sp.a[2];
      const double n0 = sp.n[0], n1 = sp.n[1], n2 = sp.n[2];
      const double b0 = sp.b0, b1 = sp.b1;
      const double* __restrict x = x_.data();
      const double* __restrict y = y_.data();
      const double* __restrict z = z_.data();
      const double* __restrict r = r_.data();
      // static_sign over the flat arrays (codes: +1, -1 certified, 0 not). With SSE2 the
      // compiler vectorises this loop when it stores doubles, not int8; measured as fast
      // either way (pinion, anchor_dense), so int8, 8 times smaller.
      for (std::size_t p = p0; p < p1; ++p) {
        const double v = n0 * (x[p] - a0) + n1 * (y[p] - a1) + n2 * (z[p] - a2);
        const double bound = b0 + r[p] * b1;
        code[p] = static_cast<std::int8_t>((v > bound) - (v < -bound));
      }
    } else {
      std::fill(code + p0, code + p1, std::int8_t{0});
    }
    const std::uint32_t* __restrict slot = slot_.data();
    long long splits = 0, positive = 0, negative = 0;
    // Sixteen fragments at a time: their codes gathered into three byte vectors, then which
    // are all certified (or known) +-1, and of those which are positive or negative, as bit
    // masks (classify_lanes: measured 4-6% faster builds than a branch per fragment). The
    // others take the exact path below in list order, re-reading their codes: a code changes only
    // from unknown to known there, so the fragments found all known stay so.
    for (std::size_t g = k0; g < k1; g += 16) {
      const std::size_t len = std::min<std::size_t>(16, k1 - g);
      alignas(16) std::int8_t ca[16] = {}, cb[16] = {}, cc[16] = {};
      for (std::size_t j = 0; j < len; ++j) {
        const std::uint32_t* sk = slot + 3 * (g + j);
        ca[j] = code[sk[0]];
        cb[j] = code[sk[1]];
        cc[j] = code[sk[2]];
      }
      const lane_masks lm = classify_lanes(ca, cb, cc, len);
      const unsigned lanes = (1u << len) - 1;
      positive += popcount16(lm.positive);
      negative += popcount16(lm.negative);
      splits += popcount16(lm.known & ~lm.positive & ~lm.negative);
      for (unsigned rest = lanes & ~lm.known; rest != 0; rest &= rest - 1) {
        const std::size_t k = g + static_cast<std::size_t>(lowest_bit(rest));
        const std::uint32_t* sk = slot + 3 * k;
        if (source_[k] == plane || classes.same(source_[k], plane)) {  // in the plane: coplanar
          code[sk[0]] = code[sk[1]] = code[sk[2]] = zero_code;
          continue;
        }
        // Not all known: the exact predicate (the third point only when the first two do not
        // straddle), kept in the codes. Known codes are read here; only unknown ones call out.
        std::array<int, 3> sg{decode(code[sk[0]]), decode(code[sk[1]]), decode(code[sk[2]])};
        for (int t = 0; t < 2; ++t)
          if (sg[t] == unknown_code) sg[t] = ask(geom, plane, fp, sk[t], code);
        if (sg[2] == unknown_code)
          sg[2] = sg[0] * sg[1] >= 0 ? ask(geom, plane, fp, sk[2], code) : 0;
        if (sg[0] == 0 && sg[1] == 0 && sg[2] == 0) classes.join(source_[k], plane, sources);
        out.add(geom::classify_signs(sg));
      }
    }
    out.splits += splits;
    out.positive += positive;
    out.negative += negative;
  }

  /// best_sign's answer for a point whose sign was not needed (the third point of a fragment
  /// whose first two straddle the plane). Not a stored code (those are zero_code and below).
  static constexpr int unknown_code = 3;
  /// The box of sample fragment k's points (fragment_box of it, from the gathered arrays).
  point_box box(std::size_t k) const {
    point_box b;
    for (std::size_t t = 3 * k; t < 3 * k + 3; ++t) {
      const std::uint32_t p = slot_[t];
      b.add({x_[p], y_[p], z_[p]}, r_[p]);
    }
    return b;
  }
  /// Keeps the codes of the candidate just counted (when the sample is the node's whole list
  /// and the candidate was counted over all of it, its exact signs per point).
  void keep_best() { code_.swap(best_code_); }
  /// The sign kept by the last keep_best() for point t of sample fragment k: -1, 0, +1, or
  /// unknown_code where it was not needed.
  int best_sign(std::size_t k, int t) const {
    return decode(best_code_[slot_[3 * k + static_cast<std::size_t>(t)]]);
  }

 private:
  /// A point's code: +1 or -1 (certified by the filter or exact), zero_code (exactly in the
  /// plane) or 0 (not known).
  static constexpr std::int8_t zero_code = 2;
  static_assert(zero_code != unknown_code, "a stored code and best_sign's unknown differ");
  /// The sign a stored code holds: -1, 0, +1, or unknown_code (code 0: not known).
  static int decode(int c) { return (c & 1) ? c : c == zero_code ? 0 : unknown_code; }
  static constexpr std::uint32_t empty = ~0u;
  [[noreturn, gnu::cold, gnu::noinline]] static void out_of_order() {
    throw usage_error("sample_batch::count: ranges must follow one another from 0 for one plane");
  }
  /// The exact sign of local point p against `plane`, kept in its code (code: count's
  /// restrict pointer to code_, through which every access goes).
  [[gnu::noinline]] int ask(const G& geom, std::uint32_t plane, const fast_plane_core& fp,
                            std::uint32_t p, std::int8_t* code) {
    const int s = exact_sign(geom, plane, fp, ids_[p]);
    code[p] = s == 0 ? zero_code : static_cast<std::int8_t>(s);
    return s;
  }
  /// G::point_sign_of point `id` against `plane`, remembered: the lists of neighbouring nodes share
  /// most points and candidate planes (below 16 fragments every fragment is a candidate), so
  /// the same slow questions recur level after level.
  int exact_sign(const G& geom, std::uint32_t plane, const fast_plane_core& fp, std::uint32_t id) {
    if (geom.is_vertex_of(plane, id)) return 0;
    int s = memo_.find(id, plane);
    if (s != sign_cache::unknown) return s;
    s = geom.point_sign_of(plane, fp, id);
    memo_.insert(id, plane, s);
    return s;
  }
  sign_cache memo_;
  std::vector<std::uint32_t> table_;  ///< gather's hash table: local indices, or empty
  std::vector<std::uint32_t> ids_;    ///< per local point: its id
  std::vector<double> x_, y_, z_, r_;
  std::vector<std::int8_t> code_;       ///< per local point, for the candidate being counted
  std::vector<std::int8_t> best_code_;  ///< the codes kept by keep_best
  std::vector<std::uint32_t> slot_;     ///< per fragment corner (3 per fragment): local point
  std::vector<std::uint32_t> upto_;     ///< upto_[k]: local points used by fragments [0, k)
  std::vector<std::uint32_t> source_;
  std::size_t next_k_ = 0;              ///< where the candidate being counted goes on
  std::uint32_t counting_plane_ = ~0u;  ///< the candidate being counted
};

}  // namespace detail
}  // namespace exbsp
