#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Writes the texture scene (scenes/textured.json), its meshes with texture coordinates
(scenes/meshes/textured/floor.obj, crate.obj and panel.ply) and its textures
(scenes/meshes/textured/checker.png, crate.png), with the standard library only.

The floor is a large quad whose checkerboard repeats three times (nearest, repeat: the squares
shrink towards the horizon, perspective-correct); the crate is a cube tilted into the floor
(the BSP splits floor and crate where they meet; each piece keeps the exact texture
coordinates), bilinear, its texture turned a quarter turn about the texture's centre by a texture
matrix ("transforms", GL_TEXTURE); the panel (PLY with u, v properties) stands upright, clamped. The
scene is lit (one directional light): each texel is multiplied by the lit colour of a white
face (GL_MODULATE).
Run: python3 scenes/make_texture_scene.py
"""
import json
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "meshes", "textured")


def write_png(path, width, height, pixel):
    """An 8-bit RGB PNG; pixel(i, j) is column i, row j from the TOP."""
    raw = b"".join(
        b"\x00" + b"".join(bytes(pixel(i, j)) for i in range(width)) for j in range(height))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    png = (b"\x89PNG\r\n\x1a\n" +
           chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
           chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
    with open(path, "wb") as f:
        f.write(png)


def checker(i, j):
    return (235, 232, 220) if (i + j) % 2 == 0 else (60, 90, 140)


def crate(i, j):
    # 16 x 16: a plank frame with a diagonal brace, so that orientation and bilinear blending show.
    edge = i < 2 or j < 2 or i > 13 or j > 13
    brace = abs(i - j) <= 1
    if edge or brace:
        return (120, 70, 30)
    return (200 - 4 * j, 150 - 3 * j, 80)


def main():
    os.makedirs(OUT, exist_ok=True)
    write_png(os.path.join(OUT, "checker.png"), 8, 8, checker)
    write_png(os.path.join(OUT, "crate.png"), 16, 16, crate)
    with open(os.path.join(OUT, "floor.obj"), "w") as f:
        f.write("# A 1 x 1 quad facing +z; the scene scales it. The checker repeats 3 times.\n"
                "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                "vt 0 0\nvt 3 0\nvt 3 3\nvt 0 3\n"
                "f 1/1 2/2 3/3 4/4\n")
    corners = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
    # Each face of the unit cube with its own corners' texture coordinates (outward winding).
    faces = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    with open(os.path.join(OUT, "crate.obj"), "w") as f:
        f.write("# A unit cube, the whole crate texture on every face.\n")
        for c in corners:
            f.write("v %d %d %d\n" % c)
        f.write("vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n")
        for face in faces:
            f.write("f " + " ".join("%d/%d" % (v + 1, t + 1) for t, v in enumerate(face)) + "\n")
    with open(os.path.join(OUT, "panel.ply"), "w") as f:
        f.write("ply\nformat ascii 1.0\ncomment an upright panel; u, v beyond [0, 1]: clamped\n"
                "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                "property float u\nproperty float v\nelement face 1\n"
                "property list uchar int vertex_indices\nend_header\n"
                "0 0 0 -0.25 -0.25\n1 0 0 1.25 -0.25\n1 0 1 1.25 1.25\n0 0 1 -0.25 1.25\n"
                "4 0 1 2 3\n")
    c, s = 0.8660254037844387, 0.5  # 30 degrees about z, then 20 about x
    cx, sx = 0.9396926207859084, 0.3420201433256687
    rot = [[c, -s, 0], [s * cx, c * cx, -sx], [s * sx, c * sx, cx]]
    crate_m = [rot[0] + [-0.2], rot[1] + [0.6], rot[2] + [-0.3], [0, 0, 0, 1]]
    crate_m = [[1.6 * v for v in row[:3]] + [row[3]] for row in crate_m[:3]] + [[0, 0, 0, 1]]
    scene = {
        "meshes": [
            {"file": "meshes/textured/floor.obj",
             "transform": [8, 0, 0, -4, 0, 8, 0, -2, 0, 0, 1, 0, 0, 0, 0, 1],
             "texture": {"png": "meshes/textured/checker.png", "filter": "nearest",
                         "wrap": "repeat"}},
            {"file": "meshes/textured/crate.obj",
             "transform": [v for row in crate_m for v in row],
             "texture": {"png": "meshes/textured/crate.png", "filter": "linear",
                         "wrap": "repeat",
                         "transforms": [{"translate": [0.5, 0.5, 0]}, {"rotate": [90, 0, 0, 1]},
                                        {"translate": [-0.5, -0.5, 0]}]}},
            {"file": "meshes/textured/panel.ply",
             "transform": [2.2, 0, 0, -3.2, 0, 1, 0, 1.5, 0, 0, 2.2, 0, 0, 0, 0, 1],
             "texture": {"png": "meshes/textured/crate.png", "filter": "linear",
                         "wrap": "clamp"}},
        ],
        "camera": {"eye": [1.8, -5.5, 3.2], "look_at": [0, 1.2, 0.4], "up": [0, 0, 1]},
        "projection": {"type": "perspective", "fovy_deg": 50, "near": 0.5, "far": 60},
        "viewport": {"width": 400, "height": 300},
        "background": [242, 244, 248],
        "effects": {"lighting": {"direction": [-0.4, -0.6, 0.8], "intensity": 0.65,
                                 "ambient": 0.4}},
    }
    with open(os.path.join(HERE, "textured.json"), "w") as f:
        json.dump(scene, f, indent=2)
        f.write("\n")


if __name__ == "__main__":
    main()
