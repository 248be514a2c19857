# SPDX-License-Identifier: LGPL-3.0-or-later
# Tests of exbsp.drawing and exbsp.drawing_set (src/python/exbsp/drawing_sets.py): one sheet
# from Python, drawing sets in this process, in a local process pool and on a Dask LocalCluster
# with two workers, all byte-identical to each other and to `exbsp drawing FOLDER`; resumable
# runs; bad arguments raise instead of crashing.
import os
import pathlib
import subprocess
import time

import pytest

import exbsp

SOURCE = os.environ.get("EXBSP_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
CLI = os.environ.get("EXBSP_CLI", os.path.join(SOURCE, "build", "src", "app", "exbsp"))


def box_off(x, y, z, dx, dy, dz):
    v = [(x + (c & 1) * dx, y + (c >> 1 & 1) * dy, z + (c >> 2 & 1) * dz) for c in range(8)]
    quads = [(0, 4, 6, 2), (1, 3, 7, 5), (0, 1, 5, 4), (2, 6, 7, 3), (0, 2, 3, 1), (4, 5, 7, 6)]
    return ("OFF\n8 6 0\n" + "".join(f"{a} {b} {c}\n" for a, b, c in v)
            + "".join("4 %d %d %d %d\n" % q for q in quads))


@pytest.fixture
def parts(tmp_path):
    folder = tmp_path / "parts"
    folder.mkdir()
    (folder / "a.off").write_text(box_off(0, 0, 0, 40, 20, 10) + "")
    (folder / "b.off").write_text(box_off(0, 0, 0, 4, 2, 1))
    (folder / "c.off").write_text(box_off(-5, -5, -5, 10, 10, 30))
    (folder / "readme.txt").write_text("not a mesh")
    return folder


OPTIONS = dict(lines_only=True, date="2026-01-01", sections=["A=0,1,0,-1"])


def contents(folder):
    return {p.name: p.read_bytes() for p in sorted(pathlib.Path(folder).iterdir())}


def test_one_sheet_in_each_format_and_paths_as_pathlike(tmp_path, parts):
    out = [tmp_path / "a.svg", tmp_path / "a.pdf", tmp_path / "a.dxf"]
    r = exbsp.drawing(parts / "a.off", out, **OPTIONS)
    assert r["written"] == [str(p) for p in out] and r["triangles"] == 12
    assert (tmp_path / "a.svg").read_text().count('inkscape:groupmode="layer"') == 6
    assert (tmp_path / "a.pdf").read_bytes().startswith(b"%PDF")
    assert b"HIDDEN" in (tmp_path / "a.dxf").read_bytes()


def test_bad_arguments_raise_and_write_nothing(tmp_path, parts):
    for kwargs, message in [(dict(sheet="A9"), "sheet"), (dict(views=["front", "side"]), "side"),
                            (dict(scale="2:3"), "scale"), (dict(sections=["A=0,0,0,1"]), "sections"),
                            (dict(projection="second-angle"), "projection")]:
        with pytest.raises(exbsp.UsageError, match=message):
            exbsp.drawing(parts / "a.off", tmp_path / "x.svg", **kwargs)
    with pytest.raises(exbsp.UsageError, match="NUL"):
        exbsp.drawing(str(parts / "a.off") + "\0.svg", tmp_path / "x.svg")
    with pytest.raises(exbsp.UsageError, match="NUL"):
        exbsp.drawing(parts / "a.off", str(tmp_path / "x.svg") + "\0/y.svg")
    with pytest.raises(exbsp.UsageError, match="does not end in"):
        exbsp.drawing(parts / "a.off", tmp_path / "x.png")
    with pytest.raises(exbsp.InputError):
        exbsp.drawing(tmp_path / "missing.off", tmp_path / "x.svg")
    assert not (tmp_path / "x.svg").exists()


def test_sets_are_the_same_bytes_in_process_in_a_pool_and_from_the_cli(tmp_path, parts):
    quiet = dict(progress=None)
    one = exbsp.drawing_set(parts, tmp_path / "one", formats=("svg", "pdf", "dxf"), workers=1,
                            **quiet, **OPTIONS)
    assert len(one["written"]) == 9 and not one["skipped"]
    pool = exbsp.drawing_set(parts, tmp_path / "pool", formats=("svg", "pdf", "dxf"), workers=2,
                             **quiet, **OPTIONS)
    assert len(pool["written"]) == 9
    assert contents(tmp_path / "one") == contents(tmp_path / "pool")
    if os.path.exists(CLI):
        subprocess.run([CLI, "drawing", str(parts), "-o", str(tmp_path / "cli"), "--formats",
                        "svg,pdf,dxf", "--lines-only", "--date", "2026-01-01", "--section",
                        "A=0,1,0,-1", "-q"], check=True)
        assert contents(tmp_path / "one") == contents(tmp_path / "cli")


def test_finished_sheets_are_not_redone(tmp_path, parts):
    out = tmp_path / "out"
    first = exbsp.drawing_set(parts, out, workers=1, progress=None, **OPTIONS)
    assert len(first["written"]) == 3
    again = exbsp.drawing_set(parts, out, workers=1, progress=None, **OPTIONS)
    assert again["written"] == [] and len(again["skipped"]) == 3
    time.sleep(0.01)
    (parts / "b.off").write_text(box_off(0, 0, 0, 5, 2, 1))  # a changed part is redrawn
    changed = exbsp.drawing_set(parts, out, workers=1, progress=None, **OPTIONS)
    assert changed["written"] == [str(out / "b.pdf")]
    forced = exbsp.drawing_set(parts, out, workers=1, progress=None, force=True, **OPTIONS)
    assert len(forced["written"]) == 3


def test_a_dask_local_cluster_gives_the_same_bytes(tmp_path, parts):
    distributed = pytest.importorskip("distributed", reason="python3-distributed is missing")
    local = exbsp.drawing_set(parts, tmp_path / "local", formats=("svg", "pdf"), workers=1,
                              progress=None, **OPTIONS)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            seen = []
            dask = exbsp.drawing_set(parts, tmp_path / "dask", formats=("svg", "pdf"),
                                     scheduler=client,
                                     progress=lambda k, n, name: seen.append((k, n, name)),
                                     **OPTIONS)
    assert len(dask["written"]) == len(local["written"]) == 6
    assert sorted(name for _, _, name in seen) == ["a.off", "b.off", "c.off"]
    assert contents(tmp_path / "local") == contents(tmp_path / "dask")
