#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Writes the example scenes (scenes/*.json) and their small OFF meshes (scenes/meshes/).

Meshes are drawn flat and unlit in their mesh colour (docs/contract.md "Scenes"), so to keep the
solids readable every part is stored as up to six OFF files, one per direction its faces
face (the dominant axis of the local normal: px, nx, py, ny, pz, nz), and the scenes give
each file a shade of the part's colour ("baked" direction shading). All the files of a scene
still go into one BSP. Shapes mirror src/scene/procedural.cpp. Coordinates are printed with
Python's repr (the shortest text that reads back as the same double), so the files hold
exactly the doubles computed here.  Run: python3 scenes/make_scenes.py
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
MESHES = os.path.join(HERE, "meshes")
SHADE = {"pz": 1.0, "ny": 0.86, "px": 0.74, "nx": 0.64, "py": 0.56, "nz": 0.5}
BUCKETS = ["pz", "ny", "px", "nx", "py", "nz"]


def num(c):
    return str(int(c)) if float(c).is_integer() else repr(float(c))


def write_off(path, vertices, faces, comment):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    used = sorted({i for f in faces for i in f})
    remap = {old: new for new, old in enumerate(used)}
    with open(path, "w") as f:
        f.write("OFF\n# %s\n" % comment)
        f.write("%d %d 0\n" % (len(used), len(faces)))
        for i in used:
            f.write(" ".join(num(c) for c in vertices[i]) + "\n")
        for face in faces:
            f.write("%d %s\n" % (len(face), " ".join(str(remap[i]) for i in face)))


def normal(v, face):
    a, b, c = v[face[0]], v[face[1]], v[face[2]]
    u = [b[k] - a[k] for k in range(3)]
    w = [c[k] - a[k] for k in range(3)]
    return [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]


def bucket(n):
    k = max(range(3), key=lambda i: abs(n[i]))
    return ("p" if n[k] > 0 else "n") + "xyz"[k]


def write_part(name, vertices, faces, comment):
    """Writes meshes/NAME/<bucket>.off; returns the buckets written, in SHADE order."""
    groups = {}
    for face in faces:
        groups.setdefault(bucket(normal(vertices, face)), []).append(face)
    for b, fs in groups.items():
        write_off(os.path.join(MESHES, name, b + ".off"), vertices, fs, "%s, faces facing %s" % (comment, b))
    return [b for b in BUCKETS if b in groups]


# ---- shapes (as src/scene/procedural.cpp) ----

def box(lo, hi):
    v = [[hi[0] if k & 1 else lo[0], hi[1] if k & 2 else lo[1], hi[2] if k & 4 else lo[2]] for k in range(8)]
    f = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    return v, f


def prism(outline, z0, z1):
    n = len(outline)
    v = [[x, y, z0] for x, y in outline] + [[x, y, z1] for x, y in outline]
    f = [[n - 1 - k for k in range(n)], [n + k for k in range(n)]]
    f += [[k, (k + 1) % n, n + (k + 1) % n, n + k] for k in range(n)]
    return v, f


def gear(teeth, root, tip, bore, thickness):
    fr, rr = [0.0, 0.2, 0.45, 0.65], [root, tip, tip, root]
    period = 2 * math.pi / teeth
    ang, rad = [], []
    for t in range(teeth):
        for k in range(4):
            ang.append((t + fr[k]) * period)
            rad.append(rr[k])
    m = len(ang)
    v = []
    for z in (-thickness / 2, thickness / 2):
        v += [[rad[i] * math.cos(ang[i]), rad[i] * math.sin(ang[i]), z] for i in range(m)]
    for z in (-thickness / 2, thickness / 2):
        v += [[bore * math.cos(ang[i]), bore * math.sin(ang[i]), z] for i in range(m)]
    ob, ot = (lambda i: i % m), (lambda i: m + i % m)
    bb, bt = (lambda i: 2 * m + i % m), (lambda i: 3 * m + i % m)
    f = []
    for i in range(m):
        f.append([bt(i), ot(i), ot(i + 1), bt(i + 1)])
        f.append([bb(i), bb(i + 1), ob(i + 1), ob(i)])
        f.append([ob(i), ob(i + 1), ot(i + 1), ot(i)])
        f.append([bb(i + 1), bb(i), bt(i), bt(i + 1)])
    return v, f


def plank(i, offset, half_length, width, slope):
    a = i * 2 * math.pi / 3
    ux, uy = math.cos(a), math.sin(a)
    nx, ny = -uy, ux
    cx, cy = -offset * nx, -offset * ny
    v = []
    for t, w in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
        tt, ww = t * half_length, w * width / 2
        v.append([cx + tt * ux + ww * nx, cy + tt * uy + ww * ny, slope * tt])
    return v, [[0, 1, 2, 3]]


def merge(*parts):
    v, f = [], []
    for pv, pf in parts:
        base = len(v)
        v += pv
        f += [[base + i for i in face] for face in pf]
    return v, f


def inward(part):
    v, f = part
    return v, [list(reversed(face)) for face in f]


# ---- transforms (row-major 4x4, column vectors) ----

def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def translate(x, y, z):
    return [[1, 0, 0, x], [0, 1, 0, y], [0, 0, 1, z], [0, 0, 0, 1]]


def rotate(deg, axis):
    x, y, z = axis
    n = math.sqrt(x * x + y * y + z * z)
    x, y, z = x / n, y / n, z / n
    a = math.radians(deg)
    c, s, k = math.cos(a), math.sin(a), 1 - math.cos(a)
    return [[x * x * k + c, x * y * k - z * s, x * z * k + y * s, 0],
            [y * x * k + z * s, y * y * k + c, y * z * k - x * s, 0],
            [z * x * k - y * s, z * y * k + x * s, z * z * k + c, 0],
            [0, 0, 0, 1]]


def compose(*ms):
    r = ms[0]
    for m in ms[1:]:
        r = matmul(r, m)
    return r


def flat(m):
    return [m[i][j] for i in range(4) for j in range(4)]


def is_identity(m):
    return flat(m) == flat(translate(0, 0, 0))


PARTS = {}


def part_meshes(name, color, transform=None):
    """Scene "meshes" entries for every bucket file of part NAME, shaded from COLOR."""
    out = []
    for b in PARTS[name]:
        entry = {"file": "meshes/%s/%s.off" % (name, b),
                 "color": [int(round(c * SHADE[b])) for c in color]}
        if transform is not None and not is_identity(transform):
            entry["transform"] = flat(transform)
        out.append(entry)
    return out


def to_json(value, indent=0):
    """JSON with objects one key per line and arrays of numbers on one line."""
    pad = "  " * indent
    if isinstance(value, dict):
        if not value:
            return "{}"
        items = ['%s  "%s": %s' % (pad, k, to_json(v, indent + 1)) for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + pad + "}"
    if isinstance(value, list) and any(isinstance(v, (dict, list)) for v in value):
        return "[\n" + ",\n".join(pad + "  " + to_json(v, indent + 1) for v in value) + "\n" + pad + "]"
    return json.dumps(value)


def write_scene(name, scene):
    with open(os.path.join(HERE, name + ".json"), "w") as f:
        f.write(to_json(scene) + "\n")


def main():
    PARTS["cube"] = write_part("cube", *box([-1, -1, -1], [1, 1, 1]), "cube [-1,1]^3, outward")
    PARTS["slab"] = write_part("slab", *box([-2.1, -0.3, -0.5], [2.1, 0.3, 0.5]), "slab 4.2 x 0.6 x 1, outward")
    PARTS["gear"] = write_part("gear", *gear(12, 1.25, 1.6, 0.5, 0.4),
                               "gear: 12 teeth, root 1.25, tip 1.6, bore 0.5, thickness 0.4")
    hexagon = [[0.36 * math.cos(k * math.pi / 3), 0.36 * math.sin(k * math.pi / 3)] for k in range(6)]
    PARTS["shaft"] = write_part("shaft", *prism(hexagon, -1.1, 1.2), "hexagonal shaft r 0.36, z in [-1.1, 1.2]")
    for i in range(3):
        PARTS["plank%d" % i] = write_part("plank%d" % i, *plank(i, 0.75, 2.1, 0.6, 0.25),
                                          "plank %d of three in cyclic overlap seen from +z" % i)
    PARTS["room"] = write_part("room", *inward(box([-4, -6, 0], [4, 6, 3])), "room 8 x 12 x 3, walls facing inward")
    PARTS["furniture"] = write_part(
        "furniture", *merge(box([-2.5, 1.5, 0], [-1.7, 2.3, 3]), box([1.7, -0.5, 0], [2.5, 0.3, 3]),
                            box([-1.0, -2.5, 0.8], [1.0, -1.5, 1.0]), box([-0.9, -2.4, 0], [-0.8, -2.3, 0.8]),
                            box([0.8, -2.4, 0], [0.9, -2.3, 0.8])),
        "two pillars and a table, outward")

    red, blue, grey, green = [220, 70, 60], [70, 130, 220], [170, 180, 195], [60, 170, 100]
    plank_colors = [[240, 190, 60], [235, 125, 45], [150, 95, 200]]
    cube_t = compose(translate(-4.6, 0.6, 1.0), rotate(25, [0, 0, 1]))
    slab_t = compose(translate(-4.6, 0.6, 1.1), rotate(-40, [0, 0, 1]), rotate(20, [1, 0, 0]), rotate(15, [0, 1, 0]))
    gear_t = translate(4.6, 0.4, 0.9)
    planks_t = translate(0.0, 0.2, 0.8)

    def planks(t):
        return sum((part_meshes("plank%d" % i, plank_colors[i], t) for i in range(3)), [])

    everything = (part_meshes("cube", red, cube_t) + part_meshes("slab", blue, slab_t) + planks(planks_t) +
                  part_meshes("gear", grey, compose(gear_t, rotate(7, [0, 0, 1]))) +
                  part_meshes("shaft", green, gear_t))
    background = [242, 244, 248]

    write_scene("perspective", {
        "meshes": everything,
        "camera": {"eye": [0.0, -8.5, 11.0], "look_at": [0.0, 0.6, 0.5], "up": [0, 0, 1]},
        "projection": {"type": "perspective", "fovy_deg": 42, "near": 1, "far": 100},
        "viewport": {"width": 800, "height": 600},
        "background": background,
        "effects": {}})

    write_scene("orthographic", {
        "meshes": part_meshes("gear", grey) + part_meshes("shaft", green) +
                  part_meshes("cube", red, compose(translate(3.2, 2.2, 0.2), rotate(25, [0, 0, 1]))) +
                  part_meshes("slab", blue, compose(translate(3.2, 2.2, 0.3), rotate(-40, [0, 0, 1]),
                                                    rotate(20, [1, 0, 0]), rotate(15, [0, 1, 0]))),
        "camera": {"eye": [8.0, -10.0, 9.0], "look_at": [1.2, 0.8, 0.2], "up": [0, 0, 1]},
        "projection": {"type": "orthographic", "left": -5.2, "right": 5.2, "bottom": -3.9, "top": 3.9,
                       "near": 1, "far": 40},
        "viewport": {"width": 800, "height": 600},
        "background": background})

    # Cabinet projection: a front view (gaze +y) whose direction of projection also points left
    # and down, so receding edges run up and to the right at half their length.
    write_scene("oblique", {
        "meshes": part_meshes("cube", red, translate(-1.6, 0.0, 0.0)) +
                  part_meshes("slab", blue, compose(translate(-1.6, 0.0, 0.1), rotate(-40, [0, 0, 1]),
                                                    rotate(20, [1, 0, 0]), rotate(15, [0, 1, 0]))) +
                  part_meshes("gear", grey, compose(translate(2.6, 0.0, 0.0), rotate(90, [1, 0, 0]))) +
                  part_meshes("shaft", green, compose(translate(2.6, 0.0, 0.0), rotate(90, [1, 0, 0]))),
        "camera": {"eye": [0.0, -10.0, 0.0], "look_at": [0.0, 0.0, 0.0], "up": [0, 0, 1]},
        "projection": {"type": "oblique", "left": -5.0, "right": 5.0, "bottom": -3.0, "top": 3.0,
                       "near": 1, "far": 30, "direction": [-0.35355339059327373, 1.0, -0.35355339059327373]},
        "viewport": {"width": 800, "height": 480},
        "background": background})

    # Off-axis frustum (glFrustum with an asymmetric window): the parts sit to the right.
    write_scene("frustum", {
        "meshes": planks(translate(0.0, 0.0, 0.0)) + part_meshes("cube", red, translate(2.9, 1.0, 0.0)) +
                  part_meshes("slab", blue, compose(translate(2.9, 1.0, 0.1), rotate(-40, [0, 0, 1]),
                                                    rotate(20, [1, 0, 0]), rotate(15, [0, 1, 0]))),
        "camera": {"eye": [-3.0, -9.0, 7.0], "look_at": [-3.0, 0.0, 0.0], "up": [0, 0, 1]},
        "projection": {"type": "frustum", "left": -0.1, "right": 0.7, "bottom": -0.3, "top": 0.3,
                       "near": 1, "far": 50},
        "viewport": {"width": 800, "height": 600},
        "background": background})

    # Camera inside a closed room: the near plane cuts the walls beside and behind the eye.
    write_scene("inside", {
        "meshes": part_meshes("room", [225, 215, 195]) + part_meshes("furniture", [120, 150, 200]) +
                  part_meshes("gear", grey, compose(translate(0.0, -2.0, 1.2), rotate(15, [0, 0, 1]))),
        "camera": {"eye": [1.5, -5.0, 1.7], "look_at": [-0.5, 1.0, 1.0], "up": [0, 0, 1]},
        "projection": {"type": "perspective", "fovy_deg": 75, "near": 0.5, "far": 50},
        "viewport": {"width": 800, "height": 600},
        "background": [0, 0, 0],
        "effects": {"backface_culling": True}})

    # Three planks in cyclic overlap, seen from above: no depth sort orders them.
    write_scene("cyclic", {
        "meshes": planks(None),
        "camera": {"eye": [0.3, -2.0, 8.0], "look_at": [0.0, 0.0, 0.0], "up": [0, 1, 0]},
        "projection": {"type": "perspective", "fovy_deg": 45, "near": 1, "far": 30},
        "viewport": {"width": 600, "height": 600},
        "background": background})


if __name__ == "__main__":
    main()
