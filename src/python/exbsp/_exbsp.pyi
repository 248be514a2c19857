# SPDX-License-Identifier: LGPL-3.0-or-later
# Type stubs of the extension exbsp._exbsp (src/python/exbsp_module.cpp; manual:
# docs/python.md). Checked by tests/python/test_packaging.py (mypy --strict on
# examples/python/render_fandisk.py) and kept beside the module in the wheel.
import os
from fractions import Fraction
from typing import Any, Callable, Dict, List, Literal, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str
version: str
HEURISTICS: Tuple[str, ...]
KERNELS: Tuple[str, ...]
DEFAULT_HEURISTIC: str

PathArg = Union[str, bytes, "os.PathLike[str]", "os.PathLike[bytes]"]
Vec3 = Union[Tuple[float, float, float], Sequence[float], npt.NDArray[np.float64]]
RGB = Tuple[int, int, int]
Faces = Union[npt.ArrayLike, Sequence[Sequence[int]]]

class Error(Exception): ...
class UsageError(Error, ValueError): ...

class InputError(Error, ValueError):
    file: str
    line: int

class LimitError(Error, MemoryError): ...
class OutputError(Error, OSError): ...

class Candidate:
    """What a score callback (build(score=...)) sees for one candidate splitter."""

    @property
    def candidate(self) -> int: ...
    @property
    def face(self) -> int: ...
    @property
    def source(self) -> int: ...
    @property
    def positive(self) -> int: ...
    @property
    def negative(self) -> int: ...
    @property
    def straddling(self) -> int: ...
    @property
    def coplanar(self) -> int: ...
    @property
    def list_size(self) -> int: ...
    @property
    def depth(self) -> int: ...

class Tree:
    """A built BSP tree (exbsp.build). Immutable; safe to share between threads."""

    @property
    def stats(self) -> Dict[str, Union[int, float, str]]: ...
    @property
    def kernel(self) -> str: ...
    def __len__(self) -> int: ...
    def order(
        self,
        *,
        eye: Optional[Vec3] = None,
        direction: Optional[Vec3] = None,
        back_to_front: bool = True,
    ) -> npt.NDArray[np.uint32]: ...
    def fragments(self) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.uint32]]: ...
    def exact(self, i: int) -> Tuple[Tuple[Fraction, Fraction, Fraction], ...]: ...
    def ancestors(self, i: int) -> List[Tuple[int, int]]: ...
    def inserted(
        self,
        vertices: npt.ArrayLike,
        faces: Faces,
        *,
        max_fragments: int = ...,
        face_ids: Optional[npt.ArrayLike] = ...,
    ) -> Tree: ...
    # render's three overloads repeat its signature: typing ties the return type to `format`
    # only this way (an image array, PNG bytes or SVG text).
    # The three overloads of render repeat their keyword list on purpose: an overload cannot
    # share one (PEP 692's Unpack of a TypedDict needs mypy 1.7; Debian 12 has mypy 1.0).
    @overload
    def render(
        self,
        *,
        width: int = ...,
        height: int = ...,
        view: str = ...,
        eye: Optional[Vec3] = ...,
        look_at: Optional[Vec3] = ...,
        up: Vec3 = ...,
        fovy_deg: float = ...,
        format: Literal["image"] = ...,
        edges: Optional[str] = ...,
        color: RGB = ...,
        background: RGB = ...,
    ) -> npt.NDArray[np.uint8]: ...
    @overload
    def render(
        self,
        *,
        width: int = ...,
        height: int = ...,
        view: str = ...,
        eye: Optional[Vec3] = ...,
        look_at: Optional[Vec3] = ...,
        up: Vec3 = ...,
        fovy_deg: float = ...,
        format: Literal["png"],
        edges: Optional[str] = ...,
        color: RGB = ...,
        background: RGB = ...,
    ) -> bytes: ...
    @overload
    def render(
        self,
        *,
        width: int = ...,
        height: int = ...,
        view: str = ...,
        eye: Optional[Vec3] = ...,
        look_at: Optional[Vec3] = ...,
        up: Vec3 = ...,
        fovy_deg: float = ...,
        format: Literal["svg"],
        edges: Optional[str] = ...,
        color: RGB = ...,
        background: RGB = ...,
    ) -> str: ...
    def save(self, path: PathArg) -> None: ...
    def serialize(self, *, reproducible: bool = ...) -> bytes: ...
    def __getstate__(self) -> bytes: ...
    def __setstate__(self, state: bytes) -> None: ...

def build(
    vertices: npt.ArrayLike,
    faces: Faces,
    *,
    kernel: str = ...,
    heuristic: Optional[str] = ...,
    seed: int = ...,
    score: Optional[Callable[[Candidate], float]] = ...,
    candidates: str = ...,
    sampled: Tuple[int, int, int] = ...,
    threads: Optional[int] = ...,
    max_fragments: int = ...,
    face_ids: Optional[npt.ArrayLike] = ...,
) -> Tree: ...
class DistributedBuild:
    """The coordinator of a distributed build (exbsp.plan_build)."""

    @property
    def input(self) -> bytes: ...
    @property
    def cells(self) -> List[bytes]: ...
    def add_part(self, i: int, part: bytes) -> None: ...
    def finish(self) -> Tree: ...

def plan_build(
    vertices: npt.ArrayLike,
    faces: Faces,
    *,
    heuristic: Optional[str] = ...,
    seed: int = ...,
    sampled: Tuple[int, int, int] = ...,
    max_fragments: int = ...,
    face_ids: Optional[npt.ArrayLike] = ...,
) -> DistributedBuild: ...
def build_cell(input: bytes, cell: bytes) -> bytes: ...
def section(
    vertices: npt.ArrayLike,
    faces: Faces,
    plane: Tuple[float, float, float, float],
    *,
    cap: bool = ...,
    exact: bool = ...,
    face_ids: Optional[npt.ArrayLike] = ...,
) -> Dict[str, Any]: ...
def load(path: PathArg) -> Tree: ...
def deserialize(data: bytes) -> Tree: ...
def read_mesh(
    path: PathArg,
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.uint32], npt.NDArray[np.uint32]]: ...
def drawing(
    input: PathArg,
    outputs: Union[PathArg, Sequence[PathArg]],
    *,
    views: Sequence[str] = ...,
    projection: str = ...,
    sheet: str = ...,
    scale: str = ...,
    units: str = ...,
    up: str = ...,
    sections: Sequence[str] = ...,
    lines_only: bool = ...,
    title: str = ...,
    number: str = ...,
    date: str = ...,
    line_widths: Tuple[float, float] = ...,
    crease_deg: float = ...,
    kernel: str = ...,
) -> Dict[str, Any]: ...
def today_date() -> str: ...
