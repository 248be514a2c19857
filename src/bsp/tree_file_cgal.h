// SPDX-License-Identifier: LGPL-3.0-or-later
// Saved trees of the CGAL kernels (epeck, gmpq, epick, double): the fragments of
// cgal_geometry<K> (docs/tree-file.md). Included at the end of geometry_cgal.h.
// Notation: tree_file.h. A fragment is its source triangle and nine coordinates: exact kernels
// write each as a canonical rational (tree_file::write_rational), so the reloaded FT has the
// same exact value; inexact ones write the double's bit pattern.
#pragma once
#include <gmp.h>

#include <limits>
#include <string>
#include <vector>

#include "bsp/geometry_cgal.h"
#include "bsp/tree_file.h"

namespace exbsp {

template <class K>
void cgal_geometry<K>::write_fragments(tree_file::writer& out,
                                       const std::vector<fragment>& fragments) const {
  out.u64(fragments.size());
  for (const fragment& f : fragments) {
    out.u32(f.source);
    for (const point& p : f.v)
      for (int k = 0; k < 3; ++k) {
        if constexpr (exact)
          tree_file::write_rational(out, kernel_traits<K>::rational(p[k]));
        else
          out.f64(CGAL::to_double(p[k]));
      }
  }
}

template <class K>
void cgal_geometry<K>::read_fragments(tree_file::reader& in, const triangle_soup& soup,
                                      const std::vector<char>& usable,
                                      std::vector<fragment>& fragments) const {
  // Smallest record: the source and nine coordinates of 8 bytes (a double, or a rational's
  // two length words).
  const std::size_t count =
      in.count("fragments", 4 + 9 * 8, std::numeric_limits<std::uint32_t>::max());
  fragments.resize(count);
  mpq_t q;
  mpq_init(q);
  try {
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t at = in.offset();
      fragment& f = fragments[i];
      f.source = in.u32("fragments");
      if (f.source >= soup.triangles.size() || !usable[f.source])
        in.fail_at(
            at, tree_file::indexed("fragments", i),
            "source " + std::to_string(f.source) + " is not a non-degenerate input triangle");
      f.face = soup.triangles[f.source].face;
      f.double_mask = 0;  // the build-time filter data is not saved; side tests take K's predicate
      f.d = {};
      f.r = {0, 0, 0};
      for (point& p : f.v) {
        typename K::FT x[3];
        for (typename K::FT& c : x) {
          if constexpr (exact) {
            tree_file::read_rational(in, "fragments", q);
            c = kernel_traits<K>::from_rational(q);
          } else {
            c = in.f64("fragments");
          }
        }
        p = point(x[0], x[1], x[2]);
      }
    }
  } catch (...) {
    mpq_clear(q);
    throw;
  }
  mpq_clear(q);
}

}  // namespace exbsp
