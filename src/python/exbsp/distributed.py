# SPDX-License-Identifier: LGPL-3.0-or-later
"""Distributed BSP builds: the tree of exbsp.build, with its subtrees grown on a Dask cluster.

build_distributed(vertices, faces, scheduler=..., **options) grows the top levels of the tree
in this process (exbsp.plan_build), sends the build's input once to every worker and each of
the (at most 16) frontier cells to a Dask task (exbsp.build_cell), and joins the parts as they
come back. The tree is the one exbsp.build(vertices, faces, **options) makes, byte for byte
(Tree.serialize(reproducible=True)): each subtree depends only on the input and its cell.

  - scheduler=None: the cells are grown here, one after the other (the reference);
  - scheduler=ADDRESS ("tcp://host:8786") or a distributed.Client / LocalCluster: one task
    per cell (Debian's python3-distributed). Every worker must import this same exbsp.

Exact kernel and named heuristics only (a score callback cannot travel). `report`, when a
dict, receives what was shipped and how long each stage took: cells, input_bytes (once per
worker), cell_bytes, part_bytes, fragments, seconds_top, seconds_cells, seconds_join, seconds.
"""
import time


def grow_cell(job):
    """One Dask task: job = (index, input, cell). Returns (index, part bytes, seconds)."""
    from . import _exbsp
    i, data, cell = job
    t0 = time.perf_counter()
    part = _exbsp.build_cell(data, cell)
    return i, part, time.perf_counter() - t0


def _grow_shipped(i, data, cell):
    return grow_cell((i, data, cell))


def build_distributed(vertices, faces, *, scheduler=None, report=None, progress=None, **options):
    """The BSP tree of a mesh with its subtrees grown on a Dask cluster (see the module's
    notes). `options` are exbsp.plan_build's (heuristic, seed, sampled, max_fragments,
    face_ids). `progress(done, total)` after each part. Returns the Tree."""
    from . import _exbsp
    t0 = time.perf_counter()
    plan = _exbsp.plan_build(vertices, faces, **options)
    data, cells = plan.input, plan.cells
    t1 = time.perf_counter()
    shipped = {"cells": len(cells), "input_bytes": len(data),
               "cell_bytes": sum(len(c) for c in cells), "part_bytes": 0, "workers": 0}

    def joined(k, i, part):
        shipped["part_bytes"] += len(part)
        plan.add_part(i, part)
        if progress:
            progress(k, len(cells))

    if not cells:
        pass
    elif scheduler is None:
        for k, cell in enumerate(cells, 1):
            _, part, _ = grow_cell((k - 1, data, cell))
            joined(k, k - 1, part)
    else:
        from distributed import Client, as_completed
        client = scheduler if isinstance(scheduler, Client) else Client(scheduler)
        try:
            shipped["workers"] = len(client.scheduler_info()["workers"])
            # The input goes to every worker once; each cell to the worker that grows it (as
            # data, not inside the task graph: a cell of a large model is hundreds of MB).
            remote = client.scatter(data, broadcast=True)
            remote_cells = client.scatter(cells)
            futures = [client.submit(_grow_shipped, i, remote, cell, pure=False)
                       for i, cell in enumerate(remote_cells)]
            for k, future in enumerate(as_completed(futures), 1):
                i, part, _ = future.result()
                joined(k, i, part)
        finally:
            if client is not scheduler:
                client.close()
    t2 = time.perf_counter()
    tree = plan.finish()
    t3 = time.perf_counter()
    if report is not None:
        report.update(shipped)
        report.update({"fragments": len(tree), "seconds_top": t1 - t0, "seconds_cells": t2 - t1,
                       "seconds_join": t3 - t2, "seconds": t3 - t0})
    return tree
