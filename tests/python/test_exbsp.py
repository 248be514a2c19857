# SPDX-License-Identifier: LGPL-3.0-or-later
# Tests of the Python module exbsp (src/python, docs/python.md), run by ctest as
#   PYTHONPATH=build/src/python /usr/bin/python3 -m pytest tests/python
# Degenerate input and misuse first; then orders, exact Fractions (checked against the same
# intersection computed with fractions in Python), sections, score callbacks and errors.
import math
import os
import threading
from fractions import Fraction

import numpy as np
import pytest

import exbsp

MESHES = os.path.join(os.environ.get("EXBSP_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..")),
                      "data", "meshes")


def mesh(name):
    path = os.path.join(MESHES, name)
    if not os.path.exists(path):
        pytest.skip(f"{path} missing (run scripts/setup)")
    return exbsp.read_mesh(path)


def exact_fragments(tree):
    return [tree.exact(i) for i in range(len(tree))]


def same_tree(a, b):
    """Same fragments (exact, face ids), nodes, depth and orders."""
    assert len(a) == len(b)
    for key in ("fragments", "splits", "nodes", "depth", "degenerate_input"):
        assert a.stats[key] == b.stats[key], key
    assert np.array_equal(a.fragments()[1], b.fragments()[1])
    assert exact_fragments(a) == exact_fragments(b)
    for eye in [(0.3, -7, 11), (-5, 2, -3), (1, 1, 1)]:
        assert np.array_equal(a.order(eye=eye), b.order(eye=eye))
        assert np.array_equal(a.order(direction=eye), b.order(direction=eye))


# Two triangles crossing each other: each plane splits the other triangle.
CROSSING_V = np.array([[-1, -1, 0.1], [1, -1, 0.3], [0, 1, -0.2],
                       [0.1, -0.7, -1], [-0.2, 0.3, 1], [0.3, 0.9, -1.1]], dtype=np.float64)
CROSSING_F = np.array([[0, 1, 2], [3, 4, 5]])

# --- degenerate input ---------------------------------------------------------------------------


def test_empty_input_gives_an_empty_tree():
    for vertices, faces in [(np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64)), ([], []), (np.zeros((0, 3)), [])]:
        t = exbsp.build(vertices, faces)
        assert len(t) == 0 and t.stats["nodes"] == 0 and t.stats["input_triangles"] == 0
        order = t.order(eye=(0, 0, 1))
        assert order.dtype == np.uint32 and order.shape == (0,)
        v, f = t.fragments()
        assert v.shape == (0, 3, 3) and v.dtype == np.float64 and f.shape == (0,) and f.dtype == np.uint32


def test_collinear_and_repeated_vertex_triangles_are_skipped_and_counted():
    v = np.array([[0, 0, 0], [1, 1, 1], [2, 2, 2], [0, 1, 0]], dtype=np.float64)
    t = exbsp.build(v, [[0, 1, 2], [0, 0, 0], [0, 1, 3]])
    assert t.stats["input_triangles"] == 3
    assert t.stats["degenerate_input"] == 2
    assert len(t) == 1 and t.fragments()[1].tolist() == [2]


def test_bad_arguments_raise_usage_errors_naming_the_argument():
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=np.float64)
    cases = [
        (dict(vertices=v[:, :2], faces=[[0, 1, 2]]), "vertices"),
        (dict(vertices=v, faces=[[0, 1, 3]]), "faces[0][2] = 3"),
        (dict(vertices=v, faces=[[0, 1, -1]]), "faces[0][2] = -1"),
        (dict(vertices=v, faces=[[0, 1]]), "faces[0] has 2 vertices"),
        (dict(vertices=v, faces=np.array([[0.0, 1.0, 2.0]])), "integer"),
        (dict(vertices=v, faces=[[0, 1.5, 2]]), "faces[0][1] is not an integer"),
        (dict(vertices=v, faces=[[0, 1, 2]], kernel="exakt"), "unknown kernel"),
        (dict(vertices=v, faces=[[0, 1, 2]], heuristic="fastest"), "unknown heuristic"),
        (dict(vertices=v, faces=[[0, 1, 2]], heuristic="custom"), "score callback"),
        (dict(vertices=v, faces=[[0, 1, 2]], heuristic="naive", score=lambda c: 0), "use heuristic 'custom'"),
        (dict(vertices=v, faces=[[0, 1, 2]], score=lambda c: 0, candidates="some"), "candidates"),
        (dict(vertices=v, faces=[[0, 1, 2]], face_ids=[0, 1]), "face_ids has 2 entries"),
        (dict(vertices=np.array([[0, 0, np.nan], [1, 0, 0], [0, 1, 0]]), faces=[[0, 1, 2]]), "non-finite"),
    ]
    for kwargs, message in cases:
        with pytest.raises(exbsp.UsageError, match=message.replace("[", r"\[").replace("]", r"\]")) as info:
            exbsp.build(**kwargs)
        assert isinstance(info.value, ValueError) and isinstance(info.value, exbsp.Error)


def test_order_needs_exactly_one_of_eye_and_direction():
    t = exbsp.build(CROSSING_V, CROSSING_F)
    with pytest.raises(exbsp.UsageError):
        t.order()
    with pytest.raises(exbsp.UsageError):
        t.order(eye=(0, 0, 5), direction=(0, 0, -1))
    with pytest.raises(exbsp.UsageError, match="zero"):
        t.order(direction=(0, 0, 0))
    with pytest.raises(exbsp.UsageError, match="finite"):
        t.order(eye=(0, math.inf, 0))
    with pytest.raises(IndexError):
        t.exact(len(t))


# --- building and ordering ----------------------------------------------------------------------


def test_polygons_are_fan_triangulated_and_keep_their_face_ids():
    v = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
    t = exbsp.build(v, [[0, 1, 2, 3], [0, 1, 4]], heuristic="naive")
    assert t.stats["input_triangles"] == 3
    assert sorted(t.fragments()[1].tolist()) == [0, 0, 1]
    # Explicit face ids (as read_mesh returns them) replace the row index.
    t = exbsp.build(v, np.array([[0, 1, 2], [0, 2, 3]], dtype=np.uint8), face_ids=[7, 7])
    assert t.fragments()[1].tolist() == [7, 7]


def test_stacked_triangles_are_ordered_back_to_front():
    n = 5
    v = np.array([p for z in range(n) for p in ([0, 0, z], [1, 0, z], [0, 1, z])], dtype=np.float64)
    f = np.arange(3 * n).reshape(n, 3)
    t = exbsp.build(v, f)
    faces = t.fragments()[1]
    assert faces[t.order(eye=(0.2, 0.2, 100))].tolist() == list(range(n))
    assert faces[t.order(eye=(0.2, 0.2, -100))].tolist() == list(reversed(range(n)))
    assert faces[t.order(direction=(0, 0, -1))].tolist() == list(range(n))
    assert faces[t.order(eye=(0.2, 0.2, 100), back_to_front=False)].tolist() == list(reversed(range(n)))


def test_exact_kernels_give_the_same_tree_and_inexact_ones_refuse_exact_output():
    trees = [exbsp.build(CROSSING_V, CROSSING_F, kernel=k) for k in ("exact", "epeck", "gmpq")]
    same_tree(trees[0], trees[1])
    same_tree(trees[0], trees[2])
    assert trees[0].stats["splits"] == 1 and trees[0].kernel == "exact"
    d = exbsp.build(CROSSING_V, CROSSING_F, kernel="double")
    with pytest.raises(exbsp.UsageError):
        d.exact(0)


def plane_segment_intersection(a, b, c, p, q):
    """plane(a, b, c) ∩ [p, q] in exact rationals (the inputs are the exact doubles)."""
    a, b, c, p, q = ([Fraction(float(x)) for x in point] for point in (a, b, c, p, q))
    u = [b[i] - a[i] for i in range(3)]
    w = [c[i] - a[i] for i in range(3)]
    n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
    fp = sum(n[i] * (p[i] - a[i]) for i in range(3))
    fq = sum(n[i] * (q[i] - a[i]) for i in range(3))
    t = fp / (fp - fq)
    return tuple(p[i] + t * (q[i] - p[i]) for i in range(3))


def test_split_points_are_exact_fractions_equal_to_the_plane_intersection():
    t = exbsp.build(CROSSING_V, CROSSING_F, heuristic="naive")  # triangle 0's plane splits triangle 1
    assert t.stats["splits"] == 1
    inputs = {tuple(Fraction(float(x)) for x in p) for p in CROSSING_V}
    made = {p for i in range(len(t)) for p in t.exact(i) if p not in inputs}
    # Triangle 1's edges that cross triangle 0's plane: the expected new points, with fractions.
    tri0, tri1 = CROSSING_V[[0, 1, 2]], CROSSING_V[[3, 4, 5]]
    expected = set()
    for i, j in ((0, 1), (1, 2), (2, 0)):
        s = [np.sign(np.dot(np.cross(tri0[1] - tri0[0], tri0[2] - tri0[0]), x - tri0[0])) for x in (tri1[i], tri1[j])]
        if s[0] * s[1] < 0:
            expected.add(plane_segment_intersection(*tri0, tri1[i], tri1[j]))
    assert len(expected) == 2 and made == expected
    for point in made:
        assert all(isinstance(x, Fraction) for x in point)
        assert any(x.denominator > 2**60 for x in point)  # not a double: the exactness is real
    # The doubles are the exact values correctly rounded.
    v, _ = t.fragments()
    for i in range(len(t)):
        assert [[float(x) for x in p] for p in t.exact(i)] == v[i].tolist()


def test_ancestors_name_the_planes_above_a_fragment():
    t = exbsp.build(CROSSING_V, CROSSING_F, heuristic="naive")
    root_faces = [i for i in range(len(t)) if not t.ancestors(i)]
    assert len(root_faces) == 1
    for i in range(len(t)):
        for plane, side in t.ancestors(i):
            assert plane == 0 and side in (1, -1)


def test_max_fragments_raises_a_limit_error_and_returns_nothing():
    with pytest.raises(exbsp.LimitError) as info:
        exbsp.build(CROSSING_V, CROSSING_F, heuristic="naive", max_fragments=2)
    assert isinstance(info.value, MemoryError)


def test_sampled_parameters_are_used():
    v, f, ids = mesh("joint.off")
    a = exbsp.build(v, f, face_ids=ids, heuristic="sampled")
    b = exbsp.build(v, f, face_ids=ids, heuristic="sampled", sampled=(1, 512, 8))
    assert a.stats["fragments"] != b.stats["fragments"] or exact_fragments(a) != exact_fragments(b)


# --- meshes and sections ------------------------------------------------------------------------


def test_read_mesh_gives_vertices_triangles_and_face_ids(tmp_path):
    path = tmp_path / "quad.off"
    path.write_text("OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 0.1\n4 0 1 2 3\n3 0 1 4\n")
    v, t, ids = exbsp.read_mesh(str(path))
    assert v.shape == (5, 3) and v.dtype == np.float64 and v[4, 2] == 0.1
    assert t.tolist() == [[0, 1, 2], [0, 2, 3], [0, 1, 4]] and t.dtype == np.uint32
    assert ids.tolist() == [0, 0, 1]
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n")
    with pytest.raises(exbsp.InputError) as info:
        exbsp.read_mesh(str(bad))
    assert info.value.file == str(bad) and info.value.line == 4 and isinstance(info.value, ValueError)


def unit_cube():
    v = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=np.float64)
    quads = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]]
    return v, quads


def test_section_of_a_cube_is_closed_with_exact_points_on_the_plane():
    v, quads = unit_cube()
    plane = (1.0, 1.0, 1.0, -0.7)  # 0.7 is not a binary fraction: the cut points are not doubles
    r = exbsp.section(v, quads, plane)
    assert r["closed"] and len(r["outline"]) == 1 and r["outline"][0]["closed"]
    A, B, C, D = (Fraction(x) for x in plane)
    for i in r["outline"][0]["points"]:
        x, y, z = r["exact"][i]
        assert A * x + B * y + C * z + D == 0
        assert [float(c) for c in r["exact"][i]] == r["points"][i].tolist()
    # kept ∪ cap is closed: every directed edge is matched by its reverse.
    edges = {}
    for tri in np.vstack([r["kept"], r["cap"]]).tolist():
        for k in range(3):
            e = (tri[k], tri[(k + 1) % 3])
            edges[e] = edges.get(e, 0) + 1
    assert all(edges.get((b, a), 0) == n for (a, b), n in edges.items())
    assert r["stats"]["cap_triangles"] == len(r["cap"]) > 0
    assert set(r["kept_faces"].tolist()) <= set(range(6)) and r["cap_face"] == 6
    assert r["points"][r["kept"]].shape == (len(r["kept"]), 3, 3)


def test_section_rejects_a_bad_plane_and_can_skip_exact_text_and_cap():
    v, quads = unit_cube()
    with pytest.raises(exbsp.UsageError):
        exbsp.section(v, quads, (0, 0, 0, 1))
    r = exbsp.section(v, quads, (0, 0, 1, -0.5), cap=False, exact=False)
    assert "exact" not in r and len(r["cap"]) == 0 and len(r["outline"]) == 1


# --- score callbacks ----------------------------------------------------------------------------


def test_a_python_score_reproduces_min_split_exactly():
    for name in ("cube.off", "cross.off", "joint.off"):
        v, f, ids = mesh(name)
        reference = exbsp.build(v, f, face_ids=ids, heuristic="min-split")
        for threads in (1, 2):
            custom = exbsp.build(v, f, face_ids=ids, score=lambda c: c.straddling, threads=threads)
            assert custom.stats["heuristic"] == "custom"
            same_tree(custom, reference)


def test_a_python_score_over_sampled_candidates_reproduces_sampled():
    v, f, ids = mesh("joint.off")
    reference = exbsp.build(v, f, face_ids=ids, heuristic="sampled", seed=7, sampled=(5, 40, 8))
    custom = exbsp.build(v, f, face_ids=ids, seed=7, sampled=(5, 40, 8), candidates="sampled",
                         score=lambda c: 8 * c.straddling + abs(c.positive - c.negative))
    same_tree(custom, reference)


def test_the_score_sees_each_candidate_with_counts_over_the_list():
    seen, reprs = [], []
    lock = threading.Lock()

    def score(c):
        with lock:
            reprs.append(repr(c))
            seen.append((c.depth, c.candidate, c.face, c.positive + c.negative + c.straddling + c.coplanar, c.list_size))
        return c.straddling

    exbsp.build(CROSSING_V, CROSSING_F, score=score)
    root = sorted(s for s in seen if s[0] == 1)
    assert [(s[1], s[2]) for s in root] == [(0, 0), (1, 1)]
    assert all(counted == size - 1 for _, _, _, counted, size in seen)
    assert reprs[0].startswith("Candidate(candidate=") and isinstance(exbsp.Candidate, type)


def test_exceptions_from_the_score_propagate_unchanged():
    class Refused(Exception):
        pass

    def refuse(c):
        if c.depth >= 2:
            raise Refused(f"depth {c.depth}")
        return c.straddling

    v, f, ids = mesh("cross.off")
    for threads in (1, 2, 4):
        with pytest.raises(Refused):
            exbsp.build(v, f, face_ids=ids, score=refuse, threads=threads)
    with pytest.raises(TypeError):
        exbsp.build(CROSSING_V, CROSSING_F, score=lambda c: "low")
    with pytest.raises(exbsp.UsageError, match="NaN"):
        exbsp.build(CROSSING_V, CROSSING_F, score=lambda c: math.nan)
    with pytest.raises(exbsp.UsageError, match="callable"):
        exbsp.build(CROSSING_V, CROSSING_F, score=3)


def test_trees_can_be_used_from_other_python_threads():
    v, f, ids = mesh("cross.off")
    t = exbsp.build(v, f, face_ids=ids)
    expected = t.order(eye=(1, 2, 3))
    results = [None] * 4

    def work(k):
        results[k] = t.order(eye=(1, 2, 3))

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    assert all(np.array_equal(r, expected) for r in results)


def test_saved_and_pickled_trees_give_the_same_tree(tmp_path):
    import pickle

    for kwargs in (dict(heuristic="min-split"), dict(score=lambda c: c.straddling - c.coplanar)):
        t = exbsp.build(CROSSING_V, CROSSING_F, **kwargs)
        path = tmp_path / "t.exbsp"
        t.save(str(path))
        for copy in (exbsp.load(str(path)), exbsp.deserialize(t.serialize()), pickle.loads(pickle.dumps(t))):
            same_tree(copy, t)
            assert copy.stats["heuristic"] == t.stats["heuristic"]
    (tmp_path / "bad.exbsp").write_bytes(t.serialize()[:-5])
    with pytest.raises(exbsp.InputError):
        exbsp.load(str(tmp_path / "bad.exbsp"))
    with pytest.raises(exbsp.OutputError) as info:
        t.save(str(tmp_path / "missing" / "t.exbsp"))
    assert isinstance(info.value, OSError)


def test_version_and_names():
    assert exbsp.__version__ == exbsp.version and exbsp.version.count(".") == 2
    assert "min-split" in exbsp.HEURISTICS and exbsp.DEFAULT_HEURISTIC in exbsp.HEURISTICS
    assert exbsp.KERNELS[0] == "exact"


# --- rendering ----------------------------------------------------------------------------------


def test_render_draws_edges_over_the_picture_only_when_asked():
    v, quads = unit_cube()
    t = exbsp.build(v, quads)
    plain = t.render(width=160, height=120)
    assert plain.shape == (120, 160, 3) and plain.dtype == np.uint8
    assert np.array_equal(plain, t.render(width=160, height=120, edges="none"))
    edged = t.render(width=160, height=120, edges="visible+hidden")
    changed = (edged != plain).any(axis=2)
    assert changed.sum() > 100
    # Edges are strokes over the faces: every changed pixel is darker than the plain one.
    darker = edged.astype(int).sum(axis=2) < plain.astype(int).sum(axis=2)
    assert (darker | ~changed).all()
    assert edged.tobytes() != plain.tobytes()
    png = t.render(width=160, height=120, format="png", edges="visible")
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    assert 'id="visible-edges"' in t.render(format="svg")  # the SVG's default: visible edges
    assert "visible-edges" not in t.render(format="svg", edges="none")
    with pytest.raises(exbsp.UsageError, match="edges must be"):
        t.render(edges="all")
