// Definitions of bsp_tree<K> and the split functions. Included only by the per-kernel
// translation units (bsp_<kernel>.cpp), which instantiate them explicitly.
// Notation: see bsp_tree.h. Heuristic indices: 0 naive, 1 min-split, 2 sampled, 3 random.
#pragma once
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <deque>
#include <exception>
#include <iterator>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "bsp/bsp_impl.h"
#include "bsp/bsp_tree.h"
#include "bsp/exact_output.h"
#include "bsp/fast_orientation.h"
#include "bsp/kernel_traits.h"
#include "mesh/errors.h"

namespace exbsp {
namespace detail {

/// splitmix64: a fixed, portable mixing function (the same stream on every machine,
/// unlike std::uniform_int_distribution).
inline std::uint64_t mix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

int heuristic_index(const std::string& name);

/// Sign of orientation(plane, vertex k of f): the certified double filter first where the
/// kernel allows it and the vertex has exact double coordinates, else the kernel's predicate.
template <class K, class Fragment>
inline int vertex_sign(const std::array<typename K::Point_3, 3>& plane, const fast_plane& fast,
                       const Fragment& f, int k) {
  if constexpr (kernel_traits<K>::fast_path) {
    if ((f.double_mask >> k) & 1) {
      const int s = fast_sign(fast, f.d[k], f.r[k]);
      if (s != 2) return s;
    }
  }
  return static_cast<int>(K().orientation_3_object()(plane[0], plane[1], plane[2], f.v[k]));
}

template <class K, class Fragment>
inline std::array<int, 3> signs_against(const std::array<typename K::Point_3, 3>& plane,
                                        const fast_plane& fast, const Fragment& f) {
  return {vertex_sign<K>(plane, fast, f, 0), vertex_sign<K>(plane, fast, f, 1),
          vertex_sign<K>(plane, fast, f, 2)};
}

/// OpenMP team size for a requested thread count (0: all cores).
inline int threads_for(unsigned requested) {
  return requested ? static_cast<int>(requested) : omp_get_max_threads();
}

/// True when f straddles the plane; sets `coplanar` when all three signs are 0.
/// Skips the third predicate when the first two already have opposite signs.
template <class K, class Fragment>
inline bool straddles(const std::array<typename K::Point_3, 3>& plane, const fast_plane& fast,
                      const Fragment& f, bool& coplanar) {
  const int s0 = vertex_sign<K>(plane, fast, f, 0);
  const int s1 = vertex_sign<K>(plane, fast, f, 1);
  coplanar = false;
  if (s0 * s1 < 0) return true;
  const int s2 = vertex_sign<K>(plane, fast, f, 2);
  if (s0 == 0 && s1 == 0 && s2 == 0) {
    coplanar = true;
    return false;
  }
  const int lo = std::min({s0, s1, s2}), hi = std::max({s0, s1, s2});
  return lo < 0 && hi > 0;
}

}  // namespace detail

namespace detail {
/// The point where [p,q] meets the plane through `a` with normal n (n = (b-a)x(c-a)).
template <class K>
typename K::Point_3 intersect_with_normal(const typename K::Point_3& a, const typename K::Vector_3& n,
                                          const typename K::Point_3& p, const typename K::Point_3& q) {
  if constexpr (kernel_traits<K>::direct_intersection) {
    return kernel_traits<K>::intersection(a, n, p, q);
  }
  using FT = typename K::FT;
  const FT fp = n * (p - a);
  const FT fq = n * (q - a);
  const FT t = fp / (fp - fq);
  typename K::Point_3 x = p + t * (q - p);
  kernel_traits<K>::collapse(x);
  return x;
}

template <class K>
typename K::Vector_3 plane_normal(const std::array<typename K::Point_3, 3>& plane) {
  typename K::Vector_3 n = CGAL::cross_product(plane[1] - plane[0], plane[2] - plane[0]);
  kernel_traits<K>::collapse_vector(n);
  return n;
}

template <class K>
split_pieces<K> split_with_normal(const std::array<typename K::Point_3, 3>& plane,
                                  const typename K::Vector_3& normal,
                                  const std::array<typename K::Point_3, 3>& t,
                                  const std::array<int, 3>& s);
}  // namespace detail

template <class K>
typename K::Point_3 plane_segment_intersection(const std::array<typename K::Point_3, 3>& plane,
                                               const typename K::Point_3& p,
                                               const typename K::Point_3& q) {
  return detail::intersect_with_normal<K>(plane[0], detail::plane_normal<K>(plane), p, q);
}

template <class K>
split_pieces<K> split_triangle(const std::array<typename K::Point_3, 3>& plane,
                               const std::array<typename K::Point_3, 3>& t,
                               const std::array<int, 3>& s) {
  if (classify_signs(s) != classification::straddling)
    throw usage_error("split_triangle: the triangle does not straddle the plane");
  return detail::split_with_normal<K>(plane, detail::plane_normal<K>(plane), t, s);
}

template <class K>
split_pieces<K> detail::split_with_normal(const std::array<typename K::Point_3, 3>& plane,
                                          const typename K::Vector_3& normal,
                                          const std::array<typename K::Point_3, 3>& t,
                                          const std::array<int, 3>& s) {
  split_pieces<K> out;
  const int zero = s[0] == 0 ? 0 : s[1] == 0 ? 1 : s[2] == 0 ? 2 : -1;
  if (zero < 0) {
    // c is the vertex alone on its side; (a,b,c) is a cyclic relabelling of t.
    int lone = 0;
    for (int i = 0; i < 3; ++i)
      if (s[i] != s[(i + 1) % 3] && s[i] != s[(i + 2) % 3]) lone = i;
    const auto& c = t[lone];
    const auto& a = t[(lone + 1) % 3];
    const auto& b = t[(lone + 2) % 3];
    const auto A = intersect_with_normal<K>(plane[0], normal, c, a);
    const auto B = intersect_with_normal<K>(plane[0], normal, b, c);
    out.piece[0] = {a, b, A};
    out.piece[1] = {b, B, A};
    out.piece[2] = {A, B, c};
    out.side = {s[(lone + 1) % 3], s[(lone + 1) % 3], s[lone]};
    const int ia = (lone + 1) % 3, ib = (lone + 2) % 3, ic = lone;
    out.origin = {{{ia, ib, -1}, {ib, -1, -1}, {-1, -1, ic}}};
    out.count = 3;
  } else {
    const auto& z = t[zero];
    const auto& a = t[(zero + 1) % 3];
    const auto& b = t[(zero + 2) % 3];
    const auto X = intersect_with_normal<K>(plane[0], normal, a, b);
    out.piece[0] = {z, a, X};
    out.piece[1] = {z, X, b};
    out.side = {s[(zero + 1) % 3], s[(zero + 2) % 3], 0};
    const int ia = (zero + 1) % 3, ib = (zero + 2) % 3;
    out.origin = {{{zero, ia, -1}, {zero, -1, ib}, {-1, -1, -1}}};
    out.count = 2;
  }
  return out;
}

/// Shared state of one build: options, counters updated by all threads, the failure flag.
template <class K>
struct bsp_tree<K>::build_context {
  build_context(const build_options& o, int h, std::chrono::steady_clock::time_point t)
      : options(o), heuristic(h), start(t) {}
  const build_options& options;
  int heuristic;
  std::chrono::steady_clock::time_point start;
  std::atomic<std::size_t> total_fragments{0}, splits{0}, placed{0}, nodes{0};
  std::atomic<bool> failed{false};
  /// Counts `added` new fragments; throws limit_error beyond options.max_fragments.
  void check_limit(std::size_t added) {
    const std::size_t total = total_fragments.fetch_add(added, std::memory_order_relaxed) + added;
    if (options.max_fragments && total > options.max_fragments)
      throw limit_error("fragment limit exceeded: the tree needs more than " +
                        std::to_string(options.max_fragments) + " fragments (--max-fragments)");
  }
};

template <class K>
bsp_tree<K>::bsp_tree(const triangle_soup& soup, const build_options& options) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const int heuristic = detail::heuristic_index(options.heuristic);
  stats_.kernel = to_string(kernel_traits<K>::id);
  stats_.heuristic = options.heuristic;
  stats_.input_triangles = soup.triangles.size();

  for (std::size_t i = 0; i < soup.vertices.size(); ++i)
    for (double x : soup.vertices[i])
      if (!std::isfinite(x))
        throw usage_error("bsp build: vertex " + std::to_string(i) + " has a non-finite coordinate");

  // Input points, and the exactly degenerate (collinear) triangles skipped: Epick's collinear
  // predicate is exact on double input, so every kernel skips the same triangles.
  const auto collinear = CGAL::Epick().collinear_3_object();
  sources_.resize(soup.triangles.size());
  fast_.resize(soup.triangles.size());
  // Fragments live in pool_ (split parents stay there, dead, until the build ends); work
  // lists hold indices, so moving a list down the tree moves 4 bytes per fragment.
  pool_.reserve(soup.triangles.size());
  std::vector<std::uint32_t> root_list;
  root_list.reserve(soup.triangles.size());
  for (std::size_t i = 0; i < soup.triangles.size(); ++i) {
    const soup_triangle& st = soup.triangles[i];
    std::array<CGAL::Epick::Point_3, 3> q;
    for (int k = 0; k < 3; ++k) {
      const vec3d& v = soup.vertices.at(st.v[k]);
      q[k] = CGAL::Epick::Point_3(v[0], v[1], v[2]);
      sources_[i][k] = point(v[0], v[1], v[2]);
    }
    if (collinear(q[0], q[1], q[2])) {
      ++stats_.degenerate_input;
      continue;
    }
    const vec3d& a = soup.vertices[st.v[0]];
    const vec3d& b = soup.vertices[st.v[1]];
    const vec3d& c = soup.vertices[st.v[2]];
    fast_[i] = make_fast_plane(a, b, c);
    root_list.push_back(static_cast<std::uint32_t>(pool_.size()));
    pool_.push_back({sources_[i], {a, b, c}, {0, 0, 0}, 7, static_cast<std::uint32_t>(i), st.face});
  }

  // The build runs in two phases with the same per-node step (grow): the top levels
  // breadth-first on this thread until there are `frontier_size` pending subtrees, then those
  // subtrees in parallel, each into its own node list and piece pool, merged in frontier order.
  // Heuristic seeds come from each node's path key, not from a creation counter, and the
  // frontier size is fixed, so the tree is the same for any number of threads.
  build_context ctx(options, heuristic, start);
  ctx.check_limit(root_list.size());
  std::deque<work> queue;
  if (!root_list.empty()) queue.push_back({std::move(root_list), -1, 0, 1, 1});
  subtree top;
  constexpr std::size_t frontier_size = 16;
  while (!queue.empty() && queue.size() < frontier_size) {
    work w = std::move(queue.front());
    queue.pop_front();
    grow_node(std::move(w), top, ctx, [&](work&& child) { queue.push_back(std::move(child)); });
  }
  // Top pieces join the shared read-only pool; refs to them become plain pool indices.
  const auto top_base = static_cast<std::uint32_t>(pool_.size());
  for (fragment& f : top.pieces) pool_.push_back(std::move(f));
  top.pieces.clear();
  const auto remap = [](std::uint32_t ref, std::uint32_t base) {
    return (ref & local_ref) ? base + (ref & ~local_ref) : ref;
  };
  for (std::uint32_t& ref : top.node_fragments) ref = remap(ref, top_base);
  for (work& w : queue)
    for (std::uint32_t& ref : w.list) ref = remap(ref, top_base);
  append_subtree(top);

  std::vector<work> frontier(std::make_move_iterator(queue.begin()), std::make_move_iterator(queue.end()));
  queue.clear();
  std::vector<subtree> parts(frontier.size());
  std::exception_ptr failure;
  const long long count = static_cast<long long>(frontier.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(detail::threads_for(options.threads))
  for (long long i = 0; i < count; ++i) {
    try {
      subtree& part = parts[static_cast<std::size_t>(i)];
      part.root_parent = frontier[static_cast<std::size_t>(i)].parent;
      part.root_side = frontier[static_cast<std::size_t>(i)].side;
      frontier[static_cast<std::size_t>(i)].parent = -1;  // local to the part from here on
      std::vector<work> stack;
      stack.push_back(std::move(frontier[static_cast<std::size_t>(i)]));
      while (!stack.empty() && !ctx.failed.load(std::memory_order_relaxed)) {
        work w = std::move(stack.back());
        stack.pop_back();
        grow_node(std::move(w), part, ctx, [&](work&& child) { stack.push_back(std::move(child)); });
      }
    } catch (...) {
#pragma omp critical(exbsp_bsp_failure)
      if (!failure) failure = std::current_exception();
      ctx.failed.store(true);
    }
  }
  if (failure) std::rethrow_exception(failure);
  for (subtree& part : parts) {
    const auto base = static_cast<std::uint32_t>(pool_.size());
    for (fragment& f : part.pieces) pool_.push_back(std::move(f));
    part.pieces.clear();
    for (std::uint32_t& ref : part.node_fragments) ref = remap(ref, base);
    append_subtree(part);
  }

  fragments_.reserve(node_fragments_.size());
  for (std::uint32_t index : node_fragments_) fragments_.push_back(std::move(pool_[index]));
  std::vector<fragment>().swap(pool_);
  std::vector<std::uint32_t>().swap(node_fragments_);
  stats_.splits = ctx.splits.load();
  stats_.fragments = fragments_.size();
  stats_.nodes = nodes_.size();
  stats_.build_seconds = std::chrono::duration<double>(clock::now() - start).count();
  stats_.peak_rss_bytes = peak_rss_bytes();
  if (options.progress)
    options.progress({fragments_.size(), ctx.total_fragments.load(), nodes_.size(), stats_.build_seconds});
}

template <class K>
void bsp_tree<K>::append_subtree(subtree& part) {
  const auto node_base = static_cast<std::int32_t>(nodes_.size());
  const auto fragment_base = static_cast<std::uint32_t>(node_fragments_.size());
  node_fragments_.insert(node_fragments_.end(), part.node_fragments.begin(), part.node_fragments.end());
  for (node nd : part.nodes) {
    nd.first += fragment_base;
    if (nd.negative >= 0) nd.negative += node_base;
    if (nd.positive >= 0) nd.positive += node_base;
    if (nd.parent >= 0) {
      nd.parent += node_base;
    } else if (part.root_parent >= 0) {  // the part's root hangs below a node built earlier
      nd.parent = part.root_parent;
      nd.side_in_parent = part.root_side;
      node& parent = nodes_[part.root_parent];
      (part.root_side > 0 ? parent.positive : parent.negative) = static_cast<std::int32_t>(nodes_.size());
    }
    stats_.depth = std::max<std::size_t>(stats_.depth, nd.depth);
    nodes_.push_back(nd);
  }
  part.nodes.clear();
  part.node_fragments.clear();
}

template <class K>
template <class PushChild>
void bsp_tree<K>::grow_node(work&& w, subtree& part, build_context& ctx, PushChild&& push_child) {
  const auto fragment_at = [&](std::uint32_t ref) -> const fragment& { return resolve(part, ref); };
  const build_options& options = ctx.options;
  const std::size_t splitter = choose_splitter(w.list, part, ctx.heuristic, options.seed, w.key, options.threads);
  const std::uint32_t plane_source = fragment_at(w.list[splitter]).source;
  const triangle& plane = sources_[plane_source];
  const fast_plane& fast = fast_[plane_source];
  std::optional<vector> normal;  // computed once per node, at its first split

  const auto id = static_cast<std::int32_t>(part.nodes.size());
  node nd;
  nd.plane_source = plane_source;
  nd.first = static_cast<std::uint32_t>(part.node_fragments.size());
  nd.parent = w.parent;
  nd.side_in_parent = w.side;
  nd.depth = w.depth;
  if (w.parent >= 0) (w.side > 0 ? part.nodes[w.parent].positive : part.nodes[w.parent].negative) = id;

  // Side tests first (in parallel for very long lists: they dominate degenerate trees), then
  // the sequential, order-keeping distribution with the exact splits.
  const std::size_t n = w.list.size();
  std::vector<std::array<std::int8_t, 3>> signs(n);
  const long long nn = static_cast<long long>(n);
#pragma omp parallel for schedule(static) if (n > 65536) num_threads(detail::threads_for(options.threads))
  for (long long jj = 0; jj < nn; ++jj) {
    const auto j = static_cast<std::size_t>(jj);
    // A fragment lies exactly in its source's plane: coplanar by construction. (Exact
    // kernels would find the same; rounded ones could not, and would loop forever.)
    const fragment& f = fragment_at(w.list[j]);
    if (f.source == plane_source) {
      signs[j] = {0, 0, 0};
      continue;
    }
    const std::array<int, 3> sj = detail::signs_against<K>(plane, fast, f);
    signs[j] = {static_cast<std::int8_t>(sj[0]), static_cast<std::int8_t>(sj[1]),
                static_cast<std::int8_t>(sj[2])};
  }
  std::vector<std::uint32_t> negative, positive;
  for (std::size_t j = 0; j < n; ++j) {
    const std::uint32_t ref = w.list[j];
    const std::array<int, 3> s{signs[j][0], signs[j][1], signs[j][2]};
    switch (classify_signs(s)) {
      case classification::coplanar: part.node_fragments.push_back(ref); break;
      case classification::positive: positive.push_back(ref); break;
      case classification::negative: negative.push_back(ref); break;
      case classification::straddling: {
        if (!normal) normal = detail::plane_normal<K>(plane);
        const fragment parent = fragment_at(ref);  // a copy: part.pieces may grow below
        const split_pieces<K> pieces = detail::split_with_normal<K>(plane, *normal, parent.v, s);
        ctx.splits.fetch_add(1, std::memory_order_relaxed);
        ctx.check_limit(static_cast<std::size_t>(pieces.count - 1));
        for (int k = 0; k < pieces.count; ++k) {
          (pieces.side[k] > 0 ? positive : negative)
              .push_back(local_ref | static_cast<std::uint32_t>(part.pieces.size()));
          part.pieces.push_back(make_piece(parent, pieces, k));
        }
        break;
      }
    }
  }
  nd.count = static_cast<std::uint32_t>(part.node_fragments.size() - nd.first);
  part.nodes.push_back(nd);
  const std::uint64_t key = w.key;
  const std::uint32_t depth = w.depth;
  w.list.clear();
  w.list.shrink_to_fit();
  if (!positive.empty()) push_child({std::move(positive), id, +1, depth + 1, detail::mix64(key * 2 + 1)});
  if (!negative.empty()) push_child({std::move(negative), id, -1, depth + 1, detail::mix64(key * 2)});

  const std::size_t placed = ctx.placed.fetch_add(nd.count, std::memory_order_relaxed) + nd.count;
  const std::size_t nodes = ctx.nodes.fetch_add(1, std::memory_order_relaxed) + 1;
  if (options.progress && (nodes & 255) == 0 && omp_get_thread_num() == 0)
    options.progress({placed, ctx.total_fragments.load(std::memory_order_relaxed), nodes,
                      std::chrono::duration<double>(std::chrono::steady_clock::now() - ctx.start).count()});
}

template <class K>
typename bsp_tree<K>::fragment bsp_tree<K>::make_piece(const fragment& parent,
                                                       const split_pieces<K>& pieces, int i) {
  // Vertices taken from the parent keep their approximations; constructed ones get one from
  // the kernel where it has one (Epick: the point itself; Epeck: its interval approximation).
  const triangle& piece = pieces.piece[i];
  fragment out{piece, {}, {0, 0, 0}, 0, parent.source, parent.face};
  for (int k = 0; k < 3; ++k) {
    const int m = pieces.origin[i][k];
    if (m >= 0 && ((parent.double_mask >> m) & 1)) {
      out.d[k] = parent.d[m];
      out.r[k] = parent.r[m];
      out.double_mask |= static_cast<std::uint8_t>(1u << k);
    } else if (m < 0 && kernel_traits<K>::approximate(piece[k], out.d[k], out.r[k])) {
      out.double_mask |= static_cast<std::uint8_t>(1u << k);
    }
  }
  return out;
}

template <class K>
std::size_t bsp_tree<K>::choose_splitter(const std::vector<std::uint32_t>& list, const subtree& part,
                                         int heuristic, std::uint64_t seed, std::uint64_t node_key,
                                         unsigned threads) const {
  if (list.size() <= 1) return 0;
  switch (heuristic) {
    case 0: return 0;
    case 1: return choose_min_split(list, part, threads);
    case 2: return choose_sampled(list, part, seed, node_key);
    default: return detail::mix64(seed ^ detail::mix64(node_key)) % list.size();
  }
}

// min-split: the fragment whose plane straddles the fewest others, ties to the earliest.
// Candidates are ranked by the key (count, index). The best complete key so far bounds the
// rest: candidate j stops as soon as (count so far, j) can no longer beat it, so once a plane
// with 0 straddlers is found at i, every later candidate is skipped at once. A fragment found
// coplanar with an earlier candidate has the same count and loses the tie: it is skipped.
// Candidates run in parallel; the result does not depend on scheduling.
template <class K>
std::size_t bsp_tree<K>::choose_min_split(const std::vector<std::uint32_t>& list, const subtree& part,
                                          unsigned threads) const {
  const auto fragment_at = [&](std::uint32_t ref) -> const fragment& { return resolve(part, ref); };
  const std::size_t n = list.size();
  std::vector<std::atomic<unsigned char>> same_plane(n);
  for (auto& f : same_plane) f.store(0, std::memory_order_relaxed);
  const auto key = [](std::uint64_t count, std::uint64_t index) { return count << 32 | index; };
  std::atomic<std::uint64_t> best{std::numeric_limits<std::uint64_t>::max()};
  const long long nn = static_cast<long long>(n);
#pragma omp parallel for schedule(dynamic, 8) if (n > 64) num_threads(detail::threads_for(threads))
  for (long long ii = 0; ii < nn; ++ii) {
    const auto i = static_cast<std::uint64_t>(ii);
    if (same_plane[i].load(std::memory_order_relaxed)) continue;
    if (key(0, i) >= best.load(std::memory_order_relaxed)) continue;
    const fragment& candidate = fragment_at(list[i]);
    const triangle& plane = sources_[candidate.source];
    const fast_plane& fast = fast_[candidate.source];
    std::uint64_t c = 0;
    bool complete = true;
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      const fragment& other = fragment_at(list[j]);
      bool coplanar = other.source == candidate.source;
      if (!coplanar && detail::straddles<K>(plane, fast, other, coplanar)) {
        if (key(++c, i) >= best.load(std::memory_order_relaxed)) {
          complete = false;
          break;
        }
      } else if (coplanar && j > i) {
        same_plane[j].store(1, std::memory_order_relaxed);
      }
    }
    if (!complete) continue;
    std::uint64_t b = best.load(std::memory_order_relaxed);
    const std::uint64_t mine = key(c, i);
    while (mine < b && !best.compare_exchange_weak(b, mine, std::memory_order_relaxed)) {
    }
  }
  return static_cast<std::size_t>(best.load() & 0xffffffffu);
}

// sampled: up to 16 candidates drawn with the seed, each scored on an evenly spaced sample
// of at most 512 fragments by 8 * splits + |positive - negative| (the split/balance score of
// classic BSP compilers); lowest score wins, ties to the earliest candidate.
template <class K>
std::size_t bsp_tree<K>::choose_sampled(const std::vector<std::uint32_t>& list, const subtree& part,
                                        std::uint64_t seed, std::uint64_t node_key) const {
  const auto fragment_at = [&](std::uint32_t ref) -> const fragment& { return resolve(part, ref); };
  const std::size_t n = list.size();
  constexpr std::size_t max_candidates = 16, max_sample = 512;
  std::vector<std::size_t> candidates;
  if (n <= max_candidates) {
    for (std::size_t i = 0; i < n; ++i) candidates.push_back(i);
  } else {
    const std::uint64_t h = detail::mix64(seed ^ detail::mix64(node_key + 0x51ed));
    for (std::size_t k = 0; k < max_candidates; ++k) candidates.push_back(detail::mix64(h + k) % n);
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  }
  const std::size_t m = std::min(n, max_sample);
  std::size_t best = candidates.front();
  long long best_score = std::numeric_limits<long long>::max();
  for (std::size_t i : candidates) {
    const fragment& candidate = fragment_at(list[i]);
    const triangle& plane = sources_[candidate.source];
    const fast_plane& fast = fast_[candidate.source];
    long long splits = 0, pos = 0, neg = 0, score = 0;
    for (std::size_t k = 0; k < m && score < best_score; ++k) {
      const std::size_t j = k * n / m;
      const fragment& other = fragment_at(list[j]);
      if (other.source == candidate.source) continue;  // coplanar by construction
      switch (classify_signs(detail::signs_against<K>(plane, fast, other))) {
        case classification::straddling: ++splits; break;
        case classification::positive: ++pos; break;
        case classification::negative: ++neg; break;
        case classification::coplanar: break;
      }
      score = 8 * splits;
    }
    score = 8 * splits + std::llabs(pos - neg);
    if (score < best_score) {
      best_score = score;
      best = i;
    }
  }
  return best;
}

template <class K>
std::size_t bsp_tree<K>::node_of_fragment(std::size_t i) const {
  // Nodes are created in build order and append their fragments as they are created,
  // so node.first is non-decreasing with the node index.
  if (i >= fragments_.size()) throw usage_error("node_of_fragment: index out of range");
  const auto it = std::upper_bound(nodes_.begin(), nodes_.end(), i,
                                   [](std::size_t v, const node& nd) { return v < nd.first; });
  return static_cast<std::size_t>(std::prev(it) - nodes_.begin());
}

template <class K>
template <class SideOf>
std::vector<std::uint32_t> bsp_tree<K>::traverse(SideOf side_of, bool back_to_front) const {
  std::vector<std::uint32_t> out;
  out.reserve(fragments_.size());
  if (nodes_.empty()) return out;
  struct task {
    std::int32_t node;
    bool emit;
  };
  std::vector<task> stack{{0, false}};
  while (!stack.empty()) {
    const task t = stack.back();
    stack.pop_back();
    const node& nd = nodes_[t.node];
    if (t.emit) {
      for (std::uint32_t k = 0; k < nd.count; ++k) out.push_back(nd.first + k);
      continue;
    }
    const int s = side_of(sources_[nd.plane_source]);
    // s > 0: negative, list, positive; s < 0: positive, list, negative; s = 0: as s > 0.
    const std::int32_t first = s < 0 ? nd.positive : nd.negative;
    const std::int32_t second = s < 0 ? nd.negative : nd.positive;
    if (second >= 0) stack.push_back({second, false});
    stack.push_back({t.node, true});
    if (first >= 0) stack.push_back({first, false});
  }
  if (!back_to_front) std::reverse(out.begin(), out.end());
  return out;
}

template <class K>
std::vector<std::uint32_t> bsp_tree<K>::order_from_eye(const point& eye, bool back_to_front) const {
  const auto orientation = K().orientation_3_object();
  return traverse([&](const triangle& p) { return static_cast<int>(orientation(p[0], p[1], p[2], eye)); },
                  back_to_front);
}

template <class K>
std::vector<std::uint32_t> bsp_tree<K>::order_for_direction(const vector& d, bool back_to_front) const {
  const vector towards_eye = -d;
  return traverse(
      [&](const triangle& p) {
        return static_cast<int>(CGAL::sign(CGAL::cross_product(p[1] - p[0], p[2] - p[0]) * towards_eye));
      },
      back_to_front);
}

/// The kernel-specific implementation behind exbsp::bsp.
template <class K>
class bsp_kernel_impl final : public bsp_impl {
public:
  bsp_kernel_impl(const triangle_soup& soup, const build_options& options) : tree_(soup, options) {}
  const build_stats& stats() const override { return tree_.stats(); }
  kernel_id kernel() const override { return kernel_traits<K>::id; }
  std::size_t fragment_count() const override { return tree_.fragments().size(); }
  fragment_d fragment(std::size_t i) const override {
    const auto& f = tree_.fragments().at(i);
    fragment_d out{f.face, {}};
    for (int k = 0; k < 3; ++k)
      out.v[k] = {kernel_traits<K>::to_double(f.v[k].x()), kernel_traits<K>::to_double(f.v[k].y()),
                  kernel_traits<K>::to_double(f.v[k].z())};
    return out;
  }
  exact_triangle fragment_exact(std::size_t i) const override {
    if constexpr (kernel_traits<K>::exact) {
      const auto& f = tree_.fragments().at(i);
      exact_triangle out;
      for (int k = 0; k < 3; ++k) {
        out[k][0] = rational_to_string(kernel_traits<K>::rational(f.v[k].x()));
        out[k][1] = rational_to_string(kernel_traits<K>::rational(f.v[k].y()));
        out[k][2] = rational_to_string(kernel_traits<K>::rational(f.v[k].z()));
      }
      return out;
    } else {
      (void)i;
      throw usage_error("exact coordinates need an exact kernel (epeck or gmpq), not " +
                        to_string(kernel_traits<K>::id));
    }
  }
  std::vector<std::uint32_t> order_from_eye(const vec3d& e, bool back_to_front) const override {
    return tree_.order_from_eye(typename K::Point_3(e[0], e[1], e[2]), back_to_front);
  }
  std::vector<std::uint32_t> order_for_direction(const vec3d& d, bool back_to_front) const override {
    return tree_.order_for_direction(typename K::Vector_3(d[0], d[1], d[2]), back_to_front);
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

private:
  bsp_tree<K> tree_;
};

}  // namespace exbsp

/// Explicit instantiation of everything kernel-specific, for one kernel K, with the factory
/// make_bsp_<NAME>. Used once per kernel translation unit.
#define EXBSP_INSTANTIATE_BSP(K, NAME)                                                          \
  namespace exbsp {                                                                             \
  template struct split_pieces<K>;                                                              \
  template split_pieces<K> split_triangle<K>(const std::array<K::Point_3, 3>&,                  \
                                             const std::array<K::Point_3, 3>&,                  \
                                             const std::array<int, 3>&);                        \
  template K::Point_3 plane_segment_intersection<K>(const std::array<K::Point_3, 3>&,           \
                                                    const K::Point_3&, const K::Point_3&);      \
  template class bsp_tree<K>;                                                                   \
  std::unique_ptr<bsp_impl> make_bsp_##NAME(const triangle_soup& soup, const build_options& o) { \
    return std::make_unique<bsp_kernel_impl<K>>(soup, o);                                       \
  }                                                                                             \
  }
