// SPDX-License-Identifier: LGPL-3.0-or-later
#include "bsp/exact_output.h"

#include <fstream>

namespace exbsp {

std::size_t peak_rss_bytes() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      std::size_t kb = 0;
      status >> kb;
      return kb * 1024;
    }
    std::getline(status, key);
  }
  return 0;
}

}  // namespace exbsp
