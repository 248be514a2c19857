// SPDX-License-Identifier: LGPL-3.0-or-later
// OpenMP helpers of the BSP build: the team size for a requested thread count, and the
// collection of an exception thrown inside a parallel loop (it must not leave the region).
// Private to src/bsp (used by bsp_tree_impl.h and heuristics.h).
#pragma once
#include <omp.h>

#include <atomic>
#include <exception>

namespace exbsp {
namespace detail {

/// OpenMP team size for a requested thread count (0: all cores).
inline int threads_for(unsigned requested) {
  return requested ? static_cast<int>(requested) : omp_get_max_threads();
}

/// Collects the first exception thrown inside an OpenMP loop body (an exception must not
/// leave a parallel region: that would terminate the process) and rethrows it outside.
class parallel_failure {
 public:
  template <class Body>
  void run(Body&& body) {
    if (failed_.load(std::memory_order_relaxed)) return;
    try {
      body();
    } catch (...) {
#pragma omp critical(exbsp_parallel_failure)
      if (!error_) error_ = std::current_exception();
      failed_.store(true);
    }
  }
  bool failed() const { return failed_.load(std::memory_order_relaxed); }
  void rethrow() {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  std::atomic<bool> failed_{false};
  std::exception_ptr error_;
};

}  // namespace detail
}  // namespace exbsp
