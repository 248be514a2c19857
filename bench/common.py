# SPDX-License-Identifier: LGPL-3.0-or-later
"""What the benchmark scripts share: paths, the corpus, kernels and heuristics, raw-data loading
and the small statistics (medians, spreads, log-log slopes) the report and the plots both use."""
import json
import math
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
MESHES = os.path.join(REPO, "data", "meshes")

CAD = ["fandisk", "rotor", "pinion", "anchor_dense", "blade", "turbine", "couplingdown", "ALSTOM_TEST4",
       "b9_mesh", "spool", "part", "joint"]
ORGANIC = ["elephant", "bunny00", "armadillo", "refined_elephant"]
# docs/contract.md "Command line": `exact` is the default kernel. epeck and gmpq are the other exact kernels
# (same tree, byte-identical orders), double and epick the inexact ones.
DEFAULT_KERNEL = "exact"
KERNELS = ["double", "epick", "exact", "epeck", "gmpq"]
INEXACT = ["double", "epick"]
HEURISTICS = ["naive", "min-split", "sampled", "random"]


def log(msg):
    print(f"[bench {time.strftime('%H:%M:%S')}] {msg}", flush=True)


def run(cmd, timeout=None, **kw):
    log(" ".join(cmd))
    return subprocess.run(cmd, check=True, timeout=timeout, **kw)


def capture(cmd):
    try:
        return subprocess.run(cmd, check=True, capture_output=True, text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return ""


def short_commit():
    """The repository's HEAD as `git rev-parse --short` prints it ("" outside a checkout)."""
    return capture(["git", "-C", REPO, "rev-parse", "--short", "HEAD"])


def cpu_model():
    """The first "model name" of /proc/cpuinfo, or "?"."""
    try:
        with open("/proc/cpuinfo") as f:
            return next((ln.split(":", 1)[1].strip() for ln in f if ln.startswith("model name")), "?")
    except OSError:
        return "?"


def mesh_path(name):
    return os.path.join(MESHES, name + ".off")


def available(names):
    return [n for n in names if os.path.exists(mesh_path(n))]


def mesh_class(name):
    return "CAD" if name in CAD else "organic"


def load_jsonl(path):
    rows = []
    if os.path.exists(path):
        with open(path) as f:
            for line in f:
                line = line.strip()
                if line:
                    rows.append(json.loads(line))
    return rows


def median(values):
    vals = sorted(v for v in values if v is not None)
    if not vals:
        return None
    n = len(vals)
    return vals[n // 2] if n % 2 else (vals[n // 2 - 1] + vals[n // 2]) / 2


def geometric_mean(values):
    vals = [v for v in values if v and v > 0]
    return math.exp(sum(map(math.log, vals)) / len(vals)) if vals else None


def slope(xs, ys):
    """Least-squares slope of log y against log x (None with fewer than 3 usable points)."""
    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys) if x and y and x > 0 and y > 0]
    if len(pts) < 3:
        return None
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx if sxx else None


def spread(rows, field):
    """(median, min, max) of a field over rows (the seeds of one size and heuristic)."""
    vals = [r.get(field) for r in rows if r.get(field) is not None]
    if not vals:
        return None
    return median(vals), min(vals), max(vals)


def by_size(rows, heuristic):
    """The ok rows of one heuristic grouped by input size (triangles): {n: [rows over seeds]}."""
    out = {}
    for r in rows:
        if r["heuristic"] == heuristic and r["status"] == "ok":
            out.setdefault(r["triangles"], []).append(r)
    return dict(sorted(out.items()))


def ensure_matplotlib():
    """matplotlib is Debian's python3-matplotlib: re-run under /usr/bin/python3 when another
    python3 (pyenv, venv) comes first on PATH and lacks it."""
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        system = "/usr/bin/python3"
        if os.path.exists(system) and os.path.realpath(sys.executable) != os.path.realpath(system):
            os.execv(system, [system] + sys.argv)
        sys.exit("bench: matplotlib is missing: run scripts/setup (apt-get install python3-matplotlib)")


def replace_results_section(begin, end, section):
    """Writes `section` (its first line `begin`, its last `end`) into bench/RESULTS.md in place of
    the text between those markers, or appends it when they are missing."""
    path = os.path.join(HERE, "RESULTS.md")
    with open(path) as f:
        text = f.read()
    if begin in text and end in text:
        text = text[:text.index(begin)] + section + text[text.index(end) + len(end):]
    else:
        text = text.rstrip("\n") + "\n\n" + section + "\n"
    with open(path, "w") as f:
        f.write(text)
