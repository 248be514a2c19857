# SPDX-License-Identifier: LGPL-3.0-or-later
"""exbsp: exact-predicate BSP trees, orders, sections and drawing sheets of triangle meshes.

The engine is the C++ extension exbsp._exbsp (pybind11); drawing_set runs `exbsp drawing`
over many parts, in a local process pool or on a Dask cluster, and build_distributed grows one
tree's subtrees on a Dask cluster. Manual: docs/python.md.
"""
from ._exbsp import *  # noqa: F401,F403  (the extension's public names)
from ._exbsp import __doc__ as _engine_doc  # noqa: F401
from ._exbsp import __version__, version  # noqa: F401
from .distributed import build_distributed  # noqa: F401
from .drawing_sets import drawing_set  # noqa: F401
