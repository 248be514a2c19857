#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Assemblies of millions of triangles (issue 27), in one command: rewrites section 9 of
bench/RESULTS.md (between <!-- assemblies:begin --> and <!-- assemblies:end -->) and draws
bench/plots/assemblies.png; raw output in bench/out/assemblies/.

    /usr/bin/python3 bench/assemblies.py [--build-dir build] [--sizes 100000,300000,1000000,3000000]
                                         [--dask-size 1000000] [--workers 1,2,4] [--huge 10000000]

Side by side in one run on this machine:
  1. per size: an assembly of bench/assembly.py (seed 1, density 1.1); `exbsp build --json`
     (exact kernel, default heuristic, all cores) under /usr/bin/time: fragments, build time,
     peak RSS; `exbsp build --save`: the saved tree's size; bench_render: the PNG frame at
     1024 x 768 (order + transform and clip + raster);
  1b. the --huge assembly (10M triangles) built by `exbsp build` with its default memory budget:
     whether it builds on this machine, its time and peak RSS;
  2. the distributed build of the --dask-size assembly (exbsp.build_distributed) on a Dask
     LocalCluster of 1, 2 and 4 worker processes (one thread each), against the local build in
     the same process: wall time, bytes shipped per fragment, and that the tree is byte-identical
     (Tree.serialize(reproducible=True));
  3. where that build spends its time (perf self time), and what more sampled candidates and
     samples would save in fragments and cost in time on the smallest assembly.
"""
import argparse
import datetime
import json
import math
import os
import re
import subprocess
import sys
import time

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(here)
sys.path.insert(0, here)
from common import cpu_model, ensure_matplotlib, replace_results_section, short_commit  # noqa: E402
import perf_profile  # noqa: E402

BEGIN, END = "<!-- assemblies:begin -->", "<!-- assemblies:end -->"


def log(msg):
    print(f"[assemblies {time.strftime('%H:%M:%S')}] {msg}", flush=True)


def num(x):
    """An integer with thin-space thousands, as the other sections print them."""
    return f"{x:,}".replace(",", " ")


def fmt_s(x):
    return f"{x * 1000:.0f} ms" if x < 1 else f"{x:.1f} s"


def timed_build(exbsp, mesh, extra=()):
    """(stats of `exbsp build --json`, peak RSS in bytes from /usr/bin/time -v)."""
    p = subprocess.run(["/usr/bin/time", "-v", exbsp, "build", mesh, "--json", *extra],
                       capture_output=True, text=True, check=True)
    rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", p.stderr).group(1)) * 1024
    return json.loads(p.stdout), rss


def frame_seconds(build_dir, mesh, out):
    jsonl = os.path.join(out, "render.jsonl")
    subprocess.run([os.path.join(build_dir, "bench/bench_render"), "--mesh", mesh, "--kernel", "exact",
                    "--frames", "3", "--orbit", "0", "--out", jsonl], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(jsonl) as f:
        r = json.loads(f.read().splitlines()[-1])
    s = r["stage_seconds_median"]
    return s["order"] + s["transform+clip"] + s["raster"]


def size_rows(args, out):
    import assembly
    rows = []
    exbsp = os.path.join(args.build_dir, "src/app/exbsp")
    for n in args.sizes:
        mesh = os.path.join(out, f"assembly-{n}.off")
        if not os.path.exists(mesh):
            v, t, chosen = assembly.make_assembly(n, seed=1, density=1.1)
            assembly.write_off(mesh, v, t)
            log(f"{mesh}: {len(chosen)} parts, {len(t)} triangles")
        stats, rss = timed_build(exbsp, mesh)
        saved = os.path.join(out, f"assembly-{n}.exbsp")
        timed_build(exbsp, mesh, ("--save", saved))
        saved_bytes = os.path.getsize(saved)
        os.remove(saved)
        frame = frame_seconds(args.build_dir, mesh, out)
        row = dict(triangles=stats["input_triangles"], fragments=stats["fragments"],
                   build=stats["build_seconds"], rss=rss, saved=saved_bytes, frame=frame,
                   depth=stats["depth"], nodes=stats["nodes"])
        rows.append(row)
        log(f"{n}: {row}")
    return rows


def huge_row(args, out):
    """The --huge assembly built with `exbsp build` and its default --max-fragments (no frame,
    no saved tree): does it build on this machine, in what time and memory."""
    import assembly
    mesh = os.path.join(out, f"assembly-{args.huge}.off")
    if not os.path.exists(mesh):
        v, t, chosen = assembly.make_assembly(args.huge, seed=1, density=1.1)
        assembly.write_off(mesh, v, t)
        log(f"{mesh}: {len(chosen)} parts, {len(t)} triangles")
        del v, t
    exbsp = os.path.join(args.build_dir, "src/app/exbsp")
    p = subprocess.run(["/usr/bin/time", "-v", exbsp, "build", mesh, "--json"], capture_output=True,
                       text=True)
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", p.stderr)
    row = dict(status=p.returncode, rss=int(rss.group(1)) * 1024 if rss else 0,
               error=p.stderr.strip().splitlines()[0] if p.returncode else "")
    if p.returncode == 0:
        row.update(json.loads(p.stdout))
    log(f"huge {args.huge}: {row}")
    return row


def dask_rows(args, out):
    """Local build and distributed builds of one assembly, in this process."""
    sys.path.insert(0, os.path.join(args.build_dir, "src/python"))
    import exbsp
    import distributed
    import assembly
    mesh = os.path.join(out, f"assembly-{args.dask_size}.off")
    if not os.path.exists(mesh):
        v, t, _ = assembly.make_assembly(args.dask_size, seed=1, density=1.1)
        assembly.write_off(mesh, v, t)
    v, f, ids = exbsp.read_mesh(mesh)
    t0 = time.perf_counter()
    local = exbsp.build(v, f, face_ids=ids)
    local_seconds = time.perf_counter() - t0
    reference = local.serialize(reproducible=True)
    fragments = len(local)
    del local
    rows = [dict(workers="local (2 threads)", seconds=local_seconds, same=True)]
    for w in args.workers:
        with distributed.LocalCluster(n_workers=w, threads_per_worker=1, processes=True,
                                      dashboard_address=None, memory_limit=0) as cluster:
            with distributed.Client(cluster) as client:
                report = {}
                t0 = time.perf_counter()
                tree = exbsp.build_distributed(v, f, face_ids=ids, scheduler=client, report=report)
                seconds = time.perf_counter() - t0
        same = tree.serialize(reproducible=True) == reference
        shipped = report["input_bytes"] * report["workers"] + report["cell_bytes"] + report["part_bytes"]
        rows.append(dict(workers=w, seconds=seconds, same=same, shipped=shipped,
                         per_fragment=shipped / fragments, report=report))
        log(f"dask {w} workers: {seconds:.1f} s, same tree: {same}, {shipped / fragments:.1f} B/fragment")
        del tree
    return rows, fragments, len(reference)


def profile_rows(args, out):
    """perf's self time of `exbsp build` on the --dask-size assembly (all cores), by category
    and the top functions (bench/perf_profile.py's rules)."""
    mesh = os.path.join(out, f"assembly-{args.dask_size}.off")
    data = os.path.join(out, "perf.build.data")
    try:
        subprocess.run(["perf", "record", "-q", "-o", data, "--",
                        os.path.join(args.build_dir, "src/app/exbsp"), "build", mesh, "--json"],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=1800)
    except (OSError, subprocess.CalledProcessError, subprocess.TimeoutExpired) as e:
        return {"error": str(e)}
    return perf_profile.read(data)


def heuristic_rows(args, out):
    """Fragments and build time of the smallest assembly with more sampled candidates and
    samples than the default (exbsp.build's `sampled`), side by side."""
    sys.path.insert(0, os.path.join(args.build_dir, "src/python"))
    import exbsp
    mesh = os.path.join(out, f"assembly-{args.sizes[0]}.off")
    v, f, ids = exbsp.read_mesh(mesh)
    rows = []
    for sampled in ((16, 512, 8), (32, 512, 8), (64, 512, 8), (64, 4096, 8), (16, 512, 16)):
        t0 = time.perf_counter()
        tree = exbsp.build(v, f, face_ids=ids, sampled=sampled)
        rows.append((sampled, len(tree), time.perf_counter() - t0, len(f)))
        log(f"sampled {sampled}: {len(tree)} fragments")
    return rows


def growth(rows):
    """(first row, last row, exponent of the build time, of n log n, of the fragments) between
    the smallest and the largest size: y grows as n^exponent."""
    a, b = rows[0], rows[-1]
    span = math.log(b["triangles"] / a["triangles"])
    nlogn = math.log(b["triangles"] * math.log(b["triangles"]) /
                     (a["triangles"] * math.log(a["triangles"]))) / span
    return (a, b, math.log(b["build"] / a["build"]) / span, nlogn,
            math.log(b["fragments"] / a["fragments"]) / span)


def goal_lines(rows, huge, dask):
    """Issue 27's goals against this run: a table."""
    if not rows:
        return []
    one = min(rows, key=lambda r: abs(math.log(r["triangles"] / 1e6)))
    out = ["", "**Goals** (issue 27) against this run:", "", "| goal | measured | status |", "|---|---|---|"]

    def row(goal, measured, met, why=""):
        out.append(f"| {goal} | {measured} | {'met' if met else 'not met' + why} |")
    per = one["fragments"] / one["triangles"]
    why = " (section 10: placement)"
    row(f"≤ 2.0 fragments per triangle at {num(one['triangles'])} triangles", f"{per:.2f}", per <= 2.0, why)
    row(f"build of {num(one['triangles'])} triangles in ≤ 10 s ({os.cpu_count()} cores)",
        fmt_s(one["build"]), one["build"] <= 10, why)
    if len(rows) >= 2:
        a, b, exponent, nlogn, _ = growth(rows)
        row(f"build time growth close to n log n, {num(a['triangles'])} to {num(b['triangles'])}",
            f"n^{exponent:.2f} (n log n: n^{nlogn:.2f})", exponent <= nlogn + 0.05)
    row(f"peak RSS ≤ 150 B per fragment at {num(one['triangles'])} triangles",
        f"{one['rss'] / one['fragments']:.0f} B", one["rss"] / one["fragments"] <= 150)
    if huge:
        ok = huge["status"] == 0
        row("a 10M-triangle assembly builds, or stops with exit status 3 and a message (never "
            "killed)",
            f"built in {fmt_s(huge['build_seconds'])}, {huge['rss'] / 1e9:.1f} GB" if ok
            else f"exit status {huge['status']}", ok or huge["status"] == 3)
    if dask:
        drows = [r for r in dask[0] if "shipped" in r]
        same = all(r["same"] for r in drows)
        row("a tree built on a Dask LocalCluster equals the local one byte for byte",
            ", ".join(f"{r['workers']} worker{'s' if r['workers'] != 1 else ''}: "
                      f"{'equal' if r['same'] else 'DIFFERENT'}" for r in drows), same)
    return out


def plot(rows, path, huge=None):
    ensure_matplotlib()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    n = [r["triangles"] for r in rows]
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    ax[0].loglog(n, [r["build"] for r in rows], "o-", label="build (2 cores)")
    ax[0].loglog(n, [r["frame"] for r in rows], "s-", label="PNG frame 1024×768")
    ref = rows[0]["build"] / (n[0] * math.log(n[0]))
    ax[0].loglog(n, [ref * x * math.log(x) for x in n], "k--", lw=0.8, label="n log n")
    if huge and huge["status"] == 0:  # built alone (no saved tree, no frame): its own marker
        h = huge["input_triangles"]
        ax[0].loglog([h], [huge["build_seconds"]], "D", color="C0", mfc="none",
                     label=f"build of {h / 1e6:.0f}M, default budget")
        ax[0].loglog([n[-1], h], [ref * x * math.log(x) for x in (n[-1], h)], "k--", lw=0.8)
        ax[1].semilogx([h], [huge["fragments"] / h], "D", color="C0", mfc="none")
        ax[1].semilogx([h], [huge["rss"] / huge["fragments"] / 100], "D", color="C1", mfc="none")
    ax[0].axhline(10, color="r", lw=0.8, ls=":", label="goal: 1M in 10 s")
    ax[0].set_xlabel("input triangles")
    ax[0].set_ylabel("seconds")
    ax[0].legend(fontsize=8, loc="upper left")
    ax[1].semilogx(n, [r["fragments"] / r["triangles"] for r in rows], "o-", label="fragments / triangle")
    ax[1].semilogx(n, [r["rss"] / r["fragments"] / 100 for r in rows], "s-",
                   label="peak RSS / fragment (100 B)")
    ax[1].axhline(2.0, color="r", lw=0.8, ls=":", label="goals: 2.0 per triangle, 150 B")
    ax[1].axhline(1.5, color="r", lw=0.8, ls=":")
    ax[1].set_xlabel("input triangles")
    ax[1].legend()
    fig.suptitle("Assemblies of rotated CGAL CAD parts (bench/assemblies.py)")
    fig.tight_layout()
    fig.savefig(path, dpi=90)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build-dir", default=os.path.join(root, "build"))
    ap.add_argument("--sizes", default="100000,300000,1000000,3000000")
    ap.add_argument("--dask-size", type=int, default=1000000)
    ap.add_argument("--workers", default="1,2,4")
    ap.add_argument("--no-dask", action="store_true")
    ap.add_argument("--huge", type=int, default=10000000,
                    help="an assembly this large built with the default memory budget (0: none)")
    args = ap.parse_args()
    args.sizes = [int(s) for s in args.sizes.split(",")]
    args.workers = [int(s) for s in args.workers.split(",")]
    out = os.path.join(here, "out/assemblies")
    os.makedirs(out, exist_ok=True)
    load_before = os.getloadavg()[0]
    commit, model = short_commit(), cpu_model()
    rows = size_rows(args, out)
    huge = huge_row(args, out) if args.huge else None
    dask = None if args.no_dask else dask_rows(args, out)
    prof = profile_rows(args, out)
    heur = heuristic_rows(args, out)
    plot(rows, os.path.join(here, "plots/assemblies.png"), huge)
    load_after = os.getloadavg()[0]

    lines = [BEGIN, "## 9. Assemblies of millions of triangles (bench/assemblies.py)", "",
             f"Written by `bench/assemblies.py` at {commit} on {datetime.date.today()} ({os.cpu_count()} "
             f"cores, {model}; load average {load_before:.1f} before, {load_after:.1f} after: read times "
             "as upper bounds). Assemblies of bench/assembly.py (seed 1, density 1.1): randomly rotated "
             "and scaled copies of ten CGAL CAD parts on a grid, neighbours interpenetrating. Exact kernel, "
             "default heuristic, all cores. Peak RSS: the whole `exbsp build` process (mesh reading "
             "included). Saved tree: `exbsp build --save`. PNG frame: bench_render at 1024×768.", "",
             "| triangles | fragments | fragments / triangle | build | peak RSS | RSS / fragment | nodes | "
             "depth | saved tree | saved B / fragment | PNG frame |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {num(r['triangles'])} | {num(r['fragments'])} | "
                     f"{r['fragments'] / r['triangles']:.2f} | {fmt_s(r['build'])} | "
                     f"{r['rss'] / 1e6:.0f} MB | {r['rss'] / r['fragments']:.0f} B | {num(r['nodes'])} | "
                     f"{r['depth']} | {r['saved'] / 1e6:.0f} MB | {r['saved'] / r['fragments']:.1f} | "
                     f"{fmt_s(r['frame'])} |")
    if len(rows) >= 2:
        a, b, exponent, nlogn, fragments = growth(rows)
        lines += ["", f"Growth of the build time from {num(a['triangles'])} to {num(b['triangles'])} "
                  f"triangles: n^{exponent:.2f} (n log n over that range: n^{nlogn:.2f}); of the "
                  f"fragments: n^{fragments:.2f}. Where the "
                  "fragments are born, and what placement costs: section 10 (bench/fragment_births.py)."]
    if huge:
        mem_total = next(int(ln.split()[1]) * 1024 for ln in open("/proc/meminfo")
                         if ln.startswith("MemTotal:"))
        lines += ["", f"**{num(args.huge)} triangles** (the same generator), `exbsp build` with its default "
                  f"`--max-fragments` on this {mem_total / 2 ** 30:.0f} GiB machine: "]
        if huge["status"] == 0:
            lines[-1] += (f"built: {num(huge['fragments'])} fragments "
                          f"({huge['fragments'] / huge['input_triangles']:.2f} per triangle) in "
                          f"{fmt_s(huge['build_seconds'])}, peak RSS {huge['rss'] / 1e9:.1f} GB "
                          f"({huge['rss'] / huge['fragments']:.0f} B per fragment), depth {huge['depth']}.")
        else:
            lines[-1] += f"exit status {huge['status']}: {huge['error']}"
    lines += ["", "![build time, frame time, fragments and memory per fragment against the input size]"
              "(plots/assemblies.png)", ""]
    if dask:
        drows, fragments, saved = dask
        lines += [f"**Distributed build** of the {num(args.dask_size)}-triangle assembly ({num(fragments)} fragments) "
                  "with exbsp.build_distributed on a Dask LocalCluster (worker processes, one thread each) "
                  "against exbsp.build in the same process. Shipped: the input once per worker, the 16 "
                  "cells, the 16 parts. Same tree: Tree.serialize(reproducible=True) equal to the local "
                  "build's. The wall time is the top (grown here), the cells (on the workers, the parts "
                  "joined as they come) and the join (the tree checked as a saved tree is).", "",
                  "| workers | wall time | top | cells | join | shipped | shipped B / fragment | same tree |",
                  "|---|---|---|---|---|---|---|---|"]
        for r in drows:
            if "shipped" in r:
                rep = r["report"]
                lines.append(f"| {r['workers']} | {fmt_s(r['seconds'])} | {fmt_s(rep['seconds_top'])} | "
                             f"{fmt_s(rep['seconds_cells'])} | {fmt_s(rep['seconds_join'])} | "
                             f"{r['shipped'] / 1e6:.0f} MB | {r['per_fragment']:.1f} | "
                             f"{'yes' if r['same'] else 'NO'} |")
            else:
                lines.append(f"| {r['workers']} | {fmt_s(r['seconds'])} | | | | — | — | (reference) |")
        one = next(r for r in drows if r["workers"] == args.workers[0])
        rep = one["report"]
        per_frag_cell = rep["seconds_cells"] / fragments
        big = 100e6 * (rows[-1]["fragments"] / rows[-1]["triangles"] if rows else 3.5)
        lines += ["", "What a 100M-triangle plant model would need, from these figures (linear scaling, "
                  "an estimate): "
                  f"{big / 1e6:.0f}M fragments at this run's fragments per triangle; the cells' work "
                  f"{per_frag_cell * big / 3600:.1f} CPU-hours at {per_frag_cell * 1e6:.1f} µs per fragment "
                  f"(one worker thread here); {one['per_fragment'] * big / 1e9:.0f} GB shipped; the coordinator "
                  f"holds the joined tree and its saved bytes, about {saved / fragments * big / 1e9:.0f} GB of "
                  "saved tree. With 16 cells, at most 16 workers share the work: the frontier size is fixed "
                  "so that every build makes the same tree, and a larger frontier for very large inputs "
                  "would be a build option of its own (same tree locally and distributed, another tree "
                  "than the default)."]
    lines += goal_lines(rows, huge, dask)
    if "rows" in prof:
        lines += ["", f"**Where the build's time goes** (perf, `exbsp build` of the {num(args.dask_size)}-triangle "
                  "assembly, all cores; self time by bench/perf_profile.py's categories, then the top "
                  "functions):", "", "| category | share |", "|---|---|"]
        for name, share in sorted(prof["categories"].items(), key=lambda kv: -kv[1]):
            if share >= 0.5:
                lines.append(f"| {name} | {share:.1f}% |")
        lines += ["", "| function | share |", "|---|---|"]
        for r in prof["rows"][:12]:
            lines.append(f"| `{perf_profile.strip_templates(r['function'])}` | {r['percent']:.1f}% |")
    if heur:
        base = heur[0]
        lines += ["", f"**More candidates and samples** (the sampled heuristic's (candidates, samples, split "
                  f"weight); default (16, 512, 8); the {num(base[3])}-triangle assembly, exbsp.build in one "
                  "process, side by side):", "",
                  "| sampled | fragments | fragments / triangle | against the default | build | against the default |",
                  "|---|---|---|---|---|---|"]
        for sampled, frags, secs, tris in heur:
            lines.append(f"| {sampled} | {num(frags)} | {frags / tris:.2f} | {frags / base[1]:.3f}× | "
                         f"{fmt_s(secs)} | {secs / base[2]:.2f}× |")
    lines.append(END)
    replace_results_section(BEGIN, END, "\n".join(lines))
    log("bench/RESULTS.md section 9 written")


if __name__ == "__main__":
    main()
