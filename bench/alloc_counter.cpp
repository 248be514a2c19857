// SPDX-License-Identifier: LGPL-3.0-or-later
// Heap accounting by replacing the global operator new/delete and GMP's memory functions.
// Sizes are malloc_usable_size of the block on both allocation and release, so no header is
// added to blocks and blocks allocated before install() are released correctly.
#include "alloc_counter.h"

#include <gmp.h>
#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace exbsp::bench::alloc_counter {
namespace {

std::atomic<bool> counting{false};
std::atomic<std::int64_t> live_bytes{0}, peak_bytes{0}, calls{0};

inline void note_allocated(void* p) {
  if (!p || !counting.load(std::memory_order_relaxed)) return;
  const auto n = static_cast<std::int64_t>(malloc_usable_size(p));
  calls.fetch_add(1, std::memory_order_relaxed);
  const std::int64_t now = live_bytes.fetch_add(n, std::memory_order_relaxed) + n;
  std::int64_t peak = peak_bytes.load(std::memory_order_relaxed);
  while (now > peak && !peak_bytes.compare_exchange_weak(peak, now, std::memory_order_relaxed)) {
  }
}

inline void note_released(void* p) {
  if (!p || !counting.load(std::memory_order_relaxed)) return;
  live_bytes.fetch_sub(static_cast<std::int64_t>(malloc_usable_size(p)), std::memory_order_relaxed);
}

void* gmp_allocate(std::size_t n) {
  void* p = std::malloc(n);
  if (!p) std::abort();  // GMP cannot recover from a failed allocation either
  note_allocated(p);
  return p;
}

void* gmp_reallocate(void* p, std::size_t, std::size_t n) {
  note_released(p);
  void* q = std::realloc(p, n);
  if (!q) std::abort();
  note_allocated(q);
  return q;
}

void gmp_release(void* p, std::size_t) {
  note_released(p);
  std::free(p);
}

void* allocate(std::size_t n) {
  void* p = std::malloc(n ? n : 1);
  if (!p) throw std::bad_alloc();
  note_allocated(p);
  return p;
}

void* allocate_aligned(std::size_t n, std::size_t alignment) {
  void* p = nullptr;
  if (alignment < sizeof(void*)) alignment = sizeof(void*);
  if (posix_memalign(&p, alignment, n ? n : 1) != 0) throw std::bad_alloc();
  note_allocated(p);
  return p;
}

void release(void* p) noexcept {
  note_released(p);
  std::free(p);
}

}  // namespace

void install() { mp_set_memory_functions(gmp_allocate, gmp_reallocate, gmp_release); }

void start() {
  counting.store(false);
  live_bytes.store(0);
  peak_bytes.store(0);
  calls.store(0);
  counting.store(true);
}

void stop() { counting.store(false); }
std::int64_t live() { return live_bytes.load(); }
std::int64_t peak() { return peak_bytes.load(); }
std::int64_t allocations() { return calls.load(); }

}  // namespace exbsp::bench::alloc_counter

// The replaceable global allocation functions. The array, nothrow and sized forms of the
// standard library forward to these four.
void* operator new(std::size_t n) { return exbsp::bench::alloc_counter::allocate(n); }
void* operator new[](std::size_t n) { return exbsp::bench::alloc_counter::allocate(n); }
void operator delete(void* p) noexcept { exbsp::bench::alloc_counter::release(p); }
void operator delete[](void* p) noexcept { exbsp::bench::alloc_counter::release(p); }
void operator delete(void* p, std::size_t) noexcept { exbsp::bench::alloc_counter::release(p); }
void operator delete[](void* p, std::size_t) noexcept { exbsp::bench::alloc_counter::release(p); }
void* operator new(std::size_t n, std::align_val_t a) {
  return exbsp::bench::alloc_counter::allocate_aligned(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a) {
  return exbsp::bench::alloc_counter::allocate_aligned(n, static_cast<std::size_t>(a));
}
void operator delete(void* p, std::align_val_t) noexcept {
  exbsp::bench::alloc_counter::release(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
  exbsp::bench::alloc_counter::release(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  exbsp::bench::alloc_counter::release(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
  exbsp::bench::alloc_counter::release(p);
}
