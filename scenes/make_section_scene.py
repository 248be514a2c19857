#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Writes scenes/section.json and its closed meshes under scenes/meshes/section/.

A flange (a 4 x 4 x 2 block with a round through-hole, genus 1), a shaft through the hole and a
pin through the flange are cut by two planes with caps: a tilted plane (the flange's cap is a
plate with a hole, the shaft's a disc inside it) and a vertical one that cuts the flange's
corner off (its cap cuts the first cap). The pin lies on the kept side, uncut, and
intersects the cut flange (one BSP for all). Every mesh is closed and outward oriented.
Run: python3 scenes/make_section_scene.py
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
N = 24  # sides of the round hole and of the shaft; 360/24 = 15 degrees, so 45 degrees is a vertex


def write_off(path, verts, faces):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(verts), len(faces)))
        for v in verts:
            f.write("%.17g %.17g %.17g\n" % v)
        for face in faces:
            f.write("%d %s\n" % (len(face), " ".join(str(i) for i in face)))


def flange(half=2.0, z0=-1.0, z1=1.0, r=1.0):
    """Block [-half, half]^2 x [z0, z1] with a hole of radius r along z."""
    verts, faces = [], []
    ring = []  # (circle point, square point) at the same angle
    for i in range(N):
        a = 2 * math.pi * i / N
        c, s = math.cos(a), math.sin(a)
        k = half / max(abs(c), abs(s))
        ring.append(((r * c, r * s), (k * c, k * s)))
    def idx(i, which, top):
        return 4 * (i % N) + 2 * which + top
    for (cp, sp) in ring:
        for p in (cp, sp):
            verts.append((p[0], p[1], z0))
            verts.append((p[0], p[1], z1))
    for i in range(N):
        j = i + 1
        # top (z1, facing +z): circle_i, square_i, square_j, circle_j is counter-clockwise
        faces.append([idx(i, 0, 1), idx(i, 1, 1), idx(j, 1, 1), idx(j, 0, 1)])
        faces.append([idx(j, 0, 0), idx(j, 1, 0), idx(i, 1, 0), idx(i, 0, 0)])  # bottom, facing -z
        faces.append([idx(i, 1, 0), idx(j, 1, 0), idx(j, 1, 1), idx(i, 1, 1)])  # outer wall
        faces.append([idx(j, 0, 0), idx(i, 0, 0), idx(i, 0, 1), idx(j, 0, 1)])  # hole wall, facing the axis
    return verts, faces


def cylinder(r, z0, z1, cx=0.0, cy=0.0):
    verts, faces = [], []
    for i in range(N):
        a = 2 * math.pi * (i + 0.5) / N
        verts.append((cx + r * math.cos(a), cy + r * math.sin(a), z0))
        verts.append((cx + r * math.cos(a), cy + r * math.sin(a), z1))
    for i in range(N):
        j = (i + 1) % N
        faces.append([2 * i, 2 * j, 2 * j + 1, 2 * i + 1])
    faces.append([2 * i + 1 for i in range(N)])  # top
    faces.append([2 * i for i in reversed(range(N))])  # bottom
    return verts, faces


def box(lo, hi):
    verts = [(hi[0] if i & 1 else lo[0], hi[1] if i & 2 else lo[1], hi[2] if i & 4 else lo[2]) for i in range(8)]
    faces = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    return verts, faces


def main():
    d = os.path.join(HERE, "meshes", "section")
    os.makedirs(d, exist_ok=True)
    write_off(os.path.join(d, "flange.off"), *flange())
    write_off(os.path.join(d, "shaft.off"), *cylinder(0.7, -2.5, 2.5))
    write_off(os.path.join(d, "pin.off"), *box((1.0, -2.6, -1.6), (1.6, 2.6, -0.4)))
    scene = {
        "meshes": [
            {"file": "meshes/section/flange.off", "color": [150, 165, 185]},
            {"file": "meshes/section/shaft.off", "color": [90, 170, 110]},
            {"file": "meshes/section/pin.off", "color": [235, 180, 60]},
        ],
        # keep z <= 0.3 + 0.15 x + 0.1 y (a tilted cut through the flange, the hole and the
        # shaft: a plate with a round hole and a disc in it) and x + y >= -3.2 (the front-left
        # corner cut away: that cap cuts the first one). The pin is below both: uncut.
        "clip_planes": [[-0.15, -0.1, -1, 0.3], [1, 1, 0, 3.2]],
        "caps": {"color": [215, 60, 50]},
        "camera": {"eye": [-4.5, -6.5, 5.0], "look_at": [0.3, 0.0, -0.3], "up": [0, 0, 1]},
        "projection": {"type": "perspective", "fovy_deg": 36, "near": 1, "far": 40},
        "viewport": {"width": 640, "height": 480},
        "background": [245, 246, 250],
        "effects": {"lighting": {"direction": [-0.4, -0.7, 1.0], "intensity": 0.75, "ambient": 0.3}},
    }
    with open(os.path.join(HERE, "section.json"), "w") as f:
        json.dump(scene, f, indent=2)
        f.write("\n")


if __name__ == "__main__":
    main()
