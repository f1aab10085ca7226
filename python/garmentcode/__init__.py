"""GarmentCode sewing patterns at Rust speed.

Build a garment from a design and a body, draw it, mesh it, write its files, and
make datasets -- the same patterns and files as the ``garmentcode`` command-line
tool, byte for byte::

    import garmentcode as gc

    pattern = gc.build({"meta": {"upper": {"v": "Shirt"}}}, gc.Body("mean_all"))
    pattern.spec           # the specification.json as a dict
    pattern.write("out/shirt", formats=["json", "svg", "mesh"])

Everything public: :class:`DesignSpace`, :class:`Body`, :func:`build`,
:class:`Pattern` (with :class:`Mesh` and :class:`Drape`), :func:`sample_dataset`,
:func:`iter_shards` / :class:`ShardDataset`, :func:`compare_specs`, the
exceptions, and :mod:`garmentcode.compat` (pygarment's names).
"""

from ._native import (
    Body,
    BodyError,
    BuildError,
    DatasetError,
    DesignError,
    DesignSpace,
    Drape,
    InputError,
    Mesh,
    Pattern,
    PatternError,
    __version__,
    build,
    builtin_designs,
    compare_specs,
    parse_yaml,
    sample_dataset,
)
from .shards import ShardDataset, iter_shards

__all__ = [
    "Body",
    "BodyError",
    "BuildError",
    "DatasetError",
    "DesignError",
    "DesignSpace",
    "Drape",
    "InputError",
    "Mesh",
    "Pattern",
    "PatternError",
    "ShardDataset",
    "__version__",
    "build",
    "builtin_designs",
    "compare_specs",
    "iter_shards",
    "parse_yaml",
    "sample_dataset",
]
