#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-3.0-or-later
# Renders the pictures of README.md "## Teaching views" into scenes/images/: each teaching scene
# with its "teaching" key (NAME.png) and, for the depth sort and the near-plane drop, the same
# scene without it (NAME_without.png: the BSP's picture, the near plane cutting). Anyone can
# rerun it:
#   scenes/make_teaching_images.sh [path/to/exbsp]   (default: $EXBSP, then build/src/app/exbsp)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
images_setup make_teaching_images "$@"

# without SCENE OUT: SCENE minus its "teaching" key, mesh paths absolute.
without() {
  python3 - "$1" "$2" <<'PY'
import json, os, sys
scene_path, out = sys.argv[1:3]
with open(scene_path) as f:
    scene = json.load(f)
scene.pop("teaching", None)
base = os.path.dirname(os.path.abspath(scene_path))
def absolute(entry):
    for mesh in entry.get("meshes", []):
        if not os.path.isabs(mesh["file"]):
            mesh["file"] = os.path.join(base, mesh["file"])
    for group in entry.get("groups", []):
        absolute(group)
absolute(scene)
with open(out, "w") as f:
    json.dump(scene, f, indent=1)
PY
}

"$exbsp" render "$here/teaching_view_volume.json" -o "$out/teaching_view_volume.png"
echo "wrote images/teaching_view_volume.png"
for space in world vrc sheared opening_45 normalised; do
  "$exbsp" render "$here/teaching_space_$space.json" -o "$out/teaching_space_$space.png"
  echo "wrote images/teaching_space_$space.png"
done
for name in teaching_cyclic teaching_near; do
  "$exbsp" render "$here/$name.json" -o "$out/$name.png"
  without "$here/$name.json" "$tmp/$name.json"
  "$exbsp" render "$tmp/$name.json" -o "$out/${name}_without.png"
  echo "wrote images/$name.png and images/${name}_without.png"
done
