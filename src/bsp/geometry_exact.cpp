// SPDX-License-Identifier: LGPL-3.0-or-later
// exbsp's exact geometry: point table, certified approximations, exact fallback.
// Notation: see geometry_exact.h. u = 2^-53 (unit roundoff).
#include "bsp/geometry_exact.h"
#include "bsp/packed_integers.h"
#include "bsp/parallel.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <gmpxx.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

#include <exbsp/core/errors.h>
#include <exbsp/mesh/gmp_memory.h>
#include "bsp/exact_output.h"
#include "geom/rational.h"

namespace exbsp {

/// A point's exact coordinates in homogeneous integers: the point is x / w, w > 0. The
/// fraction is not reduced (only common factors of two are removed): a gcd per operation
/// was most of the exact fallback's time (pinion: GMP's gcd 12% of the build). Reduced
/// rationals are made once per point, at output.
/// Kept packed (bsp/packed_integers.h): X, Y, Z, W; views()[3] is w.
struct exact_geometry::exact_value {
  detail::packed_integers xw;
};
/// Plane of an input triangle (a, b, c) in integers: f(x) = n.x - d is a positive multiple of
/// the orientation determinant (a, b, c, x) (plane_of: the vertices as integers over one
/// power of two). So for a point X / w (w > 0), orientation(a, b, c, X / w) = sign(n.X - d w).
/// Kept packed: views() are n[0], n[1], n[2], d.
struct exact_geometry::exact_plane {
  detail::packed_integers nd;
};

namespace {
constexpr double u = 1.1102230246251565e-16;

int sign_of(const mpq_class& q) { return sgn(q); }

/// The coordinates of `count` double points as integers over one power of two: point i is
/// (out[3i], out[3i+1], out[3i+2]) / 2^shift, exactly (a double is m 2^e with an integer m).
/// Returns shift, the smallest that makes every coordinate an integer (0 when all are).
mp_bitcnt_t to_integers(const vec3d* points, int count, mpz_class* out) {
  std::array<int, 9> e{};
  std::array<double, 9> m{};
  int shift = 0;
  for (int i = 0; i < 3 * count; ++i) {
    const double c = points[i / 3][i % 3];
    if (c == 0) continue;
    m[i] = std::ldexp(std::frexp(c, &e[i]), 53);  // an integer below 2^53, exactly
    e[i] -= 53;
    shift = std::max(shift, -e[i]);
  }
  for (int i = 0; i < 3 * count; ++i) {
    out[i] = m[i];
    if (m[i] != 0) mpz_mul_2exp(out[i].get_mpz_t(), out[i].get_mpz_t(), e[i] + shift);
  }
  return static_cast<mp_bitcnt_t>(shift);
}

/// Divides x[0..2] and w by their largest common power of two (cheap, unlike a gcd; it keeps
/// the dyadic input's scale factors from piling up along nested constructions).
void remove_common_twos(std::array<mpz_class, 3>& x, mpz_class& w) {
  mp_bitcnt_t shift = mpz_scan1(w.get_mpz_t(), 0);
  for (const mpz_class& c : x)
    if (sgn(c) != 0) shift = std::min(shift, mpz_scan1(c.get_mpz_t(), 0));
  if (shift == 0) return;
  for (mpz_class& c : x) mpz_fdiv_q_2exp(c.get_mpz_t(), c.get_mpz_t(), shift);
  mpz_fdiv_q_2exp(w.get_mpz_t(), w.get_mpz_t(), shift);
}

/// The smallest float >= x (x >= 0; +inf beyond the float range): a radius or error bound
/// stored in 4 bytes stays a bound.
float round_up_to_float(double x) {
  if (!(x <= FLT_MAX)) return std::numeric_limits<float>::infinity();  // NaN too
  float f = static_cast<float>(x);
  if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

/// Distance from x to the next double away from zero (an upper bound on the rounding error
/// of a round-to-nearest result x, with room to spare).
double ulp_of(double x) {
  const double a = std::fabs(x);
  return std::nextafter(a, std::numeric_limits<double>::infinity()) - a;
}
}  // namespace

exact_geometry::exact_geometry(const triangle_soup& soup) : sources_(soup.triangles.size()) {
  if (soup.vertices.size() >= (std::size_t{1} << (max_point_bits - 1)))
    throw limit_error("bsp build: too many vertices for the exact kernel's point table");
  // Input vertices are points 0 .. V-1, exactly their doubles.
  inputs_ = static_cast<std::uint32_t>(soup.vertices.size());
  rearm_gmp_memory_reserve();  // memory a failed build held may be free again
  {
    const std::lock_guard<std::mutex> lock(claim_mutex_);
    grow_chunks(inputs_);
    claimed_ = inputs_;
  }
  for (std::uint32_t i = 0; i < inputs_; ++i) at(i).c = soup.vertices[i];
}

exact_geometry::~exact_geometry() = default;

void exact_geometry::grow_chunks(std::uint32_t end) {
  const std::size_t needed = (std::size_t{end} + chunk_size - 1) >> chunk_bits;
  if (needed == 0) return;
  if (needed > table_size_) {
    // A larger table, published after its slots are copied; the old one stays readable.
    const std::size_t size = std::max({needed, 2 * table_size_, std::size_t{16}});
    std::unique_ptr<point*[]> table(new point*[size]());
    for (std::size_t c = 0; c < chunks_.size(); ++c) table[c] = chunks_[c].get();
    chunk_table_.store(table.get(), std::memory_order_release);
    chunk_tables_.push_back(std::move(table));
    table_size_ = size;
  }
  point** table = chunk_tables_.back().get();
  while (chunks_.size() < needed) {
    chunks_.emplace_back(new point[chunk_size]);
    table[chunks_.size() - 1] = chunks_.back().get();
  }
}

namespace {

/// The entry of `id` in a store with slots (1 + index; 0: none), or nullptr.
template <class T>
const T* stored(const std::deque<T>& store, const std::vector<std::uint32_t>& slot,
                std::uint32_t id) {
  return id < slot.size() && slot[id] != 0 ? &store[slot[id] - 1] : nullptr;
}

/// Keeps `made` as the entry of `id` unless one is there already (the first one stays).
template <class T>
const T& keep(std::deque<T>& store, std::vector<std::uint32_t>& slot, std::uint32_t id, T&& made) {
  if (const T* known = stored(store, slot, id)) return *known;
  if (id >= slot.size()) slot.resize(std::max<std::size_t>(id + 1, slot.size() * 3 / 2), 0);
  store.push_back(std::move(made));
  slot[id] = static_cast<std::uint32_t>(store.size());
  return store.back();
}

}  // namespace

const exact_geometry::exact_value* exact_geometry::find_exact(std::uint32_t id) const {
  const std::lock_guard<std::mutex> lock(exact_mutex_);
  return stored(exact_store_, exact_slot_, id);
}

void exact_geometry::claim_block(scratch& sc) {
  const std::lock_guard<std::mutex> lock(claim_mutex_);
  if (claimed_ > (std::uint32_t{1} << max_point_bits) - 2 * block)
    throw limit_error("bsp build: more than 2^28 points in the exact kernel's point table");
  sc.next = claimed_;
  sc.end = claimed_ + block;
  claimed_ += block;
  grow_chunks(claimed_);
}

std::uint32_t exact_geometry::allocate(scratch& sc) {
  if (sc.next == sc.end) claim_block(sc);
  return sc.next++;
}

void exact_geometry::import_points(const exact_geometry& old, std::vector<fragment>& fragments) {
  // old is complete: its claimed_ no longer changes (read without its lock).
  const std::uint32_t old_inputs = old.inputs_, count = old.claimed_ - old.inputs_;
  const std::uint32_t shift = inputs_ - old_inputs;
  const std::lock_guard<std::mutex> lock(claim_mutex_);
  if (claimed_ != inputs_)
    throw usage_error("import_points: the geometry has constructed points already");
  if (std::uint64_t{inputs_} + count > (std::uint64_t{1} << max_point_bits) - 2 * block)
    throw limit_error("bsp insert: more than 2^28 points in the exact kernel's point table");
  grow_chunks(inputs_ + count);
  claimed_ = inputs_ + count;
  const auto moved = [&](std::uint32_t id) {
    return id == none || id < old_inputs ? id : id + shift;
  };
  for (std::uint32_t k = 0; k < count; ++k) {
    const point& from = old.at(old_inputs + k);
    point& to = at(inputs_ + k);
    to = from;
    to.p = moved(from.p);
    to.q = moved(from.q);
  }
  for (fragment& f : fragments)
    for (std::uint32_t& id : f.v) id = moved(id);
}

bool exact_geometry::add_source(const triangle_soup& soup, std::uint32_t i, fragment& out) {
  const soup_triangle& st = soup.triangles[i];
  const vec3d& a = soup.vertices.at(st.v[0]);
  const vec3d& b = soup.vertices.at(st.v[1]);
  const vec3d& c = soup.vertices.at(st.v[2]);
  sources_[i] = st.v;
  using E = CGAL::Epick;
  if (E().collinear_3_object()(E::Point_3(a[0], a[1], a[2]), E::Point_3(b[0], b[1], b[2]),
                               E::Point_3(c[0], c[1], c[2])))
    return false;
  out = {st.v, i, st.face};
  return true;
}

const exact_geometry::exact_plane& exact_geometry::plane_of(std::uint32_t plane) const {
  {
    const std::lock_guard<std::mutex> lock(exact_mutex_);
    if (const exact_plane* known = stored(plane_store_, plane_slot_, plane)) return *known;
  }
  // The vertices as integers A, B, C over 2^s: with N = (B-A)x(C-A), the orientation is
  // sign(N.(x 2^s - A)) = sign((N 2^s).x - N.A), all integers.
  const std::array<vec3d, 3> corners{at(sources_[plane][0]).c, at(sources_[plane][1]).c,
                                     at(sources_[plane][2]).c};
  std::array<mpz_class, 9> v;
  const mp_bitcnt_t shift = to_integers(corners.data(), 3, v.data());
  std::array<mpz_class, 3> e1, e2;
  for (int j = 0; j < 3; ++j) {
    e1[j] = v[3 + j] - v[j];
    e2[j] = v[6 + j] - v[j];
  }
  std::array<mpz_class, 3> n;
  n[0] = e1[1] * e2[2] - e1[2] * e2[1];
  n[1] = e1[2] * e2[0] - e1[0] * e2[2];
  n[2] = e1[0] * e2[1] - e1[1] * e2[0];
  const mpz_class d = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
  for (mpz_class& c : n) mpz_mul_2exp(c.get_mpz_t(), c.get_mpz_t(), shift);
  check_gmp_memory();  // GMP ran out of memory above (gmp_memory.h): stop here, consistent
  exact_plane made{detail::packed_integers(detail::views_of(n[0], n[1], n[2], d))};
  const std::lock_guard<std::mutex> lock(exact_mutex_);
  return keep(plane_store_, plane_slot_, plane, std::move(made));
}

void exact_geometry::forget_exact_values() {
  const std::lock_guard<std::mutex> lock(exact_mutex_);
  decltype(exact_store_)().swap(exact_store_);  // swap: clear() keeps memory
  decltype(exact_slot_)().swap(exact_slot_);
  decltype(plane_store_)().swap(plane_store_);
  decltype(plane_slot_)().swap(plane_slot_);
}

struct exact_geometry::vertex_value {
  std::array<mpz_class, 3> x;
  mpz_class w;
};

bool exact_geometry::value_of(std::uint32_t id, vertex_value& vertex,
                              detail::integer_views& out) const {
  if (id >= inputs_) {
    const exact_value* known = find_exact(id);
    if (known) out = known->xw.views();
    return known != nullptr;
  }
  vertex.w = 1;
  mpz_mul_2exp(vertex.w.get_mpz_t(), vertex.w.get_mpz_t(),
               to_integers(&at(id).c, 1, vertex.x.data()));
  out = detail::views_of(vertex.x[0], vertex.x[1], vertex.x[2], vertex.w);
  return true;
}

namespace {

/// Bits of the integers of an exact value or plane (three coordinates and w or d).
std::uint64_t bits_of(const detail::integer_views& v) {
  std::uint64_t b = 0;
  for (int k = 0; k < 4; ++k) b += mpz_sizeinbase(v[k], 2);
  return b;
}

/// F = n . X - d w of a plane (n, d) and a point X / w: plane and point as views.
void plane_at(mpz_ptr out, const detail::integer_views& pl, const detail::integer_views& x) {
  mpz_mul(out, pl[3], x[3]);
  mpz_neg(out, out);
  for (int j = 0; j < 3; ++j) mpz_addmul(out, pl[j], x[j]);
}

}  // namespace

const exact_geometry::exact_value& exact_geometry::exact_of(std::uint32_t x) const {
  // Iterative over the constructed points x depends on (their ids are smaller: a point is
  // made after its endpoints), so a long chain of nested split points cannot overflow the
  // stack. Input vertices are not memoised: their doubles are their exact values.
  if (const exact_value* known = find_exact(x)) return *known;
  std::vector<std::uint32_t> stack{x};
  vertex_value vp, vq;
  while (!stack.empty()) {
    const std::uint32_t id = stack.back();
    if (find_exact(id)) {
      stack.pop_back();
      continue;
    }
    const point& pt = at(id);
    detail::integer_views P, Q;
    const bool has_p = value_of(pt.p, vp, P), has_q = value_of(pt.q, vq, Q);
    if (!has_p || !has_q) {
      if (!has_p) stack.push_back(pt.p);
      if (!has_q) stack.push_back(pt.q);
      continue;
    }
    // x = (fp q - fq p) / (fp - fq) with fp = f(p), fq = f(q) of the plane f. With p = P / wp,
    // q = Q / wq and Fp = n.P - d wp (= wp fp), Fq = n.Q - d wq, multiplying through by wp wq:
    // x = (Fp Q - Fq P) / (Fp wq - Fq wp). Fp and Fq have strictly opposite signs, so the
    // denominator is not zero; its sign is Fp's, made positive.
    const detail::integer_views pl = plane_of(pt.plane).nd.views();
    if (exact_budget_bits_ != std::numeric_limits<std::uint64_t>::max()) {
      // The value's size is about the sum of its operands' (see below): refuse before making it.
      const std::uint64_t estimate = bits_of(pl) + bits_of(P) + bits_of(Q);
      if (exact_bits_.load(std::memory_order_relaxed) + estimate > exact_budget_bits_)
        throw input_error(
            exact_budget_file_, 0,
            "its split points nest so deeply that their exact values need more than " +
                std::to_string(exact_budget_bits_ / 8 / 1024 / 1024) +
                " MB (the budget of a file of its size); exbsp writes no such file");
    }
    mpz_class Fp, Fq;
    plane_at(Fp.get_mpz_t(), pl, P);
    plane_at(Fq.get_mpz_t(), pl, Q);
    std::array<mpz_class, 3> x;
    mpz_class w;
    for (int j = 0; j < 4; ++j) {
      mpz_ptr out = j < 3 ? x[static_cast<std::size_t>(j)].get_mpz_t() : w.get_mpz_t();
      mpz_mul(out, Fp.get_mpz_t(), Q[j]);
      mpz_submul(out, Fq.get_mpz_t(), P[j]);
    }
    if (sgn(w) < 0) {
      for (mpz_class& c : x) c = -c;
      w = -w;
    }
    remove_common_twos(x, w);
    check_gmp_memory();
    exact_value made{detail::packed_integers(detail::views_of(x[0], x[1], x[2], w))};
    if (exact_budget_bits_ != std::numeric_limits<std::uint64_t>::max())
      exact_bits_.fetch_add(bits_of(made.xw.views()), std::memory_order_relaxed);
    {
      // Another thread may have made the same value meanwhile: the first one stays.
      const std::lock_guard<std::mutex> lock(exact_mutex_);
      keep(exact_store_, exact_slot_, id, std::move(made));
    }
    stack.pop_back();
  }
  return *find_exact(x);
}

int exact_geometry::exact_sign(std::uint32_t plane, std::uint32_t x) const {
  const detail::integer_views pl = plane_of(plane).nd.views();
  const detail::integer_views v = exact_of(x).xw.views();
  // sign(n . X - d w), w > 0: integers only.
  mpz_class f;
  plane_at(f.get_mpz_t(), pl, v);
  check_gmp_memory();
  return sgn(f);
}

int exact_geometry::point_sign_slow(std::uint32_t plane, const fast_plane_core& fp, std::uint32_t x,
                                    int& budget) const {
  const point& pt = at(x);
  if (pt.p == none) {
    // An input vertex: 0 when it is one of the plane's own vertices (adjacent mesh triangles),
    // else Epick's orientation, exact on doubles (filtered, exact fallback).
    if (is_vertex_of(plane, x)) return 0;
    const auto& s = sources_[plane];
    using E = CGAL::Epick;
    const auto P = [&](std::uint32_t id) {
      return E::Point_3(at(id).c[0], at(id).c[1], at(id).c[2]);
    };
    return static_cast<int>(E().orientation_3_object()(P(s[0]), P(s[1]), P(s[2]), P(x)));
  }
  if (pt.plane == plane) {
    counters_.on_own_plane.fetch_add(1, std::memory_order_relaxed);
    return 0;
  }
  if (budget > 0) {
    --budget;
    const int sp = point_sign(plane, fp, pt.p, budget);
    const int sq = point_sign(plane, fp, pt.q, budget);
    if (sp * sq >= 0) {
      // x lies strictly between p and q: not strictly opposite, they decide.
      counters_.structural.fetch_add(1, std::memory_order_relaxed);
      return (sp + sq > 0) - (sp + sq < 0);
    }
  }
  counters_.exact.fetch_add(1, std::memory_order_relaxed);
  return exact_sign(plane, x);
}

void exact_geometry::approximate(std::uint32_t id) {
  point& x = at(id);
  const point& pp = at(x.p);
  const point& pq = at(x.q);
  const std::uint32_t plane = x.plane;
  // Certified approximation: x = p + t (q - p), t = |fp| / (|fp| + |fq|) in (0, 1), with
  // |fp - vp| <= ep and |fq - vq| <= eq from the filter. p and q lie strictly on opposite
  // sides (the split's exact classification), so |fp| lies in [max(|vp| - ep, 0), |vp| + ep]
  // whatever the sign of vp, and likewise |fq|. t is monotone in |fp| and |fq|, so [t_lo,
  // t_hi] below holds the true t; the rest is the spread of p and q and rounding. An endpoint
  // too close to the plane for its sign to be certified still gives a narrow [t_lo, t_hi]
  // when the other one is far: t is then near 0 or 1 (on a 1M-triangle assembly about one
  // constructed point in six is such, and each exact value made here stays memoised).
  double vp, ep, vq, eq;
  bool certified = false;
  const fast_plane_core fp = filter(plane);
  if (fast_eval(fp, pp.c, pp.r, vp, ep) && fast_eval(fp, pq.c, pq.r, vq, eq)) {
    const double alpha = std::fabs(vp), beta = std::fabs(vq);
    const double t = alpha / (alpha + beta);
    const double alpha_lo = std::max(alpha - ep, 0.0), beta_lo = std::max(beta - eq, 0.0);
    const double t_lo = alpha_lo / (alpha_lo + (beta + eq));
    const double t_hi = (alpha + ep) / ((alpha + ep) + beta_lo);
    const double dt = std::max(t_hi - t, t - t_lo) * (1 + 8 * u) + 16 * u;
    if (dt < 1e-3 && std::isfinite(dt)) {
      double r = 0;
      for (int k = 0; k < 3; ++k) {
        const double diff = pq.c[k] - pp.c[k];
        x.c[k] = pp.c[k] + t * diff;
        const double err = std::max(pp.r, pq.r) + dt * (std::fabs(diff) + pp.r + pq.r) +
                           4 * u * (std::fabs(pp.c[k]) + std::fabs(diff));
        r = std::max(r, err);
      }
      r = r * (1 + 16 * u) + DBL_MIN;
      certified = std::isfinite(r) && r <= 1e80;
      x.r = round_up_to_float(r);
    }
  }
  if (!certified) {
    // Too close to call in doubles (or out of the filter's range): the exact value, rounded.
    const detail::integer_views e = exact_of(id).xw.views();
    double r = 0;
    for (int k = 0; k < 3; ++k) {
      x.c[k] = geom::quotient_to_double(e[k], e[3]);
      r = std::max(r, ulp_of(x.c[k]));
    }
    check_gmp_memory();
    x.r = round_up_to_float(r);
  }
}

std::uint32_t exact_geometry::construct(std::uint32_t plane, std::uint32_t p, std::uint32_t q,
                                        scratch& sc) {
  if (sc.plane != plane) {
    sc.made.clear();
    sc.plane = plane;
  }
  const std::uint64_t key = std::uint64_t{std::min(p, q)} << 32 | std::max(p, q);
  const auto found = sc.made.find(key);
  if (found != sc.made.end()) return found->second;
  const std::uint32_t id = allocate(sc);
  point& x = at(id);
  x.p = p;
  x.q = q;
  x.plane = plane;
  approximate(id);
  sc.made.emplace(key, id);
  return id;
}

void exact_geometry::split(std::uint32_t plane, const fragment& f, const geom::split_pattern& pat,
                           std::array<fragment, 3>& out, scratch& sc) {
  std::array<std::uint32_t, 5> ids{f.v[0], f.v[1], f.v[2], none, none};
  for (int j = 0; j < pat.new_points; ++j)
    ids[3 + j] = construct(plane, f.v[pat.from[j]], f.v[pat.to[j]], sc);
  for (int i = 0; i < pat.pieces; ++i)
    out[i] = {
        {ids[pat.corner[i][0]], ids[pat.corner[i][1]], ids[pat.corner[i][2]]}, f.source, f.face};
}

int exact_geometry::side_of_eye(std::uint32_t plane, const vec3d& eye) const {
  double v, bound;
  if (filter(plane, eye, 0, v, bound)) {
    if (v > bound) return 1;
    if (v < -bound) return -1;
  }
  using E = CGAL::Epick;
  const auto& src = sources_[plane];
  const auto P = [&](const vec3d& v) { return E::Point_3(v[0], v[1], v[2]); };
  return static_cast<int>(
      E().orientation_3_object()(P(at(src[0]).c), P(at(src[1]).c), P(at(src[2]).c), P(eye)));
}

int exact_geometry::side_of_direction(std::uint32_t plane, const vec3d& d) const {
  // sign(n . (-d)): the double normal's error bound first, exact rationals when too close.
  const fast_plane_core fp = filter(plane);
  const double v = -(fp.n[0] * d[0] + fp.n[1] * d[1] + fp.n[2] * d[2]);
  double bound = 0;
  for (int k = 0; k < 3; ++k) bound += fp.coef[k] * std::fabs(d[k]);
  bound = bound * (1 + 8 * u) + 1e-290;
  if (fp.valid && std::isfinite(v) && std::isfinite(bound)) {
    if (v > bound) return 1;
    if (v < -bound) return -1;
  }
  const detail::integer_views pl = plane_of(plane).nd.views();
  mpq_class dot;
  for (int j = 0; j < 3; ++j) dot += mpz_class(pl[j]) * mpq_class(d[j]);
  return -sign_of(dot);
}

void exact_geometry::prepare_output(const std::vector<fragment>& fragments) const {
  std::call_once(output_once_, [&] {
    rounded_.assign(claimed_, vec3d{});
    std::vector<char> done(claimed_, 0);
    std::vector<std::uint32_t> constructed;  // constructed points in use, by first use
    for (const fragment& f : fragments)
      for (std::uint32_t id : f.v) {
        if (done[id]) continue;
        done[id] = 1;
        const point& pt = at(id);
        if (pt.p == none)
          rounded_[id] = {pt.c[0] + 0.0, pt.c[1] + 0.0, pt.c[2] + 0.0};  // -0 prints as the exact 0
        else
          constructed.push_back(id);
      }
    // The exact values and their roundings are independent point by point: in parallel on
    // all cores (exact_of is thread-safe; a value two threads both need may be made twice,
    // the first one kept). Each thread writes only its own points' entries of rounded_.
    detail::parallel_failure failure;
    const auto n = static_cast<long long>(constructed.size());
#pragma omp parallel for schedule(dynamic, 64) if (n >= 1024) num_threads(detail::threads_for(0))
    for (long long i = 0; i < n; ++i)
      failure.run([&] {
        const std::uint32_t id = constructed[static_cast<std::size_t>(i)];
        const detail::integer_views e = exact_of(id).xw.views();
        for (int k = 0; k < 3; ++k) rounded_[id][k] = geom::quotient_to_double(e[k], e[3]);
        check_gmp_memory();
      });
    failure.rethrow();
  });
}

fragment_d exact_geometry::to_double(const fragment& f) const {
  return {f.face, {rounded_[f.v[0]], rounded_[f.v[1]], rounded_[f.v[2]]}};
}

void exact_geometry::visit_exact(const fragment& f, const exact_visitor& visit) const {
  vertex_value vertex;
  mpq_class q;
  for (int k = 0; k < 3; ++k) {
    detail::integer_views e;
    if (!value_of(f.v[k], vertex, e)) e = exact_of(f.v[k]).xw.views();
    for (int j = 0; j < 3; ++j) {
      mpq_set_num(q.get_mpq_t(), e[j]);
      mpq_set_den(q.get_mpq_t(), e[3]);
      q.canonicalize();  // the visitor gets reduced rationals
      check_gmp_memory();
      visit(k, j, q.get_mpq_t());
    }
  }
}

std::size_t exact_geometry::points_memory() const {
  std::size_t tables = 0;
  for (std::size_t size = 16; size <= table_size_; size *= 2) tables += size * sizeof(point*);
  return chunks_.size() * (chunk_size * sizeof(point) + sizeof(chunks_[0])) + tables;
}

}  // namespace exbsp
