"""Type stubs of the extension module placecat._placecat (the Rust core)."""

from os import PathLike
from typing import Any, Dict, List, Literal, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

_Path = Union[str, PathLike]
_Params = Union[None, str, Mapping[str, Any]]
_Labels = Union[npt.ArrayLike, Sequence[int]]
_Names = Union[Mapping[int, str], Sequence[Tuple[int, str]]]

MATRIX_LIMIT: int
MAX_RESTARTS: int

class PlacecatError(ValueError):
    """An error of placecat's core; the message names the file."""

def read(
    path: _Path,
    *,
    lenient: bool = False,
    max_points: Optional[int] = None,
    max_bytes: Optional[int] = None,
    origin: Optional[Tuple[float, float, float]] = None,
) -> npt.NDArray[np.float32]:
    """A scan file (PLY, PCD, KITTI .bin, LAS/LAZ, E57) as (N, 3) float32."""

def read_bytes(
    data: bytes,
    name: str,
    *,
    lenient: bool = False,
    max_points: Optional[int] = None,
    max_bytes: Optional[int] = None,
    origin: Optional[Tuple[float, float, float]] = None,
) -> npt.NDArray[np.float32]:
    """read() from a file's bytes; name tells .bin files and names errors."""

def presets() -> List[str]:
    """The names of the descriptor parameter presets."""

def preset_notes() -> List[Dict[str, Any]]:
    """Every preset's name, one-line note and whether it was withdrawn."""

def params(params: _Params = None) -> Dict[str, Any]:
    """Descriptor parameters: a preset's, or overrides over one."""

def describe(points: npt.ArrayLike, params: _Params = None) -> Descriptor:
    """Describe an (N, 3) array of points (GIL released)."""

def describe_file(
    path: _Path,
    params: _Params = None,
    *,
    lenient: bool = False,
    max_points: Optional[int] = None,
    max_bytes: Optional[int] = None,
    origin: Optional[Tuple[float, float, float]] = None,
) -> Descriptor:
    """Read and describe a scan file (GIL released); errors name the file."""

def describe_bytes(
    data: bytes,
    name: str,
    params: _Params = None,
    *,
    lenient: bool = False,
    max_points: Optional[int] = None,
    max_bytes: Optional[int] = None,
    origin: Optional[Tuple[float, float, float]] = None,
) -> Descriptor:
    """Read and describe a scan from its file's bytes (GIL released)."""

def evaluate(truth: Sequence[str], labels: Sequence[int]) -> Dict[str, Any]:
    """accuracy, ari, score, inliers, total, confusion."""

class Descriptor:
    """A scan's descriptor and the parameters it was made with; picklable."""

    @property
    def rows(self) -> int: ...
    @property
    def cols(self) -> int: ...
    @property
    def matrices(self) -> npt.NDArray[np.uint32]:
        """(orientations, rows, cols) counts."""
    @property
    def total(self) -> int: ...
    @property
    def summary(self) -> Dict[str, Any]: ...
    @property
    def unreliable(self) -> bool: ...
    @property
    def params(self) -> Dict[str, Any]: ...
    def to_json(self) -> str: ...
    def descriptor_json(self) -> str: ...
    @staticmethod
    def from_json(text: str) -> Descriptor: ...
    @staticmethod
    def from_parts(params_json: str, descriptor_json: str) -> Descriptor: ...
    def __eq__(self, other: object) -> bool: ...

class Tree:
    """Hierarchical k-means++ tree; cut anywhere, export for scipy."""

    @property
    def n(self) -> int: ...
    @property
    def nodes(self) -> List[Dict[str, Any]]: ...
    def cut(self, threshold: float) -> Dict[str, Any]:
        """labels (int32 array), threshold, categories, nodes."""
    def cut_k(self, k: int) -> Dict[str, Any]: ...
    def count_at(self, threshold: float) -> int: ...
    def linkage(self) -> npt.NDArray[np.float64]:
        """scipy.cluster.hierarchy linkage matrix, (n - 1, 4)."""

class Collection:
    """Descriptors of one parameter set and the clustering calls on them."""

    def __init__(
        self,
        descriptors: Sequence[Descriptor],
        names: Optional[Sequence[str]] = None,
        params: _Params = None,
    ) -> None: ...
    def add(self, descriptor: Descriptor, name: Optional[str] = None) -> int: ...
    def __len__(self) -> int: ...
    @property
    def names(self) -> List[str]: ...
    @property
    def params(self) -> Dict[str, Any]: ...
    @property
    def descriptors(self) -> List[Descriptor]: ...
    def delta(self, i: int, j: int) -> float: ...
    def delta_matrix(self) -> npt.NDArray[np.float32]: ...
    def kmeans(
        self,
        k: Union[int, Literal["auto"], None] = None,
        seeding: str = "plusplus",
        seed: int = 0,
        restarts: int = 1,
    ) -> Dict[str, Any]:
        """labels, k, categories, seeding, seed, iterations, converged, cost,
        restarts, restart: the cheapest of `restarts` k-means runs (1: the
        paper's single run; at most 1000). `seeding`: plusplus, random,
        stride (the paper's deterministic seeding, scans i*n/k of the set's
        order, so its result depends on that order: docs/stride-order.md) or
        spectral (each centre starts at the mean of one group of spectral
        clustering seeded with `seed`; one run, at most 2000 scans;
        recommended for sets of room scans described with indoor_searched or
        indoor_objects: docs/spectral-seeding-round.md; it needs k, as "auto"
        said one category on room sets: docs/spectral-seeding-k-dev.md)."""
    def kmedoids(self, k: int, seed: int = 0) -> Dict[str, Any]: ...
    def spectral(
        self, k: int, seed: int = 0, restarts: int = 10, neighbours: int = 7
    ) -> Dict[str, Any]:
        """Spectral clustering on the Delta matrix (at most 2000 scans):
        labels, eigenvalues (the k leading), cost, restart."""
    def hkmeans(self, seed: int = 0, restarts: int = 1) -> Tree:
        """The whole tree; `restarts` 2-means++ trials at every split, the
        cheapest kept (1: the paper's tree; at most 1000)."""
    def choose_categories(
        self, tree: Optional[Tree] = None, seeding: str = "plusplus", seed: int = 0
    ) -> Dict[str, Any]:
        """k, rule, scores, one_category: the CLI's default choice, for
        `tree`'s cuts when given, else for k-means with `seeding` (as for
        kmeans; refused for spectral seeding, which needs k:
        docs/spectral-seeding-k-dev.md)."""
    def dbscan(self, eps: float, min_points: int) -> npt.NDArray[np.int32]: ...
    def medoids(self, labels: _Labels) -> List[Tuple[int, int]]: ...
    def evaluate(self, truth: Sequence[str], labels: _Labels) -> Dict[str, Any]: ...
    def build_model(self, labels: _Labels, names: Optional[_Names] = None) -> Model: ...

class Model:
    """Named categories; the JSON of the CLI's model and the page's export."""

    @staticmethod
    def from_json(text: str) -> Model: ...
    @staticmethod
    def load(path: _Path) -> Model: ...
    def to_json(self) -> str: ...
    def save(self, path: _Path) -> None: ...
    @property
    def categories(self) -> List[Dict[str, Any]]: ...
    @property
    def params(self) -> Dict[str, Any]: ...
    def renamed(self, names: _Names) -> Model: ...
    def classify(self, descriptor: Descriptor) -> Dict[str, Any]:
        """name, label, distance, relative."""
    def classify_file(self, path: _Path, *, lenient: bool = False) -> Dict[str, Any]: ...
    def __eq__(self, other: object) -> bool: ...

class Scans:
    """The scans of a recording, one at a time: dicts with "name"
    (``run.bag:/points:000042``, ``site.e57:hall``: the file's base name),
    "points" ((N, 3) float32, the sensor's frame), "pose" (dict or None) and
    "stamp"; unreadable ones are skipped with a warning and listed in
    ``errors``, each naming the file."""

    @property
    def total(self) -> int: ...
    @property
    def met(self) -> int: ...
    @property
    def topic(self) -> Optional[str]: ...
    @property
    def errors(self) -> List[str]: ...
    def __iter__(self) -> "Scans": ...
    def __next__(self) -> Dict[str, Any]: ...

def scans(
    path: _Path,
    *,
    topic: Optional[str] = None,
    every: int = 1,
    every_metres: Optional[float] = None,
    max_points: Optional[int] = None,
    name: Optional[str] = None,
) -> Scans:
    """The scans of a ROS bag (.bag, .mcap) or an E57 survey, one at a time;
    ``name`` replaces the file's base name at the start of the scans' names."""
