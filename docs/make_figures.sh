#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-3.0-or-later
# Regenerates the README's pictures from the committed code (one command):
#   docs/make_figures.sh [BUILD_DIR]   (default build/, built by scripts/build)
# - docs/images/demo.png: `exbsp render` of the built-in demo scene;
# - docs/images/exact_vs_double.png and .json: bench/kernel_figure on the CGAL corpus's pinion
#   (data/meshes, extracted by scripts/setup): exact | double | pixels that differ;
# - docs/images/drawing.svg and drawing.png: `exbsp drawing` of the corpus's couplingdown with a
#   section, as a line drawing (SVG) and shaded as PDF, rasterised by pdftoppm (poppler).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$here/build}"
[ -x "$build/src/app/exbsp" ] && [ -x "$build/bench/kernel_figure" ] ||
  { echo "make_figures: build first (scripts/build)" >&2; exit 2; }
cd "$here"
"$build/src/app/exbsp" render -q -o "$here/docs/images/demo.png"
"$build/bench/kernel_figure" data/meshes/pinion.off "$here/docs/images/exact_vs_double.png" \
  --kernel double --view iso --size 360x360 | tee "$here/docs/images/exact_vs_double.json"
for ext in svg pdf; do
  flags=()
  [ "$ext" = svg ] && flags=(--lines-only)
  "$build/src/app/exbsp" drawing data/meshes/couplingdown.off -o "$here/docs/images/drawing.$ext" \
    --section A=0,1,0,0 --title "Coupling (CGAL corpus)" --number EXB-0001 --date 2026-11-26 -q \
    "${flags[@]}"
done
pdftoppm -r 60 -png -singlefile "$here/docs/images/drawing.pdf" "$here/docs/images/drawing"
rm "$here/docs/images/drawing.pdf"
