// SPDX-License-Identifier: LGPL-3.0-or-later
// fragment_exact_mpq: the kernel's exact values copied into mpq_class (bsp_impl::visit_exact).
#include <exbsp/bsp/exact_gmp.h>

#include "bsp/bsp_impl.h"

namespace exbsp {

exact_triangle_mpq fragment_exact_mpq(const bsp& tree, std::size_t i) {
  exact_triangle_mpq out;
  bsp_access::impl(tree).visit_exact(
      i, [&](int k, int axis, mpq_srcptr q) { mpq_set(out[k][axis].get_mpq_t(), q); });
  return out;
}

}  // namespace exbsp
