# SPDX-License-Identifier: LGPL-3.0-or-later
"""bench/plots/*.png from the raw data of a run (matplotlib, Agg). A bar that has no value (a
build stopped at the fragment limit, over its time cap, or skipped by the sweep's limits) is
not left blank: the reason is written where the bar would stand."""
import os

import common
from common import CAD, DEFAULT_KERNEL, HEURISTICS, INEXACT
from report import (accuracy_ratios, corpus_rows_by_heuristic, fragments_per_triangle, ok_wall, peer_ratios,
                    peer_tools, peers_by, status_cell)

COLORS = {"double": "#888888", "epick": "#4c72b0", "exact": "#c44e52", "epeck": "#dd8452", "gmpq": "#8172b2",
          "naive": "#dd8452", "min-split": "#55a868", "sampled": "#c44e52", "random": "#4c72b0"}
STAGE_COLORS = {"order": "#c44e52", "transform+clip": "#dd8452", "raster": "#55a868", "svg": "#4c72b0",
                "svg write": "#8172b2"}


def short_reason(r):
    """A few words for a missing bar: why the row has no value."""
    st = status_cell(r)
    if st is None:
        return None
    return {"> 4M fragments (stopped)": "stopped: fragment limit", "—": "not run"}.get(st, st)


def mark_missing(ax, x, text, color):
    """Writes `text` vertically at the foot of the bar position x (log or linear axis)."""
    lo = ax.get_ylim()[0]
    ax.text(x, lo, " " + text, rotation=90, ha="center", va="bottom", fontsize=7.5, color=color, fontweight="bold")


def legend_patch(color, label, alpha=1.0):
    """A legend entry for bars drawn one by one (an empty bar() would get no colour)."""
    from matplotlib.patches import Patch
    return Patch(facecolor=color, alpha=alpha, label=label)


def mesh_labels(meshes):
    return [m + ("" if m in CAD else "*") for m in meshes]


def accuracy_ratio_plot(plt, acc, cfg, outdir):
    by = {(r["input"], r["kernel"]): r for r in acc}
    meshes = [m for m in cfg["corpus_cad"] + cfg["corpus_organic"] if (m, "double") in by]
    if not meshes:
        return
    ratios = accuracy_ratios(acc)
    kernels = [k for k in ["epick", DEFAULT_KERNEL, "epeck", "gmpq"] if any(r["kernel"] == k for r in acc)]
    width = 0.8 / len(kernels)
    fig, ax = plt.subplots(figsize=(11, 4.8))
    ax.set_yscale("log")
    ax.set_ylim(0.3, 1000)
    for i, k in enumerate(kernels):
        xs = [j + (i - (len(kernels) - 1) / 2) * width for j in range(len(meshes))]
        vals = [ratios.get(m, {}).get(k) for m in meshes]
        ax.bar([x for x, v in zip(xs, vals) if v], [v for v in vals if v], width, label=f"{k} / double",
               color=COLORS[k])
        for x, m, v in zip(xs, meshes, vals):
            if not v:  # the kernel's own row or double's says why
                why = short_reason(by.get((m, k))) or f"double {short_reason(by.get((m, 'double')))}"
                mark_missing(ax, x, f"{k}: {why}", COLORS[k])
    ax.axhline(1.5, color="black", linestyle="--", linewidth=1, label=f"goal 1.5× ({DEFAULT_KERNEL}, CAD)")
    ax.set_xticks(range(len(meshes)))
    ax.set_xticklabels(mesh_labels(meshes), rotation=40, ha="right", fontsize=8)
    ax.set_ylabel("build time ratio to double (log)")
    ax.set_title("What accuracy costs: build time / double build time (sampled; * organic)")
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "accuracy_ratio.png"), dpi=90)
    plt.close(fig)


def accuracy_defects_plot(plt, acc, cfg, outdir):
    """Left: defects per 1000 fragments (off plane, misclassified); right: order errors per
    1000 occluding pairs, the pairs the order check sampled (not per fragment)."""
    by = {(r["input"], r["kernel"]): r for r in acc}
    meshes = [m for m in cfg["corpus_cad"] + cfg["corpus_organic"]
              if any((m, k) in by for k in INEXACT)]
    if not meshes:
        return
    fig, (left, right) = plt.subplots(1, 2, figsize=(13, 4.8), gridspec_kw={"width_ratios": [2, 1.2]})
    panels = [(left, [("off_plane", "off plane"), ("misclassified", "misclassified")], "fragments",
               "per 1000 fragments (log)"),
              (right, [("order_errors", "order errors")], "occluding_pairs", "order errors per 1000 occluding pairs (log)")]
    for ax, kinds, denominator, ylabel in panels:
        ax.set_yscale("log")
        ax.set_ylim(0.1, 2000)
        n = len(INEXACT) * len(kinds)
        width = 0.8 / n
        handles = []
        for i, k in enumerate(INEXACT):
            for j, (key, name) in enumerate(kinds):
                off = (i * len(kinds) + j - (n - 1) / 2) * width
                for x, m in enumerate(meshes):
                    r = by.get((m, k))
                    d = r.get("defects") if r else None
                    if not d or not d.get(denominator):
                        mark_missing(ax, x + off, f"{k}: {short_reason(r) or 'no check'}", COLORS[k])
                        continue
                    v = 1000 * d[key] / d[denominator]
                    if v > 0:
                        ax.bar(x + off, v, width, color=COLORS[k], alpha=[1, 0.55][j])
                    else:
                        mark_missing(ax, x + off, f"{k}: 0", COLORS[k])
                handles.append(legend_patch(COLORS[k], f"{k}: {name}", [1, 0.55][j]))
        ax.set_xticks(range(len(meshes)))
        ax.set_xticklabels(mesh_labels(meshes), rotation=40, ha="right", fontsize=8)
        ax.set_ylabel(ylabel)
        ax.legend(handles=handles, fontsize=7, loc="upper left")
    left.set_title("Exact defect counts of the inexact kernels (Epeck control: 0)")
    right.set_title("Order errors over the sampled pairs")
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "accuracy_defects.png"), dpi=90)
    plt.close(fig)


def heuristic_sweep_plot(plt, rows, key, outdir):
    """Fragments, build time and depth against n, log-log: the median over the seeds, with
    min–max error bars."""
    if not rows:
        return
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.2))
    seeds = sorted({r.get("seed", 0) for r in rows})
    for h in HEURISTICS:
        sizes = common.by_size(rows, h)
        if not sizes:
            continue
        xs = list(sizes)
        for ax, field, name in zip(axes, ["fragments", "build_seconds_median", "depth"],
                                   ["fragments", "build time (s)", "depth"]):
            spreads = [common.spread(sizes[n], field) for n in xs]
            med = [s[0] for s in spreads]
            err = [[s[0] - s[1] for s in spreads], [s[2] - s[0] for s in spreads]]
            sl = common.slope(xs, med)
            ax.errorbar(xs, med, yerr=err, fmt="o-", capsize=3, color=COLORS[h],
                        label=f"{h} (slope {sl:.2f})" if sl else h)
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("input triangles n")
            ax.set_ylabel(name)
    for ax in axes:
        ax.legend(fontsize=7)
        ax.grid(True, which="both", alpha=0.3)
    fig.suptitle(("Random soups at constant density" if key == "soup" else "Sticks grid (worst case)")
                 + f": {DEFAULT_KERNEL} kernel, log-log, median and min–max over {len(seeds)} seeds")
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, f"heuristics_{key}.png"), dpi=90)
    plt.close(fig)


def heuristics_corpus_plot(plt, corpus, acc, cfg, outdir):
    by = corpus_rows_by_heuristic(corpus, acc)
    meshes = [m for m in cfg["corpus_cad"] + cfg["corpus_organic"] if any(k[0] == m for k in by)]
    if not meshes:
        return
    fig, ax = plt.subplots(figsize=(11, 4.8))
    ax.set_yscale("log")
    ax.set_ylim(0.5, 100)
    handles = []
    for i, h in enumerate(HEURISTICS):
        xs = [j + (i - 1.5) * 0.2 for j in range(len(meshes))]
        for x, m in zip(xs, meshes):
            r = by.get((m, h))
            if r is not None and r["status"] == "ok":
                ax.bar(x, fragments_per_triangle(r), 0.2, color=COLORS[h])
            else:
                mark_missing(ax, x, f"{h}: {short_reason(r) or 'not run'}", COLORS[h])
        handles.append(legend_patch(COLORS[h], h))
    handles.append(ax.axhline(1.3, color="black", linestyle="--", linewidth=1, label="goal 1.3 (CAD)"))
    ax.set_xticks(range(len(meshes)))
    ax.set_xticklabels(mesh_labels(meshes), rotation=40, ha="right", fontsize=8)
    ax.set_ylabel("fragments / input triangle (log)")
    ax.set_title(f"Fragments per input triangle, {DEFAULT_KERNEL} kernel (* organic)")
    ax.legend(handles=handles, fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "heuristics_corpus.png"), dpi=90)
    plt.close(fig)


def render_frame_plot(plt, render, outdir):
    """Per mesh three bars: the PNG frame (order, transform+clip, raster), the SVG frame (order,
    transform+clip, svg, svg write) and OSMesa's z-buffer frame; stages stacked within a bar."""
    if not render:
        return
    fig, ax = plt.subplots(figsize=(9, 4))
    bars = [("PNG", ["order", "transform+clip", "raster"]), ("SVG", ["order", "transform+clip", "svg", "svg write"])]
    labels, x = [], 0
    seen = set()
    for r in render:
        s = r["stage_seconds_median"]
        for name, stages in bars:
            bottom = 0.0
            for st in stages:
                v = s.get(st, 0)
                ax.bar(x, v, 0.6, bottom=bottom, color=STAGE_COLORS[st], label=None if st in seen else st)
                seen.add(st)
                bottom += v
            labels.append(f"{r['input']}\n{name}")
            x += 1
        gl = r.get("osmesa", {}).get("frame_seconds_median")
        if gl:
            ax.bar(x, gl, 0.6, color="#333333", label=None if "gl" in seen else "OSMesa frame (z-buffer)")
            seen.add("gl")
        else:
            mark_missing(ax, x, "no OSMesa", "#333333")
        labels.append(f"{r['input']}\nOSMesa")
        x += 1.5
    positions = []
    x = 0
    for _ in render:
        positions += [x, x + 1, x + 2]
        x += 3.5
    ax.set_xticks(positions)
    ax.set_xticklabels(labels, fontsize=8)
    ax.set_ylabel("seconds per frame (median)")
    ax.set_title("Per-frame time at 1024×768: PNG frame, SVG frame, OSMesa")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "render_frame.png"), dpi=90)
    plt.close(fig)


def peers_plot(plt, acc, peers, cfg, outdir):
    """Per mesh: the default kernel's build time over double's, and each JavaScript BSP's over
    the default kernel's (bars over 1: exbsp faster)."""
    by = {(r["input"], r["kernel"]): r for r in acc}
    meshes = [m for m in cfg["corpus_cad"] + cfg["corpus_organic"] if ok_wall(by.get((m, DEFAULT_KERNEL)))]
    if not meshes or not peers:
        return
    pby = peers_by(peers)
    over_double, ratios = accuracy_ratios(acc), peer_ratios(acc, peers)
    series = [(f"{DEFAULT_KERNEL} / double", COLORS[DEFAULT_KERNEL],
               [over_double[m].get(DEFAULT_KERNEL) for m in meshes])]
    for t, color in zip(peer_tools(peers), ["#4c72b0", "#55a868", "#8172b2"]):
        series.append((f"{t} / {DEFAULT_KERNEL}", color, [ratios.get((m, t)) for m in meshes]))
    width = 0.8 / len(series)
    fig, ax = plt.subplots(figsize=(11, 4.5))
    ax.set_yscale("log")
    ax.set_ylim(0.08, 8)
    for i, (label, color, vals) in enumerate(series):
        xs = [j + (i - (len(series) - 1) / 2) * width for j in range(len(meshes))]
        ax.bar([x for x, v in zip(xs, vals) if v], [v for v in vals if v], width, label=label, color=color)
        for x, m, v in zip(xs, meshes, vals):
            if not v:  # double's row, or the tool's error, says why
                why = (f"double {short_reason(by.get((m, 'double')))}" if i == 0
                       else pby.get((m, label.split(" / ")[0]), {}).get("error", "not run")[:24])
                mark_missing(ax, x, why, color)
    ax.axhline(1.0, color="black", linewidth=0.8)
    ticks = [0.1, 0.2, 0.5, 1, 1.5, 2, 5]
    ax.set_yticks(ticks)
    ax.set_yticklabels([f"{t:g}×" for t in ticks])
    ax.minorticks_off()
    ax.axhline(1.5, color="black", linestyle="--", linewidth=1, label=f"goal: {DEFAULT_KERNEL} / double ≤ 1.5×")
    ax.set_xticks(range(len(meshes)))
    ax.set_xticklabels(mesh_labels(meshes), rotation=40, ha="right", fontsize=8)
    ax.set_ylabel("build time ratio (log; same machine, same run)")
    ax.set_title(f"{DEFAULT_KERNEL} over double, and the JavaScript BSPs over {DEFAULT_KERNEL} (> 1: exbsp faster)")
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "peers.png"), dpi=90)
    plt.close(fig)


def draw_all(data, cfg, outdir):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    os.makedirs(outdir, exist_ok=True)
    accuracy_ratio_plot(plt, data["accuracy"], cfg, outdir)
    accuracy_defects_plot(plt, data["accuracy"], cfg, outdir)
    heuristic_sweep_plot(plt, data["soup"], "soup", outdir)
    heuristic_sweep_plot(plt, data["sticks"], "sticks", outdir)
    heuristics_corpus_plot(plt, data["corpus"], data["accuracy"], cfg, outdir)
    render_frame_plot(plt, data["render"], outdir)
    peers_plot(plt, data["accuracy"], data.get("peers", []), cfg, outdir)
