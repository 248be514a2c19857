// SPDX-License-Identifier: LGPL-3.0-or-later
// Explicit instantiations of the tests' exact triangle/plane clipper (exact_triangle_clip.h) for
// Epeck and Simple_cartesian<Gmpq>: the only translation unit that compiles them.
#include "support/exact_triangle_clip.h"

namespace exbsp_test::oracle {

EXBSP_CLIP_EXACT_TEMPLATES(, epeck)
EXBSP_CLIP_EXACT_TEMPLATES(, gmpq_kernel)

}  // namespace exbsp_test::oracle
