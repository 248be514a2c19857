#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-3.0-or-later
# The shared libraries export exbsp's public API and nothing else: every dynamic symbol they
# define (nm -D --defined-only --demangle) is in namespace exbsp (functions, objects, and the
# typeinfo and vtables of exbsp's classes). Symbols are hidden by default
# (CXX_VISIBILITY_PRESET hidden, VISIBILITY_INLINES_HIDDEN), the public API is marked with
# EXBSP_EXPORT (<exbsp/core/export.h>, CMake's GenerateExportHeader), and a linker version
# script keeps the instantiations of std templates that GCC would give default visibility
# local (src/CMakeLists.txt). docs/package.md, "Symbols".
# Arguments: the shared libraries. Run by ctest (exported_symbols).
set -euo pipefail
[ $# -gt 0 ] || { echo "check_exports: no library given" >&2; exit 2; }
bad=0
for lib in "$@"; do
  symbols="$(nm -D --defined-only --demangle "$lib" | cut -d' ' -f3-)"
  count="$(grep -c . <<<"$symbols" || true)"
  outside="$(sed -E 's/^(typeinfo name for|typeinfo for|vtable for|VTT for|construction vtable for [^ ]+-in-|guard variable for|non-virtual thunk to|virtual thunk to|covariant return thunk to) //' \
    <<<"$symbols" | grep -v '^exbsp::' || true)"
  if [ -n "$outside" ]; then
    echo "check_exports: $(basename "$lib") exports $(grep -c . <<<"$outside") symbols outside namespace exbsp:" >&2
    head -40 <<<"$outside" >&2
    bad=1
  fi
  echo "check_exports: $(basename "$lib"): $count exported symbols"
done
exit "$bad"
