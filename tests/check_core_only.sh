#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-3.0-or-later
# The BSP core builds alone (issue 25): EXBSP_BUILD_RENDER=OFF, with the render dependencies'
# lookups disabled (libpng, CLI11, nlohmann-json, pybind11 by CMAKE_DISABLE_FIND_PACKAGE; cairo,
# Clipper and dxflib are not even looked up), builds the core and gpl libraries, installs them
# without view headers, command line or Python module, and examples/consumer builds and runs
# against that prefix with find_package(exbsp COMPONENTS core); COMPONENTS render is refused
# with the reason. A whole compile of the core: a few minutes (skipped, exit 77, under the
# sanitizer run, which would repeat it uninstrumented). Arguments: SOURCE_DIR.
set -euo pipefail
source_dir="$1"
if [ -n "${EXBSP_SANITIZED:-}" ]; then echo "skipped under the sanitizer run"; exit 77; fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "check_core_only: FAIL: $*" >&2; exit 1; }
build="$work/build" prefix="$work/prefix"
cmake -S "$source_dir" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DEXBSP_BUILD_RENDER=OFF \
  -DCMAKE_DISABLE_FIND_PACKAGE_PNG=ON -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON \
  -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON -DCMAKE_DISABLE_FIND_PACKAGE_pybind11=ON \
  >"$work/configure.txt" 2>&1 || { cat "$work/configure.txt" >&2; fail "configure"; }
for target in exbsp_view exbsp exbsp_python exbsp_render_static test_bsp; do
  if ninja -C "$build" -t targets all | grep -q "^$target:"; then fail "target $target exists"; fi
done
cmake --build "$build" -j"$(nproc)" >"$work/build.txt" 2>&1 || { tail -30 "$work/build.txt" >&2; fail "build"; }
cmake --install "$build" --prefix "$prefix" >/dev/null
[ -f "$prefix/include/exbsp/bsp/engine.h" ] || fail "no <exbsp/bsp/engine.h>"
[ ! -e "$prefix/include/exbsp/view" ] || fail "view headers installed without the render library"
[ ! -e "$prefix/include/exbsp/exbsp.h" ] || fail "exbsp.h (which includes view headers) installed"
[ ! -e "$prefix/bin/exbsp" ] || fail "the command line installed"
[ -n "$(find "$prefix" -name 'libexbsp_core.a')" ] || fail "no libexbsp_core.a"
[ -z "$(find "$prefix" -name 'libexbsp_render*')" ] || fail "a render library installed"
cmake -S "$source_dir/examples/consumer" -B "$work/consumer" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/consumer" >/dev/null
"$work/consumer/exbsp_consumer" >"$work/run.txt" || fail "exbsp_consumer"
# COMPONENTS render: not found, saying why.
mkdir -p "$work/render"
cat >"$work/render/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.18)
project(render_consumer LANGUAGES CXX)
find_package(exbsp COMPONENTS render)
message(STATUS "exbsp_FOUND=${exbsp_FOUND} render: ${exbsp_render_NOT_FOUND_MESSAGE}")
CMAKE
out="$(cmake -S "$work/render" -B "$work/render/build" -DCMAKE_PREFIX_PATH="$prefix" 2>&1 || true)"
grep -Eq "exbsp_FOUND=(FALSE|0)" <<<"$out" && grep -q "EXBSP_BUILD_RENDER=OFF" <<<"$out" \
  || { echo "$out" >&2; fail "COMPONENTS render is not refused with the reason"; }
echo "check_core_only: the core alone builds, installs and links ($(cat "$work/run.txt" | head -1))"
