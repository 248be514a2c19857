#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-3.0-or-later
# Renders the pictures of README.md "## Vector output" into scenes/images/: scenes/perspective.json
# as exbsp's PNG (vector_png.png) and as a visible-region SVG with visible and hidden edges
# ("svg": {"edges": "visible+hidden"}), rasterized by headless Chromium at 1:1
# (vector_svg_chromium.png), and the same drawing of data/meshes/fandisk.off, lit, when the
# corpus is there (vector_fandisk_chromium.png); and the README's pair of one CAD part,
# data/meshes/joint.off, lit, in a view fitted to it, as exbsp's PNG and as the visible-region SVG
# with visible and hidden edges (docs/images/joint.png, docs/images/joint.svg, and from the
# front docs/images/joint_front.svg), and the PNG with those edges drawn over it
# (docs/images/joint_edges.png) and its wireframe (docs/images/joint_wireframe.png), when the
# corpus is there. Anyone can rerun it (needs chromium):
#   scenes/make_vector_images.sh [path/to/exbsp]     (default: $EXBSP, then build/src/app/exbsp)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
images_setup make_vector_images "$@"
chromium="${CHROMIUM:-$(command -v chromium || true)}"
if [ -z "$chromium" ]; then
  echo "make_vector_images: chromium not found (apt-get install chromium)" >&2
  exit 2
fi

# with_edges SCENE OUT [MESH]: SCENE with "svg": {"edges": "visible+hidden"}, mesh paths
# absolute; with MESH, its meshes replaced by that one mesh, lit, 800 x 600.
with_edges() {
  python3 - "$@" <<'PY'
import json, os, sys
scene_path, out = sys.argv[1:3]
with open(scene_path) as f:
    scene = json.load(f)
base = os.path.dirname(os.path.abspath(scene_path))
for mesh in scene.get("meshes", []):
    if not os.path.isabs(mesh["file"]):
        mesh["file"] = os.path.join(base, mesh["file"])
if len(sys.argv) > 3:
    scene["meshes"] = [{"file": os.path.abspath(sys.argv[3]), "color": [205, 210, 220]}]
    scene["camera"] = {"eye": [2.4, 1.6, 1.3], "look_at": [0, 0, 0], "up": [0, 0, 1]}
    scene["projection"] = {"type": "perspective", "fovy_deg": 30, "near": 0.5, "far": 10}
    scene["viewport"] = {"width": 800, "height": 600}
    scene["background"] = [255, 255, 255]
    scene["effects"] = {"lighting": {"direction": [1, 0.4, 0.9], "ambient": 0.35, "intensity": 0.65}}
scene["svg"] = {"edges": "visible+hidden"}
with open(out, "w") as f:
    json.dump(scene, f, indent=1)
PY
}

# shoot SVG W H PNG: headless Chromium screenshot of SVG embedded 1:1 in a page.
shoot() {
  printf '<!DOCTYPE html><html><head><style>html,body{margin:0;overflow:hidden}img{display:block}</style></head><body><img src="%s" width="%s" height="%s"></body></html>' \
    "$1" "$2" "$3" >"$tmp/page.html"
  "$chromium" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking \
    --disable-component-update --disable-sync --hide-scrollbars --force-device-scale-factor=1 \
    --force-color-profile=srgb --user-data-dir="$tmp/profile" --screenshot="$4" --window-size="$2,$3" \
    "file://$tmp/page.html" >/dev/null 2>&1
}

"$exbsp" render "$here/perspective.json" -o "$out/vector_png.png"
with_edges "$here/perspective.json" "$tmp/perspective.json"
"$exbsp" render "$tmp/perspective.json" -o "$tmp/perspective.svg"
shoot "$tmp/perspective.svg" 800 600 "$out/vector_svg_chromium.png"
fandisk="$here/../data/meshes/fandisk.off"
if [ -f "$fandisk" ]; then
  with_edges "$here/perspective.json" "$tmp/fandisk.json" "$fandisk"
  "$exbsp" render "$tmp/fandisk.json" -o "$tmp/fandisk.svg"
  shoot "$tmp/fandisk.svg" 800 600 "$out/vector_fandisk_chromium.png"
fi
joint="$here/../data/meshes/joint.off"
if [ -f "$joint" ]; then
  docs="$here/../docs/images"
  mkdir -p "$docs"
  # `exbsp render MESH`: lit, in the view fitted to the mesh (scene/mesh_scene.h).
  "$exbsp" render "$joint" -q --size 640x480 -o "$docs/joint.png"
  "$exbsp" render "$joint" -q --size 640x480 --edges visible+hidden -o "$docs/joint.svg"
  "$exbsp" render "$joint" -q --size 640x480 --edges visible+hidden --view front -o "$docs/joint_front.svg"
  # Shaded with edges: the same edges drawn over the PNG ("raster": {"edges"}).
  "$exbsp" render "$joint" -q --size 640x480 --edges visible+hidden -o "$docs/joint_edges.png"
  "$exbsp" render "$joint" -q --size 640x480 --wireframe -o "$docs/joint_wireframe.png"
  echo "make_vector_images: wrote docs/images/joint.png ($(stat -c %s "$docs/joint.png") bytes) and joint.svg ($(stat -c %s "$docs/joint.svg") bytes)"
fi
echo "make_vector_images: wrote $(ls "$out"/vector_*.png | wc -l) images into $out"
