// SPDX-License-Identifier: LGPL-3.0-or-later
// libFuzzer target: the saved-tree loader (bsp::deserialize, docs/tree-file.md).
//
// One input = the bytes of a tree file, loaded twice: as is (the frame checks: magic,
// version, kernel, sizes, CRC-32), then with its frame repaired (body size and CRC-32
// recomputed, as a forger would), so that mutations reach the checks of the body instead of
// stopping at the checksum.
//
// Oracle, besides "exbsp::error or nothing" (fuzz_check.h), for every tree that loads: it is
// well formed, so every query answers without throwing: fragments in doubles (and exact
// coordinates on exact kernels), ancestors with sides +1 or -1 and planes in range, orders
// for an eye and a direction that are permutations of the fragment indices; and it saves to
// bytes that load again and save to the same bytes (a loaded tree's file is canonical).
#include <boost/crc.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>
#include <exbsp/mesh/gmp_memory.h>
#include "fuzz_check.h"

namespace {

using exbsp::fuzz::require;

void require_permutation(std::vector<std::uint32_t> order, std::size_t n, const char* what) {
  require(order.size() == n, what);
  std::sort(order.begin(), order.end());
  for (std::size_t i = 0; i < n; ++i) require(order[i] == i, what);
}

void check_tree(const exbsp::bsp& tree) {
  const exbsp::build_stats& s = tree.stats();
  const std::size_t n = tree.fragment_count();
  require(s.fragments == n, "stats.fragments = fragment_count()");
  require(n == 0 || s.nodes >= 1, "a tree with fragments has a root");
  try {
    const auto frags = tree.fragments_double();
    require(frags.size() == n, "fragments_double() has every fragment");
    for (std::size_t i = 0; i < n; ++i) {
      if (exbsp::is_exact(tree.kernel())) (void)tree.fragment_exact(i);
      const auto up = tree.ancestors(i);
      require(up.size() < s.depth, "fewer ancestors than the depth");
      for (const auto& a : up) {
        require(a.side == 1 || a.side == -1, "ancestor sides are +1 or -1");
        require(a.plane_face < s.input_triangles, "ancestor planes are input triangles");
      }
    }
    require_permutation(tree.order_from_eye({3, 4, 5}), n, "the eye order is a permutation");
    require_permutation(tree.order_for_direction({1, -1, 2}, false), n,
                        "the direction order is a permutation");
    const std::string saved = tree.serialize();
    const exbsp::bsp again = exbsp::bsp::deserialize(saved, "resaved.exbsp");
    require(again.serialize() == saved, "a loaded tree's file loads and saves to the same bytes");
  } catch (const exbsp::error& e) {
    std::fprintf(stderr, "exbsp fuzz: a loaded tree failed a query: %s\n", e.what());
    std::abort();
  }
}

void load(const std::string& bytes) {
  exbsp::fuzz::run_guarded([&] { check_tree(exbsp::bsp::deserialize(bytes, "fuzz.exbsp")); });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool gmp_ready = (exbsp::install_gmp_memory_functions(), true);
  (void)gmp_ready;
  std::string bytes(reinterpret_cast<const char*>(data), size);
  load(bytes);
  if (size < 28) return 0;
  const std::uint64_t body = size - 28;
  for (int i = 0; i < 8; ++i) bytes[16 + i] = static_cast<char>((body >> (8 * i)) & 0xff);
  boost::crc_32_type crc;
  crc.process_bytes(bytes.data(), size - 4);
  const std::uint32_t c = crc.checksum();
  for (int i = 0; i < 4; ++i) bytes[size - 4 + i] = static_cast<char>((c >> (8 * i)) & 0xff);
  load(bytes);
  return 0;
}
