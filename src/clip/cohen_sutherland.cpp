// SPDX-License-Identifier: LGPL-3.0-or-later
// Cohen–Sutherland clipping (see cohen_sutherland.h for the outcode notation).
//
// Implementation notes: a = the original endpoint being moved, o = the other original
// endpoint, p[i] = the current (partly clipped) endpoint i. Endpoint i is only clipped
// against a boundary its original endpoint violates ("allowed" bits), once each. p[i] may
// also be outside a boundary that the other endpoint still violates (then both are, and
// the segment is rejected). Any other outside bit of p[i] is rounding residue: the exact
// point is inside that boundary (it lies on the segment between two points inside it), so
// the coordinate is snapped to the boundary, which moves it towards the exact value. Each
// clip pass consumes one allowed bit, so there are at most 2N clip passes before a final
// accept or reject.
#include <exbsp/clip/cohen_sutherland.h>

#include <cstddef>

#include "clip/clip_checks.h"

namespace exbsp::clip {
namespace {

template <std::size_t N>
unsigned outcode_n(const std::array<double, N>& p, const box<N>& b) {
  unsigned code = 0;
  for (std::size_t k = 0; k < N; ++k) {
    if (p[k] < b.min[k])
      code |= 1u << (2 * k);
    else if (p[k] > b.max[k])
      code |= 1u << (2 * k + 1);
  }
  return code;
}

/// Boundary value for outcode bit index `bit_index` (2k: min[k], 2k+1: max[k]).
template <std::size_t N>
double boundary_value(const box<N>& b, unsigned bit_index) {
  const std::size_t k = bit_index / 2;
  return (bit_index % 2) ? b.max[k] : b.min[k];
}

unsigned lowest_bit_index(unsigned code) {
  unsigned index = 0;
  while (!(code & (1u << index))) ++index;
  return index;
}

template <std::size_t N>
std::optional<segment<N>> clip_n(const segment<N>& s, const box<N>& b, const char* function) {
  detail::require_finite(s.p0, function, "segment start");
  detail::require_finite(s.p1, function, "segment end");
  detail::require_valid_box(b, function);

  const std::array<double, N>* original[2] = {&s.p0, &s.p1};
  std::array<double, N> p[2] = {s.p0, s.p1};
  unsigned code[2] = {outcode_n(p[0], b), outcode_n(p[1], b)};
  if (trivially_accepted(code[0], code[1])) return s;  // bit-for-bit
  if (trivially_rejected(code[0], code[1])) return std::nullopt;

  // allowed[i]: boundaries endpoint i may still be clipped against (violated by its
  // original point, not used yet). A bit of p[i] is legitimate when it is allowed, or when
  // it belongs to the other endpoint's allowed bits and that endpoint still has it (then
  // the two share the bit and the segment is rejected); any other bit is residue.
  unsigned allowed[2] = {code[0], code[1]};
  for (std::size_t pass = 0; pass <= 2 * N + 1; ++pass) {
    const unsigned legitimate[2] = {allowed[0] | (allowed[1] & code[1]),
                                    allowed[1] | (allowed[0] & code[0])};
    for (int i = 0; i < 2; ++i) {
      const unsigned residue = code[i] & ~legitimate[i];
      if (!residue) continue;
      for (unsigned bit = 0; bit < 2 * N; ++bit)
        if (residue & (1u << bit)) p[i][bit / 2] = boundary_value(b, bit);
      code[i] = outcode_n(p[i], b);
    }
    if (trivially_accepted(code[0], code[1])) return segment<N>{p[0], p[1]};
    if (trivially_rejected(code[0], code[1])) return std::nullopt;

    const int i = code[0] ? 0 : 1;
    const unsigned bit = lowest_bit_index(code[i]);
    const std::size_t k = bit / 2;
    const double v = boundary_value(b, bit);
    const std::array<double, N>& a = *original[i];
    const std::array<double, N>& o = *original[1 - i];
    // Not a shared bit, so an allowed one: a violates this boundary and o does not (else
    // the start was a trivial reject), so o[k] != a[k] and t is in (0, 1].
    const double t = (v - a[k]) / (o[k] - a[k]);
    for (std::size_t j = 0; j < N; ++j) p[i][j] = (j == k) ? v : detail::lerp_within(a[j], o[j], t);
    allowed[i] &= ~(1u << bit);
    code[i] = outcode_n(p[i], b);
  }
  // Not reached (see the notes at the top); keep the endpoints inside the box regardless.
  for (auto& q : p)
    for (std::size_t k = 0; k < N; ++k) q[k] = detail::clamp_to(q[k], b.min[k], b.max[k]);
  return segment<N>{p[0], p[1]};
}

}  // namespace

unsigned outcode(const vec2d& p, const window2& window) { return outcode_n(p, window); }
unsigned outcode(const vec3d& p, const box3& box) { return outcode_n(p, box); }

std::optional<segment2> cohen_sutherland_clip(const segment2& s, const window2& window) {
  return clip_n(s, window, "cohen_sutherland_clip");
}

std::optional<segment3> cohen_sutherland_clip(const segment3& s, const box3& box) {
  return clip_n(s, box, "cohen_sutherland_clip");
}

}  // namespace exbsp::clip
