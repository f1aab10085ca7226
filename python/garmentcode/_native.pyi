"""Type stub of the compiled module ``garmentcode._native`` (re-exported by
``garmentcode``)."""

import os
from typing import Any, Callable, Dict, List, Literal, Optional, Sequence, Tuple, Union, overload

import numpy as np

__version__: str

PathLike = Union[str, os.PathLike]
#: A design: a dict (nested as the reference's design files, ``{"meta": {"upper":
#: {"v": "Shirt"}}}``, or flat ``{"meta.upper": "Shirt"}``), YAML text, a built-in
#: design name or a design file path.
DesignLike = Union[Dict[str, Any], str, os.PathLike]
#: A body: a ``Body``, a built-in body name, a body file path, or a dict of
#: measurements (every one, or ``{"base": "mean_female", "waist": 70.0, ...}``:
#: a few over a built-in body).
BodyLike = Union["Body", str, os.PathLike, Dict[str, Any]]
#: A parameter value.
Value = Union[None, bool, int, float, str]

class DesignError(ValueError):
    """A design that is not valid: unknown parameters, wrong types, out of range."""

class BodyError(ValueError):
    """A body that is not valid: unknown or missing measurements, implausible values."""

class BuildError(ValueError):
    """A valid design whose garment cannot be built on the body (or is empty)."""

class PatternError(ValueError):
    """A specification that cannot be read, or a pattern that cannot be drawn or meshed."""

class InputError(ValueError):
    """Other invalid input: bad options, unreadable or unwritable files and folders."""

class DatasetError(RuntimeError):
    """Dataset generation stopped: a sample failed, or it was interrupted."""

class Body:
    """Body measurements: ``Body()`` (the neutral body), ``Body("mean_female")``,
    ``Body("path/to/body.yaml")`` or ``Body({...})``."""

    def __init__(self, source: Optional[BodyLike] = None) -> None: ...
    @staticmethod
    def builtin() -> List[str]:
        """Names of the built-in bodies."""
    @staticmethod
    def from_yaml(text: str, name: str = "body") -> "Body":
        """A body from the text of a body file (``base: NAME`` in its ``body:``
        mapping starts from a built-in body)."""
    @staticmethod
    def from_dict(d: Dict[str, Any]) -> "Body":
        """A body from ``{measurement: value}`` (or ``{"body": {...}}``); with
        ``"base": NAME`` the measurements not given are the built-in body's (the
        web API's ``{"base": NAME, "measurements": {...}}`` reads too)."""
    @staticmethod
    def describe(name: str) -> str:
        """What a raw or ``_``-derived measurement is."""
    @property
    def name(self) -> str:
        """The built-in name or file stem."""
    @property
    def measurements(self) -> Dict[str, float]:
        """Raw measurements (cm, degrees)."""
    @property
    def derived(self) -> Dict[str, float]:
        """Derived values (``_`` names)."""
    def to_yaml(self) -> str:
        """The body file (``body_measurements.yaml``)."""
    def to_dict(self) -> Dict[str, float]:
        """Raw and derived values."""
    def __getitem__(self, name: str) -> float: ...

class DesignSpace:
    """The design space: ``DesignSpace()`` (built-in) or ``DesignSpace(file)``;
    ``extended=True`` adds the parameters past the reference (``extension.*``)."""

    def __init__(self, path: Optional[PathLike] = None, *, extended: bool = False) -> None: ...
    @property
    def source(self) -> Optional[str]:
        """The design file, or None for the built-in space."""
    @property
    def extended(self) -> bool:
        """Whether the space has the ``extension.*`` parameters."""
    @property
    def params(self) -> List[Dict[str, Any]]:
        """Every parameter: path, type, range, default, default_prob, description."""
    @property
    def paths(self) -> List[str]:
        """Parameter paths, in order."""
    def default(self) -> Dict[str, Value]:
        """Every parameter at its default."""
    def validate(self, design: DesignLike) -> Dict[str, Value]:
        """The complete checked values of a design; raises DesignError."""
    @overload
    def sample(
        self, seed: int, index: int, bodies: Optional[Union[str, Sequence[str]]] = None, *, with_body: Literal[False] = False
    ) -> Dict[str, Value]: ...
    @overload
    def sample(
        self, seed: int, index: int, bodies: Optional[Union[str, Sequence[str]]] = None, *, with_body: Literal[True]
    ) -> Tuple[Dict[str, Value], "Body"]: ...
    def sample(
        self, seed: int, index: int, bodies: Optional[Union[str, Sequence[str]]] = None, *, with_body: bool = False
    ) -> Union[Dict[str, Value], Tuple[Dict[str, Value], "Body"]]:
        """The design of sample ``index`` of ``garmentcode sample --seed seed``;
        with ``with_body=True`` ``(design, body)``, the body it was drawn for (as
        the sample's ``body_measurements.yaml``, named as in ``bodies``)."""
    def json_schema(self) -> Dict[str, Any]:
        """The JSON Schema of design files."""
    def to_yaml(self, design: Optional[DesignLike] = None) -> str:
        """A design (default: the defaults) in the reference's design-file layout."""
    def vector_labels(self) -> List[str]:
        """Names of the encoding's slots."""
    def encode(self, design: DesignLike) -> np.ndarray:
        """A design as floats in [0, 1] (numbers by range, flags, one-hot choices)."""
    def decode(self, vector: Sequence[float]) -> Dict[str, Value]:
        """The design of a vector (``encode``'s inverse): numbers rounded to the
        parameter's precision, the shortest decimal with the same encoding, so
        ``decode(encode(d)) == d`` for values such as 0.1 and ``decode(encode(x))``
        is a fixed point of the round trip for any design."""
    def __len__(self) -> int: ...

class Drape:
    """A draped garment (``Pattern.drape``)."""

    @property
    def positions(self) -> np.ndarray:
        """(V, 3) float64, cm, y up, in the box mesh's vertex order."""
    @property
    def faces(self) -> np.ndarray:
        """(F, 3) int64."""
    @property
    def vertex_labels(self) -> List[str]: ...
    @property
    def mesh(self) -> Mesh: ...
    @property
    def stats(self) -> Dict[str, Any]:
        """frames, seconds, converged, non_static_vertices, body_penetrations, self_intersections."""
    def obj(self) -> str:
        """The ``<name>_sim.obj`` text."""

class Mesh:
    """The simulation box mesh of a pattern."""

    @property
    def vertices(self) -> np.ndarray:
        """(V, 3) float64, cm."""
    @property
    def faces(self) -> np.ndarray:
        """(F, 3) int64 vertex ids."""
    @property
    def uvs(self) -> np.ndarray:
        """(T, 2) float64 texture coordinates."""
    @property
    def face_uvs(self) -> np.ndarray:
        """(F, 3) int64 texture ids."""
    @property
    def face_panels(self) -> np.ndarray:
        """(F,) int64 panel of each triangle."""
    @property
    def vertex_panels(self) -> np.ndarray:
        """(V,) int64 panel of each vertex, -1 for stitch vertices."""
    @property
    def vertex_labels(self) -> List[str]:
        """Segmentation label of each vertex."""
    @property
    def panel_names(self) -> List[str]:
        """Panel names in mesh order."""
    @property
    def stitch_pairs(self) -> List[np.ndarray]:
        """Per stitch, (n, 2) int64 vertex ids paired across the seam."""
    @property
    def rest_lengths(self) -> Tuple[np.ndarray, np.ndarray]:
        """(E, 2) int64 vertex pairs and (E,) float64 rest lengths (cm)."""
    def files(self) -> Dict[str, bytes]:
        """The mesh files, as ``garmentcode mesh`` writes them."""

class Pattern:
    """A sewing pattern, from ``build`` or ``Pattern.from_json``."""

    @staticmethod
    def from_json(source: Union[str, os.PathLike], name: Optional[str] = None) -> "Pattern":
        """Read JSON text or a specification file; ``name`` names the pattern."""
    @property
    def name(self) -> str: ...
    @property
    def spec(self) -> Dict[str, Any]:
        """The specification as a dict."""
    def to_json(self) -> str:
        """``specification.json``."""
    def svg(self, layout: str = "placed") -> str:
        """``pattern.svg``; layout "placed" or "flat"."""
    def png(self, layout: str = "placed", dpi: Optional[float] = None, background: str = "white") -> bytes:
        """``pattern.png``; layout "placed" or "flat", background "white" or "none"."""
    @property
    def checks(self) -> Optional[Dict[str, Any]]:
        """``checks.json`` with ``passed`` and ``warnings`` (None if read from a file)."""
    def problems(self) -> List[Dict[str, Any]]:
        """Structural problems, as ``garmentcode check --format json``."""
    @property
    def panels(self) -> List[str]: ...
    def panel(self, name: str) -> Dict[str, Any]:
        """A panel as the file writes it, with ``holes``, ``lines`` (lists) and
        ``layer`` (``"outer"``, ``"facing"``, ``"lining"``) always present; KeyError
        for an unknown name."""
    @property
    def stitches(self) -> List[Tuple[Tuple[str, int], Tuple[str, int]]]: ...
    @property
    def inner_stitches(self) -> List[Tuple[Dict[str, Any], Dict[str, Any]]]:
        """Stitches with a side on a hole (``"hole"``) or inner line (``"line"``)."""
    @property
    def design(self) -> Optional[Dict[str, Value]]: ...
    @property
    def body(self) -> Optional[Body]: ...
    def mesh(self, resolution: float = 1.0) -> Mesh:
        """The simulation box mesh."""
    def drape(
        self,
        body: Optional[BodyLike] = None,
        body_mesh: Optional[PathLike] = None,
        max_frames: int = 2400,
        resolution: float = 1.0,
        self_collision: bool = True,
    ) -> Drape:
        """The garment draped on the body (GIL released while it runs)."""
    def write(
        self,
        out: PathLike,
        formats: Sequence[str] = ("json", "svg", "png"),
        layout: str = "placed",
        mesh_resolution: float = 1.0,
        force: bool = False,
        dpi: Optional[float] = None,
        background: str = "white",
    ) -> List[str]:
        """Write the files of ``garmentcode build`` (formats json, svg, png, mesh,
        print); returns their names."""

def build(design: DesignLike, body: Optional[BodyLike] = None, name: Optional[str] = None) -> Pattern:
    """Build a garment."""

def builtin_designs() -> List[str]:
    """Names of the built-in designs."""

def sample_dataset(
    n: int,
    seed: int,
    out: PathLike,
    *,
    jobs: Optional[int] = None,
    bodies: Optional[Union[str, Sequence[str]]] = None,
    formats: Optional[Union[str, Sequence[str]]] = None,
    layout: Optional[str] = None,
    design_space: Optional[Union[PathLike, DesignSpace]] = None,
    extended: bool = False,
    shard: Optional[Tuple[int, int]] = None,
    progress: Optional[Callable[[int, int], Any]] = None,
    quiet: bool = True,
) -> str:
    """``garmentcode sample``; returns the summary's path. ``quiet=False`` prints
    the CLI's messages (resuming, the closing summary line) on stderr."""

def compare_specs(expected: str, actual: str, tol: Optional[float] = None) -> Dict[str, Any]:
    """The parity test's comparison of two specification texts."""

def parse_yaml(text: str) -> Any:
    """YAML text as Python values."""

def _flat_design(design: Dict[str, Any]) -> Dict[str, Value]:
    """A design dict as flat ``{path: value}``, unchecked (for ``iter_shards``)."""

_MESH_FILE_SUFFIXES: List[str]
