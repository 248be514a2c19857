#!/usr/bin/env python3
"""What exactness costs with exbsp's own exact kernel: bench/EXACT_KERNEL.md and
bench/plots/exact_kernel.png, from one command.

    bench/exact_kernel.py            the CAD and organic corpus (about 20 minutes on 2 cores)
    bench/exact_kernel.py --quick    three small meshes (a few minutes), report under bench/out/exact-quick/

Per mesh, bench_sweep builds the same input with the kernels exact, double, epeck (and gmpq on
small meshes) side by side in one process with the default heuristic (sampled), interleaved, and
reports the median wall time of the timed rounds, CPU time, peak heap per fragment (every
allocation counted, as in bench/RESULTS.md) and the tree. Then: naive on 100,000 stacked
triangles (a tree of depth 100,000), the JavaScript BSPs users would otherwise pick (bench/peers,
Node), and a callgrind profile of the exact and double builds of fandisk on one thread.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
import perf_profile  # noqa: E402
import report as fmt  # noqa: E402  (number and table formatting)
import run as base  # noqa: E402  (the main benchmark script: build, machine, sweep)

KERNELS = ["exact", "double", "epeck", "gmpq"]
GOAL_RATIO, GOAL_WORST, GOAL_BYTES, GOAL_ELEPHANT, GOAL_STACK = 1.5, 2.0, 120, 2.5, 60


def build():
    common.run(["cmake", "-S", common.REPO, "-B", base.BUILD, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
              "-DEXBSP_BUILD_BENCH=ON", "-DEXBSP_BUILD_TESTS=OFF"], stdout=subprocess.DEVNULL)
    common.run(["ninja", "-C", base.BUILD, "bench_sweep"])


def stacked_off(path, n):
    """n parallel triangles at z = 0 .. n-1: naive builds a tree of depth n."""
    with open(path, "w") as f:
        f.write(f"OFF\n{3 * n} {n} 0\n")
        for i in range(n):
            f.write(f"0 0 {i}\n1 0 {i}\n0 1 {i}\n")
        for i in range(n):
            f.write(f"3 {3 * i} {3 * i + 1} {3 * i + 2}\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--no-build", action="store_true", help="use the existing bench_sweep binary")
    ap.add_argument("--report-only", action="store_true",
                    help="rewrite the report from bench/out/ (sweep, stacked, peers); the profile is rerun")
    ap.add_argument("--reuse-sweep", action="store_true",
                    help="keep the per-mesh sweep already in bench/out/exact/ (rerun the rest)")
    ap.add_argument("--build-dir", default=base.BUILD, help="where bench/bench_sweep is (default build-bench/)")
    args = ap.parse_args()
    common.ensure_matplotlib()
    base.BUILD = os.path.abspath(args.build_dir)
    outdir = os.path.join(common.HERE, "out", "exact-quick" if args.quick else "exact")
    os.makedirs(outdir, exist_ok=True)
    report_path = os.path.join(outdir, "EXACT_KERNEL.md") if args.quick else os.path.join(common.HERE, "EXACT_KERNEL.md")
    plot_path = os.path.join(outdir, "exact_kernel.png") if args.quick else os.path.join(common.HERE, "plots",
                                                                                            "exact_kernel.png")
    if not args.no_build:
        build()
    meshes = common.available(["joint", "part", "fandisk"] if args.quick else common.CAD + common.ORGANIC)
    repeats = 1 if args.quick else 3
    stack_n = 20000 if args.quick else 100000
    machine = base.machine()

    sweep_out = os.path.join(outdir, "sweep.jsonl")
    stack_path = os.path.join(outdir, f"stacked_{stack_n}.off")
    stack_out = os.path.join(outdir, "stacked.jsonl")
    peers_out = os.path.join(common.HERE, "out", "peers.jsonl")
    reuse = (args.reuse_sweep or args.report_only) and os.path.exists(sweep_out)
    if not reuse:
        if os.path.exists(sweep_out):
            os.remove(sweep_out)
        for name in meshes:
            base.sweep({"time_cap": 120}, sweep_out, "exact", ["mesh:" + common.mesh_path(name)], KERNELS, ["sampled"],
                       repeats, ["--limit", "gmpq=2500", "--repeats-for", "gmpq=1", "--time-cap-for", "gmpq=30"])
    if not args.report_only:
        stacked_off(stack_path, stack_n)
        if os.path.exists(stack_out):
            os.remove(stack_out)
        # Epeck needs minutes here (quadratic naive on a depth-100,000 tree): capped at 120 s,
        # and only its counted build (the timed round would double that).
        base.sweep({"time_cap": 600}, stack_out, "stacked", ["mesh:" + stack_path], ["exact", "epeck"], ["naive"], 1,
                   ["--max-fragments", str(stack_n + 1), "--time-cap-for", "epeck=120", "--repeats-for", "epeck=0"])
        peers_script = os.path.join(common.HERE, "peers", "run.sh")
        if os.path.exists(peers_script):
            try:
                common.run(["bash", peers_script] + [common.mesh_path(m) for m in meshes], timeout=3600)
            except (OSError, subprocess.CalledProcessError, subprocess.TimeoutExpired) as e:
                common.log(f"warning: peers: {e}")
    peers = []
    if os.path.exists(peers_out):
        try:
            peers = [json.loads(l) for l in open(peers_out) if l.strip()]
        except ValueError as e:
            common.log(f"warning: peers: {e}")
    profile_mesh = "joint" if args.quick else "fandisk"
    profile = {k: perf_profile.profile(base.BUILD, outdir, profile_mesh, k) for k in ["exact", "double"]}
    machine["load_end"] = os.getloadavg()

    rows = common.load_jsonl(sweep_out)
    stack_rows = common.load_jsonl(stack_out)
    write_report(report_path, plot_path, machine, meshes, rows, stack_rows, stack_n, peers, profile, profile_mesh,
                 args.quick)
    common.log(f"wrote {report_path}")


def median_wall(r):
    if r.get("status", "ok") != "ok":
        return None
    return r.get("build_seconds_median")


def write_report(path, plot_path, machine, meshes, rows, stack_rows, stack_n, peers, profile, profile_mesh, quick):
    by = {(os.path.basename(r["input"]).replace(".off", ""), r["kernel"]): r for r in rows}
    lines = ["# The exact kernel: what exactness costs", "",
             f"Generated by `bench/exact_kernel.py{' --quick' if quick else ''}` at commit `{machine['commit']}`"
             f"{' (uncommitted changes)' if machine['dirty'] else ''} on {machine['cpu']}, {machine['nproc']} cores, "
             f"{machine['memory_gib']} GiB; load average {machine['load_start'][0]:.1f} at the start and "
             f"{machine['load_end'][0]:.1f} at the end (a shared machine: every figure below is a ratio measured "
             "side by side in one process, kernels interleaved).", ""]
    # Goal table.
    ratios, cpu_ratios, bytes_pf = {}, {}, {}
    table_rows = []
    for m in meshes:
        e, d, p, g = (by.get((m, k)) for k in ["exact", "double", "epeck", "gmpq"])
        if not e or not d:
            continue
        we, wd, wp, wg = (median_wall(r) if r else None for r in (e, d, p, g))
        r = we / wd if we and wd else None
        ratios[m] = r
        if e.get("cpu_seconds_median") and d.get("cpu_seconds_median"):
            cpu_ratios[m] = e["cpu_seconds_median"] / d["cpu_seconds_median"]
        bytes_pf[m] = e.get("peak_heap_bytes_per_fragment")
        table_rows.append([m, "CAD" if m in common.CAD else "organic", fmt.fmt_int(e.get("input_triangles")),
                           fmt.fmt_int(e.get("fragments")), fmt.fmt_int(d.get("fragments")), fmt.fmt_s(we),
                           fmt.fmt_s(wd), fmt.fmt_ratio(r), fmt.fmt_s(wp), fmt.fmt_ratio(wp / we if wp and we else None),
                           fmt.fmt_s(wg) if wg else "–",
                           f"{bytes_pf[m]:.0f}" if bytes_pf[m] else "–",
                           f"{p.get('peak_heap_bytes_per_fragment', 0):.0f}" if p else "–"])
    cad = [ratios[m] for m in meshes if m in common.CAD and ratios.get(m)]
    lines += ["## Goals (issue 10)", ""]
    if cad:
        med, worst = statistics.median(cad), max(cad)
        worst_mesh = max((m for m in meshes if m in common.CAD and ratios.get(m)), key=lambda m: ratios[m])
        lines.append(f"- exact / double build time, same heuristic (sampled), CAD meshes: **median {med:.2f}×** "
                     f"(goal ≤ {GOAL_RATIO}×: {'met' if med <= GOAL_RATIO else 'not met'}), **worst {worst:.2f}×** on "
                     f"{worst_mesh} (goal ≤ {GOAL_WORST}×: {'met' if worst <= GOAL_WORST else 'not met'}).")
        cpu = [cpu_ratios[m] for m in meshes if m in common.CAD and cpu_ratios.get(m)]
        if cpu:
            lines.append(f"  In CPU time: median {statistics.median(cpu):.2f}×.")
    bpf = [b for b in bytes_pf.values() if b]
    if bpf:
        lines.append(f"- peak heap per stored fragment with exact: median {statistics.median(bpf):.0f} B, "
                     f"largest {max(bpf):.0f} B (goal ≤ {GOAL_BYTES} B: "
                     f"{'met' if max(bpf) <= GOAL_BYTES else 'not met'}).")
    el = by.get(("refined_elephant", "exact"))
    if el and median_wall(el):
        lines.append(f"- refined_elephant, default heuristic, {machine['nproc']} cores: **{median_wall(el):.2f} s** "
                     f"wall (goal < {GOAL_ELEPHANT} s: {'met' if median_wall(el) < GOAL_ELEPHANT else 'not met'}).")
    for r in stack_rows:
        w = r.get("counted_build_seconds") if r.get("status", "ok") == "ok" else None
        w = median_wall(r) or w
        status = r.get("status", "ok")
        lines.append(f"- naive on {stack_n:,} stacked triangles (depth {r.get('depth', '?')}), {r['kernel']}: "
                     + (f"**{w:.1f} s**" if w else f"{status} ({r.get('reason', '')})")
                     + (f" (goal < {GOAL_STACK} s: {'met' if w and w < GOAL_STACK else 'not met'})"
                        if r["kernel"] == "exact" else ""))
    lines += ["", "## Per mesh", "",
              "Wall time is the median of the timed rounds; `× double` is exact / double on the same input; "
              "`epeck / exact` is how much faster the new default is than the previous one. Fragments differ "
              "between exact and double because rounded split points make a different (and wrong) tree; "
              "exact, epeck and gmpq build the identical tree (tests/test_exact_kernel.cpp).", ""]
    lines.append(fmt.table(["mesh", "class", "triangles", "fragments (exact)", "fragments (double)", "exact s",
                         "double s", "× double", "epeck s", "epeck / exact", "gmpq s", "B/fragment exact",
                         "B/fragment epeck"], table_rows))
    # Peers.
    lines += ["", "## Peers: JavaScript BSPs with an epsilon (bench/peers)", ""]
    if peers:
        pby = {}
        for r in peers:
            pby[(os.path.basename(r.get("mesh", "")).replace(".off", ""), r.get("tool"))] = r
        tools = sorted({r.get("tool") for r in peers if r.get("tool")})
        hdr = ["mesh", "exact s", "exact fragments"]
        for t in tools:
            hdr += [f"{t} s", f"{t} triangles", f"exact faster than {t}"]
        prow, faster = [], {t: [0, 0] for t in tools}
        for m in meshes:
            e = by.get((m, "exact"))
            we = median_wall(e) if e else None
            row = [m, fmt.fmt_s(we), fmt.fmt_int(e.get("fragments")) if e else "–"]
            for t in tools:
                r = pby.get((m, t), {})
                s = r.get("build_seconds")
                row += [fmt.fmt_s(s) if s else (r.get("error", "–")[:30] if r else "–"),
                        fmt.fmt_int(r.get("pieces_triangulated")) if r.get("pieces_triangulated") is not None else "–",
                        (f"{s / we:.1f}×" if s and we else "–")]
                if s and we and m in common.CAD:
                    faster[t][1] += 1
                    faster[t][0] += s > we
            prow.append(row)
        versions = ", ".join(sorted({f"{r['tool']} {r.get('version', '')}" for r in peers if r.get("tool")}))
        lines += [f"Tools: {versions}, run by Node {machine.get('node', '')} on the same machine in the same run "
                  "(best of 3 builds each). Pieces are polygons stored in the tree, fan-triangulated for comparison "
                  "with exbsp's triangles.", ""]
        lines.append(fmt.table(hdr, prow))
        for t in tools:
            lines.append(f"- exact faster than {t} on {faster[t][0]} of {faster[t][1]} CAD meshes "
                         "(goal: all).")
    else:
        lines.append("Skipped: node/npm missing or bench/peers absent (see bench/peers/README.md).")
    # Profile.
    lines += ["", f"## Where the time goes ({profile_mesh}, one thread, perf samples, self time)", ""]
    for k in ["exact", "double"]:
        pk = profile.get(k, {})
        if pk.get("rows"):
            lines.append(f"{k}:")
            lines.append("")
            for item in pk["rows"][:8]:
                lines.append(f"- {item['percent']:.1f}%  `{fmt.short_function(item['function'])[:110]}`")
            lines.append("")
        else:
            lines.append(f"{k}: not available ({pk.get('error', 'perf missing')})")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    plot(plot_path, meshes, ratios, peers, by)


def plot(path, meshes, ratios, peers, by):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    ms = [m for m in meshes if ratios.get(m)]
    if not ms:
        return
    fig, ax = plt.subplots(figsize=(9, 4))
    xs = range(len(ms))
    ax.bar([x - 0.2 for x in xs], [ratios[m] for m in ms], 0.4, label="exact / double", color="#c44e52")
    pr = []
    for m in ms:
        e = median_wall(by[(m, "exact")])
        s = next((r.get("build_seconds") for r in peers
                  if r.get("tool") == "csg.js" and os.path.basename(r.get("mesh", "")).startswith(m + ".")), None)
        pr.append(s / e if s and e else 0)
    if any(pr):
        ax.bar([x + 0.2 for x in xs], pr, 0.4, label="csg.js / exact", color="#4c72b0")
    ax.axhline(1.5, color="#444", ls="--", lw=1, label="goal 1.5×")
    ax.axhline(1.0, color="#999", lw=0.8)
    ax.set_xticks(list(xs))
    ax.set_xticklabels(ms, rotation=40, ha="right")
    ax.set_ylabel("time ratio (same machine, same run)")
    ax.set_title("exbsp exact kernel: cost over plain double, and csg.js over exact")
    ax.legend()
    fig.tight_layout()
    os.makedirs(os.path.dirname(path), exist_ok=True)
    fig.savefig(path, dpi=110)


if __name__ == "__main__":
    main()
