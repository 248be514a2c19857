# SPDX-License-Identifier: LGPL-3.0-or-later
"""Builds, orders and renders a mesh with the exbsp Python package (docs/python.md).

    python3 examples/python/render_fandisk.py [MESH] [OUT_PREFIX]

Writes OUT_PREFIX.png (the fitted iso view), OUT_PREFIX_front.svg (visible regions and edges)
and prints the tree's statistics and the first fragments of the back-to-front order. Typed:
`mypy --strict` passes on it (tests/python/test_packaging.py).
"""
import pathlib
import sys

import numpy as np
import numpy.typing as npt

import exbsp


def main(argv: list[str]) -> int:
    mesh = pathlib.Path(argv[1] if len(argv) > 1 else "data/meshes/fandisk.off")
    prefix = argv[2] if len(argv) > 2 else "fandisk"
    vertices, triangles, face_ids = exbsp.read_mesh(mesh)
    tree: exbsp.Tree = exbsp.build(vertices, triangles, face_ids=face_ids)
    stats = tree.stats
    print(f"{mesh.name}: {stats['input_triangles']} triangles -> {stats['fragments']} fragments, "
          f"{stats['splits']} splits, kernel {tree.kernel}")
    order: npt.NDArray[np.uint32] = tree.order(eye=(3.0, -4.0, 5.0))
    print("back to front:", [int(i) for i in order[:8]], "...")
    png: bytes = tree.render(width=640, height=480, format="png")
    pathlib.Path(prefix + ".png").write_bytes(png)
    svg: str = tree.render(width=640, height=480, view="front", format="svg")
    pathlib.Path(prefix + "_front.svg").write_text(svg)
    image: npt.NDArray[np.uint8] = tree.render(width=64, height=48)
    painted = int(np.count_nonzero(np.any(image != np.array([250, 250, 252], np.uint8), axis=2)))
    print(f"{prefix}.png ({len(png)} bytes), {prefix}_front.svg ({len(svg)} characters); "
          f"a 64x48 image has {painted} painted pixels")
    return 0 if painted > 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
