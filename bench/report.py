# SPDX-License-Identifier: LGPL-3.0-or-later
"""bench/RESULTS.md from the raw data of a run: tables, readings (every figure computed from the
data, none typed in) and the method notes. No measurement and no plotting here (run.py and
plots.py); every function takes the loaded rows and returns markdown, so the report can be
rewritten from old raw data (`bench/run.py --report-only`) and unit-checked (test_report.py).

Kernels: `exact` is the default (docs/contract.md "Command line"); the goals and readings are about it, with
Epeck (CGAL's lazy exact kernel, the same tree) beside it."""
import json
import os
import re

import common
import perf_profile
from common import CAD, DEFAULT_KERNEL, HEURISTICS, INEXACT, KERNELS, ORGANIC


# ----------------------------------------------------------------------------------------------
# Formatting


def fmt_s(x):
    if x is None:
        return "—"
    if x >= 100:
        return f"{x:.0f} s"
    if x >= 10:
        return f"{x:.1f} s"
    if x >= 0.1:
        return f"{x:.2f} s"
    if x >= 0.001:
        return f"{x * 1000:.1f} ms"
    return f"{x * 1e6:.0f} µs"


def fmt_ratio(x):
    return "—" if x is None else f"{x:.2f}×"


def fmt_int(x):
    return "—" if x is None else f"{round(x):,}".replace(",", " ")


def fmt_mb(b):
    return "—" if b is None else f"{b / 2**20:.1f}"


def fmt_range(s, fmt=fmt_int):
    """median (min–max) of a spread; the range only when it is not a single value."""
    if s is None:
        return "—"
    med, lo, hi = s
    return fmt(med) if lo == hi else f"{fmt(med)} ({fmt(lo)}–{fmt(hi)})"


def table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    for r in rows:
        out.append("| " + " | ".join(str(c) for c in r) + " |")
    return "\n".join(out)


def status_cell(r):
    """Why a row has no figures ("skipped", "> 60 s", ...), or None when it has them."""
    if r is None:
        return "—"
    if r["status"] == "skipped":
        return "skipped"
    if r["status"] == "timeout":
        return f"> {r['time_cap']:.0f} s"
    if r["status"] == "limit":
        return "> 4M fragments (stopped)"
    if r["status"] != "ok":
        return r["status"]
    return None


def ratio_summary(ratios):
    """{median, geo, min: (mesh, r), max: (mesh, r), within: [meshes <= 1.5], count} of (mesh, r)."""
    vals = [v for _, v in ratios]
    return {"median": common.median(vals), "geo": common.geometric_mean(vals), "count": len(ratios),
            "min": min(ratios, key=lambda x: x[1]), "max": max(ratios, key=lambda x: x[1]),
            "within": [m for m, v in ratios if v <= 1.5]}


# ----------------------------------------------------------------------------------------------
# 1. What accuracy costs


def accuracy_ratios(rows, field="build_seconds_median"):
    """{mesh: {kernel: time / double time}} (None where either build has no time)."""
    by = {(r["input"], r["kernel"]): r for r in rows}
    out = {}
    for (m, k), r in by.items():
        d = by.get((m, "double"))
        t, dt = r.get(field), d.get(field) if d else None
        out.setdefault(m, {})[k] = t / dt if t and dt else None
    return out


def section_accuracy(rows, cfg, plot_rel):
    by = {(r["input"], r["kernel"]): r for r in rows}
    meshes = [m for m in cfg["corpus_cad"] + cfg["corpus_organic"] if any(k[0] == m for k in by)]
    kernels = [k for k in KERNELS if any(r["kernel"] == k for r in rows)]
    lines = ["## 1. What accuracy costs (heuristic `sampled`, seed 0)", ""]
    lines.append(
        f"Per mesh, the kernels ({', '.join(kernels)}; `{DEFAULT_KERNEL}` is the default) are built side by "
        f"side in one process: first one counted build each (heap accounting, statistics, exact defect "
        f"checks), then {cfg['repeats']} round(s) that build once with every kernel in turn; time = median "
        f"wall time of those rounds (CPU time in the raw data). `gmpq` runs only on meshes of at most "
        f"{cfg['gmpq_max']} triangles (it is about two orders of magnitude slower than the other exact "
        f"kernels); each build is capped at {cfg['time_cap']} s. Memory: peak live heap bytes during the "
        f"build (operator new and GMP allocations counted by their malloc_usable_size), divided by the "
        f"fragments.")
    lines.append("")
    hdr = ["mesh", "class", "triangles", "kernel", "fragments", "splits", "depth", "build s (wall)", "× double",
           "CPU s", "× double (CPU)", "peak heap MB", "B/fragment"]
    ratios, cpu_ratios = accuracy_ratios(rows), accuracy_ratios(rows, "cpu_seconds_median")
    trows = []
    for m in meshes:
        for k in KERNELS:
            r = by.get((m, k))
            if r is None:
                continue
            st = status_cell(r)
            if st:
                trows.append([m, common.mesh_class(m), fmt_int(r["triangles"]), k, st] + [""] * 8)
                continue
            trows.append([m, common.mesh_class(m), fmt_int(r["triangles"]), k, fmt_int(r.get("fragments")),
                          fmt_int(r.get("splits")), fmt_int(r.get("depth")), fmt_s(r.get("build_seconds_median")),
                          fmt_ratio(ratios[m].get(k)), fmt_s(r.get("cpu_seconds_median")),
                          fmt_ratio(cpu_ratios[m].get(k)), fmt_mb(r.get("peak_heap_bytes")),
                          f"{r.get('peak_heap_bytes_per_fragment', 0):.0f}"])
    lines.append(table(hdr, trows))
    lines.append("")

    # Goal: the default kernel within 1.5x of double on the CAD corpus.
    summary = {}
    cad = [(m, ratios[m][DEFAULT_KERNEL]) for m in meshes if m in CAD and ratios.get(m, {}).get(DEFAULT_KERNEL)]
    organic = [(m, ratios[m][DEFAULT_KERNEL]) for m in meshes
               if m in ORGANIC and ratios.get(m, {}).get(DEFAULT_KERNEL)]
    epeck = [(m, ratios[m]["epeck"]) for m in meshes if m in CAD and ratios.get(m, {}).get("epeck")]
    if cad:
        summary.update({"cad_" + k: v for k, v in ratio_summary(cad).items()})
        summary["cad_cpu_median"] = common.median(cpu_ratios[m].get(DEFAULT_KERNEL) for m, _ in cad)
    # Fragments per second: is the extra time the kernel or the different tree?
    frag_ratio = []
    for m in meshes:
        d, e = by.get((m, "double")), by.get((m, DEFAULT_KERNEL))
        if d and e and d.get("build_seconds_median") and e.get("build_seconds_median") and d.get("fragments"):
            frag_ratio.append((m, e["fragments"] / d["fragments"],
                               (e["build_seconds_median"] / e["fragments"]) /
                               (d["build_seconds_median"] / d["fragments"])))
    summary["frag_ratio"] = frag_ratio

    lines.append(f"![exact/double time ratio per mesh]({plot_rel}/accuracy_ratio.png)")
    lines.append("")
    if cad:
        e = ratio_summary(epeck) if epeck else None
        lines.append(
            f"**Reading.** Goal: the default exact build (`{DEFAULT_KERNEL}`) within 1.5× of the double build on "
            f"the CAD corpus. Where we stand: {DEFAULT_KERNEL}/double median {summary['cad_median']:.2f}× in wall "
            f"time (geometric mean {summary['cad_geo']:.2f}×; median of the CPU-time ratios "
            f"{summary['cad_cpu_median'] or 0:.2f}×, less exposed to the other jobs on the machine) over "
            f"{summary['cad_count']} CAD meshes, from {summary['cad_min'][1]:.2f}× ({summary['cad_min'][0]}) to "
            f"{summary['cad_max'][1]:.2f}× ({summary['cad_max'][0]}); within 1.5×: "
            f"{', '.join(summary['cad_within']) if summary['cad_within'] else 'none'}. "
            + (f"Epeck, the same tree with CGAL's lazy kernel: median {e['median']:.2f}×. " if e else "")
            + ("Organic meshes: " + ", ".join(f"{m} {v:.2f}×" for m, v in organic) + ". " if organic else "")
            + "The kernels do not build the same tree: rounded split points (double, Epick) land off "
            "their planes, so later planes see them straddling and split them again, and the sampled "
            "heuristic's scores change with the signs; the double tree has "
            + (", ".join(f"{m} {1 / fr:.1f}×" for m, fr, _ in frag_ratio[:4]) if frag_ratio else "more")
            + f" the {DEFAULT_KERNEL} fragments. Per fragment, {DEFAULT_KERNEL} costs "
            + (", ".join(f"{m} {pf:.1f}×" for m, _, pf in frag_ratio[:4]) if frag_ratio else "—")
            + " the double kernel's time.")
        lines.append("")
    lines += defects_text(rows, meshes, cfg, plot_rel)
    return "\n".join(lines), summary


def defects_totals(rows):
    """Per kernel: sums of fragments, off plane, misclassified, non-finite, order errors and
    occluding pairs over every checked mesh."""
    tot = {}
    for r in rows:
        d = r.get("defects")
        if not d:
            continue
        t = tot.setdefault(r["kernel"], {"frag": 0, "off": 0, "order": 0, "occ": 0, "nf": 0, "mis": 0})
        t["frag"] += d["fragments"]
        t["off"] += d["off_plane"]
        t["order"] += d["order_errors"]
        t["occ"] += d["occluding_pairs"]
        t["nf"] += d.get("non_finite", 0)
        t["mis"] += d["misclassified"]
    return tot


def defects_text(rows, meshes, cfg, plot_rel):
    by = {(r["input"], r["kernel"]): r for r in rows}
    eyes = next((r["defects"].get("eyes") for r in rows if r.get("defects")), 4)
    lines = ["### Defects of the inexact kernels (exact checks, no epsilon)", ""]
    lines.append(
        "Counted on the tree of the counted build by the tests' exact tree checker "
        "(tests/support/tree_checker.h; definitions: bench/defects.h). Order errors: from "
        f"{eyes} eyes around the mesh, rays through up to {cfg['order_samples']} sample points per eye "
        "(4 per fragment on small trees, else the centroids of every k-th fragment) are intersected exactly with every fragment they cross; each pair of "
        "fragments crossed at different depths is an occluding pair (the nearer hides the farther "
        "there), and an error when the back-to-front order draws the nearer first. Shown as errors / "
        "occluding pairs. The Epeck rows are the checker's control (up to "
        f"{cfg['control_max']} triangles, {cfg['exact_order_samples']} rays per eye): they must be 0.")
    lines.append("")
    hdr = ["mesh", "kernel", "fragments", "non-finite", "off plane", "not tiling / split sources",
           "misclassified", "order errors / occluding pairs", "check s"]
    drows = []
    for m in meshes:
        for k in INEXACT + ["epeck"]:
            r = by.get((m, k))
            if not r or "defects" not in r:
                continue
            d = r["defects"]
            drows.append([m, k, fmt_int(d["fragments"]), fmt_int(d.get("non_finite", 0)), fmt_int(d["off_plane"]),
                          f"{fmt_int(d['not_tiling'])} / {fmt_int(d['split_sources'])}", fmt_int(d["misclassified"]),
                          f"{fmt_int(d['order_errors'])} / {fmt_int(d['occluding_pairs'])}", fmt_s(d["seconds"])])
    lines.append(table(hdr, drows))
    lines.append("")
    lines.append(f"![defects per 1000 fragments and order errors per 1000 pairs]({plot_rel}/accuracy_defects.png)")
    lines.append("")
    tot = defects_totals(rows)
    parts = []
    for k in INEXACT:
        t = tot.get(k)
        if t and t["frag"]:
            parts.append(f"{k}: {100 * t['off'] / t['frag']:.0f}% of fragments off their plane, "
                         f"{100 * t['mis'] / t['frag']:.0f}% misclassified, {fmt_int(t['nf'])} non-finite, "
                         f"{fmt_int(t['order'])} order errors in {fmt_int(t['occ'])} occluding pairs "
                         f"({100 * t['order'] / max(t['occ'], 1):.2f}%)")
    e = tot.get("epeck")
    if parts:
        lines.append(
            "**Reading.** Over all checked meshes, " + "; ".join(parts) + ". "
            + (f"The Epeck control: {fmt_int(e['off'] + e['mis'] + e['order'] + e['nf'])} defects in "
               f"{fmt_int(e['frag'])} fragments. " if e and e["frag"] else "")
            + "Most rounded split points are off their plane (a rounded point on a plane is the exception), "
            "which is harmless on screen; what shows is the order errors: a fragment drawn over one that "
            "hides it. Epick's exact predicates remove the wrong signs on input points but not on its own "
            "rounded constructions, so it still misorders.")
        lines.append("")
    return lines


# ----------------------------------------------------------------------------------------------
# 2. Heuristics


def heuristic_cell(rows):
    """'fragments (min–max) / depth / time' over the seeds of one size, or why it is missing."""
    ok = [r for r in rows if r["status"] == "ok"]
    if not ok:
        return status_cell(rows[0]) if rows else "—"
    return (f"{fmt_range(common.spread(ok, 'fragments'))} / {fmt_int(common.median(r['depth'] for r in ok))} / "
            f"{fmt_s(common.median(r.get('build_seconds_median') for r in ok))}")


def heuristic_slopes(rows):
    """{heuristic: (sizes, fragments slope, time slope, depth slope)} fitted to the medians over seeds."""
    out = {}
    for h in HEURISTICS:
        sizes = common.by_size(rows, h)
        xs = list(sizes)
        med = {f: [common.median(r.get(f) for r in sizes[n]) for n in xs]
               for f in ("fragments", "build_seconds_median", "depth")}
        out[h] = (xs, common.slope(xs, med["fragments"]), common.slope(xs, med["build_seconds_median"]),
                  common.slope(xs, med["depth"]))
    return out


def section_heuristics(soup_rows, stick_rows, corpus_rows, accuracy_rows, cfg, plot_rel):
    seeds = sorted({r.get("seed", 0) for r in soup_rows + stick_rows}) or [0]
    lines = [f"## 2. Naive vs min-split vs sampled vs random (`{DEFAULT_KERNEL}` kernel)", ""]
    lines.append(
        "`naive` = first triangle of the list; `min-split` = the plane straddling the fewest others "
        "(exact count, early exit, OpenMP); `sampled` = 16 seeded candidates scored on a sample of 512; "
        "`random` = a seeded random splitter. Generated inputs (tests/support/inputs.h): random soups of n "
        "triangles at constant density (one per unit volume, neighbours intersect), and the sticks grid "
        "(k + k sticks in two layers, 4k triangles), the quadratic worst case of autopartitions. "
        f"Every size runs with {len(seeds)} seeds ({', '.join(map(str, seeds))}): seed s is the soup's seed "
        "and the heuristic's, so a random soup changes with s and the sticks do not (there only sampled "
        "and random vary). Cells: median fragments over the seeds (min–max), median depth, median time "
        f"(each seed: the median of {cfg['heuristic_repeats']} timed build(s) after a counted one).")
    lines.append("")
    slopes = {}
    for title, rows, key in [("Random soups", soup_rows, "soup"), ("Sticks", stick_rows, "sticks")]:
        lines.append(f"### {title}")
        lines.append("")
        sizes = sorted({r["triangles"] for r in rows})
        hdr = ["n (triangles)"] + [f"{h} fragments / depth / s" for h in HEURISTICS]
        trows = []
        for n in sizes:
            trows.append([fmt_int(n)] + [heuristic_cell([x for x in rows if x["triangles"] == n and x["heuristic"] == h])
                                         for h in HEURISTICS])
        lines.append(table(hdr, trows))
        lines.append("")
        srows = []
        for h, (xs, sf, st, sd) in heuristic_slopes(rows).items():
            slopes[(key, h)] = (sf, st, sd)
            srows.append([h, f"{xs[0] if xs else '—'}–{xs[-1] if xs else '—'}",
                          "—" if sf is None else f"{sf:.2f}", "—" if st is None else f"{st:.2f}",
                          "—" if sd is None else f"{sd:.2f}"])
        lines.append(table(["heuristic", "n range", "slope: fragments", "slope: build time", "slope: depth"], srows))
        lines.append("")
        lines.append(f"![{title}]({plot_rel}/heuristics_{key}.png)")
        lines.append("")

    def s(key, h, i):
        v = slopes.get((key, h), (None, None, None))[i]
        return "—" if v is None else f"{v:.2f}"
    lines.append(
        "**Reading.** Slopes are least-squares fits of log y on log n over the medians of the sizes each "
        "heuristic ran (y ∝ n^slope); the error bars of the plots are the min–max over the seeds. "
        "Textbook claims: naive O(n³) work, min-split O(n²) (its selection alone counts straddlers for all "
        "pairs of the list), and Θ(n²) fragments for the sticks, the autopartition lower bound. Random "
        f"soups: fragments grow with slope {s('soup', 'naive', 0)} (naive), {s('soup', 'min-split', 0)} "
        f"(min-split), {s('soup', 'sampled', 0)} (sampled), {s('soup', 'random', 0)} (random). Build time: "
        f"naive {s('soup', 'naive', 1)}, min-split {s('soup', 'min-split', 1)}, sampled "
        f"{s('soup', 'sampled', 1)}, random {s('soup', 'random', 1)}. Sticks: fragments slope naive "
        f"{s('sticks', 'naive', 0)}, min-split {s('sticks', 'min-split', 0)}, sampled {s('sticks', 'sampled', 0)}, "
        f"random {s('sticks', 'random', 0)}. Above 2 (the bound for convex-polygon fragments) means the "
        "contract's triangles: a triangle cut by m parallel planes one after the other becomes Θ(m²) "
        "triangles, not m + 1 convex pieces. Depth slopes: "
        f"naive {s('sticks', 'naive', 2)}, min-split {s('sticks', 'min-split', 2)}, "
        f"sampled {s('sticks', 'sampled', 2)}, random {s('sticks', 'random', 2)}.")
    lines.append("")
    corpus_text, summary = corpus_heuristics(corpus_rows, accuracy_rows, cfg, plot_rel)
    return "\n".join(lines + corpus_text), summary


def corpus_rows_by_heuristic(corpus_rows, accuracy_rows):
    """{(mesh, heuristic): row}: the corpus sweep plus the default kernel's sampled run of section 1."""
    rows = corpus_rows + [r for r in accuracy_rows if r["kernel"] == DEFAULT_KERNEL]
    return {(r["input"], r["heuristic"]): r for r in rows}


def fragments_per_triangle(r):
    return r["fragments"] / max(r["triangles"] - r.get("degenerate_input", 0), 1)


def corpus_heuristics(corpus_rows, accuracy_rows, cfg, plot_rel):
    lines = ["### Corpus: fragments per input triangle", ""]
    lines.append(f"In parentheses: seconds of the counted build (one build, heap accounting on; the time "
                 f"cap is {cfg['corpus_cap']} s); naive and random run only up to {cfg['naive_random_max']} "
                 f"triangles, min-split up to {cfg['min_split_max']}. The sampled column is the "
                 f"`{DEFAULT_KERNEL}` run of section 1.")
    lines.append("")
    by = corpus_rows_by_heuristic(corpus_rows, accuracy_rows)
    meshes = [m for m in cfg["corpus_cad"] + cfg["corpus_organic"] if any(k[0] == m for k in by)]
    hdr = ["mesh", "class", "triangles"] + [f"{h} frag/tri (s)" for h in HEURISTICS] + ["best"]
    trows, best = [], {}
    for m in meshes:
        tri = next((by[(m, h)]["triangles"] for h in HEURISTICS if (m, h) in by), None)
        row = [m, common.mesh_class(m), fmt_int(tri)]
        cand = []
        for h in HEURISTICS:
            r = by.get((m, h))
            st = status_cell(r)
            if st:
                row.append(st)
                continue
            fpt = fragments_per_triangle(r)
            cand.append((fpt, h))
            row.append(f"{fpt:.2f} ({fmt_s(r.get('counted_build_seconds'))})")
        b = min(cand) if cand else None
        best[m] = b
        row.append(f"{b[1]} {b[0]:.2f}" if b else "—")
        trows.append(row)
    lines.append(table(hdr, trows))
    lines.append("")
    lines.append(f"![fragments per input triangle]({plot_rel}/heuristics_corpus.png)")
    lines.append("")
    cad_best = [(m, best[m]) for m in meshes if m in CAD and best.get(m)]
    met = [m for m, b in cad_best if b[0] <= 1.3]
    geo = common.geometric_mean(fragments_per_triangle(by[(m, "sampled")]) for m in meshes
                                if m in CAD and (m, "sampled") in by and by[(m, "sampled")]["status"] == "ok")
    if cad_best:
        lines.append(
            "**Reading.** Goal: a heuristic with at most 1.3 fragments per input triangle on the CAD corpus. "
            "Best per CAD mesh: " + ", ".join(f"{m} {b[1]} {b[0]:.2f}" for m, b in cad_best) + ". "
            f"At most 1.3 on {len(met)} of {len(cad_best)} CAD meshes" + (f" ({', '.join(met)})" if met else "") + "; "
            + (f"sampled (the default) averages {geo:.2f} (geometric mean) on CAD. " if geo else "")
            + f"min-split runs only up to {cfg['min_split_max']} triangles (time cap {cfg['corpus_cap']} s).")
        lines.append("")
    return lines, {"cad_best": cad_best, "cad_met": met, "sampled_geo": geo}


# ----------------------------------------------------------------------------------------------
# 3. Rendering, 4. micro-benchmarks


def svg_frame_seconds(r):
    """The SVG frame: the same order and transform+clip as the PNG frame, then svg and svg write."""
    s = r["stage_seconds_median"]
    return s.get("order", 0) + s.get("transform+clip", 0) + s.get("svg", 0) + s.get("svg write", 0)


def svg_ratio(r):
    png = r.get("png_frame_seconds")
    return f"{svg_frame_seconds(r) / png:.1f}×" if png else "—"


def section_render(rows, plot_rel):
    lines = ["## 3. Rendering: per-frame time", ""]
    if not rows:
        lines.append("bench_render produced no results in this run.")
        return "\n".join(lines)
    kernel = rows[0].get("kernel", DEFAULT_KERNEL)
    lines.append(
        f"bench_render: one `{kernel}` build (sampled), then per frame the pipeline stages of view/stages.h "
        "for a fixed perspective camera at 1024×768: order (back-to-front traversal), transform+clip, "
        "raster (painter's algorithm, no z-buffer) for the PNG frame; svg (document string) and svg write "
        "(atomic file) for the SVG frame, which needs the same order and transform+clip. Median over the "
        "frames. OSMesa: Mesa's off-screen OpenGL (llvmpipe) draws the INPUT triangles with a z-buffer, same "
        "matrices and face colours, from a vertex buffer (glClear + glDrawArrays + glFinish). Pixel "
        "agreement: share of pixels with the same colour.")
    lines.append("")
    hdr = ["mesh", "triangles", "fragments", "build s", "order", "transform+clip", "raster", "PNG frame",
           "svg", "svg write", "SVG / PNG frame", "SVG MB", "OSMesa frame", "OSMesa 1st", "pixel agreement"]
    trows = []
    for r in rows:
        s = r["stage_seconds_median"]
        g = r.get("osmesa", {})
        trows.append([r["input"], fmt_int(r["triangles"]), fmt_int(r["fragments"]), fmt_s(r["build_seconds"]),
                      fmt_s(s.get("order")), fmt_s(s.get("transform+clip")), fmt_s(s.get("raster")),
                      fmt_s(r["png_frame_seconds"]), fmt_s(s.get("svg")), fmt_s(s.get("svg write")),
                      svg_ratio(r), f"{r['svg_bytes'] / 2**20:.1f}", fmt_s(g.get("frame_seconds_median")),
                      fmt_s(g.get("first_frame_seconds")),
                      f"{100 * g['pixel_agreement']:.2f}%" if "pixel_agreement" in g else "—"])
    lines.append(table(hdr, trows))
    lines.append("")
    renderer = next((r["osmesa"].get("renderer") for r in rows if r.get("osmesa", {}).get("renderer")), "n/a")
    lines.append(f"OpenGL renderer: `{renderer}`.")
    lines.append("")
    lines.append(f"![per-frame time]({plot_rel}/render_frame.png)")
    lines.append("")
    parts = []
    for r in rows:
        g = r.get("osmesa", {})
        if g.get("frame_seconds_median"):
            parts.append(f"{r['input']}: the painter's PNG frame (order + transform+clip + raster) takes "
                         f"{fmt_s(r['png_frame_seconds'])} for {fmt_int(r['fragments'])} fragments, "
                         f"{r['png_frame_seconds'] / g['frame_seconds_median']:.1f}× OSMesa's "
                         f"{fmt_s(g['frame_seconds_median'])} for {fmt_int(r['triangles'])} triangles")
    if parts:
        svg_parts = [f"{r['input']} {svg_ratio(r)} ({fmt_s(svg_frame_seconds(r))}, {r['svg_bytes'] / 1000:.0f} KB)"
                     for r in rows if r.get("png_frame_seconds")]
        lines.append("**Reading.** " + "; ".join(parts) + ". The build is a one-off per scene; a frame for a new "
                     "eye repeats only the traversal and the rest. The SVG frame (order, transform+clip, visible "
                     "regions with visible and hidden edges, writing) costs, against the PNG frame of the same view: "
                     + "; ".join(svg_parts) + ". The goal is at most 5×: the visible regions (Clipper Booleans per "
                     "fragment) are where the time goes.")
        lines.append("")
    return "\n".join(lines)


def section_micro(data):
    """Section 4 from bench_micro's JSON (a dict; None when it did not run)."""
    lines = ["## 4. Micro-benchmarks (bench_micro, Google Benchmark)", ""]
    if not data:
        lines.append("bench_micro produced no results in this run.")
        return "\n".join(lines), {}
    lines.append("CPU time per iteration (Google Benchmark's cpu_time: less exposed than wall time to "
                 "the other jobs on the machine). Orientation: 1024 sets of four double points, `/0` in "
                 "general position (uniform in the unit cube), `/1` exactly coplanar (dyadic points on "
                 "z = x + y); `fast` is exbsp's certified double filter (fast_orientation.h), `undecided` "
                 "the share it leaves to the exact predicate. Split: a triangle straddling a plane, no "
                 "vertex on it. Order: traversal of a 2000-triangle soup's tree. Build: a 300-triangle "
                 "soup, sampled, 1 thread.")
    lines.append("")
    trows, cpu = [], {}
    for b in data.get("benchmarks", []):
        unit = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1}[b.get("time_unit", "ns")]
        t = b["cpu_time"] * unit
        cpu[b["name"]] = t
        counters = ", ".join(f"{k} {b[k]:.3g}" for k in ("undecided", "fragments") if k in b)
        trows.append([b["name"] + (f" ({b['label']})" if b.get("label") else ""),
                      f"{t * 1e9:.1f} ns" if t < 1e-6 else fmt_s(t), counters])
    lines.append(table(["benchmark", "CPU time per iteration", "counters"], trows))
    lines.append("")

    def ratio(a, b):
        return f"{cpu[a] / cpu[b]:.1f}×" if a in cpu and b in cpu and cpu[b] else "—"
    lines.append(
        "**Reading.** Relative to a plain double orientation: in general position the certified "
        f"filter costs {ratio('BM_orientation/fast/0', 'BM_orientation/double/0')}, Epick "
        f"{ratio('BM_orientation/epick/0', 'BM_orientation/double/0')}, Epeck "
        f"{ratio('BM_orientation/epeck/0', 'BM_orientation/double/0')}, Gmpq "
        f"{ratio('BM_orientation/gmpq/0', 'BM_orientation/double/0')}; on exactly coplanar points "
        f"every filter fails and the exact fallback decides: Epick "
        f"{ratio('BM_orientation/epick/1', 'BM_orientation/double/1')}, Epeck "
        f"{ratio('BM_orientation/epeck/1', 'BM_orientation/double/1')}. One split: Epeck "
        f"{ratio('BM_split_triangle/epeck', 'BM_split_triangle/double')} and Gmpq "
        f"{ratio('BM_split_triangle/gmpq', 'BM_split_triangle/double')} the double split. Whole small "
        f"build: Epeck {ratio('BM_build/epeck/300', 'BM_build/double/300')}, Gmpq "
        f"{ratio('BM_build/gmpq/300', 'BM_build/double/300')} the double build (same tree here).")
    lines.append("")
    return "\n".join(lines), cpu


# ----------------------------------------------------------------------------------------------
# 5. Profile


def section_profile(prof):
    """Section 5 from perf profiles {"mesh", kernel: {"rows", "categories"} or {"error"}}."""
    lines = ["## 5. Where an exact build spends its time (perf)", ""]
    main = prof.get(DEFAULT_KERNEL, {}) if prof else {}
    if not prof or "rows" not in main:
        lines.append("perf did not run: " + json.dumps(main.get("error") if main else prof))
        return "\n".join(lines)
    kernels = [k for k in (DEFAULT_KERNEL, "epeck", "double") if "rows" in prof.get(k, {})]
    lines.append(
        f"`perf record` of timed single-threaded builds of {prof['mesh']} (sampled) per kernel; self time, "
        "sampled (perf, not callgrind: valgrind does not honour the rounding-mode switches of the interval "
        "filters, so under valgrind the exact kernels' predicates change). Categories by where the code "
        "lives: the shared object (GMP, MPFR, libc, libstdc++) and, inside the binary, the function's "
        "outermost namespace (bench/perf_profile.py).")
    lines.append("")
    cats = {k: prof[k]["categories"] for k in kernels}
    crows = [[name] + [f"{cats[k].get(name, 0):.1f}%" for k in kernels] for name in perf_profile.CATEGORIES]
    lines.append(table(["category"] + [f"{k} (share of its build)" for k in kernels], crows))
    lines.append("")
    for k in kernels:
        lines.append(f"### {k}, self time (top 12)")
        lines.append("")
        rows = [[f"{r['percent']:.1f}%", os.path.basename(r["dso"]), "`" + short_function(r["function"]) + "`"]
                for r in prof[k]["rows"][:12]]
        lines.append(table(["share", "object", "function"], rows))
        lines.append("")
    c = cats[DEFAULT_KERNEL]
    top = prof[DEFAULT_KERNEL]["rows"][0] if prof[DEFAULT_KERNEL]["rows"] else None
    exact_arith = c.get(perf_profile.CATEGORIES[0], 0) + c.get(perf_profile.CATEGORIES[1], 0)
    lines.append(
        f"**Reading.** The `{DEFAULT_KERNEL}` build spends {c.get('exbsp', 0):.0f}% of its time in exbsp's own "
        f"code, {exact_arith:.0f}% in rational arithmetic (GMP, MPFR), "
        f"{c.get(perf_profile.CATEGORIES[2], 0) + c.get(perf_profile.CATEGORIES[3], 0):.0f}% in the C and C++ "
        f"runtimes (malloc, free, memcpy, operator new) and {c.get(perf_profile.CATEGORIES[4], 0):.0f}% in CGAL's templates"
        + (f"; the most expensive function is `{short_function(top['function'])}` ({top['percent']:.1f}%)" if top else "")
        + "." + (f" Epeck, for the same tree: {prof['epeck']['categories'].get(perf_profile.CATEGORIES[0], 0):.0f}% "
                 "in GMP." if "epeck" in kernels else ""))
    lines.append("")
    return "\n".join(lines)


def short_function(fn):
    fn = fn.replace("CGAL::Lazy_kernel_generic_base", "LazyKernel")
    if len(fn) > 140:
        fn = fn[:137] + "..."
    return fn.replace("|", "\\|")


# ----------------------------------------------------------------------------------------------
# The whole report


# Issue 10's goals for the default kernel: build time over double (median, worst), bytes per
# fragment, refined_elephant on 2 cores, naive on the stacked input, faster than csg.js.
GOAL_RATIO, GOAL_WORST, GOAL_BYTES, GOAL_ELEPHANT, GOAL_STACK = 1.5, 2.0, 120, 2.5, 60


def ok_wall(r):
    """The median wall time of a row that finished, else None."""
    return r.get("build_seconds_median") if r and r.get("status", "ok") == "ok" else None


def peers_by(peers):
    """{(mesh name, tool): row} of the peers' JSON lines."""
    return {(os.path.basename(r.get("mesh", "")).replace(".off", ""), r.get("tool")): r for r in peers
            if r.get("tool")}


def peer_tools(peers):
    return sorted({r["tool"] for r in peers if r.get("tool")})


def peer_ratios(acc_rows, peers):
    """{(mesh, tool): the tool's build time / the default kernel's} where both finished
    (over 1: exbsp faster)."""
    wall = {r["input"]: ok_wall(r) for r in acc_rows if r["kernel"] == DEFAULT_KERNEL}
    out = {}
    for (m, tool), r in peers_by(peers).items():
        s, we = r.get("build_seconds"), wall.get(m)
        if s and we:
            out[(m, tool)] = s / we
    return out


def stacked_seconds(r):
    """The default kernel's time on the stacked input: the timed round, else the counted build."""
    if r.get("status", "ok") != "ok":
        return None
    return r.get("build_seconds_median") or r.get("counted_build_seconds")


def goals_table(acc_sum, heur_sum, acc_rows, stacked=(), peers=()):
    """The goal table at the top of the report (issue 10's goals first)."""
    goals = []
    d = DEFAULT_KERNEL
    if acc_sum.get("cad_count"):
        goals.append([f"`{d}` build / `double` build, same heuristic (sampled), CAD corpus: median ≤ {GOAL_RATIO}×",
                      f"median {acc_sum['cad_median']:.2f}× wall ({acc_sum.get('cad_cpu_median') or 0:.2f}× CPU), "
                      f"{len(acc_sum['cad_within'])} of {acc_sum['cad_count']} meshes within",
                      "met" if acc_sum["cad_median"] <= GOAL_RATIO else "not met"])
        worst_m, worst = acc_sum["cad_max"]
        goals.append([f"… and worst ≤ {GOAL_WORST}×", f"{worst:.2f}× ({worst_m})",
                      "met" if worst <= GOAL_WORST else "not met"])
    bpf = [(r["input"], r["peak_heap_bytes_per_fragment"]) for r in acc_rows
           if r["kernel"] == d and r.get("status", "ok") == "ok" and r.get("peak_heap_bytes_per_fragment")]
    if bpf:
        worst = max(bpf, key=lambda x: x[1])
        goals.append([f"peak heap per stored fragment with `{d}` ≤ {GOAL_BYTES} B (every mesh)",
                      f"median {common.median(b for _, b in bpf):.0f} B, largest {worst[1]:.0f} B ({worst[0]})",
                      "met" if worst[1] <= GOAL_BYTES else "not met"])
    elephant = next((r for r in acc_rows if r["input"] == "refined_elephant" and r["kernel"] == d), None)
    if ok_wall(elephant):
        t = ok_wall(elephant)
        goals.append([f"refined_elephant (89k triangles), `{d}`, default heuristic, 2 cores: under {GOAL_ELEPHANT} s",
                      f"{t:.2f} s wall, {elephant.get('cpu_seconds_median', 0):.2f} s CPU "
                      f"({fmt_int(elephant['fragments'])} fragments)", "met" if t < GOAL_ELEPHANT else "not met"])
    for r in stacked:
        if r["kernel"] != d:
            continue
        t = stacked_seconds(r)
        goals.append([f"naive on {fmt_int(r['triangles'])} stacked triangles (depth {fmt_int(r['triangles'])}), "
                      f"`{d}`: under {GOAL_STACK} s",
                      f"{t:.1f} s (depth {fmt_int(r.get('depth'))})" if t else status_cell(r) or "—",
                      "met" if t and t < GOAL_STACK else "not met"])
    ratios = peer_ratios(acc_rows, peers)
    for tool in peer_tools(peers):
        measured = [(m, ratios[(m, tool)]) for m in CAD if (m, tool) in ratios]
        losers = [m for m, ratio in measured if ratio <= 1]
        if measured:
            goals.append([f"`{d}` builds faster than {tool} on every CAD mesh",
                          f"{len(measured) - len(losers)} of {len(measured)}"
                          + (f" (slower on {', '.join(losers)})" if losers else ""),
                          "met" if not losers else "not met"])
    if heur_sum.get("cad_best"):
        met = len(heur_sum["cad_met"]) == len(heur_sum["cad_best"])
        goals.append(["≤ 1.3 fragments per input triangle on CAD (best heuristic per mesh)",
                      f"{len(heur_sum['cad_met'])} of {len(heur_sum['cad_best'])} meshes; sampled geometric mean "
                      + (f"{heur_sum['sampled_geo']:.2f}" if heur_sum.get("sampled_geo") else "—"),
                      "met" if met else "not met"])
    return table(["goal", "measured", "status"], goals) if goals else "(no corpus data in this run)"


def goals_per_mesh(acc_rows, peers):
    """Per CAD mesh: the default kernel's time over double, its bytes per fragment and csg.js's
    time over it."""
    d = DEFAULT_KERNEL
    by = {(r["input"], r["kernel"]): r for r in acc_rows}
    over_double = accuracy_ratios(acc_rows)
    ratios = peer_ratios(acc_rows, peers)
    tools = peer_tools(peers)
    rows = []
    for m in CAD:
        e, x = by.get((m, d)), by.get((m, "double"))
        if not e:
            continue
        wx = ok_wall(x)
        row = [m, fmt_s(ok_wall(e)), fmt_s(wx) if wx else (status_cell(x) if x else "—"),
               fmt_ratio(over_double[m].get(d)),
               f"{e['peak_heap_bytes_per_fragment']:.0f}" if e.get("peak_heap_bytes_per_fragment") else "—"]
        row += [f"{ratios[(m, t)]:.2f}×" if (m, t) in ratios else "—" for t in tools]
        rows.append(row)
    if not rows:
        return ""
    hdr = ["CAD mesh", f"{d} s", "double s", f"{d} / double", "B/fragment"] + [f"{t} / {d}" for t in tools]
    return table(hdr, rows)


def section_peers(acc_rows, peers, node, plot_rel):
    """Section 6: csg.js and JSCAD built side by side with exbsp on the same meshes."""
    lines = ["## 6. Peers: JavaScript BSPs with an epsilon (bench/peers)", ""]
    if not peers:
        lines.append("Skipped in this run: node/npm missing or bench/peers absent (bench/peers/README.md).")
        return "\n".join(lines)
    d = DEFAULT_KERNEL
    by = {(r["input"], r["kernel"]): r for r in acc_rows}
    pby = peers_by(peers)
    ratios = peer_ratios(acc_rows, peers)
    tools = peer_tools(peers)
    versions = ", ".join(sorted({f"{r['tool']} {r.get('version', '')}".strip() for r in peers if r.get("tool")}))
    lines += [f"Tools: {versions}, run by Node {node or '(version not recorded)'} on the same machine in the "
              "same run as section 1 (each: one untimed warm-up build, then the median of 3 timed builds, as for exbsp). They store convex polygons; `triangles` counts them "
              "fan-triangulated, to compare with exbsp's stored triangles. Ratios over 1 mean exbsp is faster.",
              ""]
    hdr = ["mesh", f"{d} s", f"{d} fragments"]
    for t in tools:
        hdr += [f"{t} s", f"{t} triangles", f"{t} / {d}"]
    rows = []
    meshes = [m for m in CAD + ORGANIC if by.get((m, d))]
    for m in meshes:
        e = by[(m, d)]
        row = [m + ("" if m in CAD else "*"), fmt_s(ok_wall(e)), fmt_int(e.get("fragments"))]
        for t in tools:
            r = pby.get((m, t), {})
            s = r.get("build_seconds")
            row += [fmt_s(s) if s else (r.get("error", "—")[:30] if r else "—"),
                    fmt_int(r.get("pieces_triangulated")) if r.get("pieces_triangulated") is not None else "—",
                    f"{ratios[(m, t)]:.2f}×" if (m, t) in ratios else "—"]
        rows.append(row)
    lines.append(table(hdr, rows))
    lines += ["", "\\* organic mesh.", "", f"![{d} and the JavaScript BSPs against double]({plot_rel}/peers.png)", ""]
    return "\n".join(lines)


METHOD_NOTES = [
    "## Method notes",
    "",
    "- Memory is **counted allocations**, not RSS: bench/alloc_counter.cpp replaces operator new/delete "
    "and GMP's memory functions and sums malloc_usable_size of live blocks; the peak during the "
    "counted build, minus what was live before it, is `peak heap`; bytes per fragment = peak / fragments. "
    "The timed builds run with the accounting off.",
    "- Defects are exact: the tests' tree checker (tests/support/tree_checker.h) copies the tree into "
    "Epeck (double coordinates are the rationals they are) and evaluates every invariant exactly. No "
    "epsilon anywhere; the only tolerance widens the boxes that select the candidate fragments of a ray "
    "by a bound on the ray's rounding, which can only add candidates.",
    "- \"Plain double with an epsilon\" is **not measured**: the double kernel (Simple_cartesian<double>) "
    "is epsilon-free.",
    "- Generated inputs are deterministic (splitmix64); section 2 runs every size with several seeds.",
    "- Threads: builds use all cores (2); min-split's candidate loop, the side tests of lists over 65536 "
    "fragments and the subtrees below the first 16 are the parallel parts. Profiles use 1 thread.",
    "- Raw data: bench/out/full/*.jsonl (one JSON line per input × kernel × heuristic × seed; git-ignored).",
    "",
]


def write(path, meta, cfg, data, plot_rel, command):
    """Writes RESULTS.md from meta (machine, run), cfg and data {accuracy, soup, sticks, corpus,
    render, micro, profile}."""
    acc = data["accuracy"]
    acc_text, acc_sum = section_accuracy(acc, cfg, plot_rel)
    heur_text, heur_sum = section_heuristics(data["soup"], data["sticks"], data["corpus"], acc, cfg, plot_rel)
    micro_text, _ = section_micro(data.get("micro"))
    head = [
        "# exbsp benchmark results" + (" (QUICK MODE: small inputs, not the reference figures)" if meta.get("quick") else ""),
        "",
        f"Regenerate everything below (tables, readings, plots) from the repository root with **`{command}`**"
        f" (this run: {meta['minutes']:.0f} minutes; needs scripts/setup for the meshes, matplotlib and perf).",
        "",
        f"- Machine: {meta['cpu']} (lscpu model name), nproc = {meta['nproc']}, {meta['memory_gib']} GiB, "
        f"{meta['kernel']}; {meta['compiler']}; CGAL {meta['cgal']}; Release (-O3), -ffp-contract=off, -frounding-math.",
        f"- Shared machine (other engineers compile on it): load average {meta['load_start'][0]:.1f} at the start, "
        f"{meta['load_end'][0]:.1f} at the end; times are medians of interleaved runs.",
        f"- Commit: `{meta['commit']}`" + (" with uncommitted changes in the working tree" if meta["dirty"] else "")
        + f"; run {meta['date']}.",
        "",
        "## Goals: where we stand",
        "",
        goals_table(acc_sum, heur_sum, acc, data.get("stacked", []), data.get("peers", [])),
        "",
        goals_per_mesh(acc, data.get("peers", [])),
        "",
    ]
    text = "\n".join(head) + "\n" + acc_text + "\n" + heur_text + "\n" + section_render(data["render"], plot_rel) + \
        "\n" + micro_text + "\n" + section_profile(data.get("profile")) + "\n\n" + \
        section_peers(acc, data.get("peers", []), data.get("node", ""), plot_rel) + "\n\n" + "\n".join(METHOD_NOTES)
    # Sections 7 and later (the hidden-line drawing, drawing sets, assemblies, fragment births)
    # are written by their own scripts between <!-- name:begin --> and <!-- name:end -->: kept as
    # they stand, in their order, when the rest is regenerated.
    if os.path.exists(path):
        with open(path) as f:
            old = f.read()
        for m in re.finditer(r"<!-- ([a-z0-9-]+):begin -->.*?<!-- \1:end -->", old, re.S):
            text = text.rstrip("\n") + "\n\n" + m.group(0) + "\n"
    with open(path, "w") as f:
        f.write(text)
