# SPDX-License-Identifier: LGPL-3.0-or-later
# Type stubs of the package exbsp: the extension's names (_exbsp.pyi), drawing_set and
# build_distributed.
import numpy.typing as npt
from typing import Any, Callable, Dict, Optional, Sequence, Union

from ._exbsp import *  # noqa: F401,F403
from ._exbsp import DEFAULT_HEURISTIC as DEFAULT_HEURISTIC
from ._exbsp import HEURISTICS as HEURISTICS
from ._exbsp import KERNELS as KERNELS
from ._exbsp import Candidate as Candidate
from ._exbsp import DistributedBuild as DistributedBuild
from ._exbsp import Error as Error
from ._exbsp import InputError as InputError
from ._exbsp import LimitError as LimitError
from ._exbsp import OutputError as OutputError
from ._exbsp import PathArg
from ._exbsp import Tree as Tree
from ._exbsp import UsageError as UsageError
from ._exbsp import __version__ as __version__
from ._exbsp import build as build
from ._exbsp import build_cell as build_cell
from ._exbsp import deserialize as deserialize
from ._exbsp import drawing as drawing
from ._exbsp import load as load
from ._exbsp import plan_build as plan_build
from ._exbsp import read_mesh as read_mesh
from ._exbsp import section as section
from ._exbsp import today_date as today_date
from ._exbsp import version as version

def drawing_set(
    parts: Union[PathArg, Sequence[PathArg]],
    outdir: PathArg,
    *,
    formats: Sequence[str] = ...,
    workers: Optional[int] = ...,
    scheduler: object = ...,
    force: bool = ...,
    progress: Callable[[int, int, str], None] = ...,
    **options: object,
) -> Dict[str, Any]: ...

def build_distributed(
    vertices: npt.ArrayLike,
    faces: Any,
    *,
    scheduler: object = ...,
    report: Optional[Dict[str, Any]] = ...,
    progress: Optional[Callable[[int, int], None]] = ...,
    **options: object,
) -> Tree: ...
