// SPDX-License-Identifier: LGPL-3.0-or-later
// libFuzzer target: the STL reader (read_mesh_data with mesh_format::stl). Oracle: fuzz_mesh.h.
#include "fuzz_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return exbsp::fuzz::fuzz_mesh(data, size, exbsp::mesh_format::stl, "fuzz.stl");
}
