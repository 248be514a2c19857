#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-3.0-or-later
# Installs the built exbsp into a temporary prefix and checks the package as a consumer sees it:
#   1. only public headers are installed, each compiles alone against <prefix>/include (no
#      private header, no CGAL outside adapters/cgal_face_graph.h), warning-free under
#      -Wall -Wextra -Werror;
#   2. the exported targets carry no compile options (no -Wall/-Werror/-ffp-contract/
#      -frounding-math/-fsanitize) and no absolute library paths (imported targets instead);
#   3. examples/consumer (find_package(exbsp)) and examples/viewer (find_package(exbsp
#      COMPONENTS openmesh): OpenMesh reader and adapter, BSP, PNG) build and run, against the
#      static library and, when installed, the shared one (BUILD_SHARED_LIBS=ON);
#   4. find_package(exbsp) works on a machine without OpenMesh unless the component is asked.
# Arguments: BUILD_DIR SOURCE_DIR.
set -euo pipefail
# (grep -q reads from here-strings, never from a pipe: with pipefail, grep -q quitting at the
# first match makes the writer's SIGPIPE fail the pipeline, which inverts `if` tests.)
build_dir="$1"
source_dir="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
cmake --install "$build_dir" --prefix "$prefix" >/dev/null
cmake_dir="$prefix/lib/cmake/exbsp"
[ -d "$cmake_dir" ] || cmake_dir="$(dirname "$(find "$prefix" -name exbspConfig.cmake | head -1)")"
fail() { echo "install_consumer: FAIL: $*" >&2; exit 1; }

# A sanitized exbsp is instrumented: its consumers must link the sanitizer runtimes too.
consumer_flags=()
if grep -q '^EXBSP_SANITIZE:BOOL=ON' "$build_dir/CMakeCache.txt"; then
  consumer_flags=(-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined
                  -DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined)
fi
cxx="$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build_dir/CMakeCache.txt")"
cxx="${cxx:-c++}"

# 1. Headers.
headers="$(cd "$prefix/include" && find exbsp -name '*.h' | sort)"
grep -q '^exbsp/exbsp.h$' <<<"$headers" || fail "no umbrella header exbsp/exbsp.h"
grep -q '^exbsp/core/version.h$' <<<"$headers" || fail "no exbsp/core/version.h"
for private in bsp_tree_impl.h bsp_impl.h bsp_tree.h kernel_ geometry_ reader_util.h fast_orientation.h \
               exact_output.h split_pattern.h cut_plane.h rational.h json_reader.h clip_checks.h rasterizer.h; do
  if grep -q "/$private" <<<"$headers"; then fail "private header installed: $private"; fi
done
cgal_users="$(cd "$prefix/include" && grep -l '#include <CGAL/' $headers || true)"
[ "$cgal_users" = "exbsp/adapters/cgal_face_graph.h" ] || fail "headers including CGAL: $cgal_users"
check_header() {  # one translation unit holding only `#include <HEADER>`
  echo "#include <$1>" | "$cxx" -std=c++17 -fsyntax-only -Wall -Wextra -Werror -I "$prefix/include" -x c++ - \
    || { echo "install_consumer: $1 does not compile alone" >&2; return 1; }
}
export -f check_header
export cxx prefix
echo "$headers" | xargs -P 2 -I{} bash -c 'check_header {}' || fail "an installed header does not compile alone"
echo "install_consumer: $(echo "$headers" | wc -l) public headers, each self-contained"

# 2. Exported interface.
targets="$(cat "$cmake_dir"/exbspTargets*.cmake)"
if grep -q 'INTERFACE_COMPILE_OPTIONS' <<<"$targets"; then fail "exported INTERFACE_COMPILE_OPTIONS"; fi
if grep -Eq -- '-W(all|extra|error)|-ffp-contract|-frounding-math|-fsanitize' <<<"$targets"; then
  fail "exported compile or sanitizer flags"
fi
links="$(grep 'INTERFACE_LINK_LIBRARIES' <<<"$targets" || true)"
if grep -q '"/' <<<"$links"; then fail "absolute path in the link interface"; fi
echo "install_consumer: exported targets carry no compile options and no absolute library paths"

# 3. The examples, static and shared.
# Two interpenetrating unit cubes (the second shifted by (1/2, 1/4, 1/8)): the BSP must split.
awk 'BEGIN {
  print "OFF"; print "16 12 0"
  split("0 0 0 1 0 0 1 1 0 0 1 0 0 0 1 1 0 1 1 1 1 0 1 1", c, " ")
  for (s = 0; s < 2; ++s) for (i = 0; i < 8; ++i)
    print c[3*i+1] + s / 2, c[3*i+2] + s / 4, c[3*i+3] + s / 8
  split("0 3 2 1 4 5 6 7 0 1 5 4 1 2 6 5 2 3 7 6 3 0 4 7", q, " ")
  for (s = 0; s < 2; ++s) for (f = 0; f < 6; ++f)
    print 4, q[4*f+1] + 8*s, q[4*f+2] + 8*s, q[4*f+3] + 8*s, q[4*f+4] + 8*s
}' >"$work/two_cubes.off"
variants=(static)
if [ -n "$(find "$prefix" -name 'libexbsp.so*' | head -1)" ]; then variants+=(shared); fi
for variant in "${variants[@]}"; do
  shared=OFF
  [ "$variant" = shared ] && shared=ON
  for example in consumer viewer; do
    b="$work/build-$example-$variant"
    cmake -S "$source_dir/examples/$example" -B "$b" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" \
      -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=$shared "${consumer_flags[@]}" >/dev/null
    cmake --build "$b" >/dev/null
    if grep -Eq -- '-W(all|extra|error)|-ffp-contract|-frounding-math' "$b/build.ninja"; then
      fail "$example ($variant) is compiled with exbsp's private flags"
    fi
  done
  loads="$(ldd "$work/build-viewer-$variant/exbsp_viewer")"
  if [ "$variant" = shared ]; then
    [[ "$loads" == *libexbsp.so* ]] || fail "the shared viewer does not load libexbsp.so"
  else
    [[ "$loads" != *libexbsp.so* ]] || fail "the static viewer loads libexbsp.so"
  fi
  "$work/build-consumer-$variant/exbsp_consumer" >/dev/null || fail "exbsp_consumer ($variant)"
  "$work/build-viewer-$variant/exbsp_viewer" "$source_dir/tests/data/cube.off" "$work/cube.png" "$work/cube_fragments.off" \
    || fail "exbsp_viewer ($variant) on cube.off"
  "$work/build-viewer-$variant/exbsp_viewer" "$work/two_cubes.off" "$work/two_cubes.png" "$work/two_cubes_fragments.off" \
    | tee "$work/viewer.log"
  grep -q ' 0 splits' "$work/viewer.log" && fail "the intersecting cubes were not split"
  grep -q '89 50 4e 47 0d 0a 1a 0a' <<<"$(od -An -tx1 -N8 "$work/two_cubes.png")" || fail "viewer output is not a PNG"
  echo "install_consumer: examples built and ran against the $variant library"
done

# 4. Without OpenMesh the package still loads (the component alone is then not found).
b="$work/build-no-openmesh"
mkdir -p "$b/src"
cat >"$b/src/CMakeLists.txt" <<'EOF'
cmake_minimum_required(VERSION 3.18)
project(no_openmesh LANGUAGES CXX)
find_package(exbsp REQUIRED)
if(TARGET exbsp::openmesh OR TARGET OpenMeshCore)
  message(FATAL_ERROR "find_package(exbsp) looked up OpenMesh without being asked")
endif()
find_package(exbsp COMPONENTS openmesh)
if(exbsp_FOUND OR TARGET exbsp::openmesh)
  message(FATAL_ERROR "the openmesh component was found without OpenMesh")
endif()
EOF
cmake -S "$b/src" -B "$b/build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_DISABLE_FIND_PACKAGE_OpenMesh=ON \
  >"$b/log" 2>&1 || { cat "$b/log"; fail "find_package(exbsp) needs OpenMesh"; }
echo "install_consumer: find_package(exbsp) works without OpenMesh"
echo "install_consumer: OK"
