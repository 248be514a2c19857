#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Drawing sets, in one command: sheets per second of exbsp.drawing_set on the CGAL corpus's CAD
parts with 1 worker (in process), 2 local worker processes and a Dask LocalCluster of 2
workers, side by side in one run; rewrites section 8 of bench/RESULTS.md (between the markers
<!-- drawing-sets:begin --> and <!-- drawing-sets:end -->, appended when missing) and keeps
the raw figures in bench/out/drawing_sets.json.

    /usr/bin/python3 bench/drawing_sets.py [--build-dir build] [--repeats 3]

Each configuration draws every part (front, top, left, iso; PDF and DXF) into a fresh folder; the sets must be byte-identical across
configurations (checked). Build first: scripts/build.
"""
import argparse
import datetime
import hashlib
import json
import os
import shutil
import statistics
import sys
import tempfile
import time

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(here)
sys.path.insert(0, here)
from common import CAD, available, mesh_path, replace_results_section, short_commit  # noqa: E402
from hidden_lines import machine  # noqa: E402

BEGIN, END = "<!-- drawing-sets:begin -->", "<!-- drawing-sets:end -->"


def digest(folder):
    h = hashlib.sha256()
    for name in sorted(os.listdir(folder)):
        h.update(name.encode())
        with open(os.path.join(folder, name), "rb") as f:
            h.update(f.read())
    return h.hexdigest()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build-dir", default=os.path.join(root, "build"))
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    sys.path.insert(0, os.path.join(args.build_dir, "src", "python"))
    import exbsp
    from distributed import Client, LocalCluster

    parts = available(CAD)
    if not parts:
        print("drawing_sets: the CGAL corpus is missing (scripts/setup extracts it)", file=sys.stderr)
        return 2
    work = tempfile.mkdtemp(prefix="exbsp-drawing-sets-")
    folder = os.path.join(work, "parts")
    os.makedirs(folder)
    for p in parts:
        shutil.copy(mesh_path(p), folder)
    # The options are the same for every part of a set, so no section (one plane would miss
    # some parts): the four views only.
    options = dict(formats=("pdf", "dxf"), views=["front", "top", "left", "iso"], lines_only=False,
                   date="2026-01-01", force=True, progress=None)
    commit = short_commit()
    load_before = os.getloadavg()[0]
    # Per-sheet cost, one worker.
    per_sheet = []
    for p in parts:
        t0 = time.perf_counter()
        r = exbsp.drawing(os.path.join(folder, p + ".off"), [os.path.join(work, p + ".pdf")],
                          date="2026-01-01")
        per_sheet.append((p, r["triangles"], time.perf_counter() - t0))
    results = {}
    digests = {}
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    client = Client(cluster)
    try:
        configs = [("1 worker (in process)", dict(workers=1)),
                   ("2 local worker processes", dict(workers=2)),
                   ("Dask LocalCluster, 2 workers", dict(scheduler=client))]
        for _ in range(args.repeats):
            for name, extra in configs:  # interleaved, so that drift hits every configuration
                out = os.path.join(work, "out-" + str(len(results.get(name, []))) + "-" + name[:1])
                r = exbsp.drawing_set(folder, out, **options, **extra)
                assert len(r["written"]) == 2 * len(parts), r
                results.setdefault(name, []).append(r["seconds"])
                digests.setdefault(name, set()).add(digest(out))
                shutil.rmtree(out)
    finally:
        client.close()
        cluster.close()
    load_after = os.getloadavg()[0]
    identical = len(set().union(*digests.values())) == 1
    raw = {"commit": commit, "machine": machine(), "parts": parts, "seconds": results,
           "per_sheet": per_sheet, "identical": identical}
    os.makedirs(os.path.join(here, "out"), exist_ok=True)
    with open(os.path.join(here, "out", "drawing_sets.json"), "w") as f:
        json.dump(raw, f, indent=1)
    shutil.rmtree(work)

    base = statistics.median(results[configs[0][0]])
    lines = [BEGIN, "## 8. Drawing sets (bench/drawing_sets.py)", "",
             f"Written by `bench/drawing_sets.py` at {commit} on {datetime.date.today()} ({machine()}; "
             f"load average {load_before:.1f} before, {load_after:.1f} after). "
             f"{len(parts)} CAD parts of the CGAL corpus, one A3 sheet each (front, top, left, iso, shaded, "
             "auto scale), written as PDF and DXF by `exbsp.drawing_set`; median of "
             f"{args.repeats} runs per configuration, configurations interleaved. The sets are "
             + ("byte-identical across configurations." if identical else "**not** byte-identical (a bug)."),
             "", "| where the sheets are made | set time | sheets / s | speed-up |", "|---|---|---|---|"]
    for name, _ in configs:
        t = statistics.median(results[name])
        lines.append(f"| {name} | {t:.2f} s | {len(parts) / t:.2f} | {base / t:.2f}× |")
    lines += ["", "Each sheet alone (one worker, shaded, PDF only):", "",
              "| part | triangles | sheet |", "|---|---|---|"]
    for p, tris, s in per_sheet:
        lines.append(f"| {p} | {tris:,} | {s:.2f} s |".replace(",", " "))
    lines += ["", "The BSP build of each part already uses both cores (OpenMP), so two workers on "
              "this 2-core machine gain less than 2×; on a cluster each worker has its own cores.", END]
    section = "\n".join(lines)
    replace_results_section(BEGIN, END, section)
    print(section)
    return 0 if identical else 1


if __name__ == "__main__":
    sys.exit(main())
