"""Reading datasets in the shard layout (``garmentcode sample --layout shards``).

A shard is a tar archive of whole samples; every file of a sample is named after
its key (``rand_0000042.specification.json``, ``rand_0000042.design_params.yaml``,
...). :func:`iter_shards` yields one dict per sample, decoded as the rest of the
package gives them (a design as flat ``{path: value}``, the mesh as a
:class:`Mesh`), and :class:`ShardDataset` wraps it for PyTorch's
``IterableDataset`` (splitting the shards over the data-loader's workers) without
depending on PyTorch or WebDataset.
"""

from __future__ import annotations

import json
import os
import tarfile
from typing import Any, Callable, Dict, Iterator, List, Optional, Sequence, Union

from ._native import _MESH_FILE_SUFFIXES, Pattern, _flat_design, parse_yaml

PathLike = Union[str, "os.PathLike[str]"]


def shard_paths(source: Union[PathLike, Sequence[PathLike]]) -> List[str]:
    """The shard files of a dataset folder (``shard-*.tar``, sorted), or the given
    list of shard files as it is."""
    if isinstance(source, (str, os.PathLike)):
        path = os.fspath(source)
        if os.path.isdir(path):
            names = sorted(n for n in os.listdir(path) if n.startswith("shard-") and n.endswith(".tar"))
            return [os.path.join(path, n) for n in names]
        return [path]
    return [os.fspath(p) for p in source]


#: Member suffixes of a sample's mesh files (``boxmesh.obj``, ``sim_segmentation.txt``, ...).
MESH_SUFFIXES = frozenset(s.lstrip("_") for s in _MESH_FILE_SUFFIXES)


def _decode(suffix: str, data: bytes) -> Any:
    """A member's content: the design as flat ``{path: value}`` (as
    ``Pattern.design`` and ``DesignSpace.sample`` give it), JSON and YAML parsed,
    text decoded, the rest as bytes."""
    if suffix == "design_params.yaml":
        return _flat_design(parse_yaml(data.decode("utf-8")))
    if suffix.endswith(".json"):
        return json.loads(data)
    if suffix.endswith(".yaml"):
        return parse_yaml(data.decode("utf-8"))
    if suffix.endswith(".svg") or suffix.endswith(".txt"):
        return data.decode("utf-8")
    return data


def iter_shards(
    source: Union[PathLike, Sequence[PathLike]],
    decode: bool = True,
    keys: Optional[Callable[[str], bool]] = None,
) -> Iterator[Dict[str, Any]]:
    """Yield the samples of shards, in order, as dicts.

    ``source`` is a dataset folder (its ``shard-*.tar`` files) or a list of shard
    files. Each sample is ``{"__key__": "rand_0000042", "__shard__": path,
    "specification.json": {...}, "design_params.yaml": {...}, ...}``: one entry per
    file, named by its suffix after the key. With ``decode`` (the default) JSON and
    YAML files are parsed, SVG decoded to text, ``design_params.yaml`` is the
    design as flat ``{path: value}`` (as ``Pattern.design``), and the mesh files
    (``--formats mesh``) are one entry ``"mesh"``: the :class:`Mesh` of the
    sample's pattern, with the arrays of ``Pattern.mesh()`` (its ``files()`` are
    the shard's mesh files, byte for byte). Without ``decode`` every value is the
    file's bytes. ``keys(key)`` may select the samples to read (the others are
    skipped unread).
    """
    for path in shard_paths(source):
        with tarfile.open(path, mode="r:") as tar:
            sample: Optional[Dict[str, Any]] = None
            for member in tar:
                if not member.isfile():
                    continue
                key, dot, suffix = member.name.partition(".")
                if not dot:
                    raise ValueError(f"{path}: member {member.name!r} is not named KEY.SUFFIX")
                if key != (sample or {}).get("__key__"):
                    if sample is not None and sample["__wanted__"]:
                        yield _finish(sample)
                    sample = {"__key__": key, "__shard__": path, "__wanted__": keys is None or keys(key)}
                if not sample["__wanted__"]:
                    continue
                if decode and suffix in MESH_SUFFIXES:
                    sample["__mesh__"] = True  # made from the specification by _finish
                    continue
                handle = tar.extractfile(member)
                data = handle.read() if handle is not None else b""
                if decode and suffix == "specification.json":
                    sample["__spec__"] = data
                sample[suffix] = _decode(suffix, data) if decode else data
            if sample is not None and sample["__wanted__"]:
                yield _finish(sample)


def _finish(sample: Dict[str, Any]) -> Dict[str, Any]:
    """A sample without the reader's own entries, its mesh made (when decoding a
    sample with mesh files): the dataset's box mesh, at the sampler's resolution."""
    del sample["__wanted__"]
    spec = sample.pop("__spec__", None)
    if sample.pop("__mesh__", False):
        if spec is None:
            raise ValueError(f"{sample['__shard__']}: {sample['__key__']} has mesh files but no specification.json")
        sample["mesh"] = Pattern.from_json(spec.decode("utf-8"), name=sample["__key__"]).mesh()
    return sample


class ShardDataset:
    """An iterable over a shard dataset's samples (see :func:`iter_shards`),
    usable as a PyTorch ``IterableDataset``::

        class Garments(garmentcode.ShardDataset, torch.utils.data.IterableDataset):
            pass

        loader = torch.utils.data.DataLoader(Garments("data/"), num_workers=4, batch_size=None)

    Inside a data-loader worker each worker reads every ``num_workers``-th shard
    (found through ``torch.utils.data.get_worker_info`` when PyTorch is loaded), so
    no sample is read twice. ``transform`` is applied to every sample.
    """

    def __init__(
        self,
        source: Union[PathLike, Sequence[PathLike]],
        decode: bool = True,
        transform: Optional[Callable[[Dict[str, Any]], Any]] = None,
    ) -> None:
        self.shards = shard_paths(source)
        self.decode = decode
        self.transform = transform
        self._len: Optional[int] = None

    def __len__(self) -> int:
        """The number of samples in all the shards (read from the archives'
        member headers once, skipping the files' contents)."""
        if self._len is None:
            count = 0
            for path in self.shards:
                with tarfile.open(path, mode="r:") as tar:
                    count += len({m.name.partition(".")[0] for m in tar if m.isfile()})
            self._len = count
        return self._len

    def __repr__(self) -> str:
        folders = sorted({os.path.dirname(os.path.abspath(p)) for p in self.shards})
        where = f" in {folders[0]!r}" if len(folders) == 1 else ""
        return f"ShardDataset({len(self.shards)} shards{where}, decode={self.decode})"

    def _worker_shards(self) -> List[str]:
        import sys

        torch = sys.modules.get("torch")
        info = torch.utils.data.get_worker_info() if torch is not None else None
        if info is None:
            return self.shards
        return self.shards[info.id :: info.num_workers]

    def __iter__(self) -> Iterator[Any]:
        for sample in iter_shards(self._worker_shards(), decode=self.decode):
            yield self.transform(sample) if self.transform is not None else sample
