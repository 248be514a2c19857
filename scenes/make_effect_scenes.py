#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Writes the effect and curve scenes (scenes/effects_*.json, scenes/curves.json) and the one
mesh they add (scenes/meshes/floor/pz.off, a 1 x 1 quad facing +z, scaled by transforms).

They reuse the parts of make_scenes.py. effects_lighting.json gives every bucket file of a part
the SAME colour: the lighting effect shades them (without it the parts are flat silhouettes).
The other scenes keep make_scenes.py's baked direction shades. Every scene is 400 x 300.
Run: python3 scenes/make_effect_scenes.py   (scenes/make_effect_images.sh renders them)
"""
import glob
import math
import os

import make_scenes as ms

HERE = ms.HERE
BACKGROUND = [242, 244, 248]


def buckets(name):
    files = glob.glob(os.path.join(ms.MESHES, name, "*.off"))
    have = {os.path.splitext(os.path.basename(f))[0] for f in files}
    return [b for b in ms.BUCKETS if b in have]


def part(name, color, transform=None, baked=True):
    out = []
    for b in buckets(name):
        shade = ms.SHADE[b] if baked else 1.0
        entry = {"file": "meshes/%s/%s.off" % (name, b), "color": [int(round(c * shade)) for c in color]}
        if transform is not None and not ms.is_identity(transform):
            entry["transform"] = ms.flat(transform)
        out.append(entry)
    return out


def scale(sx, sy, sz):
    return [[sx, 0, 0, 0], [0, sy, 0, 0], [0, 0, sz, 0], [0, 0, 0, 1]]


def floor(color, transform):
    return [{"file": "meshes/floor/pz.off", "color": color, "transform": ms.flat(transform)}]


def helix(centre, radius, z0, rise_per_turn, quarter_turns):
    """Cubic Bézier pieces of a helix (one per quarter turn; circle factor k = 0.5523)."""
    k = 4.0 / 3.0 * math.tan(math.pi / 8)
    cx, cy = centre
    curves = []
    for q in range(quarter_turns):
        a0, a1 = q * math.pi / 2, (q + 1) * math.pi / 2
        z_a, z_b = z0 + rise_per_turn * q / 4, z0 + rise_per_turn * (q + 1) / 4
        p0 = [cx + radius * math.cos(a0), cy + radius * math.sin(a0), z_a]
        p3 = [cx + radius * math.cos(a1), cy + radius * math.sin(a1), z_b]
        t0 = [-math.sin(a0), math.cos(a0)]
        t1 = [-math.sin(a1), math.cos(a1)]
        dz = (z_b - z_a) / 3
        p1 = [p0[0] + k * radius * t0[0], p0[1] + k * radius * t0[1], z_a + dz]
        p2 = [p3[0] - k * radius * t1[0], p3[1] - k * radius * t1[1], z_b - dz]
        curves.append([[round(c, 6) for c in p] for p in (p0, p1, p2, p3)])
    return curves


def uv_sphere(slices, stacks):
    """(vertices, triangles) of a unit UV sphere around z, outward winding, shared vertices."""
    verts = [[0.0, 0.0, 1.0]]
    for j in range(1, stacks):
        th = math.pi * j / stacks
        for i in range(slices):
            ph = 2 * math.pi * i / slices
            verts.append([round(math.sin(th) * math.cos(ph), 9), round(math.sin(th) * math.sin(ph), 9),
                          round(math.cos(th), 9)])
    verts.append([0.0, 0.0, -1.0])
    south = len(verts) - 1

    def at(i, j):
        return 1 + (j - 1) * slices + i % slices
    tris = []
    for i in range(slices):
        tris.append([0, at(i, 1), at(i + 1, 1)])
        for j in range(1, stacks - 1):
            tris.append([at(i, j), at(i, j + 1), at(i + 1, j + 1)])
            tris.append([at(i, j), at(i + 1, j + 1), at(i + 1, j)])
        tris.append([at(i, stacks - 1), south, at(i + 1, stacks - 1)])
    return verts, tris


def main():
    ms.write_off(os.path.join(ms.MESHES, "floor", "pz.off"), [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]],
                 [[0, 1, 2, 3]], "unit floor quad facing +z (scaled by the scene transforms)")
    ms.write_off(os.path.join(ms.MESHES, "sphere", "sphere.off"), *uv_sphere(32, 16),
                 "unit UV sphere, 32 slices x 16 stacks (smooth shading's scene)")
    red, blue, grey, green = [220, 70, 60], [70, 130, 220], [170, 180, 195], [60, 170, 100]
    plank_colors = [[240, 190, 60], [235, 125, 45], [150, 95, 200]]
    cube_t = ms.compose(ms.translate(-4.6, 0.6, 1.0), ms.rotate(25, [0, 0, 1]))
    slab_t = ms.compose(ms.translate(-4.6, 0.6, 1.1), ms.rotate(-40, [0, 0, 1]), ms.rotate(20, [1, 0, 0]),
                        ms.rotate(15, [0, 1, 0]))
    gear_t = ms.translate(4.6, 0.4, 0.9)
    planks_t = ms.translate(0.0, 0.2, 0.8)
    small = {"width": 400, "height": 300}

    def planks(t, baked=True):
        return sum((part("plank%d" % i, plank_colors[i], t, baked) for i in range(3)), [])

    def everything(baked=True):
        return (part("cube", red, cube_t, baked) + part("slab", blue, slab_t, baked) + planks(planks_t, baked) +
                part("gear", grey, ms.compose(gear_t, ms.rotate(7, [0, 0, 1])), baked) +
                part("shaft", green, gear_t, baked))

    def lit_parts(lighting):
        """The demo parts in one colour per part, on a floor, with the given lighting."""
        return {
            "meshes": everything(baked=False) + floor([200, 200, 190], ms.compose(ms.translate(-9, -7, -0.2),
                                                                                  scale(18, 13, 1))),
            "camera": {"eye": [0.0, -8.5, 11.0], "look_at": [0.0, 0.6, 0.5], "up": [0, 0, 1]},
            "projection": {"type": "perspective", "fovy_deg": 48, "near": 1, "far": 100},
            "viewport": small,
            "background": BACKGROUND,
            "effects": {"lighting": lighting}}

    # Lighting: lit from the upper left.
    ms.write_scene("effects_lighting",
                   lit_parts({"direction": [-0.45, -0.55, 0.7], "intensity": 0.75, "ambient": 0.3}))
    # Highlights: a headlight (the light follows the camera) and a point light above the right,
    # with Blinn-Phong highlights.
    ms.write_scene("effects_highlights",
                   lit_parts({"headlight": True, "intensity": 0.5, "ambient": 0.25, "specular": 0.3,
                              "shininess": 24, "lights": [{"position": [5, -2, 6], "intensity": 0.35}]}))

    # Smooth shading: a sphere, the gear and its shaft in one colour each; the sphere and the
    # shaft are curved (normals averaged across their edges), the gear's teeth keep their creases.
    # A key light and a weak fill light from the right, as CAD viewers light parts.
    smooth_parts = ([{"file": "meshes/sphere/sphere.off", "color": [210, 90, 70],
                      "transform": ms.flat(ms.compose(ms.translate(-0.9, 0.4, 1.3), scale(1.4, 1.4, 1.4)))}] +
                    part("gear", grey, ms.compose(gear_t, ms.rotate(7, [0, 0, 1])), False) +
                    part("shaft", green, gear_t, False) +
                    floor([200, 200, 190], ms.compose(ms.translate(-9, -7, -0.2), scale(18, 13, 1))))
    ms.write_scene("effects_smooth", {
        "meshes": smooth_parts,
        "camera": {"eye": [1.6, -8.5, 5.5], "look_at": [1.6, 0.5, 1.0], "up": [0, 0, 1]},
        "projection": {"type": "perspective", "fovy_deg": 50, "near": 1, "far": 100},
        "viewport": small,
        "background": BACKGROUND,
        "effects": {"lighting": {"direction": [-0.45, -0.55, 0.7], "intensity": 0.7, "ambient": 0.25,
                                 "lights": [{"direction": [0.6, -0.3, 0.3], "intensity": 0.3}],
                                 "smooth": True, "crease_deg": 35}}})

    # Fog: an avenue of pillars on a long floor, far plane at 40 while the floor runs to 90:
    # without fog the far plane cuts floor and pillars with a hard edge ("pop" when moving).
    pillars = []
    for k in range(12):
        for side in (-1, 1):
            t = ms.compose(ms.translate(side * 3.0, 4.0 + 7.0 * k, 1.5), scale(0.5, 0.5, 1.5))
            pillars += part("cube", [200, 110, 70] if side < 0 else [90, 120, 200], t)
    ms.write_scene("effects_fog", {
        "meshes": pillars + floor([150, 160, 150], ms.compose(ms.translate(-6, -2, 0), scale(12, 92, 1))),
        "camera": {"eye": [0.0, -4.0, 2.2], "look_at": [0.0, 20.0, 1.5], "up": [0, 0, 1]},
        "projection": {"type": "perspective", "fovy_deg": 50, "near": 0.5, "far": 40},
        "viewport": small,
        "background": [205, 210, 220],
        "effects": {"fog": {"mode": "linear", "start": 6, "end": 38}}})

    # Depth of field: focus on the gear (middle); the cube in front and the planks behind blur.
    desk = {
        "meshes": part("cube", red, ms.compose(ms.translate(-1.3, -2.4, 0.3), ms.rotate(25, [0, 0, 1]),
                                               scale(0.5, 0.5, 0.5))) +
                  part("gear", grey, ms.compose(ms.translate(0.4, 1.0, 0.9), ms.rotate(7, [0, 0, 1]))) +
                  part("shaft", green, ms.translate(0.4, 1.0, 0.9)) +
                  planks(ms.translate(1.0, 7.0, 0.8)) +
                  floor([200, 200, 190], ms.compose(ms.translate(-6, -6, -0.2), scale(12, 20, 1))),
        "camera": {"eye": [-1.5, -9.0, 3.8], "look_at": [0.4, 1.0, 0.9], "up": [0, 0, 1]},
        "projection": {"type": "perspective", "fovy_deg": 40, "near": 1, "far": 60},
        "viewport": small,
        "background": BACKGROUND}
    ms.write_scene("effects_dof", {**desk, "effects": {"depth_of_field": {
        "focal_length": 0.05, "f_number": 0.1, "focus_distance": 10.6, "samples": 48}}})
    # Exposure: the same desk; the camera pans 0.8 right during the frame, the shutter open for
    # 60% of it (motion blur: the near cube smears more than the far planks).
    ms.write_scene("effects_exposure", {**desk, "effects": {"exposure": {
        "shutter": 0.6, "samples": 24,
        "camera_end": {"eye": [-0.7, -9.0, 3.8], "look_at": [1.2, 1.0, 0.9], "up": [0, 0, 1]}}}})

    # Antialias: the gear and the planks, 4 x 4 samples.
    ms.write_scene("effects_antialias", {
        "meshes": part("gear", grey, ms.compose(ms.translate(1.6, 0.4, 0.9), ms.rotate(7, [0, 0, 1]))) +
                  part("shaft", green, ms.translate(1.6, 0.4, 0.9)) + planks(ms.translate(-2.2, 0.2, 0.8)),
        "camera": {"eye": [-0.3, -8.0, 8.0], "look_at": [-0.3, 0.4, 0.6], "up": [0, 0, 1]},
        "projection": {"type": "perspective", "fovy_deg": 38, "near": 1, "far": 60},
        "viewport": small,
        "background": BACKGROUND,
        "effects": {"antialias": {"samples": 4}}})

    # Curves: a helix around the gear and its shaft (in front of and behind them), a curve
    # piercing the slab (with its control polygon), one weaving through the cyclic planks, and a curve drawn on a face.
    curves = [{"bezier": c, "color": [20, 20, 20]} for c in helix((4.6, 0.4), 1.9, -0.1, 1.0, 10)]
    curves.append({"bezier": [[-7.2, -1.2, 2.6], [-5.4, 2.6, 0.0], [-4.0, -2.0, 2.4], [-2.4, 2.4, 0.6]],
                   "color": [200, 20, 120], "control_polygon": {"color": [250, 200, 0]}})
    curves.append({"bezier": [[-2.4, -1.8, 0.3], [-1.0, 3.0, 2.2], [0.6, -3.0, -0.4], [2.4, 2.2, 1.6]],
                   "color": [0, 110, 60]})
    top = 1.0 + 1.0  # the cube's top face z (cube [-1,1]^3 moved up by 1)
    curves.append({"bezier": [[-5.2, 0.2, top], [-4.6, 1.4, top], [-4.0, 0.0, top]], "color": [255, 255, 255]})
    ms.write_scene("curves", {
        "meshes": everything(),
        "curves": curves,
        "camera": {"eye": [0.0, -8.5, 11.0], "look_at": [0.0, 0.6, 0.5], "up": [0, 0, 1]},
        "projection": {"type": "perspective", "fovy_deg": 48, "near": 1, "far": 100},
        "viewport": small,
        "background": BACKGROUND})


if __name__ == "__main__":
    main()
