#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-3.0-or-later
# The installed pkg-config modules work (cmake/pkgconfig.cmake): the build is installed into a
# temporary prefix (and moved, to check that the modules find their prefix themselves), then
#   1. `pkg-config --cflags --libs exbsp-core` compiles, links and runs examples/consumer, and
#      names neither cairo, Clipper, libpng nor the render or GPL libraries;
#   2. `pkg-config --cflags --libs exbsp-render exbsp-gpl` builds a program using both;
#   3. `--static` adds each component's private dependencies.
# Arguments: BUILD_DIR SOURCE_DIR. Run by ctest (pkgconfig_consumer).
set -euo pipefail
build_dir="$1"
source_dir="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "check_pkgconfig: FAIL: $*" >&2; exit 1; }
command -v pkg-config >/dev/null || fail "pkg-config is missing (scripts/setup installs it)"
cmake --install "$build_dir" --prefix "$work/installed" >/dev/null
mv "$work/installed" "$work/moved"
prefix="$work/moved"
pc="$(dirname "$(find "$prefix" -name exbsp-core.pc | head -1)")"
[ -f "$pc/exbsp-core.pc" ] || fail "exbsp-core.pc is not installed"
export PKG_CONFIG_PATH="$pc"
cxx="$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build_dir/CMakeCache.txt")"
cxx="${cxx:-c++}"
flags=()
if grep -q '^EXBSP_SANITIZE:BOOL=ON' "$build_dir/CMakeCache.txt"; then flags=(-fsanitize=address,undefined); fi
static=()
if [ -z "$(find "$prefix" -name 'libexbsp_core.so*' | head -1)" ]; then static=(--static); fi
libdir="$(pkg-config --variable=libdir exbsp-core)"

# 1. The core alone.
core="$(pkg-config "${static[@]}" --cflags --libs exbsp-core)"
if grep -Eq 'cairo|polyclipping|png|exbsp_render|exbsp_gpl' <<<"$core"; then fail "exbsp-core brings: $core"; fi
# shellcheck disable=SC2086
"$cxx" -std=c++17 "${flags[@]}" "$source_dir/examples/consumer/main.cpp" -o "$work/consumer" $core \
  -Wl,-rpath,"$libdir" || fail "examples/consumer does not build with pkg-config --cflags --libs exbsp-core"
"$work/consumer" >/dev/null || fail "examples/consumer built with pkg-config failed"
echo "check_pkgconfig: exbsp-core: $core"

# 2. render and gpl.
cat >"$work/all.cpp" <<'END_OF_PROGRAM'
#include <exbsp/clip/section_cap.h>
#include <exbsp/exbsp.h>

int main() {
  const exbsp::triangle_soup box = exbsp::scene::make_box({0, 0, 0}, {1, 1, 1});
  const exbsp::section_result r = exbsp::section_with_cap(box, {0, 0, 1, -0.5});
  const std::vector<std::uint8_t> png = exbsp::view::encode_png(exbsp::view::image(4, 4, {0, 0, 0}));
  return !r.cap.empty() && png.size() > 8 ? 0 : 1;
}
END_OF_PROGRAM
all="$(pkg-config "${static[@]}" --cflags --libs exbsp-render exbsp-gpl)"
# shellcheck disable=SC2086
"$cxx" -std=c++17 "${flags[@]}" "$work/all.cpp" -o "$work/all" $all -Wl,-rpath,"$libdir" \
  || fail "a program of render and gpl does not build with pkg-config"
"$work/all" || fail "the render and gpl program failed"
echo "check_pkgconfig: exbsp-render exbsp-gpl: $all"

# 3. Private dependencies for static linking.
render_static="$(pkg-config --static --libs exbsp-render)"
for lib in -lexbsp_render -lexbsp_core -lcairo -lpolyclipping -lpng16 -lgmp; do
  grep -q -- "$lib" <<<"$render_static" || fail "pkg-config --static --libs exbsp-render lacks $lib: $render_static"
done
echo "check_pkgconfig: OK"
