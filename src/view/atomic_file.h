// The atomic output writer moved to mesh/atomic_file.h (the lowest module, shared with the
// command line); this header keeps the view:: spelling working.
#pragma once
#include "mesh/atomic_file.h"

namespace exbsp::view {
using exbsp::write_file_atomically;
}  // namespace exbsp::view
