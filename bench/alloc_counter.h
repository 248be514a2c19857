// SPDX-License-Identifier: LGPL-3.0-or-later
// Heap accounting for bench_sweep: live and peak heap bytes while counting is on.
//
// What is counted: every block from the global operator new (all variants) and every block
// GMP allocates (mp_set_memory_functions: the limbs of CGAL's and exbsp's rationals), each
// by its malloc_usable_size (the bytes glibc really hands out, allocator headers excluded).
// Not counted: thread stacks, static data, direct malloc calls by other libraries (none on
// the BSP build path). Blocks freed while counting that were allocated before count as
// negative, so peak() is the high-water mark of (live now - live at start()).
// alloc_counter.cpp replaces the global operator new/delete; link it into one program only.
#pragma once
#include <cstdint>

namespace exbsp::bench::alloc_counter {

/// Installs the GMP memory functions. Call once at the start of main, before any GMP use.
void install();
/// Starts counting from zero.
void start();
/// Stops counting (the values stay readable).
void stop();
/// Live bytes (relative to start()).
std::int64_t live();
/// High-water mark of live() since start().
std::int64_t peak();
/// Allocation calls since start().
std::int64_t allocations();

}  // namespace exbsp::bench::alloc_counter
