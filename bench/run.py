#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Regenerates bench/RESULTS.md and bench/plots/*.png: the ONE command of the benchmarks.

    bench/run.py                the full run (10-17 minutes on the 2-core reference machine, 2026-11-24)
    bench/run.py --quick        small inputs only (a few minutes), to check that everything runs;
                                writes bench/out/quick/RESULTS.md and bench/out/quick/plots/ instead
    bench/run.py --report-only  rewrites the report and plots from the raw data of the last run

It builds the bench targets in Release (build-bench/, -DEXBSP_BUILD_BENCH=ON), runs bench_sweep,
bench_render, bench_micro and perf, the naive heuristic on 100,000 stacked triangles (a tree of
depth 100,000) and the JavaScript BSPs users would otherwise pick (bench/peers: csg.js and JSCAD,
with Node; skipped with a message where node is missing), keeps the raw JSON lines in bench/out/
(git-ignored) and writes the report. Every figure in the report comes from this run. This file runs the measurements;
report.py writes the prose and tables, plots.py the plots, perf_profile.py reads the profiles,
common.py holds what they share.
"""
import argparse
import datetime
import json
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import perf_profile  # noqa: E402
from common import (CAD, DEFAULT_KERNEL, HEURISTICS, HERE, KERNELS, ORGANIC, REPO, available, capture,  # noqa: E402,F401
                    ensure_matplotlib, load_jsonl, log, mesh_path, run)

BUILD = os.path.join(REPO, "build-bench")

FULL = {
    "repeats": 3,
    "time_cap": 120,
    "gmpq_max": 2500,             # gmpq is 60-200x the other exact kernels: only meshes up to this many triangles,
    "gmpq_cap": 30,               # one timed build, capped at 30 s
    "control_max": 20000,         # Epeck defect checks (the checker's control) up to here
    "order_samples": 20000,
    "exact_order_samples": 2000,
    "corpus_cad": CAD,
    "corpus_organic": ORGANIC,
    "seeds": [0, 1, 2],           # section 2: every size with each seed (spread: min-max)
    "soups_all": [250, 500, 1000, 2000, 4000],   # every heuristic
    "soups_fast": [8000, 16000, 32000],           # sampled and random only
    "sticks_all": [4, 8, 16, 32],                 # every heuristic
    "sticks_fast": [64],                          # naive, sampled, random (min-split > 30 s)
    "heuristic_repeats": 1,       # timed builds per seed (the seeds give the repeats)
    "corpus_heuristic_repeats": 0,  # corpus heuristics: the counted build's time (fragments are the point)
    "corpus_cap": 60,
    "min_split_max": 6000,
    "naive_random_max": 20000,    # naive and random take ~1 min per build on the 50k-90k organic meshes
    "render_meshes": ["fandisk", "bunny00", "refined_elephant"],
    "render_frames": 5,
    "profile_mesh": "fandisk",
    "micro_min_time": "0.2",
    "stack_n": 100000,            # naive on n stacked triangles: depth n (issue 10's goal: under 60 s)
    "stack_epeck_cap": 120,       # Epeck needs minutes there: its counted build only, capped
    "peers": True,                # csg.js and JSCAD (bench/peers, Node) on the corpus
}
QUICK = dict(FULL, **{
    "repeats": 1,
    "time_cap": 30,
    "gmpq_max": 1000,
    "gmpq_cap": 10,
    "corpus_cad": ["part", "joint"],
    "corpus_organic": [],
    "seeds": [0, 1],
    "soups_all": [125, 250, 500],
    "soups_fast": [1000, 2000],
    "sticks_all": [4, 8],
    "sticks_fast": [16],
    "render_meshes": ["joint"],
    "render_frames": 2,
    "profile_mesh": "joint",
    "micro_min_time": "0.01",
    "stack_n": 20000,
    "stack_epeck_cap": 30,
})


# ----------------------------------------------------------------------------------------------
# Build and machine


def build():
    run(["cmake", "-S", REPO, "-B", BUILD, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
         "-DEXBSP_BUILD_BENCH=ON", "-DEXBSP_BUILD_TESTS=OFF"], stdout=subprocess.DEVNULL)
    run(["ninja", "-C", BUILD, "bench_sweep", "bench_render", "bench_micro"])


def machine():
    lscpu = capture(["lscpu"])
    model = re.search(r"Model name:\s*(.*)", lscpu)
    mem = 0
    with open("/proc/meminfo") as f:
        for line in f:
            if line.startswith("MemTotal:"):
                mem = int(line.split()[1]) * 1024
    cxx = ""
    cache = os.path.join(BUILD, "CMakeCache.txt")
    if os.path.exists(cache):
        m = re.search(r"CMAKE_CXX_COMPILER:FILEPATH=(.*)", open(cache).read())
        if m:
            cxx = capture([m.group(1), "--version"]).splitlines()[0]
    cgal = ""
    if os.path.exists("/usr/include/CGAL/version.h"):
        m = re.search(r"#define CGAL_VERSION (\S+)", open("/usr/include/CGAL/version.h").read())
        cgal = m.group(1) if m else ""
    return {
        "cpu": model.group(1).strip() if model else "unknown",
        "nproc": capture(["nproc"]),
        "memory_gib": round(mem / 2**30, 1),
        "kernel": capture(["uname", "-sr"]),
        "compiler": cxx,
        "cgal": cgal,
        "commit": capture(["git", "-C", REPO, "rev-parse", "--short=12", "HEAD"]),
        "dirty": bool(capture(["git", "-C", REPO, "status", "--porcelain", "--untracked-files=no"])),
        "load_start": os.getloadavg(),
    }


# ----------------------------------------------------------------------------------------------
# Stages


def sweep(cfg, out, label, inputs, kernels, heuristics, repeats, extra=(), timeout=3600, time_cap=None):
    cmd = [os.path.join(BUILD, "bench", "bench_sweep"), "--label", label, "--out", out,
           "--kernels", ",".join(kernels), "--heuristics", ",".join(heuristics),
           "--repeats", str(repeats), "--time-cap", str(time_cap or cfg["time_cap"])]
    for spec in inputs:
        cmd += ["--input", spec]
    cmd += list(extra)
    try:
        run(cmd, timeout=timeout)
    except (subprocess.CalledProcessError, subprocess.TimeoutExpired) as e:
        log(f"warning: {label} {inputs}: {e}")


def stage_accuracy(cfg, out):
    for name in available(cfg["corpus_cad"] + cfg["corpus_organic"]):
        sweep(cfg, out, "accuracy", ["mesh:" + mesh_path(name)], KERNELS, ["sampled"], cfg["repeats"],
              ["--limit", f"gmpq={cfg['gmpq_max']}", "--repeats-for", "gmpq=1",
               "--time-cap-for", f"gmpq={cfg['gmpq_cap']}", "--defects", "--control-max-triangles", str(cfg["control_max"]),
               "--order-samples", str(cfg["order_samples"]),
               "--exact-order-samples", str(cfg["exact_order_samples"])])


def stage_heuristics(cfg, out):
    """Generated inputs with every seed of cfg["seeds"] (the soup's seed and the heuristic's),
    then the corpus (sampled comes from the accuracy stage: same kernel, same seed, same tree)."""
    for seed in cfg["seeds"]:
        s = ["--seed", str(seed)]
        for n in cfg["soups_all"]:
            sweep(cfg, out, "soup", [f"soup:{n}:{seed}"], [DEFAULT_KERNEL], HEURISTICS, cfg["heuristic_repeats"], s)
        for n in cfg["soups_fast"]:
            sweep(cfg, out, "soup", [f"soup:{n}:{seed}"], [DEFAULT_KERNEL], ["sampled", "random"],
                  cfg["heuristic_repeats"], s)
        for k in cfg["sticks_all"]:
            sweep(cfg, out, "sticks", [f"sticks:{k}"], [DEFAULT_KERNEL], HEURISTICS, cfg["heuristic_repeats"], s)
        for k in cfg["sticks_fast"]:
            sweep(cfg, out, "sticks", [f"sticks:{k}"], [DEFAULT_KERNEL], ["naive", "sampled", "random"],
                  cfg["heuristic_repeats"], s)
    for name in available(cfg["corpus_cad"] + cfg["corpus_organic"]):
        sweep(cfg, out, "corpus", ["mesh:" + mesh_path(name)], [DEFAULT_KERNEL], ["naive", "min-split", "random"],
              cfg["corpus_heuristic_repeats"],
              ["--limit", f"min-split={cfg['min_split_max']}", "--limit", f"naive={cfg['naive_random_max']}",
               "--limit", f"random={cfg['naive_random_max']}"], time_cap=cfg["corpus_cap"])


def stage_render(cfg, out, outdir):
    for name in available(cfg["render_meshes"]):
        cmd = [os.path.join(BUILD, "bench", "bench_render"), "--mesh", mesh_path(name), "--kernel", DEFAULT_KERNEL,
               "--frames", str(cfg["render_frames"]), "--out", out, "--svg", os.path.join(outdir, "render.svg")]
        try:
            run(cmd, timeout=1800)
        except (subprocess.CalledProcessError, subprocess.TimeoutExpired) as e:
            log(f"warning: render {name}: {e}")


def stage_micro(cfg, out):
    cmd = [os.path.join(BUILD, "bench", "bench_micro"), f"--benchmark_min_time={cfg['micro_min_time']}",
           "--benchmark_format=json", f"--benchmark_out={out}", "--benchmark_out_format=json"]
    try:
        run(cmd, timeout=1800, stdout=subprocess.DEVNULL)
    except (subprocess.CalledProcessError, subprocess.TimeoutExpired) as e:
        log(f"warning: micro: {e}")


def stacked_off(path, n):
    """n parallel triangles at z = 0 .. n-1: naive builds a tree of depth n."""
    with open(path, "w") as f:
        f.write(f"OFF\n{3 * n} {n} 0\n")
        for i in range(n):
            f.write(f"0 0 {i}\n1 0 {i}\n0 1 {i}\n")
        for i in range(n):
            f.write(f"3 {3 * i} {3 * i + 1} {3 * i + 2}\n")


def stage_stacked(cfg, out, outdir):
    """Naive on cfg["stack_n"] stacked triangles with the default kernel and Epeck (one counted
    build each; the default kernel also one timed round)."""
    n = cfg["stack_n"]
    path = os.path.join(outdir, f"stacked_{n}.off")
    stacked_off(path, n)
    sweep(dict(cfg, time_cap=600), out, "stacked", ["mesh:" + path], [DEFAULT_KERNEL, "epeck"], ["naive"], 1,
          ["--max-fragments", str(n + 1), "--time-cap-for", f"epeck={cfg['stack_epeck_cap']}",
           "--repeats-for", "epeck=0"], timeout=7200)


def stage_peers(cfg, out):
    """csg.js and JSCAD on the corpus (bench/peers/run.sh, which installs them with npm); their
    JSON lines are copied to `out`."""
    script = os.path.join(HERE, "peers", "run.sh")
    produced = os.path.join(HERE, "out", "peers.jsonl")
    if os.path.exists(produced):
        os.remove(produced)
    meshes = [mesh_path(m) for m in available(cfg["corpus_cad"] + cfg["corpus_organic"])]
    try:
        run(["sh", script] + meshes, timeout=3600)
    except (OSError, subprocess.CalledProcessError, subprocess.TimeoutExpired) as e:
        log(f"warning: peers: {e}")
    if os.path.exists(produced):
        os.replace(produced, out)


PROFILE_KERNELS = [DEFAULT_KERNEL, "epeck", "double"]


def stage_profile(cfg, outdir):
    """perf profiles of single-threaded builds, one per kernel of PROFILE_KERNELS."""
    result = {"mesh": cfg["profile_mesh"]}
    for kernel in PROFILE_KERNELS:
        result[kernel] = perf_profile.profile(BUILD, outdir, cfg["profile_mesh"], kernel)
    return result


# ----------------------------------------------------------------------------------------------


def load_data(outdir):
    """The raw data of a run, as report.write and plots.draw_all take it."""
    acc = load_jsonl(os.path.join(outdir, "accuracy.jsonl"))
    heur = load_jsonl(os.path.join(outdir, "heuristics.jsonl"))
    micro = os.path.join(outdir, "micro.json")
    profile_json = os.path.join(outdir, "profile.json")
    profile = json.load(open(profile_json)) if os.path.exists(profile_json) else {}
    for kernel in PROFILE_KERNELS:  # re-read the perf files: the categories may have changed
        data = os.path.join(outdir, f"perf.{kernel}.data")
        if os.path.exists(data) and "rows" in profile.get(kernel, {}):
            profile[kernel] = perf_profile.read(data)
    return {
        "accuracy": acc,
        "soup": [r for r in heur if r["label"] == "soup"],
        "sticks": [r for r in heur if r["label"] == "sticks"],
        "corpus": [r for r in heur if r["label"] == "corpus"],
        "render": load_jsonl(os.path.join(outdir, "render.jsonl")),
        "micro": json.load(open(micro)) if os.path.exists(micro) else None,
        "profile": profile,
        "stacked": load_jsonl(os.path.join(outdir, "stacked.jsonl")),
        "peers": load_jsonl(os.path.join(outdir, "peers.jsonl")),
    }


def main():
    ensure_matplotlib()
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="small inputs, report under bench/out/quick/")
    ap.add_argument("--no-build", action="store_true", help="use the existing build-bench/ binaries")
    ap.add_argument("--report-only", action="store_true", help="rewrite the report from the existing raw data")
    args = ap.parse_args()
    import plots  # noqa: E402  (after ensure_matplotlib: it may re-run this script under Debian's python3)
    import report  # noqa: E402

    cfg = QUICK if args.quick else FULL
    outdir = os.path.join(HERE, "out", "quick" if args.quick else "full")
    report_path = os.path.join(outdir if args.quick else HERE, "RESULTS.md")
    plotdir = os.path.join(outdir if args.quick else HERE, "plots")
    os.makedirs(outdir, exist_ok=True)
    meta_json = os.path.join(outdir, "meta.json")
    t0 = time.time()
    if not args.report_only:
        if not os.path.exists(mesh_path("fandisk")):
            log("warning: data/meshes/ is missing: run scripts/setup (corpus sections will be empty)")
        if not args.no_build:
            build()
        meta = machine()
        for name in ["accuracy.jsonl", "heuristics.jsonl", "render.jsonl", "micro.json", "profile.json",
                     "stacked.jsonl", "peers.jsonl"]:
            if os.path.exists(os.path.join(outdir, name)):
                os.remove(os.path.join(outdir, name))
        stage_accuracy(cfg, os.path.join(outdir, "accuracy.jsonl"))
        stage_heuristics(cfg, os.path.join(outdir, "heuristics.jsonl"))
        stage_stacked(cfg, os.path.join(outdir, "stacked.jsonl"), outdir)
        if cfg.get("peers"):
            stage_peers(cfg, os.path.join(outdir, "peers.jsonl"))
            meta["node"] = capture(["node", "--version"])
        stage_render(cfg, os.path.join(outdir, "render.jsonl"), outdir)
        stage_micro(cfg, os.path.join(outdir, "micro.json"))
        json.dump(stage_profile(cfg, outdir), open(os.path.join(outdir, "profile.json"), "w"))
        meta["load_end"] = os.getloadavg()
        meta["minutes"] = (time.time() - t0) / 60
        meta["date"] = datetime.datetime.now().strftime("%Y-%m-%d %H:%M")
        meta["quick"] = args.quick
        json.dump(meta, open(meta_json, "w"))
    meta = json.load(open(meta_json))
    data = load_data(outdir)
    data["node"] = meta.get("node", "")  # Node's version (empty when node was missing)
    plots.draw_all(data, cfg, plotdir)
    report.write(report_path, meta, cfg, data, "plots", "bench/run.py --quick" if args.quick else "bench/run.py")
    log(f"wrote {os.path.relpath(report_path, REPO)} and {os.path.relpath(plotdir, REPO)}/ "
        f"({(time.time() - t0) / 60:.1f} min)")


if __name__ == "__main__":
    sys.exit(main())
