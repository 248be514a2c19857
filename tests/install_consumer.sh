#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-3.0-or-later
# Installs the built exbsp into a temporary prefix and checks the package as a consumer sees it:
#   1. only public headers are installed, each compiles alone against <prefix>/include (no
#      private header, no CGAL outside adapters/cgal_face_graph.h), warning-free under
#      -Wall -Wextra -Werror;
#   2. the exported targets carry no compile options (no -Wall/-Werror/-ffp-contract/
#      -frounding-math/-fsanitize) and no absolute library paths (imported targets instead);
#   3. examples/consumer (find_package(exbsp COMPONENTS core)) and examples/viewer
#      (find_package(exbsp COMPONENTS openmesh render): OpenMesh reader and adapter, BSP, PNG)
#      build and run, against the static libraries and, when installed, the shared ones
#      (BUILD_SHARED_LIBS=ON); the shared viewer loads libexbsp_core and libexbsp_render, never
#      the GPL libexbsp_gpl;
#   4. find_package(exbsp) works on a machine without OpenMesh unless the component is asked;
#   5. COMPONENTS core works where cairo, Clipper, libpng and OpenMP cannot be found: their
#      lookups are disabled or point at files that do not exist, and the consumer's targets,
#      compile and link lines and loaded libraries show none of them (the static core library
#      alone still needs the OpenMP runtime, so there OpenMP stays findable);
#   6. a consumer of every component (core, render, gpl, openmesh) builds and runs: a capped
#      section (gpl) of a procedural box (core), an image written as PNG (render).
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
for private in section_impl.h bsp_tree_impl.h bsp_impl.h bsp_tree.h kernel_ geometry_ reader_util.h fast_orientation.h \
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
targets="$(cat "$cmake_dir"/exbsp_*_targets*.cmake)"
if grep -q 'INTERFACE_COMPILE_OPTIONS' <<<"$targets"; then fail "exported INTERFACE_COMPILE_OPTIONS"; fi
if grep -Eq -- '-W(all|extra|error)|-ffp-contract|-frounding-math|-fsanitize' <<<"$targets"; then
  fail "exported compile or sanitizer flags"
fi
links="$(grep 'INTERFACE_LINK_LIBRARIES' <<<"$targets" || true)"
if grep -q '"/' <<<"$links"; then fail "absolute path in the link interface"; fi
core_targets="$(cat "$cmake_dir"/exbsp_core_targets*.cmake)"
if grep -Eiq 'cairo|polyclipping|PNG' <<<"$core_targets"; then fail "the core targets name cairo, Clipper or libpng"; fi
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
if [ -n "$(find "$prefix" -name 'libexbsp_core.so*' | head -1)" ]; then variants+=(shared); fi
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
    [[ "$loads" == *libexbsp_core.so* && "$loads" == *libexbsp_render.so* ]] \
      || fail "the shared viewer does not load libexbsp_core.so and libexbsp_render.so"
    [[ "$loads" != *libexbsp_gpl.so* ]] || fail "the (LGPL) viewer loads the GPL libexbsp_gpl.so"
  else
    [[ "$loads" != *libexbsp_* ]] || fail "the static viewer loads a shared exbsp library"
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

# 5. The core alone, where cairo, Clipper, libpng and OpenMP cannot be found. CMake's own
# lookups are disabled (CMAKE_DISABLE_FIND_PACKAGE_<Pkg>); exbsp's cairo.cmake and
# polyclipping.cmake find_path/find_library results are preset to files that do not exist, so
# that any use of them fails the build; and the consumer must not even have the targets.
for variant in "${variants[@]}"; do
  shared=OFF
  hide=(-DCMAKE_DISABLE_FIND_PACKAGE_PNG=ON -DCMAKE_DISABLE_FIND_PACKAGE_PkgConfig=ON
        -DEXBSP_CAIRO_INCLUDE_DIR=/nonexistent/include -DEXBSP_CAIRO_LIBRARY=/nonexistent/libcairo.so
        -DEXBSP_POLYCLIPPING_INCLUDE_DIR=/nonexistent/include
        -DEXBSP_POLYCLIPPING_LIBRARY=/nonexistent/libpolyclipping.so)
  if [ "$variant" = shared ]; then
    shared=ON
    hide+=(-DCMAKE_DISABLE_FIND_PACKAGE_OpenMP=ON)
  fi
  b="$work/core-only-$variant"
  mkdir -p "$b/src"
  cat >"$b/src/CMakeLists.txt" <<END_OF_PROJECT
cmake_minimum_required(VERSION 3.18)
project(core_only LANGUAGES CXX)
find_package(exbsp 0.1 REQUIRED COMPONENTS core)
foreach(t exbsp::render exbsp::gpl exbsp::cairo exbsp::polyclipping PNG::PNG)
  if(TARGET \${t})
    message(FATAL_ERROR "find_package(exbsp COMPONENTS core) made \${t}")
  endif()
endforeach()
if("$shared" STREQUAL "ON" AND TARGET OpenMP::OpenMP_CXX)
  message(FATAL_ERROR "find_package(exbsp COMPONENTS core) looked up OpenMP for the shared library")
endif()
add_executable(exbsp_consumer $source_dir/examples/consumer/main.cpp)
target_link_libraries(exbsp_consumer PRIVATE exbsp::core)
END_OF_PROJECT
  cmake -S "$b/src" -B "$b/build" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
    -DBUILD_SHARED_LIBS=$shared "${hide[@]}" "${consumer_flags[@]}" >"$b/log" 2>&1 \
    || { cat "$b/log"; fail "find_package(exbsp COMPONENTS core) ($variant) needs more than GMP"; }
  cmake --build "$b/build" >>"$b/log" 2>&1 || { cat "$b/log"; fail "the core-only consumer ($variant) does not build"; }
  if grep -Eiq 'cairo|polyclipping|png|nonexistent' "$b/build/build.ninja"; then
    fail "the core-only consumer ($variant) is compiled or linked with cairo, Clipper or libpng"
  fi
  loads="$(ldd "$b/build/exbsp_consumer")"
  if grep -Eq 'libcairo|libpolyclipping|libpng|libexbsp_render|libexbsp_gpl' <<<"$loads"; then
    fail "the core-only consumer ($variant) loads: $loads"
  fi
  if [ "$variant" = shared ]; then
    [[ "$loads" == *libexbsp_core.so* ]] || fail "the shared core-only consumer does not load libexbsp_core.so"
  fi
  "$b/build/exbsp_consumer" >/dev/null || fail "the core-only consumer ($variant) failed"
  hidden="cairo, Clipper, libpng"
  [ "$variant" = shared ] && hidden+=", OpenMP"
  echo "install_consumer: COMPONENTS core builds and runs ($variant) without $hidden"
done

# 6. Every component at once.
for variant in "${variants[@]}"; do
  shared=OFF
  [ "$variant" = shared ] && shared=ON
  b="$work/all-$variant"
  mkdir -p "$b/src"
  cat >"$b/src/CMakeLists.txt" <<'END_OF_PROJECT'
cmake_minimum_required(VERSION 3.18)
project(all_components LANGUAGES CXX)
find_package(exbsp 0.1 REQUIRED COMPONENTS core render gpl openmesh)
add_executable(all_components main.cpp)
target_link_libraries(all_components PRIVATE exbsp::exbsp exbsp::openmesh)
END_OF_PROJECT
  cat >"$b/src/main.cpp" <<'END_OF_PROGRAM'
#include <exbsp/clip/convex_hull.h>
#include <exbsp/clip/section_cap.h>
#include <exbsp/exbsp.h>

#include <cstdio>

int main(int argc, char** argv) {
  const exbsp::triangle_soup box = exbsp::scene::make_box({0, 0, 0}, {1, 1, 1});  // core
  const exbsp::section_result core = exbsp::section(box, {0, 0, 1, -0.5});       // core
  const exbsp::section_result capped = exbsp::section_with_cap(box, {0, 0, 1, -0.5});  // gpl
  const auto hull =
      exbsp::clip::convex_hull_half_spaces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});  // gpl
  exbsp::view::image img(8, 8, {255, 255, 255});  // render
  if (argc > 1) exbsp::view::write_png(img, argv[1]);
  std::printf("cap %zu, hull %zu\n", capped.cap.size(), hull.size());
  return core.cap.empty() && !capped.cap.empty() && hull.size() == 4 ? 0 : 1;
}
END_OF_PROGRAM
  cmake -S "$b/src" -B "$b/build" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
    -DBUILD_SHARED_LIBS=$shared "${consumer_flags[@]}" >"$b/log" 2>&1 \
    || { cat "$b/log"; fail "find_package(exbsp COMPONENTS core render gpl openmesh) ($variant)"; }
  cmake --build "$b/build" >>"$b/log" 2>&1 || { cat "$b/log"; fail "the all-components consumer ($variant) does not build"; }
  "$b/build/all_components" "$b/out.png" || fail "the all-components consumer ($variant) failed"
  echo "install_consumer: COMPONENTS core render gpl openmesh build and run ($variant)"
done
echo "install_consumer: OK"
