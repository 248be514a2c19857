# SPDX-License-Identifier: LGPL-3.0-or-later
"""Drawing sets: one `exbsp drawing` sheet per part, in parallel, locally or on a Dask cluster.

drawing_set(parts, outdir, ...) makes OUTDIR/NAME.EXT for every mesh NAME.off/.obj/.ply/.stl
(a folder: its mesh files, sorted; or a list of files) and every format. One job per sheet:
the sheet is made once and written in each format. The bytes are those of
`exbsp drawing FOLDER -o OUTDIR --formats ...` (same title, date and options), whichever
worker made them:

  - workers=1: in this process, one sheet after the other;
  - workers=N (default: the machine's cores): a local pool of N processes (spawned: the
    engine's OpenMP threads are not fork-safe);
  - scheduler=ADDRESS (a Dask scheduler, "tcp://host:8786") or a distributed.Client /
    LocalCluster: one Dask task per sheet (Debian's python3-distributed). Every worker must
    import this same exbsp (same version), and see the input and output paths.

Resumable: a sheet whose files all exist and are newer than the part is not redone (files are
renamed into place whole, so an existing file is a finished one); force=True redoes them.
Progress: `progress(done, total, name)` after each sheet (default: a line on stderr).
"""
import os
import sys
import time

MESH_EXTENSIONS = (".off", ".obj", ".ply", ".stl")


def _parts_of(parts):
    if isinstance(parts, (str, os.PathLike)) and os.path.isdir(parts):
        folder = os.fspath(parts)
        names = sorted(n for n in os.listdir(folder) if n.lower().endswith(MESH_EXTENSIONS)
                       and os.path.isfile(os.path.join(folder, n)))
        if not names:
            raise ValueError(f"{folder}: no mesh file (.off, .obj, .ply, .stl) in the folder")
        return [os.path.join(folder, n) for n in names]
    if isinstance(parts, (str, os.PathLike)):
        return [os.fspath(parts)]
    return [os.fspath(p) for p in parts]


def _outputs(part, outdir, formats):
    stem = os.path.splitext(os.path.basename(part))[0]
    return [os.path.join(outdir, f"{stem}.{f}") for f in formats]


def _finished(part, outputs):
    try:
        made = min(os.stat(o).st_mtime_ns for o in outputs)
    except FileNotFoundError:
        return False
    return made >= os.stat(part).st_mtime_ns


def draw_one(job):
    """One sheet: job = (part, outputs, options). Returns (part, outputs, seconds)."""
    from . import _exbsp
    part, outputs, options = job
    t0 = time.perf_counter()
    _exbsp.drawing(part, outputs, **options)
    return part, outputs, time.perf_counter() - t0


def _say(done, total, name):
    print(f"exbsp: sheet {done}/{total}: {name}", file=sys.stderr, flush=True)


def drawing_set(parts, outdir, *, formats=("pdf",), workers=None, scheduler=None, force=False,
                progress=_say, **options):
    """Drawing sheets of many parts (see the module's notes). `options` are exbsp.drawing's
    (views, projection, sheet, scale, units, sections, lines_only, number, date, line_widths,
    crease_deg, kernel); the title is each part's name unless given. Returns
    {"written": [...], "skipped": [...], "seconds": wall time}."""
    t0 = time.perf_counter()
    formats = [formats] if isinstance(formats, str) else list(formats)
    for f in formats:
        if f not in ("svg", "pdf", "dxf"):
            raise ValueError(f"formats: unknown format {f!r} (expected svg, pdf or dxf)")
    if not formats:
        raise ValueError("formats: at least one of svg, pdf, dxf")
    from . import _exbsp
    outdir = os.fspath(outdir)
    os.makedirs(outdir, exist_ok=True)
    options = dict(options)
    if not options.get("date"):
        options["date"] = _exbsp.today_date()  # one date for every sheet, on every worker
    jobs, skipped = [], []
    for part in _parts_of(parts):
        outputs = _outputs(part, outdir, formats)
        if not force and _finished(part, outputs):
            skipped.extend(outputs)
            continue
        opts = dict(options)
        opts.setdefault("title", os.path.splitext(os.path.basename(part))[0])
        jobs.append((part, outputs, opts))
    written = []
    total = len(jobs)

    def done(k, result):
        written.extend(result[1])
        if progress:
            progress(k, total, os.path.basename(result[0]))

    if not jobs:
        pass
    elif scheduler is not None:
        from distributed import Client, as_completed
        client = scheduler if isinstance(scheduler, Client) else Client(scheduler)
        try:
            futures = client.map(draw_one, jobs, pure=False)
            for k, future in enumerate(as_completed(futures), 1):
                done(k, future.result())
        finally:
            if client is not scheduler:
                client.close()
    else:
        if workers is None:
            workers = os.cpu_count() or 1
        if workers < 1:
            raise ValueError("workers: must be at least 1")
        if workers == 1 or total == 1:
            for k, job in enumerate(jobs, 1):
                done(k, draw_one(job))
        else:
            import concurrent.futures
            import multiprocessing
            context = multiprocessing.get_context("spawn")
            with concurrent.futures.ProcessPoolExecutor(max_workers=workers,
                                                        mp_context=context) as pool:
                futures = [pool.submit(draw_one, job) for job in jobs]
                for k, future in enumerate(concurrent.futures.as_completed(futures), 1):
                    done(k, future.result())
    return {"written": sorted(written), "skipped": sorted(skipped),
            "seconds": time.perf_counter() - t0}
