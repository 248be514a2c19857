// Explicit instantiations of the exact triangle/plane clipper (exact_triangle_clip.h) for
// Epeck and Simple_cartesian<Gmpq>: the only translation unit that compiles them.
#include "clip/exact_triangle_clip.h"

namespace exbsp::clip {

EXBSP_CLIP_EXACT_TEMPLATES(, epeck)
EXBSP_CLIP_EXACT_TEMPLATES(, gmpq_kernel)

}  // namespace exbsp::clip
