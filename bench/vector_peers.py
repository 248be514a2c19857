#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Vector drawings of interpenetrating parts: exbsp's SVG against matplotlib's mplot3d and
three.js's SVGRenderer, each checked pixel by pixel against Mesa's z-buffer image of the same
triangles under the same camera. Writes bench/VECTOR_PEERS.md and bench/plots/vector_peers.png
(raw figures and images in bench/out/vector_peers/).

    bench/vector_peers.py                       build exbsp and zbuffer_render into build-bench/, run
    bench/vector_peers.py --build-dir build --no-build    use binaries already built there

Scenes (400 x 300, five views each): a cube pierced by a slab; three planks in a cyclic
overlap (no depth order of the parts exists); and, as a control, the cube alone (no
interpenetration: what is left there is rasterization, not order). Every face has its own
colour. Per tool and view:
  - exbsp: `exbsp render SCENE.json -o VIEW.svg` (visible regions, the default), one mesh per
    face, gluLookAt + gluPerspective camera;
  - three.js (npm `three` + `jsdom`, bench/peers/vector/): SVGRenderer with its defaults, the
    same camera (PerspectiveCamera), one Mesh per face;
  - matplotlib (Debian python3-matplotlib): mplot3d's Poly3DCollection of the face polygons,
    view_init(elev, azim) of the same direction, perspective projection, axes hidden.
Each SVG is rasterized by headless Chromium without anti-aliasing (shape-rendering:
crispEdges), so every pixel has one face's colour. The reference is Mesa's z-buffer (OSMesa,
bench/zbuffer_render) of the same triangles under the matrix the tool used: exbsp's
gluPerspective x gluLookAt computed here, three.js's projectionMatrix x matrixWorldInverse as
it reports them, mplot3d's projection matrix (Axes3D.M) followed by its axes' display
transform. A covered pixel (not background in the reference or the drawing) is wrong when its
colour is not the reference's (colours classified to the nearest face colour). "Interior":
the same count restricted to pixels whose 3 x 3 neighbourhood in the reference is one colour,
so that edges rasterized a pixel apart do not count: what remains is faces drawn in the wrong
order (or not at all).

Skips, with a message, the tools whose programs are missing (node/npm for three.js, matplotlib);
without chromium or zbuffer_render (OSMesa) nothing can be measured and it stops with a message.
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import run as base  # noqa: E402  (build directory, matplotlib under Debian's python3)

WIDTH, HEIGHT = 400, 300
BACKGROUND = (242, 244, 248)
FOVY = 40.0
PEERS_DIR = os.path.join(HERE, "peers", "vector")
OUT = os.path.join(HERE, "out", "vector_peers")
CHROMIUM_CANDIDATES = ["chromium", "chromium-browser", "google-chrome"]


def log(msg):
    print(f"[vector_peers {time.strftime('%H:%M:%S')}] {msg}", flush=True)


# ----------------------------------------------------------------------------------------------
# Geometry: boxes as six outward quads, one colour per face


def sub(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def add(a, b):
    return [a[0] + b[0], a[1] + b[1], a[2] + b[2]]


def scale(s, a):
    return [s * a[0], s * a[1], s * a[2]]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def unit(a):
    return scale(1 / math.sqrt(dot(a, a)), a)


def rotation(axis, degrees):
    """Rotation matrix (rows) about a unit axis."""
    x, y, z = unit(axis)
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    C = 1 - c
    return [[c + x * x * C, x * y * C - z * s, x * z * C + y * s],
            [y * x * C + z * s, c + y * y * C, y * z * C - x * s],
            [z * x * C - y * s, z * y * C + x * s, c + z * z * C]]


def apply(m, v):
    return [dot(m[0], v), dot(m[1], v), dot(m[2], v)]


def box(centre, axes, half, colours):
    """Six outward, counter-clockwise (seen from outside) quads of the box centre + sum of
    +-half[k] axes[k] (orthonormal axes), with colours[0..5]."""
    faces = []
    for k in range(3):
        n = scale(half[k], axes[k])
        e1 = scale(half[(k + 1) % 3], axes[(k + 1) % 3])
        e2 = scale(half[(k + 2) % 3], axes[(k + 2) % 3])
        for side in (0, 1):
            c = add(centre, n) if side == 0 else sub(centre, n)
            q = [sub(sub(c, e1), e2), sub(add(c, e1), e2), add(add(c, e1), e2), add(sub(c, e1), e2)]
            outward = n if side == 0 else scale(-1, n)
            if dot(cross(sub(q[1], q[0]), sub(q[2], q[0])), outward) < 0:
                q = [q[0], q[3], q[2], q[1]]
            faces.append({"polygon": q, "color": list(colours[2 * k + side])})
    return faces


def shades(base_rgb):
    """Six distinct shades of a colour (one per box face)."""
    return [tuple(int(round(c * f)) for c in base_rgb) for f in (1.0, 0.84, 0.70, 0.58, 0.47, 0.38)]


def cube_alone():
    return box([0, 0, 0], [[0, 0, 1], [1, 0, 0], [0, 1, 0]], [1, 1, 1], shades((235, 120, 60)))


def pierced_cube():
    cube = cube_alone()
    r = rotation([0, 0, 1], 25)
    r2 = rotation([0, 1, 0], 18)
    axes = [apply(r, apply(r2, a)) for a in ([0, 0, 1], [1, 0, 0], [0, 1, 0])]  # thin axis first: lightest
    slab = box([0.1, -0.1, 0.15], axes, [0.16, 2.1, 0.55], shades((80, 150, 240)))
    return cube + slab


def cyclic_planks():
    """Three planks at 120 degrees, each tilted along its length so that it passes over the next
    and under the previous one: a cyclic overlap (no part is wholly in front of another)."""
    faces = []
    alpha = math.radians(8)
    for k, base_rgb in enumerate([(235, 120, 60), (80, 150, 240), (90, 190, 100)]):
        theta = math.radians(120 * k)
        d = [math.cos(theta), math.sin(theta), 0]
        n = [-math.sin(theta), math.cos(theta), 0]
        length_axis = add(scale(math.cos(alpha), d), [0, 0, math.sin(alpha)])
        thickness_axis = add(scale(-math.sin(alpha), d), [0, 0, math.cos(alpha)])
        faces += box(scale(-0.75, n), [thickness_axis, length_axis, n], [0.08, 2.2, 0.4], shades(base_rgb))
    return faces


# (azimuth, elevation) in degrees: the eye is at look_at + distance (cos e cos a, cos e sin a, sin e), z up
SCENES = [
    ("pierced_cube", "a cube pierced by a slab", pierced_cube,
     [(30, 25), (110, 35), (200, 15), (290, 45), (345, 65)]),
    ("cyclic_planks", "three planks in a cyclic overlap", cyclic_planks,
     [(0, 70), (60, 55), (150, 80), (230, 60), (300, 75)]),
    ("control_cube", "control: the cube alone (no overlap)", cube_alone,
     [(30, 25), (110, 35), (200, 15), (290, 45), (345, 65)]),
]


def radius(faces):
    return max(math.sqrt(dot(p, p)) for f in faces for p in f["polygon"])


def camera(faces, azim, elev):
    r = radius(faces)
    dist = 1.15 * r / math.sin(math.radians(FOVY / 2))
    a, e = math.radians(azim), math.radians(elev)
    eye = [dist * math.cos(e) * math.cos(a), dist * math.cos(e) * math.sin(a), dist * math.sin(e)]
    return {"eye": eye, "look_at": [0, 0, 0], "up": [0, 0, 1], "fovy_deg": FOVY,
            "near": max(0.1, dist - 2 * r), "far": dist + 2 * r}


def glu_clip_matrix(cam):
    """gluPerspective(fovy, W/H, near, far) x gluLookAt(eye, look_at, up), row-major."""
    f = unit(sub(cam["look_at"], cam["eye"]))
    s = unit(cross(f, cam["up"]))
    u = cross(s, f)
    eye = cam["eye"]
    view = [s + [-dot(s, eye)], u + [-dot(u, eye)], scale(-1, f) + [dot(f, eye)], [0, 0, 0, 1]]
    t = 1 / math.tan(math.radians(cam["fovy_deg"]) / 2)
    n, fa = cam["near"], cam["far"]
    proj = [[t * HEIGHT / WIDTH, 0, 0, 0], [0, t, 0, 0],
            [0, 0, (fa + n) / (n - fa), 2 * fa * n / (n - fa)], [0, 0, -1, 0]]
    return [sum(proj[i][k] * view[k][j] for k in range(4)) for i in range(4) for j in range(4)]


def triangles(faces):
    tris, cols = [], []
    for f in faces:
        p = f["polygon"]
        for i in range(1, len(p) - 1):
            tris.append(p[0] + p[i] + p[i + 1])
            cols.append(f["color"])
    return tris, cols


# ----------------------------------------------------------------------------------------------
# The three drawers


def draw_exbsp(exbsp, workdir, name, faces, views):
    meshes = []
    for k, f in enumerate(faces):
        path = os.path.join(workdir, f"{name}_face{k}.off")
        with open(path, "w") as out:
            out.write(f"OFF\n{len(f['polygon'])} 1 0\n")
            for p in f["polygon"]:
                out.write(" ".join(repr(float(c)) for c in p) + "\n")
            out.write(f"{len(f['polygon'])} " + " ".join(str(i) for i in range(len(f["polygon"]))) + "\n")
        meshes.append({"file": os.path.basename(path), "color": f["color"]})
    results = []
    for v, (azim, elev) in enumerate(views):
        cam = camera(faces, azim, elev)
        scene = {"meshes": meshes, "camera": {"eye": cam["eye"], "look_at": cam["look_at"], "up": cam["up"]},
                 "projection": {"type": "perspective", "fovy_deg": cam["fovy_deg"], "near": cam["near"],
                                "far": cam["far"]},
                 "viewport": {"width": WIDTH, "height": HEIGHT}, "background": list(BACKGROUND)}
        scene_path = os.path.join(workdir, f"{name}_v{v}.json")
        with open(scene_path, "w") as out:
            json.dump(scene, out, indent=1)
        svg = os.path.join(OUT, f"exbsp_{name}_v{v}.svg")
        subprocess.run([exbsp, "render", scene_path, "-o", svg], check=True)
        results.append({"svg": svg, "clip_from_world": glu_clip_matrix(cam), "nearer": "smaller"})
    return results


def draw_three(workdir, name, faces, views):
    jobs = []
    for v, (azim, elev) in enumerate(views):
        jobs.append({"out": os.path.join(OUT, f"three_{name}_v{v}.svg"), "width": WIDTH, "height": HEIGHT,
                     "background": list(BACKGROUND), "camera": camera(faces, azim, elev), "faces": faces})
    path = os.path.join(workdir, f"three_{name}.json")
    with open(path, "w") as out:
        json.dump({"jobs": jobs}, out)
    subprocess.run(["node", os.path.join(PEERS_DIR, "three_svg.mjs"), path], check=True)
    results = []
    for job in jobs:
        with open(job["out"] + ".json") as f:
            info = json.load(f)
        results.append({"svg": job["out"], "clip_from_world": info["clip_from_world"], "nearer": "smaller"})
    return results


def draw_matplotlib(name, faces, views):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    r = radius(faces)
    bg = [c / 255 for c in BACKGROUND]
    results = []
    for v, (azim, elev) in enumerate(views):
        fig = plt.figure(figsize=(WIDTH / 72, HEIGHT / 72), dpi=72, facecolor=bg)
        ax = fig.add_axes([0, 0, 1, 1], projection="3d", facecolor=bg)
        ax.set_axis_off()
        ax.set_proj_type("persp", focal_length=1 / math.tan(math.radians(FOVY) / 2))
        ax.view_init(elev=elev, azim=azim)
        ax.set_xlim(-r, r)
        ax.set_ylim(-r, r)
        ax.set_zlim(-r, r)
        ax.set_box_aspect((1, 1, 1), zoom=1.5)
        ax.add_collection3d(Poly3DCollection([f["polygon"] for f in faces],
                                             facecolors=[[c / 255 for c in f["color"]] for f in faces],
                                             edgecolors="none", linewidths=0))
        svg = os.path.join(OUT, f"matplotlib_{name}_v{v}.svg")
        fig.savefig(svg, format="svg", facecolor=bg)
        # The projection of that drawing: data -> (x, y, z, w) by Axes3D.M, then (x/w, y/w) to
        # display pixels (origin bottom left, y up, 72 dpi = SVG units) by the axes' transData.
        M = [list(map(float, row)) for row in ax.M]
        A = ax.transData.get_affine().get_matrix()
        rows = [[2 / WIDTH * (A[0][0] * M[0][j] + A[0][1] * M[1][j] + A[0][2] * M[3][j]) - M[3][j] for j in range(4)],
                [2 / HEIGHT * (A[1][0] * M[0][j] + A[1][1] * M[1][j] + A[1][2] * M[3][j]) - M[3][j] for j in range(4)],
                list(M[2]), list(M[3])]
        plt.close(fig)
        results.append({"svg": svg, "rows": rows})
    # Depth: mplot3d's projected z = z/w grows away from the viewer (its painter draws the largest
    # first); scaled into [-w, w] so that Mesa clips nothing; w made positive.
    tris, _ = triangles(faces)
    for res in results:
        rows = res.pop("rows")
        ws, zs = [], []
        for t in tris:
            for i in range(3):
                p = t[3 * i:3 * i + 3] + [1.0]
                ws.append(sum(rows[3][j] * p[j] for j in range(4)))
                zs.append(sum(rows[2][j] * p[j] for j in range(4)))
        if all(w < 0 for w in ws):
            rows = [[-x for x in row] for row in rows]
            ws = [-w for w in ws]
            zs = [-z for z in zs]
        if not all(w > 0 for w in ws):
            raise RuntimeError("matplotlib view with points behind its eye")
        k = 0.9 / max(abs(z / w) for z, w in zip(zs, ws))
        rows[2] = [k * x for x in rows[2]]
        res["clip_from_world"] = [x for row in rows for x in row]
        res["nearer"] = "smaller"
    return results


# ----------------------------------------------------------------------------------------------
# Rasterizing and comparing


def crisp_copy(svg, out):
    """The SVG with a style forcing aliased rendering, sized WIDTH x HEIGHT pixels."""
    with open(svg) as f:
        text = f.read()
    start = text.index("<svg")
    end = text.index(">", start)
    with open(out, "w") as f:
        f.write(text[:end + 1] + "<style>*{shape-rendering:crispEdges}</style>" + text[end + 1:])


def screenshots(chromium, svgs, workdir, tag):
    """Rasterizes the SVGs with headless Chromium, stacked in one page; returns numpy images."""
    import numpy as np
    from PIL import Image

    items = []
    for i, svg in enumerate(svgs):
        copy = os.path.join(workdir, f"{tag}_{i}.svg")
        crisp_copy(svg, copy)
        items.append(f'<img src="file://{copy}" width="{WIDTH}" height="{HEIGHT}">')
    page = os.path.join(workdir, f"{tag}.html")
    with open(page, "w") as f:
        f.write("<!DOCTYPE html><html><head><style>html,body{margin:0;padding:0;overflow:hidden;background:#000}"
                "img{display:block}</style></head><body>" + "".join(items) + "</body></html>")
    png = os.path.join(workdir, f"{tag}.png")
    profile = os.path.join(workdir, f"{tag}.profile")
    subprocess.run([chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                    "--disable-background-networking", "--disable-component-update", "--disable-sync",
                    "--hide-scrollbars", "--force-device-scale-factor=1", "--force-color-profile=srgb",
                    f"--user-data-dir={profile}", f"--screenshot={png}",
                    f"--window-size={WIDTH},{HEIGHT * len(svgs)}", f"file://{page}"],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=300)
    shot = np.asarray(Image.open(png).convert("RGB"))
    return [shot[i * HEIGHT:(i + 1) * HEIGHT] for i in range(len(svgs))]


def classify(img, palette):
    """Index of the nearest palette colour of every pixel."""
    import numpy as np
    d = ((img[:, :, None, :].astype(np.int32) - palette[None, None, :, :]) ** 2).sum(axis=3)
    return d.argmin(axis=2)


def compare(shot, reference, palette):
    import numpy as np
    a, b = classify(shot, palette), classify(reference, palette)
    covered = (a != 0) | (b != 0)  # palette[0] is the background
    wrong = covered & (a != b)
    pad = np.pad(b, 1, mode="edge")
    uniform = np.ones_like(b, dtype=bool)
    for dy in (0, 1, 2):
        for dx in (0, 1, 2):
            uniform &= pad[dy:dy + HEIGHT, dx:dx + WIDTH] == b
    interior = covered & uniform
    return {"covered": int(covered.sum()), "wrong": int(wrong.sum()),
            "interior": int(interior.sum()), "interior_wrong": int((wrong & interior).sum()),
            "exact_colours": float((shot == reference).all(axis=2).mean())}, wrong


# ----------------------------------------------------------------------------------------------
# Report


def pct(x):
    return f"{100 * x:.2f}" if x >= 0.0001 or x == 0 else f"{100 * x:.3f}"


def span(values):
    lo, hi = pct(min(values)), pct(max(values))
    return lo if lo == hi else f"{lo}–{hi}"


def versions(node_ok):
    import matplotlib
    v = {"matplotlib": matplotlib.__version__}
    if node_ok:
        try:
            with open(os.path.join(PEERS_DIR, "node_modules", "three", "package.json")) as f:
                v["three"] = json.load(f)["version"]
            with open(os.path.join(PEERS_DIR, "node_modules", "jsdom", "package.json")) as f:
                v["jsdom"] = json.load(f)["version"]
        except OSError:
            pass
        v["node"] = base.capture(["node", "--version"])
    return v


def write_report(results, meta, plot_rel, views_rel):
    tools = [t for t in ("exbsp", "matplotlib", "three") if any(r["tool"] == t for r in results)]
    label = {"exbsp": "exbsp (visible regions)", "matplotlib": "matplotlib mplot3d",
             "three": "three.js SVGRenderer"}
    lines = ["# Vector drawings of interpenetrating parts: exbsp, matplotlib, three.js",
             "",
             "Written by `bench/vector_peers.py` (rerun it to refresh; it explains the method in its",
             "docstring). Each drawing (SVG, 400×300) is rasterized by headless Chromium without",
             "anti-aliasing and compared pixel by pixel with Mesa's z-buffer image (OSMesa) of the same",
             "triangles under the matrix that tool used. **Wrong**: covered pixels (not background in",
             "the reference or the drawing) showing another face than the z-buffer, in % of the covered",
             "pixels. **Interior**: the same, counting only pixels at least one pixel away from every edge",
             "of the reference (edges rasterized a pixel apart do not count): faces in the wrong order.",
             "",
             f"Versions: {', '.join(f'{k} {v}' for k, v in meta['versions'].items())}. Run {meta['date']}.",
             "",
             "## Summary: wrong % of the covered pixels over the five views (interior, i.e. order errors)",
             "",
             "| tool | " + " | ".join(title for _, title, _, _ in SCENES) + " |",
             "|---|" + "---:|" * len(SCENES)]
    for tool in tools:
        cells = []
        for name, _, _, _ in SCENES:
            rows = [r for r in results if r["tool"] == tool and r["scene"] == name]
            w = [r["wrong"] / r["covered"] for r in rows if r["covered"]]
            i = [r["interior_wrong"] / r["interior"] for r in rows if r["interior"]]
            cells.append(f"{span(w)} ({span(i)})" if w and i else "–")
        lines.append(f"| {label[tool]} | " + " | ".join(cells) + " |")
    lines += ["",
              "Reading: wrong pixels outside the interior are edges a pixel apart (rasterization, not order);",
              "the control scene, which has no overlap, shows that floor for each tool (three.js enlarges",
              "every triangle by 0.5 px, its `overdraw` against anti-aliasing gaps, so its edges cost more).",
              "Interior errors are faces painted in the wrong order: mplot3d sorts whole polygons by their",
              "mean depth, three.js triangles by theirs; neither splits anything, so interpenetrating or",
              "cyclically overlapping faces cannot come out right. exbsp draws the visible part of each",
              "face (exact BSP order, then 2D Booleans); an interior error there, when one shows, is a",
              "one-pixel pinhole where two Boolean results of one face round a shared point 1/100 px apart",
              "and the aliased rasterizer misses the pixel centre in between.",
              "",
              f"![one view per scene, wrong pixels in red; left to right exbsp, matplotlib, three.js; top: the pierced cube, view 1; bottom: the planks, view 4]({views_rel})",
              ""]
    for name, title, _, views in SCENES:
        lines += [f"## {title}", "", "Views (azimuth°, elevation°): " +
                  ", ".join(f"({a}, {e})" for a, e in views) + ".", ""]
        head = "| tool | " + " | ".join(f"view {i + 1} wrong % (interior %)" for i in range(len(views))) + \
               " | wrong %, range |"
        lines += [head, "|---|" + "---:|" * (len(views) + 1)]
        for tool in tools:
            rows = sorted((r for r in results if r["tool"] == tool and r["scene"] == name), key=lambda r: r["view"])
            if not rows:
                continue
            cells = []
            fr = []
            for r in rows:
                w = r["wrong"] / r["covered"] if r["covered"] else 0
                i = r["interior_wrong"] / r["interior"] if r["interior"] else 0
                fr.append(w)
                cells.append(f"{pct(w)} ({pct(i)})")
            lines.append(f"| {label[tool]} | " + " | ".join(cells) + f" | {span(fr)} |")
        lines.append("")
    for note in meta["notes"]:
        lines.append(f"- {note}")
    lines += ["", f"![wrong pixels per view]({plot_rel})", "",
              "A rerun keeps each drawing, its rasterization and its reference in `bench/out/vector_peers/`",
              "(not committed; `*_wrong.png`: the drawing with its wrong pixels in red).", ""]
    return "\n".join(lines)


def views_figure(path, shown=(("pierced_cube", 0), ("cyclic_planks", 3))):
    """The rasterized drawings of one view per scene, wrong pixels in red, tools side by side."""
    import numpy as np
    from PIL import Image
    rows = []
    for name, view in shown:
        images = []
        for tool in ("exbsp", "matplotlib", "three"):
            f = os.path.join(OUT, f"{tool}_{name}_v{view}_wrong.png")
            images.append(np.asarray(Image.open(f).convert("RGB")) if os.path.exists(f)
                          else np.full((HEIGHT, WIDTH, 3), BACKGROUND, dtype=np.uint8))
        rows.append(np.concatenate(images, axis=1))
    Image.fromarray(np.concatenate(rows, axis=0)).save(path, optimize=True)


def plot(results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    tools = [t for t in ("exbsp", "matplotlib", "three") if any(r["tool"] == t for r in results)]
    colours = {"exbsp": "#2a7", "matplotlib": "#e83", "three": "#38c"}
    fig, axes = plt.subplots(1, len(SCENES), figsize=(12, 3.6), sharey=True)
    for ax, (name, title, _, views) in zip(axes, SCENES):
        width = 0.8 / len(tools)
        for k, tool in enumerate(tools):
            rows = sorted((r for r in results if r["tool"] == tool and r["scene"] == name), key=lambda r: r["view"])
            xs = [r["view"] + (k - (len(tools) - 1) / 2) * width for r in rows]
            ys = [100 * r["wrong"] / r["covered"] if r["covered"] else 0 for r in rows]
            ax.bar(xs, ys, width, label=tool, color=colours[tool])
        ax.set_title(title, fontsize=9)
        ax.set_xticks(range(len(views)))
        ax.set_xticklabels([f"{a}°/{e}°" for a, e in views], fontsize=7)
        ax.grid(axis="y", alpha=0.3)
    axes[0].set_ylabel("wrong pixels, % of covered")
    axes[0].legend(fontsize=8)
    fig.suptitle("Pixels showing the wrong face against Mesa's z-buffer (400×300, Chromium, no anti-aliasing)",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


# ----------------------------------------------------------------------------------------------


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build-dir", default=base.BUILD, help="where src/app/exbsp and bench/zbuffer_render are")
    ap.add_argument("--no-build", action="store_true", help="use the binaries already in --build-dir")
    args = ap.parse_args()
    base.ensure_matplotlib()
    import numpy as np
    from PIL import Image

    build = os.path.abspath(args.build_dir)
    if not args.no_build:
        base.run(["cmake", "-S", REPO, "-B", build, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                  "-DEXBSP_BUILD_BENCH=ON"], stdout=subprocess.DEVNULL)
        base.run(["cmake", "--build", build, "--target", "exbsp", "zbuffer_render"])
    exbsp = os.path.join(build, "src", "app", "exbsp")
    zbuffer = os.path.join(build, "bench", "zbuffer_render")
    chromium = next((shutil.which(c) for c in CHROMIUM_CANDIDATES if shutil.which(c)), None)
    if not chromium:
        log("skipped: headless Chromium is needed to rasterize the SVGs (apt-get install chromium)")
        return 0
    for path, what in ((exbsp, "exbsp"), (zbuffer, "zbuffer_render (OSMesa: apt-get install libosmesa6-dev)")):
        if not os.access(path, os.X_OK):
            log(f"skipped: no {what} at {path} (build it, or drop --no-build)")
            return 0
    notes = []
    # bench/peers/setup.sh installs nodejs and npm (apt-get) and the pinned npm packages.
    setup = os.path.join(os.path.dirname(PEERS_DIR), "setup.sh")
    node_ok = subprocess.run([setup]).returncode == 0 and bool(shutil.which("node") and shutil.which("npm"))
    if not node_ok:
        log("three.js skipped: node and npm are needed (apt-get install nodejs npm)")
        notes.append("three.js was skipped: node/npm missing on the machine that ran this.")

    os.makedirs(OUT, exist_ok=True)
    results = []
    with tempfile.TemporaryDirectory(prefix="vector_peers_") as work:
        drawings = []  # (tool, scene, view, svg, clip_from_world, nearer)
        for name, _, make, views in SCENES:
            faces = make()
            log(f"{name}: {len(faces)} faces, {len(views)} views")
            per_tool = {"exbsp": draw_exbsp(exbsp, work, name, faces, views),
                        "matplotlib": draw_matplotlib(name, faces, views)}
            if node_ok:
                per_tool["three"] = draw_three(work, name, faces, views)
            for tool, rows in per_tool.items():
                for v, r in enumerate(rows):
                    drawings.append({"tool": tool, "scene": name, "view": v, "faces": faces, **r})
        # Mesa's references
        jobs = []
        for d in drawings:
            tris, cols = triangles(d["faces"])
            d["reference"] = os.path.join(OUT, f"{d['tool']}_{d['scene']}_v{d['view']}_zbuffer.png")
            jobs.append({"out": d["reference"], "width": WIDTH, "height": HEIGHT, "background": list(BACKGROUND),
                         "clip_from_world": d["clip_from_world"], "nearer": d["nearer"],
                         "triangles": tris, "colors": cols})
        jobs_path = os.path.join(work, "zbuffer_jobs.json")
        with open(jobs_path, "w") as f:
            json.dump({"jobs": jobs}, f)
        base.run([zbuffer, jobs_path])
        # Chromium, one stacked page per tool
        for tool in sorted({d["tool"] for d in drawings}):
            mine = [d for d in drawings if d["tool"] == tool]
            log(f"rasterizing {len(mine)} {tool} drawings with {chromium}")
            for d, img in zip(mine, screenshots(chromium, [d["svg"] for d in mine], work, tool)):
                ref = np.asarray(Image.open(d["reference"]).convert("RGB"))
                palette = np.array([BACKGROUND] + [tuple(f["color"]) for f in d["faces"]], dtype=np.int32)
                figures, wrong = compare(img, ref, palette)
                shown = img.copy()
                shown[wrong] = (255, 0, 0)
                stem = os.path.join(OUT, f"{tool}_{d['scene']}_v{d['view']}")
                Image.fromarray(img).save(stem + "_chromium.png")
                Image.fromarray(shown).save(stem + "_wrong.png")
                results.append({"tool": tool, "scene": d["scene"], "view": d["view"], **figures})
                log(f"{tool} {d['scene']} view {d['view']}: {figures['wrong']} of {figures['covered']} covered "
                    f"pixels wrong, {figures['interior_wrong']} of {figures['interior']} interior")
    meta = {"date": time.strftime("%Y-%m-%d"), "versions": versions(node_ok), "notes": notes}
    meta["versions"]["chromium"] = base.capture([chromium, "--version"]) or "?"
    with open(os.path.join(OUT, "results.json"), "w") as f:
        json.dump({"meta": meta, "results": results}, f, indent=1)
    os.makedirs(os.path.join(HERE, "plots"), exist_ok=True)
    plot(results, os.path.join(HERE, "plots", "vector_peers.png"))
    views_figure(os.path.join(HERE, "plots", "vector_peers_views.png"))
    with open(os.path.join(HERE, "VECTOR_PEERS.md"), "w") as f:
        f.write(write_report(results, meta, "plots/vector_peers.png", "plots/vector_peers_views.png"))
    log("wrote bench/VECTOR_PEERS.md, bench/plots/vector_peers.png and bench/plots/vector_peers_views.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
