# SPDX-License-Identifier: LGPL-3.0-or-later
"""Where a build spends its time: perf sampling of one single-threaded bench_sweep build, self
time per (shared object, function), and the same grouped into categories.

perf, not callgrind: valgrind does not honour the rounding-mode switches of CGAL's interval
filters (which the exact kernels use), so under valgrind those predicates, and the tree, change.

Categories come from where the code lives, not from the names of particular functions: the
shared object (libgmp, libmpfr, libc, libstdc++, the kernel), and for code in the benchmark
binary itself the outermost namespace of the function (exbsp::, CGAL::, std::). Renaming or
moving a function inside exbsp therefore leaves the categories right.
"""
import os
import re
import subprocess

import common

CATEGORIES = [
    "GMP arithmetic (libgmp)",
    "rational to interval (libmpfr)",
    "C library: malloc, free, memcpy (libc)",
    "C++ runtime: operator new, exceptions (libstdc++)",
    "CGAL templates (inlined into the binary: lazy exact, filters)",
    "exbsp",
    "C++ standard library templates",
    "operating system (kernel)",
    "other",
]


def strip_templates(fn):
    """The function's qualified name without template arguments and parameters."""
    prev = None
    while prev != fn:
        prev, fn = fn, re.sub(r"<[^<>]*>", "", fn)
    fn = re.sub(r"\(.*$", "", fn)
    return fn.split(" ")[-1]  # drop a return type ("void exbsp::f" -> "exbsp::f")


def category(dso, function):
    dso = os.path.basename(dso or "")
    if dso.startswith("libgmp"):
        return CATEGORIES[0]
    if dso.startswith("libmpfr"):
        return CATEGORIES[1]
    if dso.startswith("libc.") or dso.startswith("libc-"):
        return CATEGORIES[2]
    if dso.startswith("libstdc++") or dso.startswith("libgcc"):
        return CATEGORIES[3]
    if dso.startswith("[kernel") or (dso == "[unknown]" and function.startswith("0xffff")):
        return CATEGORIES[7]
    namespace = strip_templates(function).split("::")[0]
    if namespace == "CGAL":
        return CATEGORIES[4]
    if namespace in ("exbsp", "exbsp_test"):
        return CATEGORIES[5]
    if namespace in ("std", "__gnu_cxx"):
        return CATEGORIES[6]
    return CATEGORIES[8]


def parse_report(text):
    """Rows {percent, dso, function} of `perf report --sort dso,sym -t ';'`."""
    rows = []
    for line in text.splitlines():
        if line.startswith("#") or ";" not in line:
            continue
        parts = [p.strip() for p in line.split(";", 2)]
        if len(parts) != 3 or not parts[0].endswith("%"):
            continue
        function = re.sub(r"^\[[.k]\]\s*", "", parts[2])
        rows.append({"percent": float(parts[0].rstrip("%")), "dso": parts[1], "function": function})
    return rows


def categorize(rows):
    """Share (percent of the samples) per category, every category present."""
    out = {name: 0.0 for name in CATEGORIES}
    for r in rows:
        out[category(r["dso"], r["function"])] += r["percent"]
    return out


def profile(build_dir, outdir, mesh, kernel, heuristic="sampled", repeats=3):
    """perf record of `repeats` timed single-threaded builds of `mesh` with `kernel`; returns
    {"rows": [...], "categories": {...}} or {"error": ...}."""
    data = os.path.join(outdir, f"perf.{kernel}.data")
    cmd = ["perf", "record", "-q", "-o", data, "--", os.path.join(build_dir, "bench", "bench_sweep"), "--label",
           "profile", "--out", os.devnull, "--kernels", kernel, "--heuristics", heuristic, "--repeats", str(repeats),
           "--skip-counted", "--threads", "1", "--input", "mesh:" + common.mesh_path(mesh)]
    try:
        common.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=1800)
    except (OSError, subprocess.CalledProcessError, subprocess.TimeoutExpired) as e:
        return {"error": str(e)}
    return read(data)


def read(data):
    """The rows and categories of a perf.data file (rerun by --report-only: the rules may change)."""
    try:
        text = subprocess.run(["perf", "report", "-i", data, "--stdio", "--no-children", "--sort", "dso,sym",
                               "-t", ";", "-g", "none"], check=True, capture_output=True, text=True).stdout
    except (OSError, subprocess.CalledProcessError) as e:
        return {"error": str(e)}
    rows = parse_report(text)
    return {"rows": rows[:300], "categories": categorize(rows)}
