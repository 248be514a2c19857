// SPDX-License-Identifier: LGPL-3.0-or-later
// The command line's memory and thread policy (resources.h).
#include "app/resources.h"
#include "app/cli_parse.h"

#include "bsp/kernels.h"
#include "core/name_list.h"

#include <omp.h>
#include <sys/resource.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <thread>
#include <utility>
#include <vector>

namespace exbsp::cli {

void fix_malloc_mmap_threshold() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
#endif
}

std::uint64_t available_memory_bytes() {
  std::uint64_t available = 0;
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kib = 0;
  std::string unit;
  while (meminfo >> key >> kib >> unit)
    if (key == "MemAvailable:") {
      available = kib * 1024;
      break;
    }
  struct rlimit as {};
  if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
    const auto cap = static_cast<std::uint64_t>(as.rlim_cur);
    available = available ? std::min(available, cap) : cap;
  }
  return available;
}

namespace {
std::uint64_t bytes_per_fragment(const kernel_row& r, fragment_use use) {
  return use == fragment_use::build ? r.build_bytes_per_fragment : r.bytes_per_fragment;
}
}  // namespace

std::size_t default_fragment_budget(kernel_id kernel, fragment_use use) {
  const std::uint64_t bytes = available_memory_bytes();
  if (bytes == 0) return 0;
  return static_cast<std::size_t>(
      std::max<std::uint64_t>(bytes / 2 / bytes_per_fragment(kernel_row_of(kernel), use), 10000));
}

std::string max_fragments_help(fragment_use use) {
  // "640 bytes per fragment for exact, epick and double, 1300 for epeck and gmpq": the
  // kernels grouped by their row's bytes per fragment, in table order.
  std::vector<std::pair<std::uint64_t, std::vector<std::string>>> groups;
  for (const kernel_row& r : kernel_table()) {
    const std::uint64_t b = bytes_per_fragment(r, use);
    auto g =
        std::find_if(groups.begin(), groups.end(), [&](const auto& x) { return x.first == b; });
    if (g == groups.end()) g = groups.insert(groups.end(), {b, {}});
    g->second.push_back(r.name);
  }
  std::string text =
      "stop with exit status 3 when the tree would need more fragments (0: no limit; default: "
      "half the available memory at ";
  for (std::size_t i = 0; i < groups.size(); ++i) {
    text += (i == 0 ? "" : ", ") + std::to_string(groups[i].first) +
            (i == 0 ? " bytes per fragment for " : " for ") + name_list(groups[i].second, "and");
  }
  return text + ")";
}

unsigned max_threads() { return max_build_threads(); }

void sanitize_omp_num_threads() {
  const char* env = std::getenv("OMP_NUM_THREADS");
  if (!env) return;
  const std::string text(env);
  const std::string first = text.substr(0, text.find(','));
  unsigned long value = 0;
  const auto r = std::from_chars(first.data(), first.data() + first.size(), value);
  const bool ok = r.ec == std::errc() && r.ptr == first.data() + first.size() && value >= 1 &&
                  value <= max_threads();
  if (ok) return;
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  std::cerr << "exbsp: warning: OMP_NUM_THREADS='" << text.substr(0, 40)
            << "' ignored (expected 1.." << max_threads() << "); using " << hw << " threads\n";
  omp_set_num_threads(static_cast<int>(hw));
}

void start_thread_pool() {
#pragma omp parallel
  {}
}

}  // namespace exbsp::cli
