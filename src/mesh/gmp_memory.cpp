// SPDX-License-Identifier: LGPL-3.0-or-later
// GMP memory functions that throw std::bad_alloc (see gmp_memory.h). GMP requires the
// allocation functions never to return NULL; throwing is the only way out besides abort().
// GMP is compiled with -fexceptions on Debian (libgmp is built so C++ exceptions may cross
// it, which gmpxx relies on), so the exception reaches the caller's catch.
#include <exbsp/mesh/gmp_memory.h>

#include <gmp.h>

#include <atomic>
#include <cstdlib>
#include <mutex>
#include <new>

namespace exbsp {

namespace {

// The reserve. An exception thrown out of a GMP function can leave the number being written
// unusable: GMP 6.2's mpz_mul, for one, records the new size of its destination before
// asking for the memory, so when the allocation throws, the destination's destructor frees
// a pointer it does not own and glibc aborts ("free(): invalid pointer"; seen with exbsp's
// exact kernel under a 200 MB address-space cap). So the first failure does not throw: it
// frees the reserve, retries, and marks memory exhausted; the caller's next check
// (check_gmp_memory, in C++ code between GMP calls) throws std::bad_alloc, with every
// number in a consistent state. Only a failure after the reserve is spent throws from GMP.
// 4 MB, not 1: one exact value takes kilobytes, but once glibc has raised its mmap threshold
// (it does when a large block is freed) a failed allocation falls back to mapping at least
// 1 MB at a time, which a 1 MB reserve, freed, did not make room for (test_hostile, GmpMemory).
constexpr std::size_t reserve_bytes = std::size_t{4} << 20;
std::atomic<void*> reserve{nullptr};
std::atomic<bool> exhausted{false};
std::atomic<bool> installed{false};

/// Frees the reserve (once) and marks memory exhausted; false when it was already spent.
bool spend_reserve() {
  void* r = reserve.exchange(nullptr);
  if (!r) return false;
  std::free(r);
  exhausted.store(true);
  return true;
}

void* throwing_allocate(std::size_t size) {
  void* p = std::malloc(size ? size : 1);
  if (!p && spend_reserve()) p = std::malloc(size ? size : 1);
  if (!p) throw std::bad_alloc();
  return p;
}

void* throwing_reallocate(void* old, std::size_t /*old_size*/, std::size_t new_size) {
  void* p = std::realloc(old, new_size ? new_size : 1);
  if (!p && spend_reserve()) p = std::realloc(old, new_size ? new_size : 1);
  if (!p) throw std::bad_alloc();
  return p;
}

void release(void* p, std::size_t /*size*/) { std::free(p); }

}  // namespace

void rearm_gmp_memory_reserve() {
  if (!installed.load() || reserve.load()) return;
  void* r = std::malloc(reserve_bytes);  // address space only: never written, so never resident
  if (!r) return;                        // still short of memory: the next check throws
  void* expected = nullptr;
  if (!reserve.compare_exchange_strong(expected, r)) {
    std::free(r);
    return;
  }
  exhausted.store(false);
}

void check_gmp_memory() {
  if (exhausted.load(std::memory_order_relaxed)) throw std::bad_alloc();
}

void install_gmp_memory_functions() {
  installed.store(true);
  rearm_gmp_memory_reserve();
  mp_set_memory_functions(throwing_allocate, throwing_reallocate, release);
  // An exception from GMP often unwinds through glibc's own C frames (pthread_once, which
  // std::call_once and CGAL's lazy kernel use). Their personality routine dlopen()s
  // libgcc_s on first use, and when memory has run out that dlopen fails and glibc aborts
  // ("libgcc_s.so.1 must be installed for unwinding to work"; seen under a 200 MB cap).
  // One exception thrown through std::call_once now, while memory is plentiful, loads it.
  std::once_flag flag;
  try {
    std::call_once(flag, [] { throw std::bad_alloc(); });
  } catch (const std::bad_alloc&) {
  }
}

}  // namespace exbsp
