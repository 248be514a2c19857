#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-3.0-or-later
# Renders the pictures of README.md "## Effects" into scenes/images/: every effect scene with
# its effect (NAME.png) and the same scene without it (NAME_without.png), and the curve scene
# with and without its curves. 400 x 300 each. Anyone can rerun it:
#   scenes/make_effect_images.sh [path/to/exbsp]     (default: $EXBSP, then build/src/app/exbsp)
# The "without" scenes are temporary copies with "effects" (or "curves") removed and mesh paths
# made absolute; nothing else changes.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
images_setup make_effect_images "$@"

# without SCENE KEY OUT: SCENE minus its top-level KEY, mesh paths absolute.
without() {
  python3 - "$1" "$2" "$3" <<'PY'
import json, os, sys
scene_path, key, out = sys.argv[1:4]
with open(scene_path) as f:
    scene = json.load(f)
scene.pop(key, None)
base = os.path.dirname(os.path.abspath(scene_path))
for mesh in scene.get("meshes", []):
    if not os.path.isabs(mesh["file"]):
        mesh["file"] = os.path.join(base, mesh["file"])
with open(out, "w") as f:
    json.dump(scene, f, indent=1)
PY
}

for name in effects_lighting effects_fog effects_dof effects_antialias effects_exposure; do
  "$exbsp" render "$here/$name.json" -o "$out/$name.png"
  without "$here/$name.json" effects "$tmp/$name.json"
  "$exbsp" render "$tmp/$name.json" -o "$out/${name}_without.png"
  echo "wrote images/$name.png and images/${name}_without.png"
done
"$exbsp" render "$here/effects_highlights.json" -o "$out/effects_highlights.png"
echo "wrote images/effects_highlights.png"
"$exbsp" render "$here/effects_smooth.json" -o "$out/effects_smooth.png"
python3 - "$here/effects_smooth.json" "$tmp/effects_smooth_flat.json" <<'PY'
import json, os, sys
with open(sys.argv[1]) as f:
    scene = json.load(f)
scene["effects"]["lighting"]["smooth"] = False
base = os.path.dirname(os.path.abspath(sys.argv[1]))
for mesh in scene["meshes"]:
    mesh["file"] = os.path.join(base, mesh["file"])
with open(sys.argv[2], "w") as f:
    json.dump(scene, f, indent=1)
PY
"$exbsp" render "$tmp/effects_smooth_flat.json" -o "$out/effects_smooth_flat.png"
echo "wrote images/effects_smooth.png and images/effects_smooth_flat.png"
"$exbsp" render "$here/curves.json" -o "$out/curves.png"
without "$here/curves.json" curves "$tmp/curves.json"
"$exbsp" render "$tmp/curves.json" -o "$out/curves_without.png"
echo "wrote images/curves.png and images/curves_without.png"
