// SPDX-License-Identifier: LGPL-3.0-or-later
// Shared oracle of the exbsp fuzz targets (tests/fuzz/README.md).
//
// A target feeds one input to a parser inside run_guarded(). The contract (docs/contract.md
// sections 2, 5, 7): bad input is reported by throwing exbsp::error or a subclass; the
// library never aborts. So exbsp::error is the only accepted exception: any other exception,
// a failed invariant (require), a sanitizer report, a crash or a timeout is a finding, and
// libFuzzer keeps the input as a crash-*/timeout-* artifact.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <typeinfo>

#include <exbsp/core/errors.h>

namespace exbsp::fuzz {

/// Stops the run (SIGABRT: libFuzzer saves the input) when `ok` is false.
inline void require(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "exbsp fuzz: invariant violated: %s\n", what);
  std::abort();
}

/// Runs `parse`; exbsp::error is the expected rejection of bad input, anything else aborts.
template <class F>
void run_guarded(F&& parse) {
  try {
    parse();
  } catch (const exbsp::error&) {
    // Bad input, reported the documented way.
  } catch (const std::exception& e) {
    std::fprintf(stderr, "exbsp fuzz: unexpected exception %s: %s\n", typeid(e).name(), e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "exbsp fuzz: unexpected exception of a non-std type\n");
    std::abort();
  }
}

}  // namespace exbsp::fuzz
