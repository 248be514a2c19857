#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Writes the modelling and viewing example scenes (groups, transforms, camera forms, viewport,
ortho2d, lines, trackball) and the `exbsp clip` inputs under scenes/clip/. They reuse the parts
that make_scenes.py writes under scenes/meshes/. Run: python3 scenes/make_viewing_scenes.py"""
import os

from make_scenes import HERE, SHADE, to_json

BUCKETS = {"cube": ["pz", "ny", "px", "nx", "py", "nz"], "gear": ["pz", "ny", "px", "nx", "py", "nz"],
           "shaft": ["pz", "ny", "px", "nx", "py", "nz"], "slab": ["pz", "ny", "px", "nx", "py", "nz"]}
RED, BLUE, GREEN, GREY, GOLD = [220, 70, 60], [70, 130, 220], [60, 170, 100], [170, 180, 195], [240, 190, 60]
BACKGROUND = [242, 244, 248]


def part(name, color, transforms=None):
    out = []
    for b in BUCKETS[name]:
        entry = {"file": "meshes/%s/%s.off" % (name, b), "color": [int(round(c * SHADE[b])) for c in color]}
        if transforms:
            entry["transforms"] = transforms
        out.append(entry)
    return out


def write(name, scene):
    with open(os.path.join(HERE, name + ".json"), "w") as f:
        f.write(to_json(scene) + "\n")


def demo_parts():
    """The pierced cube, the gear on its shaft and a slab, as groups with transforms lists."""
    return [
        {"transforms": [{"translate": [-3, 0, 1]}, {"rotate": [25, 0, 0, 1]}],
         "meshes": part("cube", RED),
         "groups": [{"transforms": [{"rotate": [-35, 1, 0, 0]}], "meshes": part("slab", BLUE)}]},
        {"transforms": [{"translate": [3, 0.4, 0.9]}],
         "meshes": part("shaft", GREEN),
         "groups": [{"transforms": [{"rotate": [7, 0, 0, 1]}], "meshes": part("gear", GREY)}]},
    ]


def view(camera, projection=None, width=400, height=300, **extra):
    scene = {"groups": demo_parts(), "camera": camera}
    if projection:
        scene["projection"] = projection
    scene["viewport"] = {"width": width, "height": height}
    scene["background"] = BACKGROUND
    scene.update(extra)
    return scene


PERSPECTIVE = {"type": "perspective", "fovy_deg": 42, "near": 1, "far": 100}


def main():
    # A robot arm: each joint is a group; the column-major matrix (as pasted from OpenGL) is a
    # translation by (0, 0, 2.2) and must not be transposed. One mesh lies far outside the view
    # (rejected by its bounding box before the BSP build; render --verbose says so).
    forearm = {"transforms": [{"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 2.2, 1], "order": "column-major"},
                              {"rotate": [50, 0, 1, 0]}],
               "meshes": part("cube", GOLD, [{"translate": [0, 0, 1.1]}, {"scale": [0.3, 0.3, 1.1]}]),
               "groups": [{"transforms": [{"translate": [0, 0, 2.4]}],
                           "meshes": part("gear", GREY, [{"rotate": [90, 1, 0, 0]}, {"scale": [0.5, 0.5, 0.5]}])}]}
    upper = {"transforms": [{"translate": [0, 0, 0.6]}, {"rotate": [-30, 0, 1, 0]}],
             "meshes": part("cube", BLUE, [{"translate": [0, 0, 1.1]}, {"scale": [0.35, 0.35, 1.1]}]),
             "groups": [forearm]}
    arm = {"transforms": [{"rotate": [30, 0, 0, 1]}],
           "meshes": part("cube", RED, [{"scale": [1.2, 1.2, 0.3]}]),
           "groups": [upper]}
    write("groups", {"meshes": part("cube", GREEN, [{"translate": [0, 0, -60]}]),  # behind the floor: rejected
                     "groups": [arm],
                     "camera": {"eye": [8, -9.5, 6], "look_at": [0.3, 0, 2.4], "up": [0, 0, 1]},
                     "projection": PERSPECTIVE, "viewport": {"width": 400, "height": 300},
                     "background": BACKGROUND})

    write("camera_look", view({"position": [0, -9, 6], "look": [0, 9, -5.5], "up": [0, 0, 1]}, PERSPECTIVE))
    write("camera_polar", view({"polar": {"distance": 11, "twist_deg": 0, "elevation_deg": -60, "azimuth_deg": -20,
                                          "look_at": [0, 0, 0.8]}}, PERSPECTIVE))
    write("camera_pilot", view({"pilot": {"position": [-8, -5, 2.5], "roll_deg": 0, "pitch_deg": -80,
                                          "heading_deg": 55}}, PERSPECTIVE))
    # PHIGS: VPN tilted towards the viewer, off-centre PRP (off-axis frustum) ...
    write("phigs_perspective", view({"phigs": {"vrp": [0, 0, 0.8], "vpn": [0.3, -1, 0.8], "vup": [0, 0, 1],
                                               "prp": [4, 2, 14], "window": [-7, 7, -4.25, 6.25],
                                               "front": 5, "back": -30, "projection": "perspective"}}))
    # ... and a parallel view whose PRP is off the window's centre: an oblique (cavalier-like) view.
    write("phigs_oblique", view({"phigs": {"vrp": [0, 0, 0], "vpn": [0, -1, 0], "vup": [0, 0, 1],
                                           "prp": [-4, -3, 8], "window": [-6, 6, -2.5, 6.5],
                                           "front": 10, "back": -10, "projection": "parallel"}}))
    # glLoadMatrix: the projection given as a matrix, here glFrustum(-0.55, 0.35, -0.3, 0.37, 1,
    # 100) times a shear x += 0.2 z (a view through a tilted window): exbsp finds its centre of
    # projection from the matrix and orders the tree from it.
    l, r, b, t, n, f = -0.55, 0.35, -0.3, 0.37, 1.0, 100.0
    frustum = [[2 * n / (r - l), 0, (r + l) / (r - l), 0], [0, 2 * n / (t - b), (t + b) / (t - b), 0],
               [0, 0, -(f + n) / (f - n), -2 * f * n / (f - n)], [0, 0, -1, 0]]
    shear = [[1, 0, 0.2, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]
    raw = [round(sum(frustum[i][k] * shear[k][j] for k in range(4)), 12) for i in range(4) for j in range(4)]
    write("projection_matrix", view({"eye": [2, -10, 6], "look_at": [0, 0, 0.8], "up": [0, 0, 1]},
                                    {"type": "matrix", "matrix": raw}))
    # A 300x150 letterboxed viewport at (80, 40) inside a 400x300 image; glOrtho with a negative near.
    floor = {"file": "meshes/floor/pz.off", "color": [205, 215, 228],
             "transforms": [{"translate": [-9, -7, -0.05]}, {"scale": [18, 14, 1]}]}
    write("viewport", {**view({"eye": [5, -6, 6], "look_at": [0, 0, 0.8], "up": [0, 0, 1]},
                              {"type": "orthographic", "left": -6, "right": 6, "bottom": -4.5, "top": 4.5,
                               "near": -20, "far": 20}),
                       "meshes": [floor],
                       "viewport": {"width": 300, "height": 150, "x": 80, "y": 40},
                       "image": {"width": 400, "height": 300}, "aspect": "fit"})
    # gluOrtho2D: a flat drawing, no camera; lines clipped by both algorithms.
    write("ortho2d", {"meshes": [{"file": "meshes/floor/pz.off", "color": [200, 215, 235],
                                  "transforms": [{"translate": [-6, -4, 0]}, {"scale": [9, 7, 1]}]},
                                 {"file": "meshes/floor/pz.off", "color": [245, 215, 120],
                                  "transforms": [{"translate": [-1, -2, 0.5]}, {"rotate": [20, 0, 0, 1]},
                                                 {"scale": [6, 5, 1]}]}],
                      "lines": [{"points": [[-12, -2, 0.8], [0, 9, 0.8], [12, -2, 0.8], [-12, -2, 0.8]], "color": [200, 40, 40],
                                 "clipper": "cohen-sutherland"},
                                {"points": [[-12, 6, 0.8], [12, -6, 0.8]], "color": [40, 40, 200], "clipper": "liang-barsky"}],
                      "projection": {"type": "ortho2d", "left": -8, "right": 8, "bottom": -6, "top": 6},
                      "viewport": {"width": 400, "height": 300}, "background": [255, 255, 255]})
    # Lines in 3D: a wire piercing the cube and the slab, drawn in BSP order; one runs behind the eye.
    write("lines", view({"eye": [0, -9, 6], "look_at": [0, 0, 0.8], "up": [0, 0, 1]}, PERSPECTIVE,
                        lines=[{"points": [[-7, 0, 1], [7, 0, 1]], "color": [0, 0, 0], "clipper": "cohen-sutherland"},
                               {"points": [[-3, -3, 0], [-3, 3, 2], [3, 3, 2], [3, -3, 0]], "color": [200, 0, 160],
                                "clipper": "liang-barsky"},
                               {"points": [[1, -20, 0.5], [1, 20, 0.5]], "color": [0, 120, 0],
                                "clipper": "cohen-sutherland"}]))
    write("trackball", view({"eye": [0, -9, 6], "look_at": [0, 0, 0.8], "up": [0, 0, 1]}, PERSPECTIVE,
                            trackball="virtual"))

    clip_dir = os.path.join(HERE, "clip")
    os.makedirs(clip_dir, exist_ok=True)
    inputs = {
        "segments_rect": {"region": {"rect": [0, 0, 8, 5]},
                          "segments": [[[-2, 1], [10, 4]], [[1, 1], [4, 3]], [[-3, -2], [-1, 7]], [[2, -2], [9, 8]],
                                       [[6, 6], [10, 2]], [[-1, 3], [3, 7]]]},
        "concave_polygon": {"region": {"rect": [0, 1, 9, 3]},
                            "polygons": [[[0.5, 0], [8.5, 0], [8.5, 4], [7, 4], [7, 0.5], [6, 0.5], [6, 4], [4.5, 4],
                                          [4.5, 0.5], [3.5, 0.5], [3.5, 4], [2, 4], [2, 0.5], [1.5, 0.5], [1.5, 4],
                                          [0.5, 4]]]},
        "convex_region": {"region": {"convex": [[0, 0], [6, -1], [8, 3], [4, 6], [-1, 4]]},
                          "polygons": [[[-2, 1], [5, -3], [10, 2], [3, 8]], [[5, 2], [9, 6], [6, 7]]]},
        "box_3d": {"region": {"box": [0, 0, 0, 1, 1, 1]},
                   "segments": [[[-1, 0.5, 0.5], [2, 0.5, 0.5]], [[0.5, 0.5, 0.5], [0.5, 0.5, 3]],
                                [[2, 2, 2], [3, 3, 3]]],
                   "polygons": [[[-1, -1, 0.5], [2, -1, 0.5], [2, 2, 0.5], [-1, 2, 0.5]]]},
    }
    for name, doc in inputs.items():
        with open(os.path.join(clip_dir, name + ".json"), "w") as f:
            f.write(to_json(doc) + "\n")


if __name__ == "__main__":
    main()
