# SPDX-License-Identifier: LGPL-3.0-or-later
# Tests of distributed builds from Python (exbsp.plan_build, exbsp.build_cell,
# exbsp.build_distributed in src/python/exbsp/distributed.py): the tree grown cell by cell here,
# in any order, and on a Dask LocalCluster with two worker processes is the tree exbsp.build
# makes, byte for byte (serialize(reproducible=True)); what cannot travel is refused.
import os
import pathlib

import numpy as np
import pytest

import exbsp

ROOT = pathlib.Path(os.environ.get("EXBSP_SOURCE_DIR",
                                   pathlib.Path(__file__).resolve().parents[2]))
FANDISK = ROOT / "data" / "meshes" / "fandisk.off"


def soup(n=400, seed=3):
    """n random triangles in a box, some crossing each other (splits)."""
    rng = np.random.default_rng(seed)
    centres = rng.uniform(-10, 10, size=(n, 1, 3))
    return (centres + rng.normal(0, 2.5, size=(n, 3, 3))).reshape(-1, 3), \
        np.arange(3 * n).reshape(n, 3)


def mesh():
    if FANDISK.exists():
        v, f, ids = exbsp.read_mesh(FANDISK)
        return v, f, dict(face_ids=ids)
    v, f = soup()
    return v, f, {}


def test_cells_grown_here_in_reverse_order_give_the_local_tree():
    v, f = soup()
    for heuristic in ("naive", "sampled", "random"):
        plan = exbsp.plan_build(v, f, heuristic=heuristic, seed=5)
        cells = plan.cells
        assert len(cells) == 16
        parts = [exbsp.build_cell(plan.input, c) for c in cells]
        for i in reversed(range(len(parts))):
            plan.add_part(i, parts[i])
        tree = plan.finish()
        local = exbsp.build(v, f, heuristic=heuristic, seed=5)
        assert tree.serialize(reproducible=True) == local.serialize(reproducible=True), heuristic
        assert tree.serialize(reproducible=True) != tree.serialize()  # the timings differ
        assert tree.stats["fragments"] == local.stats["fragments"]
        with pytest.raises(exbsp.UsageError):
            plan.finish()


def test_a_dask_local_cluster_builds_the_same_tree():
    distributed = pytest.importorskip("distributed", reason="python3-distributed is missing")
    v, f, extra = mesh()
    local = exbsp.build(v, f, **extra)
    report = {}
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            seen = []
            tree = exbsp.build_distributed(v, f, scheduler=client, report=report,
                                           progress=lambda k, n: seen.append((k, n)), **extra)
    assert tree.serialize(reproducible=True) == local.serialize(reproducible=True)
    assert np.array_equal(tree.order(eye=(3, -40, 17)), local.order(eye=(3, -40, 17)))
    assert seen == [(k, 16) for k in range(1, 17)]
    assert report["cells"] == 16 and report["workers"] == 2
    assert report["fragments"] == len(local)
    assert report["cell_bytes"] > 0 and report["part_bytes"] > 0
    here = exbsp.build_distributed(v, f, **extra)
    assert here.serialize(reproducible=True) == local.serialize(reproducible=True)


def test_what_cannot_travel_is_refused_and_bad_bytes_are_input_errors():
    v, f = soup(200)
    with pytest.raises(exbsp.UsageError):
        exbsp.plan_build(v, f, heuristic="custom")
    plan = exbsp.plan_build(v, f)
    with pytest.raises(exbsp.InputError):
        exbsp.build_cell(plan.input, plan.cells[0][:-5])
    with pytest.raises(exbsp.InputError):
        exbsp.build_cell(plan.cells[0], plan.cells[0])
    with pytest.raises(exbsp.InputError):
        plan.add_part(0, exbsp.build_cell(plan.input, plan.cells[1]))
