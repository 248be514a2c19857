// SPDX-License-Identifier: LGPL-3.0-or-later
// Work split over threads in the view (the raster's bands, the SVG drawing's items): run a
// function on n workers, this thread being worker 0, and rethrow the first exception once all
// have stopped. Plain std::thread: the view does not link OpenMP (the core-only build and the
// render component must not need it). Internal to view.
#pragma once
#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace exbsp::view {

/// The default number of workers: one per hardware thread, at most 8 (the raster's bands and
/// the drawing's items; their results do not depend on the count).
inline unsigned hardware_workers() {
  return std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
}

/// Calls work(w) for w in [0, workers) on as many threads (w = 0 on this one); rethrows the
/// first exception (by worker) after all have returned.
template <class Work>
void run_workers(unsigned workers, Work work) {
  std::vector<std::exception_ptr> errors(std::max(1u, workers));
  auto guarded = [&](unsigned w) {
    try {
      work(w);
    } catch (...) {
      errors[w] = std::current_exception();
    }
  };
  std::vector<std::thread> threads;
  unsigned w = 1;
  for (; w < workers; ++w) {
    try {
      threads.emplace_back(guarded, w);
    } catch (...) {
      break;  // no thread to be had: this one does the remaining workers' share
    }
  }
  for (unsigned rest = w; rest < workers; ++rest) guarded(rest);
  guarded(0);
  for (std::thread& t : threads) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

/// Calls body(i, worker) for every i in [0, n) on up to `workers` threads, taking indices in
/// chunks (up to 64, at least 8 per worker); the first exception stops the others' taking.
template <class Body>
void parallel_for(std::size_t n, unsigned workers, Body body) {
  const std::size_t chunk = std::clamp<std::size_t>(n / (8 * std::max(1u, workers)), 1, 64);
  workers = static_cast<unsigned>(std::min<std::size_t>(workers, (n + chunk - 1) / chunk));
  if (workers <= 1) {
    for (std::size_t i = 0; i < n; ++i) body(i, 0u);
    return;
  }
  std::atomic<std::size_t> next{0};
  run_workers(workers, [&](unsigned w) {
    try {
      for (std::size_t i; (i = next.fetch_add(chunk)) < n;)
        for (std::size_t j = i; j < std::min(n, i + chunk); ++j) body(j, w);
    } catch (...) {
      next.store(n);
      throw;
    }
  });
}

}  // namespace exbsp::view
