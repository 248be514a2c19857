#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Assemblies for the benchmarks: rotated and translated copies of CGAL's CAD parts, packed so
that neighbours interpenetrate a little, as a CAD viewer opens them (issue 27).

    /usr/bin/python3 bench/assembly.py --triangles 1000000 [--seed 1] [--density 1.1] -o a.off

Parts (data/meshes, extracted by scripts/setup): fandisk, rotor, pinion, anchor_dense, turbine,
couplingdown, spool, blade, b9_mesh, ALSTOM_TEST4, drawn with a seeded generator until the
triangle count is reached. Each is scaled to a bounding-box diagonal of 1 (times a random factor
in [0.75, 1.25]), turned by a uniformly random rotation (rounded doubles: its flat faces stop
being exactly coplanar, as placement does to real parts) and put at the centre of a cell of a
cubic grid whose spacing is 1 / density (so density > 1 packs parts into each other), with a
jitter of a tenth of a cell. The same seed and arguments give the same file on every machine
(numpy's PCG64, doubles printed with 17 significant digits).
"""
import argparse
import os
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(here)
PARTS = ("fandisk", "rotor", "pinion", "anchor_dense", "turbine", "couplingdown", "spool", "blade",
         "b9_mesh", "ALSTOM_TEST4")


def read_off(path):
    """(vertices (n, 3) float64, triangles (m, 3) int64) of an OFF file, polygons fanned."""
    with open(path) as f:
        lines = [ln.split("#", 1)[0].strip() for ln in f]
    lines = [ln for ln in lines if ln]
    head = lines[0]
    rest = lines[1:]
    if head != "OFF":  # "OFF n m k" on one line
        counts = head[3:].split()
    else:
        counts, rest = rest[0].split(), rest[1:]
    nv, nf = int(counts[0]), int(counts[1])
    v = np.array([[float(x) for x in ln.split()[:3]] for ln in rest[:nv]], dtype=np.float64)
    tris = []
    for ln in rest[nv:nv + nf]:
        w = [int(x) for x in ln.split()]
        k, idx = w[0], w[1:1 + w[0]]
        tris.extend((idx[0], idx[i], idx[i + 1]) for i in range(1, k - 1))
    return v, np.array(tris, dtype=np.int64)


def random_rotation(rng):
    q = rng.normal(size=4)
    q /= np.linalg.norm(q)
    a, b, c, d = q
    return np.array([[a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)],
                     [2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)],
                     [2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d]])


def make_assembly(triangles, seed=1, density=1.1, parts=PARTS, mesh_dir=None):
    """(vertices, triangles, part names) of an assembly of at least `triangles` triangles."""
    mesh_dir = mesh_dir or os.path.join(root, "data", "meshes")
    library = {}
    for name in parts:
        path = os.path.join(mesh_dir, name + ".off")
        if not os.path.exists(path):
            sys.exit(f"assembly: {path} missing (scripts/setup extracts the CGAL corpus)")
        v, t = read_off(path)
        lo, hi = v.min(axis=0), v.max(axis=0)
        library[name] = ((v - (lo + hi) / 2) / np.linalg.norm(hi - lo), t)
    rng = np.random.default_rng(seed)
    chosen, total = [], 0
    while total < triangles:
        name = parts[int(rng.integers(len(parts)))]
        chosen.append(name)
        total += len(library[name][1])
    side = int(np.ceil(len(chosen) ** (1 / 3)))
    spacing = 1.0 / density
    vertices, tris, base = [], [], 0
    for k, name in enumerate(chosen):
        v, t = library[name]
        cell = np.array([k % side, k // side % side, k // (side * side)], dtype=np.float64)
        centre = (cell + rng.uniform(-0.1, 0.1, size=3)) * spacing
        placed = (v * rng.uniform(0.75, 1.25)) @ random_rotation(rng).T + centre
        vertices.append(placed)
        tris.append(t + base)
        base += len(v)
    return np.concatenate(vertices), np.concatenate(tris), chosen


def write_off(path, v, t):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(v)} {len(t)} 0\n")
        np.savetxt(f, v, fmt="%.17g")
        np.savetxt(f, np.hstack([np.full((len(t), 1), 3), t]), fmt="%d")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--triangles", type=int, required=True)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--density", type=float, default=1.1,
                    help="parts per unit of grid spacing (> 1: neighbours interpenetrate)")
    ap.add_argument("-o", "--output", required=True)
    args = ap.parse_args()
    v, t, chosen = make_assembly(args.triangles, args.seed, args.density)
    write_off(args.output, v, t)
    print(f"assembly: {len(chosen)} parts, {len(t)} triangles, {len(v)} vertices -> {args.output}")


if __name__ == "__main__":
    main()
