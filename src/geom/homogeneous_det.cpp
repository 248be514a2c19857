// SPDX-License-Identifier: LGPL-3.0-or-later
// Filtered exact determinants (notation in homogeneous_det.h).
//
// D is evaluated by eliminating a pivot row k with w = 1: every other row i becomes the
// direction d_i = h_i - w_i h_k, and D = -(-1)^k det3(d_i, i != k in order) (moving the pivot to
// the first row takes k adjacent swaps; the expansion along the w column then has the single
// entry 1 at (0, 3), whose cofactor sign is -1). Differences first keep the interval tight
// for points far from the origin.
#include "geom/homogeneous_det.h"

#include <stdexcept>

namespace exbsp::geom {

namespace {

template <class T>
T det3(const T* u, const T* v, const T* w) {
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
         u[2] * (v[0] * w[1] - v[1] * w[0]);
}

int pivot_of(const std::array<hpoint, 4>& rows) {
  for (int k = 0; k < 4; ++k)
    if (rows[k].w == 1) return k;
  throw std::logic_error("det_value: no row is a point");
}

/// D computed in number type T from rows converted by `of` (notation above).
template <class T, class Of>
T determinant(const std::array<hpoint, 4>& rows, Of of) {
  const int k = pivot_of(rows);
  const hpoint& p = rows[static_cast<std::size_t>(k)];
  const T px = of(p.x), py = of(p.y), pz = of(p.z);
  T d[3][3];
  int r = 0;
  for (int i = 0; i < 4; ++i) {
    if (i == k) continue;
    const hpoint& h = rows[static_cast<std::size_t>(i)];
    d[r][0] = h.w ? of(h.x) - px : of(h.x);
    d[r][1] = h.w ? of(h.y) - py : of(h.y);
    d[r][2] = h.w ? of(h.z) - pz : of(h.z);
    ++r;
  }
  const T v = det3(d[0], d[1], d[2]);
  return (k % 2 == 0) ? T(-v) : v;
}

int sign_of(const interval& i) {
  if (i.inf() > 0) return 1;
  if (i.sup() < 0) return -1;
  if (i.inf() == 0 && i.sup() == 0) return 0;
  return 2;  // undecided
}

}  // namespace

namespace {

bool same_row(const hpoint& a, const hpoint& b) {
  return a.w == b.w && a.x == b.x && a.y == b.y && a.z == b.z;
}

}  // namespace

det_value::det_value(const hpoint& h0, const hpoint& h1, const hpoint& h2, const hpoint& h3)
    : rows_{h0, h1, h2, h3} {
  // Two equal rows: exactly zero. The edge tests meet this at every shared vertex (a triangle
  // of the fan around an edge's end), where the interval would straddle zero and send the
  // sign to GMP (6x the edge stage's time on bunny00).
  if (same_row(h0, h1) || same_row(h0, h2) || same_row(h0, h3) || same_row(h1, h2) ||
      same_row(h1, h3) || same_row(h2, h3))
    approx_ = interval(0);
  else
    approx_ = determinant<interval>(rows_, [](double v) { return interval(v); });
}

const mpq_class& det_value::exact() const {
  if (!exact_)
    exact_ = std::make_shared<const mpq_class>(
        determinant<mpq_class>(rows_, [](double v) { return mpq_class(v); }));
  return *exact_;
}

int det_value::sign() const {
  const int s = sign_of(approx_);
  return s != 2 ? s : sgn(exact());
}

double det_value::to_double() const {
  if (exact_) return exact_->get_d();
  return 0.5 * (approx_.inf() + approx_.sup());
}

int det_value::same_rows_sign(const det_value& other) const {
  int at[4];
  for (int i = 0; i < 4; ++i) {
    at[i] = -1;
    for (int j = 0; j < 4 && at[i] < 0; ++j)
      if (same_row(rows_[static_cast<std::size_t>(i)], other.rows_[static_cast<std::size_t>(j)]))
        at[i] = j;
    if (at[i] < 0) return 0;
    for (int k = 0; k < i; ++k)
      if (at[k] == at[i]) return 0;  // two equal rows
  }
  int inversions = 0;
  for (int i = 0; i < 4; ++i)
    for (int k = i + 1; k < 4; ++k) inversions += at[i] > at[k];
  return inversions % 2 == 0 ? 1 : -1;
}

int sign_of_difference_of_products(const det_value& p, const det_value& q, const det_value& r,
                                   const det_value& s) {
  const int filtered = sign_of(p.approx() * q.approx() - r.approx() * s.approx());
  if (filtered != 2) return filtered;
  // The same determinants on both sides (the crossings of one plane through the eye and the
  // shared side of two neighbouring triangles, met at every occluder's inner edge): with
  // p = u r and q = v s (u, v = +-1), pq - rs = (uv - 1) rs, decided without GMP.
  for (const auto& [a, b] : {std::pair<const det_value*, const det_value*>{&r, &s}, {&s, &r}}) {
    const int u = p.same_rows_sign(*a), v = q.same_rows_sign(*b);
    if (u != 0 && v != 0) return u * v == 1 ? 0 : -a->sign() * b->sign();
  }
  const mpq_class v = p.exact() * q.exact() - r.exact() * s.exact();
  return sgn(v);
}

double crossing::to_double() const {
  switch (kind) {
    case kind_type::zero:
      return 0;
    case kind_type::one:
      return 1;
    case kind_type::inner:
      break;
  }
  const double av = a.to_double(), bv = b.to_double();
  const double t = av / (av - bv);
  return t < 0 ? 0 : t > 1 ? 1 : t;
}

int compare(const crossing& x, const crossing& y) {
  using k = crossing::kind_type;
  auto rank = [](k v) { return v == k::zero ? 0 : v == k::inner ? 1 : 2; };
  if (x.kind != k::inner || y.kind != k::inner) {
    const int rx = rank(x.kind), ry = rank(y.kind);
    return (rx > ry) - (rx < ry);
  }
  // t1 - t2 = (a2 b1 - a1 b2) / ((a1 - b1)(a2 - b2)), and sign(a_i - b_i) = sign(a_i).
  return sign_of_difference_of_products(y.a, x.b, x.a, y.b) * x.a.sign() * y.a.sign();
}

}  // namespace exbsp::geom
