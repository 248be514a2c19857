// SPDX-License-Identifier: LGPL-3.0-or-later
// The combinatorial half of the split convention (docs/contract.md "The BSP"), shared by every
// geometry (CGAL kernels and exbsp's own exact points) and by every user of it (the tree, the
// section, the clipping oracle of the tests): which new points a straddling triangle needs,
// and which corners each piece takes, from the three vertex signs alone.
//
// Notation: parent triangle t = (t0, t1, t2); corner code 0..2 = parent vertex t[code],
// 3 + j = the j-th new point, which lies on segment [t[from[j]], t[to[j]]].
//   no vertex on the plane: c is the vertex alone on its side, (a, b, c) the cyclic
//     relabelling of t; new points A = plane ∩ [c, a], B = plane ∩ [b, c];
//     pieces (a, b, A), (b, B, A) on a/b's side, then (A, B, c) on c's side;
//   one vertex z on the plane: (z, a, b) the cyclic relabelling; X = plane ∩ [a, b];
//     pieces (z, a, X) on a's side, then (z, X, b) on b's side.
#pragma once
#include <array>
#include <cstdint>

namespace exbsp::geom {

enum class classification { coplanar, positive, negative, straddling };

/// Classification from the three vertex signs (each -1, 0 or +1).
inline classification classify_signs(const std::array<int, 3>& s) {
  const bool any_pos = s[0] > 0 || s[1] > 0 || s[2] > 0;
  const bool any_neg = s[0] < 0 || s[1] < 0 || s[2] < 0;
  if (any_pos && any_neg) return classification::straddling;
  if (any_pos) return classification::positive;
  if (any_neg) return classification::negative;
  return classification::coplanar;
}

struct split_pattern {
  int new_points = 0;                  ///< 1 (a vertex on the plane) or 2
  std::array<std::uint8_t, 2> from{};  ///< new point j lies on [t[from[j]], t[to[j]]]
  std::array<std::uint8_t, 2> to{};
  int pieces = 0;                                       ///< 2 or 3
  std::array<std::array<std::uint8_t, 3>, 3> corner{};  ///< corner codes per piece
  std::array<int, 3> side{};                            ///< +1 / -1 per piece
};

/// The pattern for a straddling triangle with vertex signs s.
/// Precondition: classify_signs(s) == straddling.
inline split_pattern make_split_pattern(const std::array<int, 3>& s) {
  split_pattern p;
  const int zero = s[0] == 0 ? 0 : s[1] == 0 ? 1 : s[2] == 0 ? 2 : -1;
  if (zero < 0) {
    int lone = 0;
    for (int i = 0; i < 3; ++i)
      if (s[i] != s[(i + 1) % 3] && s[i] != s[(i + 2) % 3]) lone = i;
    const auto c = static_cast<std::uint8_t>(lone), a = static_cast<std::uint8_t>((lone + 1) % 3),
               b = static_cast<std::uint8_t>((lone + 2) % 3);
    p.new_points = 2;
    p.from = {c, b};  // A on [c, a], B on [b, c]
    p.to = {a, c};
    p.pieces = 3;
    p.corner = {{{a, b, 3}, {b, 4, 3}, {3, 4, c}}};
    p.side = {s[a], s[a], s[c]};
  } else {
    const auto z = static_cast<std::uint8_t>(zero), a = static_cast<std::uint8_t>((zero + 1) % 3),
               b = static_cast<std::uint8_t>((zero + 2) % 3);
    p.new_points = 1;
    p.from = {a, 0};  // X on [a, b]
    p.to = {b, 0};
    p.pieces = 2;
    p.corner = {{{z, a, 3}, {z, 3, b}, {0, 0, 0}}};
    p.side = {s[a], s[b], 0};
  }
  return p;
}

/// Splits triangle t (corners of any type: points, point indices) by pattern p: new point j
/// is cut(t[from[j]], t[to[j]]), made in order j = 0, 1 (the edge visitor: it sees which
/// edge it cuts); then emit(side, {corner, corner, corner}) runs once per piece, in order.
template <class Corner, class Cut, class Emit>
void apply_split(const split_pattern& p, const std::array<Corner, 3>& t, Cut&& cut, Emit&& emit) {
  std::array<Corner, 5> corner{t[0], t[1], t[2], Corner{}, Corner{}};
  for (int j = 0; j < p.new_points; ++j) corner[3 + j] = cut(t[p.from[j]], t[p.to[j]]);
  for (int k = 0; k < p.pieces; ++k) {
    const auto& c = p.corner[k];
    emit(p.side[k], std::array<Corner, 3>{corner[c[0]], corner[c[1]], corner[c[2]]});
  }
}

}  // namespace exbsp::geom
