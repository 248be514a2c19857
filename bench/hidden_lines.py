#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-3.0-or-later
"""The hidden-line drawing's figures, in one command: rewrites section 7 of bench/RESULTS.md
(between the markers <!-- hidden-lines:begin --> and <!-- hidden-lines:end -->, appended when
they are missing) and keeps the raw output in bench/out/hidden_lines/.

    /usr/bin/python3 bench/hidden_lines.py [--build-dir build] [--frames 5] [--no-peers]

It measures, side by side in one run on this machine:
  1. cost: bench_render (exact build, then per frame the PNG stages and the SVG stage with
     visible regions, visible and hidden edges) on fandisk, bunny00 and refined_elephant at
     1024 x 768: the SVG frame (order + transform+clip + svg + svg write) against the PNG frame
     (order + transform+clip + raster), and the SVG's size;
  2. seams: bench/seams.py (librsvg and Chromium against exbsp's PNG, 800 x 600, lit);
  3. peers: bench/hlr_peers.py (Open CASCADE's hidden-line removal through FreeCAD against
     exbsp, both judged by the ray-cast oracle of the tests), when FreeCAD is installed.
Build first: scripts/build (the bench targets are on by default).
"""
import argparse
import datetime
import json
import os
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(here)
sys.path.insert(0, here)
from common import cpu_model, replace_results_section, short_commit  # noqa: E402

BEGIN, END = "<!-- hidden-lines:begin -->", "<!-- hidden-lines:end -->"


def fmt_s(x):
    return f"{x * 1000:.1f} ms" if x < 1 else f"{x:.2f} s"


def machine():
    return f"{os.cpu_count()} cores, {cpu_model()}"


def cost_rows(build, frames, out):
    rows = []
    for mesh in ("fandisk", "bunny00", "refined_elephant"):
        path = os.path.join(root, "data/meshes", mesh + ".off")
        if not os.path.exists(path):
            print(f"hidden_lines: {path} missing (scripts/setup extracts the CGAL corpus)")
            continue
        jsonl = os.path.join(out, "render.jsonl")
        subprocess.run([os.path.join(build, "bench/bench_render"), "--mesh", path, "--kernel", "exact",
                        "--frames", str(frames), "--orbit", "0", "--out", jsonl,
                        "--svg", os.path.join(out, mesh + ".svg")], check=True,
                       stdout=subprocess.DEVNULL)
        with open(jsonl) as f:
            r = json.loads(f.read().splitlines()[-1])
        s = r["stage_seconds_median"]
        png = s["order"] + s["transform+clip"] + s["raster"]
        png_all = s["order"] + s["transform+clip"] + s.get("raster all cores", s["raster"])
        svg = s["order"] + s["transform+clip"] + s["svg"] + s["svg write"]
        rows.append((mesh, r["triangles"], r["fragments"], png, svg, r["svg_bytes"],
                     r.get("svg_phase_seconds_median", {}), s["svg"], png_all, s.get("svg cpu"),
                     r.get("stage_seconds_first", {}).get("svg")))
        print(f"hidden_lines: {mesh}: PNG frame {fmt_s(png)}, SVG frame {fmt_s(svg)} "
              f"({svg / png:.1f}x), {r['svg_bytes'] / 1000:.0f} KB", flush=True)
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build-dir", default=os.path.join(root, "build"))
    ap.add_argument("--frames", type=int, default=5)
    ap.add_argument("--no-peers", action="store_true")
    args = ap.parse_args()
    out = os.path.join(here, "out/hidden_lines")
    os.makedirs(out, exist_ok=True)
    load_before = os.getloadavg()[0]
    commit = short_commit()
    cost = cost_rows(args.build_dir, args.frames, out)
    seam_md = os.path.join(out, "seams.md")
    subprocess.run([sys.executable, os.path.join(here, "seams.py"), "--exbsp",
                    os.path.join(args.build_dir, "src/app/exbsp"), "--out", os.path.join(out, "seams"),
                    "--markdown", seam_md], check=True, stdout=subprocess.DEVNULL)
    peers_md = os.path.join(out, "hlr_peers.md")
    peers_ok = False
    if not args.no_peers and os.path.exists(os.path.join(here, "hlr_peers.py")):
        p = subprocess.run([sys.executable, os.path.join(here, "hlr_peers.py"), "--build-dir", args.build_dir,
                            "--out", peers_md], capture_output=True, text=True)
        peers_ok = p.returncode == 0 and os.path.exists(peers_md)
        if not peers_ok:
            print("hidden_lines: peers skipped:\n" + p.stdout[-2000:] + p.stderr[-2000:])
    load_after = os.getloadavg()[0]

    lines = [BEGIN, "## 7. The hidden-line drawing (bench/hidden_lines.py)", "",
             f"Written by `bench/hidden_lines.py` at {commit} on {datetime.date.today()} ({machine()}; "
             f"load average {load_before:.1f} before, {load_after:.1f} after: read times as upper bounds, "
             "ratios as measured side by side).", "",
             "**Cost.** bench_render at 1024×768, exact build, median of "
             f"{args.frames} frames. PNG frame: order + transform+clip + raster, the raster in one band "
             "(its default) or in one band per core. SVG frame: order + transform+clip + svg (visible "
             "regions, exact visible and hidden edges, the document) + write; the svg stage uses both "
             "cores (the edges on a second thread; the coverage walk in eight strips of tile rows, "
             "regions and underlay groups, all split over the cores).", ""]
    lines.append("| mesh | triangles | fragments | PNG frame | PNG frame, all cores | SVG frame | "
                 "SVG / PNG | SVG / PNG all cores | SVG size |")
    lines.append("|---|---|---|---|---|---|---|---|---|")
    for mesh, tris, frags, png, svg, size, _, _, png_all, _, _ in cost:
        lines.append(f"| {mesh} | {tris:,} | {frags:,} | {fmt_s(png)} | {fmt_s(png_all)} | {fmt_s(svg)} | "
                     f"{svg / png:.1f}× | {svg / png_all:.1f}× | {size / 1000:.0f} KB |".replace(",", " "))
    phase_names = ["snap", "coverage", "regions", "underlays", "edges (own thread)", "edges wait"]
    lines += ["", "The goal is an SVG frame at most 5× the PNG frame. Where the svg stage's time goes "
              "(median seconds; the edges run on a second thread while the coverage is made, so the stage "
              "waits only for what is left of them; the rest of the stage is the SVG text; svg CPU: the "
              "stage's CPU time over all its threads, from getrusage; the feature edges' view-independent "
              "part, the soup's edge graph, and which meshes are outward closed (their back faces are "
              "left out of the walk) are made in the first frame and kept for the next views, as the "
              "tree is: the first frame's svg stage, which pays for them, is shown apart):", "",
              "| mesh | svg stage | first frame's svg stage | svg CPU | " + " | ".join(phase_names) +
              " |",
              "|---|---|---|---|" + "---|" * len(phase_names)]
    for mesh, _, _, _, _, _, phases, stage, _, cpu, first in cost:
        lines.append(f"| {mesh} | {fmt_s(stage)} | {fmt_s(first) if first is not None else '–'} | "
                     f"{fmt_s(cpu) if cpu is not None else '–'} | " +
                     " | ".join(fmt_s(phases[n]) if n in phases else "–" for n in phase_names) + " |")
    lines += ["",
              "**Seams** (bench/seams.py: exbsp's SVG rasterized by librsvg and Chromium against its own PNG, "
              "800×600, lit, edges none; a seam pixel lies inside the part and outside the colour range of its "
              "3×3 neighbours in the PNG):", ""]
    with open(seam_md) as f:
        lines.append(f.read().strip())
    lines.append("")
    peers_lead = "**Peers** (bench/hlr_peers.py"
    if peers_ok:
        lines += [peers_lead + ": Open CASCADE's hidden-line removal through FreeCAD, and exbsp, "
                  "on the same meshes and parallel views, each judged by the ray-cast oracle of "
                  "tests/support/hidden_line_oracle.h):", ""]
        with open(peers_md) as f:
            lines.append(f.read().strip())
        lines.append("")
    else:
        # Without FreeCAD here, keep the peers table of the last run that had it (it says its own
        # commit and machine) rather than dropping it.
        with open(os.path.join(here, "RESULTS.md")) as f:
            text = f.read()
        if BEGIN in text and END in text:
            old = text[text.index(BEGIN):text.index(END)]
            if peers_lead in old:
                lines += ["(The peers table below is from an earlier run: hlr_peers.py did not run this "
                          "time.)", "", old[old.index(peers_lead):].strip(), ""]
    lines.append(END)
    section = "\n".join(lines)
    replace_results_section(BEGIN, END, section)
    print(section)
    return 0


if __name__ == "__main__":
    sys.exit(main())
