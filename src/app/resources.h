// SPDX-License-Identifier: LGPL-3.0-or-later
// The command line's memory and thread policy: how much the process may use, the default
// --max-fragments derived from it, the --threads limit and the repair of OMP_NUM_THREADS. The
// library itself has no policy (0 means no limit); these defaults belong to the command line.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <exbsp/bsp/engine.h>

namespace exbsp::cli {

/// The memory this process may still use: MemAvailable, or the address-space limit when it is
/// lower (0 when neither is known).
std::uint64_t available_memory_bytes();

/// What a command does with its tree, for its memory per fragment: `build` only builds (and
/// saves); the others also make a frame, a document or a drawing of it.
enum class fragment_use { build, command };

/// The default --max-fragments: half the available memory at the kernel's bytes per fragment
/// (kernel_row::bytes_per_fragment, or build_bytes_per_fragment for fragment_use::build: the
/// other half for the input, the output and the allocator's slack), at least 10,000; 0 (no
/// limit) when the available memory is unknown.
std::size_t default_fragment_budget(kernel_id kernel, fragment_use use = fragment_use::command);

/// The --max-fragments help text of build (fragment_use::build) or of order and render (from
/// the kernel table).
std::string max_fragments_help(fragment_use use = fragment_use::command);

/// The most threads --threads accepts (the library's limit: 4 per hardware thread, at most
/// 1024; libgomp crashes or fails on team sizes in the tens of thousands).
unsigned max_threads();

/// OMP_NUM_THREADS is read by libgomp before main; a value it accepts but cannot honour
/// (100000) crashes the first parallel region. Anything but a number in 1..max_threads()
/// (first entry of a nesting list) is replaced by the hardware thread count, with a warning.
void sanitize_omp_num_threads();

/// Fixes glibc's mmap threshold at its initial 128 KiB. glibc raises the threshold each time a
/// large block allocated by mmap is freed, so that the build's later large vectors (fragment
/// lists, exact-point chunks) come from the heap, whose freed holes stay resident. `exbsp
/// build --json` (peak_rss_bytes, the peak at the build's end) of bench/assembly.py's
/// assemblies, side by side: 316,935 triangles peaked at 230 MB
/// with the moving threshold and 184 MB with a fixed one; 1,000,622 triangles (3,515,359
/// fragments) at 725 MB and 606 MB (206 and 172 B per fragment), the build times the same. A
/// no-op without glibc; the library leaves the allocator alone (the command line's policy).
void fix_malloc_mmap_threshold();

/// Starts OpenMP's thread pool now: libgomp cannot report an allocation failure (it prints
/// "Out of memory allocating N bytes" and exits 1), so the pool and its team are made while
/// memory is plentiful, and later parallel regions of the same size reuse them.
void start_thread_pool();

}  // namespace exbsp::cli
