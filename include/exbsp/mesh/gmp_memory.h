// SPDX-License-Identifier: LGPL-3.0-or-later
// GMP allocation failures as C++ exceptions. GMP's default allocator calls abort() when
// malloc fails; exbsp's contract is that the library never aborts, so programs using the
// exact kernels (gmpq, epeck) should install these functions once, before any GMP number is
// created (the exbsp command line does so first thing in main).
#pragma once
#include <exbsp/core/export.h>

namespace exbsp {

/// Makes GMP (and MPFR, which allocates through GMP) throw std::bad_alloc instead of aborting
/// when memory runs out (mp_set_memory_functions). Call once at startup, before any mpz/mpq
/// value exists: memory GMP allocated with the previous functions must not be freed with
/// these (they use malloc/realloc/free, as GMP's defaults do, so mixing is in fact harmless).
/// It also loads glibc's unwinder for C frames (see gmp_memory.cpp), without which such an
/// exception crossing pthread_once aborts when memory is exhausted.
/// Caveat: GMP is C, so the exception unwinds through C frames; GMP's own objects being built
/// at that moment leak, which is acceptable when the program is out of memory anyway.
/// An exception from inside GMP can also leave the number being written unusable, so the
/// first failure is absorbed by a 1 MB reserve of address space instead (gmp_memory.cpp):
/// the call completes and check_gmp_memory then throws from C++.
EXBSP_EXPORT void install_gmp_memory_functions();

/// Throws std::bad_alloc when the reserve has been spent (memory ran out inside GMP). Call it
/// between GMP calls, where every number is consistent (exbsp's exact kernel does).
EXBSP_EXPORT void check_gmp_memory();

/// Makes a new reserve after memory was freed (each exact build starts with it), and clears
/// the exhausted mark once there is one. Does nothing before install_gmp_memory_functions.
EXBSP_EXPORT void rearm_gmp_memory_reserve();

}  // namespace exbsp
