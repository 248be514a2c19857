// SPDX-License-Identifier: LGPL-3.0-or-later
// OpenMP helpers of the BSP build: the team size for a requested thread count, and the
// collection of an exception thrown inside a parallel loop (it must not leave the region).
// Private to src/bsp (used by bsp_tree_impl.h and heuristics.h).
#pragma once
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <thread>

namespace exbsp {
namespace detail {

/// The largest team the build makes: 4 per hardware thread, at most 1024 (libgomp crashes or
/// exits on team sizes in the tens of thousands; engine.h max_build_threads).
inline int team_limit() {
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  return static_cast<int>(std::min(1024u, 4 * hw));
}

/// OpenMP team size for a requested thread count (0: all cores, i.e. OMP_NUM_THREADS or the
/// core count, clamped to team_limit(): an absurd OMP_NUM_THREADS in a program that embeds the
/// library, such as a Python interpreter, must not crash it).
inline int threads_for(unsigned requested) {
  return std::min(
      requested ? static_cast<int>(std::min<unsigned>(requested, 1u << 30)) : omp_get_max_threads(),
      team_limit());
}

/// Cancellation inside long steps. Progress is reported once per 256 nodes, but one node can
/// take minutes (min-split at the root of a large mesh is n^2 classifications), so the build's
/// own thread (the caller of bsp::build, OpenMP's master thread in every team it starts) also
/// calls `report` from inside the heuristics' candidate loops (poll()), at most every 100 ms.
/// Whatever `report` throws (a cancelling progress callback) stops the build as from anywhere
/// else. Other threads have no poller: they never call back.
struct build_poller {
  std::function<void()> report;
  std::chrono::steady_clock::time_point next;
};
inline thread_local build_poller* current_poller = nullptr;

/// Calls the poller of this thread when one is set and 100 ms have passed since its last call.
inline void poll() {
  build_poller* p = current_poller;
  if (!p) return;
  const auto now = std::chrono::steady_clock::now();
  if (now < p->next) return;
  p->next = now + std::chrono::milliseconds(100);
  p->report();
}

/// Sets this thread's poller for its lifetime (restores the previous one).
class scoped_poller {
 public:
  explicit scoped_poller(build_poller* p) : previous_(current_poller) { current_poller = p; }
  ~scoped_poller() { current_poller = previous_; }
  scoped_poller(const scoped_poller&) = delete;
  scoped_poller& operator=(const scoped_poller&) = delete;

 private:
  build_poller* previous_;
};

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
