#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Writes the teaching-view scenes (scene key "teaching", README.md "Teaching views"): an
observed camera's view volume and reference frame drawn into the scene, the depth-sort painter
on three planks in cyclic overlap, and dropping polygons at the near plane instead of cutting
them. They reuse the parts make_scenes.py writes under scenes/meshes/.
Run: python3 scenes/make_teaching_scenes.py"""
from make_viewing_scenes import BACKGROUND, PERSPECTIVE, demo_parts, view, write

PLANKS = [{"file": "meshes/plank%d/pz.off" % k, "color": c}
          for k, c in enumerate([[240, 190, 60], [235, 125, 45], [150, 95, 200]])]


def main():
    # A second camera looks at the gear from the front left; the scene's camera sees it, its
    # view volume (near and far rectangles, side edges, the pyramid's tip at its eye) and its
    # eye-coordinate axes x (u, red), y (v, green), z (n, blue), all depth-ordered by the BSP.
    write("teaching_view_volume",
          view({"eye": [-6.5, -9, 7.5], "look_at": [0.8, -2.5, 1], "up": [0, 0, 1]},
               {"type": "perspective", "fovy_deg": 50, "near": 1, "far": 100},
               teaching={"view_volume": {
                   "camera": {"eye": [-1, -7, 2.5], "look_at": [3, 0.4, 0.9], "up": [0, 0, 1]},
                   "projection": {"type": "perspective", "fovy_deg": 30, "near": 3, "far": 9.5},
                   "color": [40, 40, 40], "axis_length": 1.5}}))
    # Three planks, each over the next: no depth order exists. The depth sort paints them by
    # their farthest corners and gets one overlap wrong; the BSP splits a plank and gets all
    # three right (the picture without "teaching").
    write("teaching_cyclic", {"meshes": PLANKS,
                              "camera": {"eye": [0.3, -2.0, 8.0], "look_at": [0, 0, 0], "up": [0, 1, 0]},
                              "projection": {"type": "perspective", "fovy_deg": 45, "near": 1, "far": 30},
                              "viewport": {"width": 300, "height": 300},
                              "background": BACKGROUND,
                              "teaching": {"painter": "depth_sort"}})
    # The near plane (at 5) passes through the pierced cube and its slab: cut ("clip", the
    # picture without "teaching") it shows their insides; "drop" leaves out every polygon with
    # a corner in front of it instead, the cheap alternative of the course notes.
    write("teaching_near",
          view({"eye": [-4.2, -5.2, 3.4], "look_at": [-1.5, 1, 0.8], "up": [0, 0, 1]},
               {"type": "perspective", "fovy_deg": 55, "near": 5, "far": 100},
               teaching={"near_plane": "drop"}))


if __name__ == "__main__":
    main()
