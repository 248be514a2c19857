#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Writes the teaching-view scenes (scene key "teaching", README.md "Teaching views"): an
observed camera's view volume and reference frame drawn into the scene, the depth-sort painter
on three planks in cyclic overlap, and dropping polygons at the near plane instead of cutting
them, and the scene drawn in each space of a PHIGS camera's normalisation (world, VRC, sheared
VRC, the 45 degree opening, the normalised cube). They reuse the parts make_scenes.py writes
under scenes/meshes/.
Run: python3 scenes/make_teaching_scenes.py"""
import math

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
    # The PHIGS normalisation step by step (the notes' "Varias Vistas" pictures): one observed
    # PHIGS camera, its PRP off the window's centre so that the shear shows; the same parts
    # drawn in each space by a camera that frames that space's view volume.
    for space in SPACES:
        write("teaching_space_" + space, space_scene(space))


# The observed PHIGS camera of the normalisation scenes.
OBSERVED = {"vrp": [0.3, -2.5, 1.0], "vpn": [-0.3, -1, 0.45], "vup": [0, 0, 1], "prp": [1.2, 0.6, 7],
            "window": [-3.2, 3.2, -1.4, 2.0], "front": 0.5, "back": -5, "projection": "perspective"}
SPACES = ["world", "vrc", "sheared", "opening_45", "normalised"]


def _unit(a):
    n = math.sqrt(sum(x * x for x in a))
    return [x / n for x in a]


def _cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def volume_corners(space):
    """The observed view volume's eight corners in `space`, for framing only (the matrices
    themselves are exbsp's: `exbsp matrices` prints them)."""
    o = OBSERVED
    n = _unit(o["vpn"])
    u = _unit(_cross(o["vup"], n))
    v = _cross(n, u)
    pu, pv, pn = o["prp"]
    umin, umax, vmin, vmax = o["window"]
    cu, cv = (umin + umax) / 2, (vmin + vmax) / 2
    out = []
    for plane in (o["front"], o["back"]):
        t = (pn - plane) / pn
        for a in (umin, umax):
            for b in (vmin, vmax):
                p = [pu + t * (a - pu), pv + t * (b - pv), plane]  # VRC
                if space == "world":
                    out.append([o["vrp"][i] + p[0] * u[i] + p[1] * v[i] + p[2] * n[i] for i in range(3)])
                    continue
                if space == "vrc":
                    out.append(p)
                    continue
                x, y, z = p[0] - pu, p[1] - pv, p[2] - pn  # T(-PRP)
                x, y = x + (cu - pu) / pn * z, y + (cv - pv) / pn * z  # SHper
                if space == "sheared":
                    out.append([x, y, z])
                    continue
                x, y = x * 2 * pn / (umax - umin), y * 2 * pn / (vmax - vmin)  # Sper
                if space == "opening_45":
                    out.append([x, y, z])
                    continue
                out.append([1 if a == umax else -1, 1 if b == vmax else -1, 1 if plane == o["front"] else -1])
    return out


def space_scene(space):
    """The demo parts drawn in `space`, seen from the front right, above, framing the volume."""
    corners = volume_corners(space)
    centre = [sum(c[i] for c in corners) / 8 for i in range(3)]
    radius = max(math.sqrt(sum((c[i] - centre[i]) ** 2 for i in range(3))) for c in corners)
    fovy = 40
    distance = 1.08 * radius / math.sin(math.radians(fovy / 2))
    if space == "world":
        direction, up = _unit([0.9, -1.6, 1.1]), [0, 0, 1]
    else:  # VRC-like spaces: v up, the viewer on +n's side, to the right
        direction, up = _unit([1.5, 0.8, 1.1]), [0, 1, 0]
    eye = [round(centre[i] + distance * direction[i], 4) for i in range(3)]
    look_at = [round(c, 4) for c in centre]
    axis_length = 1.5 if space in ("world", "vrc") else (0.5 if space == "normalised" else 1.5)
    return view({"eye": eye, "look_at": look_at, "up": up},
                {"type": "perspective", "fovy_deg": fovy, "near": round(distance / 20, 4),
                 "far": round(distance * 4, 4)},
                teaching={"view_volume": {"camera": {"phigs": OBSERVED}, "space": space,
                                          "color": [40, 40, 40], "axis_length": axis_length}})


if __name__ == "__main__":
    main()
