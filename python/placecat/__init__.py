"""placecat: unsupervised place categorisation of 3D lidar scans.

NDT-histogram descriptors (Magnusson et al., IROS 2017), clustering and
named models, from numpy. Everything here is the Rust core (the same code
as the ``placecat`` CLI and the web page) through the extension module
``placecat._placecat``; ``placecat.fleet`` maps describe over a Dask
cluster.

>>> import placecat
>>> points = placecat.read("scan.pcd")            # (N, 3) float32
>>> d = placecat.describe(points, "indoor")        # or a dict of overrides
>>> set_ = placecat.Collection([d, ...], names=[...])
>>> tree = set_.hkmeans()
>>> labels = tree.cut_k(set_.choose_categories(tree)["k"])["labels"]
"""

from ._placecat import (
    MATRIX_LIMIT,
    MAX_RESTARTS,
    Collection,
    Descriptor,
    Model,
    PlacecatError,
    Scans,
    Tree,
    describe,
    describe_bytes,
    describe_file,
    evaluate,
    params,
    preset_notes,
    presets,
    read,
    read_bytes,
    scans,
)

__all__ = [
    "MATRIX_LIMIT",
    "MAX_RESTARTS",
    "Collection",
    "Descriptor",
    "Model",
    "PlacecatError",
    "Scans",
    "Tree",
    "describe",
    "describe_bytes",
    "describe_file",
    "evaluate",
    "params",
    "preset_notes",
    "presets",
    "read",
    "read_bytes",
    "scans",
]
