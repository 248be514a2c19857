# SPDX-License-Identifier: LGPL-3.0-or-later
# Tree.inserted (docs/python.md "Incremental insertion"): a naive tree that takes new triangles
# is the tree exbsp.build makes with heuristic='naive' of the old triangles followed by the new
# ones, byte for byte; the original stays as it was; other heuristics and the fragment limit
# are refused. Run by ctest with the other tests of tests/python.
import os

import numpy as np
import pytest

import exbsp

MESHES = os.path.join(os.environ.get("EXBSP_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..")),
                      "data", "meshes")


def random_mesh(n, seed):
    rng = np.random.default_rng(seed)
    centres = rng.uniform(0, 4, size=(n, 1, 3))
    vertices = (centres + rng.uniform(-0.6, 0.6, size=(n, 3, 3))).reshape(-1, 3)
    faces = np.arange(3 * n, dtype=np.int64).reshape(n, 3)
    return vertices, faces


def concatenated(old, new):
    """The input bsp::build sees for old followed by new (triangle_soup::append)."""
    (v0, f0), (v1, f1) = old, new
    return np.vstack([v0, v1]), np.vstack([f0, f1 + len(v0)])


def same_bytes(a, b):
    return a.serialize(reproducible=True) == b.serialize(reproducible=True)


@pytest.mark.parametrize("kernel", ["exact", "epeck", "double"])
def test_inserted_is_the_naive_build_of_the_concatenation(kernel):
    old, new = random_mesh(60, 1), random_mesh(40, 2)
    tree = exbsp.build(*old, kernel=kernel, heuristic="naive")
    grown = tree.inserted(*new)
    whole = exbsp.build(*concatenated(old, new), kernel=kernel, heuristic="naive")
    assert same_bytes(grown, whole)
    assert grown.stats["splits"] > 0 and grown.stats["input_triangles"] == 100
    for eye in [(0.3, -7, 11), (2, 2, 2), (-5, 2, -3)]:
        assert np.array_equal(grown.order(eye=eye), whole.order(eye=eye))
        assert np.array_equal(grown.order(direction=eye), whole.order(direction=eye))
    # Face ids continue after the old ones.
    assert grown.fragments()[1].max() == 99


def test_the_original_stays_and_inserts_chain():
    parts = [random_mesh(30, s) for s in (3, 4, 5)]
    tree = exbsp.build(*parts[0], heuristic="naive")
    before = tree.serialize(reproducible=True)
    grown = tree.inserted(*parts[1]).inserted(*parts[2])
    assert tree.serialize(reproducible=True) == before
    whole = exbsp.build(*concatenated(concatenated(parts[0], parts[1]), parts[2]), heuristic="naive")
    assert same_bytes(grown, whole)
    assert same_bytes(tree.inserted(np.zeros((0, 3)), []), tree)


def test_a_corpus_mesh_in_halves():
    path = os.path.join(MESHES, "joint.off")
    if not os.path.exists(path):
        pytest.skip(f"{path} missing (run scripts/setup)")
    vertices, triangles, face_ids = exbsp.read_mesh(path)
    half = len(triangles) // 2
    tree = exbsp.build(vertices, triangles[:half], heuristic="naive", face_ids=face_ids[:half])
    grown = tree.inserted(vertices, triangles[half:], face_ids=face_ids[half:] - face_ids[half])
    whole = exbsp.build(np.vstack([vertices, vertices]),
                        np.vstack([triangles[:half], triangles[half:] + len(vertices)]),
                        heuristic="naive",
                        face_ids=np.concatenate([face_ids[:half],
                                                 face_ids[half:] - face_ids[half] + face_ids[half - 1] + 1]))
    assert same_bytes(grown, whole)


def test_other_heuristics_and_the_limit_are_refused():
    old, new = random_mesh(30, 6), random_mesh(30, 7)
    with pytest.raises(exbsp.UsageError, match="naive"):
        exbsp.build(*old, heuristic="sampled").inserted(*new)
    tree = exbsp.build(*old, heuristic="naive")
    with pytest.raises(exbsp.LimitError):
        tree.inserted(*new, max_fragments=len(tree) + 1)
    with pytest.raises(exbsp.UsageError):
        tree.inserted(*new[:1], [[0, 1, 99]])
