#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Seams of the vector drawing: exbsp's SVG rasterized by librsvg (rsvg-convert) and by headless
Chromium, compared pixel by pixel with exbsp's own PNG of the same view (the painter's raster,
no anti-aliasing). Anti-aliasing renderers blend the pixels along each region's boundary with
what lies below it; where two regions meet, the background can show through ("conflation"),
a faint light line between faces. exbsp draws underlays under its regions against that
(include/exbsp/view/vector_drawing.h).

    /usr/bin/python3 bench/seams.py [--exbsp build/src/app/exbsp] [--meshes fandisk,joint]
        [--size 800x600] [--out bench/out/seams] [--markdown bench/seams.md]

Per mesh (its default view: `exbsp render MESH`, lit, edges none) and rasterizer:
  - within 8: the share of all pixels whose colour is within 8 levels (each channel) of the PNG;
  - seam pixels: pixels inside the part (no background in the PNG's 5 x 5 neighbourhood)
    whose colour lies more than 8 levels outside the range of the PNG's 3 x 3 neighbourhood
    (a blend of two neighbouring faces stays inside that range; the background showing
    through a seam does not): in pixels and as a share of the pixels inside.
Several --exbsp binaries (comma separated) are measured side by side, e.g. before and after a
change.
"""
import argparse
import os
import shutil
import subprocess
import sys

import numpy as np
from PIL import Image

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(here)


def chromium_png(chromium, svg, width, height, png):
    html = svg + ".html"
    with open(html, "w") as f:
        f.write("<html><head><style>html,body{margin:0;padding:0;overflow:hidden}"
                "img{display:block}</style></head><body><img src=\"%s\"></body></html>"
                % os.path.basename(svg))
    profile = svg + ".profile"
    shutil.rmtree(profile, ignore_errors=True)
    subprocess.run([chromium, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
                    "--disable-background-networking", "--disable-component-update",
                    "--hide-scrollbars", "--force-device-scale-factor=1",
                    "--force-color-profile=srgb", "--user-data-dir=" + profile,
                    "--screenshot=" + png, "--window-size=%d,%d" % (width, height),
                    "file://" + os.path.abspath(html)],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    shutil.rmtree(profile, ignore_errors=True)


def load(png):
    return np.asarray(Image.open(png).convert("RGB")).astype(np.int16)


def measure(reference, shot, background, tolerance=8):
    diff = np.abs(reference - shot).max(axis=2)
    near = diff <= tolerance
    # Inside the part: no background pixel in the reference's 5 x 5 neighbourhood.
    h, w, _ = reference.shape
    is_background = (reference == np.array(background, np.int16)).all(axis=2)
    inside = np.ones((h, w), bool)
    low = reference.copy()
    high = reference.copy()
    for dy in range(-2, 3):
        for dx in range(-2, 3):
            inside &= ~np.roll(np.roll(is_background, dy, axis=0), dx, axis=1)
            if abs(dy) <= 1 and abs(dx) <= 1:
                shifted = np.roll(np.roll(reference, dy, axis=0), dx, axis=1)
                low = np.minimum(low, shifted)
                high = np.maximum(high, shifted)
    inside[:2, :] = inside[-2:, :] = False
    inside[:, :2] = inside[:, -2:] = False
    # A seam: a colour outside the range of the reference's 3 x 3 neighbourhood (a blend of
    # two neighbouring faces stays inside it; the background showing through does not).
    outside = ((shot < low - tolerance) | (shot > high + tolerance)).any(axis=2)
    seams = inside & outside
    return {"within": float(near.mean()), "seam_pixels": int(seams.sum()),
            "flat_pixels": int(inside.sum())}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exbsp", default=os.path.join(root, "build/src/app/exbsp"))
    ap.add_argument("--meshes", default="fandisk,joint,pinion")
    ap.add_argument("--size", default="800x600")
    ap.add_argument("--out", default=os.path.join(here, "out/seams"))
    ap.add_argument("--markdown", default=None)
    args = ap.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    rsvg = shutil.which("rsvg-convert")
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if not rsvg and not chromium:
        print("seams: neither rsvg-convert (librsvg2-bin) nor chromium is installed: nothing to measure")
        return 0
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for k, exbsp in enumerate(args.exbsp.split(",")):
        for mesh in args.meshes.split(","):
            path = os.path.join(root, "data/meshes", mesh + ".off")
            if not os.path.exists(path):
                print("seams: %s missing (scripts/setup extracts the CGAL corpus)" % path)
                continue
            base = os.path.join(args.out, "%s-%d" % (mesh, k))
            for ext in ("png", "svg"):
                edges = ["--edges", "none"] if ext == "svg" else []  # PNG has no edges
                subprocess.run([exbsp, "render", path, "--size", args.size, *edges,
                                "--quiet", "-o", base + "." + ext], check=True)
            reference = load(base + ".png")
            background = tuple(int(v) for v in reference[0, 0])  # the corner: background
            for name, ok in (("librsvg", rsvg), ("chromium", chromium)):
                if not ok:
                    continue
                shot = base + "." + name + ".png"
                if name == "librsvg":
                    subprocess.run([rsvg, "-o", shot, base + ".svg"], check=True)
                else:
                    chromium_png(chromium, base + ".svg", width, height, shot)
                m = measure(reference, load(shot), background)
                rows.append((exbsp, mesh, name, m))
                print("%s %s %s: %.2f%% of pixels within 8 levels, %d seam pixels (%.3f%% of %d inside)"
                      % (exbsp, mesh, name, 100 * m["within"], m["seam_pixels"],
                         100 * m["seam_pixels"] / max(1, m["flat_pixels"]), m["flat_pixels"]),
                      flush=True)
    lines = ["| exbsp | mesh | rasterizer | pixels within 8 levels of the PNG | seam pixels (inside the part) |",
             "|---|---|---|---|---|"]
    for exbsp, mesh, name, m in rows:
        lines.append("| %s | %s | %s | %.2f%% | %d (%.3f%%) |" % (
            os.path.relpath(exbsp, root), mesh, name, 100 * m["within"], m["seam_pixels"],
            100 * m["seam_pixels"] / max(1, m["flat_pixels"])))
    table = "\n".join(lines)
    print(table)
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(table + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
