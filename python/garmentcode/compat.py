"""pygarment's names for the common pipeline, so that a script written for
pygarment runs with its imports changed to this module::

    from garmentcode.compat import BodyParameters, MetaGarment, Properties

    body = BodyParameters("assets/bodies/mean_all.yaml")
    piece = MetaGarment("t-shirt", body, design)   # design: the `design` dict of a design file
    pattern = piece.assembly()
    if piece.is_self_intersecting():
        ...
    folder = pattern.serialize("out", tag="_v1", to_subfolder=True, with_3d=False, with_printable=True)
    body.save(folder)

Covered (same files as pygarment unless said otherwise):

- ``BodyParameters(param_file)``: ``params`` (raw and ``_`` derived values),
  ``[key]`` (setting a raw value re-derives the others), iteration over the keys,
  ``load``, ``load_from_dict``, ``save(path, name='body_measurements')``.
- ``MetaGarment(name, body, design)``: ``name``, ``assembly()``,
  ``is_self_intersecting()``, ``length()``, ``assert_total_length(tol=1)``; the
  design is checked when the garment is made (``garmentcode.DesignError``).
- The assembled pattern (``VisPattern``-like): ``name``, ``spec``,
  ``panel_order()``, ``serialize(path, to_subfolder=True, tag='', with_3d=True,
  with_text=True, view_ids=True, with_printable=False, empty_ok=False)`` writing
  ``NAME[_TAG]_specification.json``, ``_pattern.svg``, ``_pattern.png`` and, with
  ``with_printable``, ``_print_pattern.svg`` (the flat layout). Not written: the
  3D preview (``with_3d``) and the printable PDF; ``with_text`` and ``view_ids`` do
  not change the drawing.
- ``BoxMesh(path, res=1.0)``: ``load()``, then ``vertices``, ``faces``,
  ``vertex_texture``, ``faces_with_texture``, ``stitch_segmentation``,
  ``orig_lens`` and ``serialize(paths, tag='', ...)`` writing the pattern's files
  and the mesh files (``_boxmesh.obj``, ``_material.mtl``,
  ``_sim_segmentation.txt``, ``_orig_lens.pickle``, ``_vertex_labels.yaml``,
  ``_texture_fabric.png``, plus ``_sim_mesh.obj`` and ``_boxmesh.ply``) into
  ``paths.out_el`` (a ``PathCofig``) or into ``paths`` itself when it is a folder.
  Not written: the ``_texture.png`` preview of the UV layout.
- ``Properties(filename)``: a JSON file as a dict (``[key]``, ``get``,
  ``serialize(filename)``), as pygarment's ``data_config.Properties`` for reading
  ``system.json``.

Not covered: the garment-program classes themselves (``Panel``, ``Edge``,
``Component``, interfaces: garments are programs of the Rust library), the
simulation (``pygarment.meshgen.simulation``), the GUI, and the design sampler's
class (``garmentcode.sample_dataset`` and ``DesignSpace.sample`` replace it).
"""

from __future__ import annotations

import json
import os
import warnings
from pathlib import Path
from typing import Any, Dict, Iterator, List, Optional, Union

import numpy as np

from ._native import Body, Pattern, build

PathLike = Union[str, "os.PathLike[str]"]

__all__ = ["BodyParameters", "BoxMesh", "MetaGarment", "Properties", "VisPattern"]


class BodyParameters:
    """Body measurements from a body file, as pygarment's ``BodyParameters``."""

    def __init__(self, param_file: PathLike = "") -> None:
        self._raw: Dict[str, Any] = {}
        self._body: Optional[Body] = None
        self.params: Dict[str, Any] = {}
        if param_file:
            self.load(param_file)

    def load(self, param_file: PathLike) -> None:
        """Load (more) values from a body file."""
        body = Body(os.fspath(param_file))
        self._raw.update(body.measurements)
        self._update()

    def load_from_dict(self, in_dict: Dict[str, Any]) -> None:
        """Update raw values from a dict (derived ``_`` keys are ignored)."""
        self._raw.update({k: v for k, v in in_dict.items() if not k.startswith("_")})
        self._update()

    def _update(self) -> None:
        self._body = Body.from_dict(self._raw)
        self.params = self._body.to_dict()

    @property
    def body(self) -> Body:
        """The measurements as a ``garmentcode.Body``."""
        if self._body is None:
            raise ValueError("BodyParameters: no measurements loaded")
        return self._body

    def __getitem__(self, key: str) -> Any:
        return self.params[key]

    def __setitem__(self, key: str, value: Any) -> None:
        """Set a raw measurement; the derived values follow."""
        if key.startswith("_"):
            raise KeyError(f"{key}: derived values are computed from the raw measurements")
        self._raw[key] = value
        self._update()

    def __iter__(self) -> Iterator[str]:
        return iter(self.params)

    def save(self, path: PathLike, name: str = "body_measurements") -> None:
        """Write ``NAME.yaml`` (the ``body:`` mapping, derived values included) into
        the folder ``path``."""
        Path(path, f"{name}.yaml").write_text(self.body.to_yaml())


def _body_of(body: Any) -> Any:
    return body.body if isinstance(body, BodyParameters) else body


class VisPattern:
    """An assembled pattern with pygarment's ``VisPattern`` methods; ``pattern`` is
    the ``garmentcode.Pattern``."""

    def __init__(self, pattern: Pattern) -> None:
        self.pattern = pattern

    @property
    def name(self) -> str:
        """The pattern's name."""
        return self.pattern.name

    @property
    def spec(self) -> Dict[str, Any]:
        """The specification as a dict."""
        return self.pattern.spec

    def panel_order(self, force_update: bool = False) -> List[str]:
        """Panel names in the pattern's panel order."""
        return list(self.spec.get("panel_order") or self.pattern.panels)

    def serialize(
        self,
        path: PathLike,
        to_subfolder: bool = True,
        tag: str = "",
        with_3d: bool = True,
        with_text: bool = True,
        view_ids: bool = True,
        with_printable: bool = False,
        empty_ok: bool = False,
        print_panel_dist: int = 10,
    ) -> str:
        """Write the specification and drawings as pygarment does; returns the
        folder written into."""
        if not self.pattern.panels and not empty_ok:
            raise RuntimeError(f"{type(self).__name__}::ERROR::Asked to save an empty pattern")
        if tag:
            tag = "_" + tag
        folder = os.path.join(os.fspath(path), self.name + tag) if to_subfolder else os.fspath(path)
        os.makedirs(folder, exist_ok=True)
        prefix = os.path.join(folder, self.name + tag)
        Path(prefix + "_specification.json").write_text(self.pattern.to_json())
        if not self.pattern.panels:
            return folder
        Path(prefix + "_pattern.svg").write_text(self.pattern.svg())
        Path(prefix + "_pattern.png").write_bytes(self.pattern.png())
        if with_printable:
            Path(prefix + "_print_pattern.svg").write_text(self.pattern.svg(layout="flat"))
        if with_3d:
            warnings.warn("garmentcode.compat: the 3D preview (with_3d) is not drawn", stacklevel=2)
        return folder


class MetaGarment:
    """A garment of the library from a design, as pygarment's ``MetaGarment``."""

    def __init__(self, name: str, body: Any, design: Dict[str, Any]) -> None:
        self.name = name
        self.body = body
        self.design = design
        self._pattern = build(design, _body_of(body), name=name)

    def assembly(self) -> VisPattern:
        """The sewing pattern."""
        return VisPattern(self._pattern)

    def is_self_intersecting(self) -> bool:
        """Whether a panel outline crosses itself."""
        return bool(self._pattern.checks["self_intersecting"])

    def length(self) -> float:
        """The garment's length (cm), as the reference's length check sums it."""
        return float(self._pattern.checks["total_length"])

    def assert_total_length(self, tol: float = 1) -> None:
        """Raise if the garment is longer than the floor allows (the reference's
        check, with ``tol`` cm)."""
        checks = self._pattern.checks
        if checks["total_length"] > checks["floor_length"] + tol:
            raise ValueError(
                f"{type(self).__name__}::{self.name}::ERROR::Total length {checks['total_length']} "
                f"exceeds the floor length {checks['floor_length']}"
            )


class BoxMesh(VisPattern):
    """The simulation box mesh of a specification file, as pygarment's ``BoxMesh``."""

    def __init__(self, path: PathLike, res: float = 1.0) -> None:
        super().__init__(Pattern.from_json(os.fspath(path)))
        self.mesh_resolution = res
        self.loaded = False
        self.mesh: Any = None

    def load(self) -> None:
        """Mesh the pattern."""
        self.mesh = self.pattern.mesh(resolution=self.mesh_resolution)
        self.loaded = True

    def _mesh(self) -> Any:
        if not self.loaded:
            raise RuntimeError("BoxMesh: call load() first")
        return self.mesh

    @property
    def vertices(self) -> np.ndarray:
        """Vertex positions (cm)."""
        return self._mesh().vertices

    @property
    def faces(self) -> np.ndarray:
        """Triangles (vertex ids)."""
        return self._mesh().faces

    @property
    def vertex_texture(self) -> np.ndarray:
        """Texture coordinates."""
        return self._mesh().uvs

    @property
    def faces_with_texture(self) -> np.ndarray:
        """Texture ids of each triangle's corners."""
        return self._mesh().face_uvs

    @property
    def stitch_segmentation(self) -> List[str]:
        """Each vertex's segmentation label."""
        return self._mesh().vertex_labels

    @property
    def orig_lens(self) -> Dict[tuple, float]:
        """Rest lengths ``{(i, j): cm}`` of the edges near stitches."""
        pairs, lengths = self._mesh().rest_lengths
        return {(int(i), int(j)): float(x) for (i, j), x in zip(pairs, lengths)}

    def serialize(self, paths: Any, tag: str = "", with_3d: bool = False, with_text: bool = False, view_ids: bool = False, **_: Any) -> str:  # type: ignore[override]
        """Write the pattern's files and the mesh files into ``paths.out_el`` (or
        the folder ``paths``); returns the folder."""
        folder = os.fspath(getattr(paths, "out_el", paths))
        os.makedirs(folder, exist_ok=True)
        super().serialize(folder, to_subfolder=False, tag=tag, with_3d=with_3d, with_text=with_text, view_ids=view_ids)
        for name, data in self._mesh().files().items():
            Path(folder, name).write_bytes(data)
        return folder


class Properties:
    """A JSON file as a dict (pygarment's ``data_config.Properties``)."""

    def __init__(self, filename: PathLike = "", clean_stats: bool = False) -> None:
        self.properties: Dict[str, Any] = {}
        if filename:
            with open(filename) as f:
                self.properties = json.load(f)

    def __getitem__(self, key: str) -> Any:
        return self.properties[key]

    def __setitem__(self, key: str, value: Any) -> None:
        self.properties[key] = value

    def __contains__(self, key: str) -> bool:
        return key in self.properties

    def get(self, key: str, default: Any = None) -> Any:
        """A value, or ``default``."""
        return self.properties.get(key, default)

    def serialize(self, filename: PathLike, backup: Any = None) -> None:
        """Write the properties as JSON."""
        with open(filename, "w") as f:
            json.dump(self.properties, f, indent=2)
