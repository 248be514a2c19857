# SPDX-License-Identifier: LGPL-3.0-or-later
# Hostile input to the Python module (issue "hostile input, round two"): each case crashed,
# aborted, hung or answered wrongly before its fix. A crash takes the user's interpreter with
# it, so the dangerous ones run in a subprocess and check its exit status.
import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import exbsp

SOURCE = os.environ.get("EXBSP_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
FANDISK = os.path.join(SOURCE, "data", "meshes", "fandisk.off")
TRI = (np.eye(3), [[0, 1, 2]])


def run_python(code, env=None, prefix=()):
    """Runs `code` in a fresh interpreter with this exbsp; returns the CompletedProcess."""
    e = dict(os.environ)
    e["PYTHONPATH"] = os.pathsep.join(p for p in sys.path if p)
    e.update(env or {})
    return subprocess.run([*prefix, sys.executable, "-c", textwrap.dedent(code)], env=e,
                          capture_output=True, text=True, timeout=300)


def test_thread_counts_out_of_range_raise():
    limit = exbsp.build(*TRI).stats["input_triangles"]  # the module works
    assert limit == 1
    for threads in (100000, 2**31, 10**6):
        with pytest.raises(exbsp.UsageError, match="threads"):
            exbsp.build(*TRI, threads=threads)


def test_an_absurd_omp_num_threads_is_clamped():
    r = run_python("""
        import exbsp, numpy as np
        t = exbsp.build(np.random.default_rng(0).random((300, 3)), [[i, i + 1, i + 2] for i in range(297)])
        print(len(t) > 0)
    """, env={"OMP_NUM_THREADS": "100000"})
    assert r.returncode == 0 and r.stdout.strip() == "True", (r.returncode, r.stderr[-2000:])


def test_an_uninitialised_tree_raises_instead_of_crashing():
    r = run_python("""
        import exbsp
        t = exbsp.Tree.__new__(exbsp.Tree)
        for call in (lambda: t.order(eye=(1, 2, 3)), lambda: len(t), lambda: t.stats,
                     lambda: t.fragments(), lambda: t.exact(0), lambda: t.save("x.exbsp"),
                     lambda: t.serialize(), lambda: exbsp.Tree.order(5, eye=(1, 1, 1))):
            try:
                call()
                print("no error")
            except TypeError as e:
                print("TypeError")
        u = exbsp.Tree.__new__(exbsp.Tree)
        try:
            u.__setstate__(b"not a tree")
        except exbsp.InputError:
            print("InputError")
        try:
            len(u)
        except TypeError:
            print("TypeError")
    """)
    assert r.returncode == 0, (r.returncode, r.stderr[-2000:])
    assert r.stdout.split() == ["TypeError"] * 8 + ["InputError", "TypeError"]


def test_interpreter_exit_during_a_build_in_a_daemon_thread_does_not_abort():
    r = run_python("""
        import threading, time
        import numpy as np
        import exbsp
        rng = np.random.default_rng(1)
        v = rng.random((3000, 3))
        f = [[i, i + 1, i + 2] for i in range(2997)]
        def build_forever():
            while True:
                exbsp.build(v, f, score=lambda c: c.straddling, heuristic="custom")
        threading.Thread(target=build_forever, daemon=True).start()
        time.sleep(0.5)
        print("exit")
    """)
    assert r.returncode == 0, (r.returncode, r.stderr[-2000:])
    assert "exit" in r.stdout


@pytest.mark.skipif(not os.path.exists(FANDISK), reason="the CGAL corpus is missing")
def test_ctrl_c_stops_a_min_split_build_within_a_second():
    r = run_python(f"""
        import os, signal, threading, time
        import exbsp
        v, t, ids = exbsp.read_mesh({FANDISK!r})
        sent = []
        def interrupt():
            time.sleep(1.0)
            sent.append(time.time())
            os.kill(os.getpid(), signal.SIGINT)
        threading.Thread(target=interrupt, daemon=True).start()
        try:
            exbsp.build(v, t, heuristic="min-split")
            print("finished")
        except KeyboardInterrupt:
            print("%.3f" % (time.time() - sent[0]))
    """)
    assert r.returncode == 0, r.stderr[-2000:]
    assert r.stdout.strip() != "finished"
    assert float(r.stdout.strip()) < 1.0


@pytest.mark.skipif(bool(os.environ.get("EXBSP_SANITIZED")),
                    reason="AddressSanitizer needs more address space than the cap leaves")
def test_allocation_failures_raise_memory_error():
    r = run_python("""
        import numpy as np, exbsp
        faces = np.zeros((10**8, 3), np.int8)
        try:
            exbsp.build(np.eye(3), faces)
        except MemoryError:
            print("MemoryError")
    """, prefix=("prlimit", "--as=1500000000"))
    assert r.stdout.strip() == "MemoryError", (r.returncode, r.stdout, r.stderr[-2000:])


def test_paths_with_a_nul_byte_are_refused(tmp_path):
    tree = exbsp.build(*TRI)
    victim = tmp_path / "victim.txt"
    victim.write_text("keep me")
    with pytest.raises(exbsp.UsageError, match="NUL"):
        tree.save(str(victim) + "\0.exbsp")
    assert victim.read_text() == "keep me"
    tree.save(tmp_path / "s.exbsp")  # os.PathLike is a path
    with pytest.raises(exbsp.UsageError, match="NUL"):
        exbsp.load(str(tmp_path / "s.exbsp") + "\0/no/such/file")
    with pytest.raises(exbsp.UsageError, match="NUL"):
        exbsp.read_mesh(str(tmp_path / "m.off") + "\0")
    assert len(exbsp.load(tmp_path / "s.exbsp")) == len(tree)


def test_a_saved_tree_not_in_canonical_form_is_refused():
    # An exact tree with one constructed point appended that no fragment uses: every check of
    # the format passes (the point is a valid SEG(p, q, plane): a copy of an existing one), but
    # saving the loaded tree would drop it and give other bytes. Only the canonical form loads.
    import struct
    import zlib
    rng = np.random.default_rng(7)
    v = rng.random((60, 3))
    f = [[3 * i, 3 * i + 1, 3 * i + 2] for i in range(20)]
    data = bytearray(exbsp.build(v, f, heuristic="naive").serialize())
    assert exbsp.deserialize(bytes(data)).serialize() == bytes(data)  # the real file loads
    at = 24 + 8 * 8 + 8
    (n,) = struct.unpack_from("<I", data, at)
    at += 4 + n + 12 + 4
    (vertices,) = struct.unpack_from("<Q", data, at)
    at += 8 + 24 * vertices
    (triangles,) = struct.unpack_from("<Q", data, at)
    at += 8 + 16 * triangles
    (points,) = struct.unpack_from("<Q", data, at)
    assert points > 0, "the build made no split point"
    first = at + 8
    end = first + 12 * points
    forged = data[:at] + struct.pack("<Q", points + 1) + data[first:end] + data[first:first + 12] + data[end:]
    body = len(forged) - 28
    struct.pack_into("<Q", forged, 16, body)
    struct.pack_into("<I", forged, len(forged) - 4, zlib.crc32(bytes(forged[:-4])))
    with pytest.raises(exbsp.InputError, match="canonical"):
        exbsp.deserialize(bytes(forged))
