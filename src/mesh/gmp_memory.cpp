// GMP memory functions that throw std::bad_alloc (see gmp_memory.h). GMP requires the
// allocation functions never to return NULL; throwing is the only way out besides abort().
// GMP is compiled with -fexceptions on Debian (libgmp is built so C++ exceptions may cross
// it, which gmpxx relies on), so the exception reaches the caller's catch.
#include "mesh/gmp_memory.h"

#include <gmp.h>

#include <cstdlib>
#include <mutex>
#include <new>

namespace exbsp {

namespace {

void* throwing_allocate(std::size_t size) {
  void* p = std::malloc(size ? size : 1);
  if (!p) throw std::bad_alloc();
  return p;
}

void* throwing_reallocate(void* old, std::size_t /*old_size*/, std::size_t new_size) {
  void* p = std::realloc(old, new_size ? new_size : 1);
  if (!p) throw std::bad_alloc();
  return p;
}

void release(void* p, std::size_t /*size*/) { std::free(p); }

}  // namespace

void install_gmp_memory_functions() {
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
