"""Fleet scale on Dask: describe millions of scans on a dask.distributed
cluster, gather only the descriptors, cluster them without an n x n
matrix, and write Parquet plus a model the page can load.

The run is in two stages, each restartable:

1. ``describe(source, out, client)``: the scan files (a folder walked
   recursively, a list of paths, or an fsspec URL such as
   ``s3://bucket/runs/``) are split into batches; each batch is read and
   described on a worker (the GIL released, so a worker's threads run in
   parallel) and only its descriptors (a few hundred bytes each) come back.
   The driver writes each finished batch as ``out/descriptors/part-N.parquet``
   (file, descriptor JSON, error), atomically. A rerun lists the parts and
   skips every file already described, so a stopped run goes on where it
   stopped. At most ``in_flight`` batches are out at once, so the driver's
   memory does not grow with the number of files.
2. ``categorise(out)``: hierarchical k-means++ (or k-means) on at most
   ``sample`` descriptors (all of them when there are fewer), the number of
   categories chosen by the CLI's default rule (``restarts``: 2-means++
   trials at every split of the tree, or k-means runs, the cheapest kept;
   1, the default, is the paper's method), a model of those
   categories (``out/model.json``: the page's "Load model" reads it); then
   every described scan, streamed one part at a time, is put into its
   nearest category by that model, written to ``out/categories.parquet``
   (file, descriptor, category, distance). Above placecat.MATRIX_LIMIT
   (5,000) scans the tree is built without the n x n Delta matrix, as the
   core does. Memory bound of the driver: the sample's descriptors
   (measured: about 4 KiB each while loading, 384 MiB at the default
   100,000) plus one part, and the names of the described files (for the
   skip, ~100 bytes a file); nothing else grows with the fleet.
"""

from __future__ import annotations

import json
import os
import random
import sys
from dataclasses import dataclass, field
from typing import Any, Iterable, Iterator, List, Mapping, Optional, Sequence, Tuple, Union

import placecat

SCAN_EXTENSIONS = (".ply", ".pcd", ".bin", ".las", ".laz", ".e57")

Source = Union[str, "os.PathLike[str]", Sequence[str]]


def _is_url(path: str) -> bool:
    return "://" in path


def _visible(rel: str) -> bool:
    """No part of the path below the walked folder is hidden: hidden entries
    are editor and OS leftovers (macOS ``._000000.bin``), not scans; the
    CLI's describe skips them too."""
    return not any(part.startswith(".") for part in rel.replace("\\", "/").split("/"))


def list_scans(source: Source) -> List[str]:
    """The scan files of a source, sorted: a folder (walked with its
    subfolders, symbolic links followed, hidden files and folders skipped,
    as the CLI's describe does), one file,
    an fsspec URL of a folder (``s3://...``, ``file:///...``), or a list of
    any of these."""
    if not isinstance(source, (str, os.PathLike)):
        return sorted({f for s in source for f in list_scans(s)})
    src = os.fspath(source)
    if _is_url(src):
        import fsspec

        fs, root = fsspec.core.url_to_fs(src)
        if fs.isfile(root):
            return [src]
        base = root.rstrip("/") + "/"
        return sorted(
            fs.unstrip_protocol(p)
            for p in fs.find(root)
            if p.lower().endswith(SCAN_EXTENSIONS) and _visible(p[len(base) :] if p.startswith(base) else p)
        )
    if os.path.isfile(src):
        return [src]
    if not os.path.isdir(src):
        raise placecat.PlacecatError(f"{src}: I/O: no such file or folder")
    out = []
    for dirpath, dirnames, filenames in os.walk(src, followlinks=True):
        dirnames[:] = [d for d in dirnames if _visible(d)]
        out.extend(os.path.join(dirpath, f) for f in filenames if f.lower().endswith(SCAN_EXTENSIONS) and _visible(f))
    return sorted(out)


def describe_batch(files: Sequence[str], params: Any, lenient: bool = False) -> List[Tuple[str, Optional[str], Optional[str]]]:
    """Read and describe files on a worker: (file, descriptor JSON or None,
    error or None) for each. Local paths are read by the core; URLs
    through fsspec, then described from their bytes."""
    out = []
    for f in files:
        try:
            if _is_url(f):
                import fsspec

                with fsspec.open(f, "rb") as fh:
                    data = fh.read()
                d = placecat.describe_bytes(data, f, params, lenient=lenient)
            else:
                d = placecat.describe_file(f, params, lenient=lenient)
            out.append((f, d.descriptor_json(), None))
        except placecat.PlacecatError as e:
            out.append((f, None, str(e)))
        except OSError as e:  # fsspec's: the URL cannot be opened
            out.append((f, None, f"{f}: I/O: {e}"))
    return out


@dataclass
class DescribeReport:
    """What a describe run did."""

    files: int = 0
    skipped: int = 0  # already described by an earlier run
    described: int = 0
    errors: List[Tuple[str, str]] = field(default_factory=list)


def _parts_dir(out: str) -> str:
    return os.path.join(out, "descriptors")


def _parts(out: str) -> List[str]:
    d = _parts_dir(out)
    if not os.path.isdir(d):
        return []
    return sorted(os.path.join(d, p) for p in os.listdir(d) if p.startswith("part-") and p.endswith(".parquet"))


def _check_params(out: str, params: Any) -> str:
    """The run's parameters as JSON, written on the first run; a rerun with
    other parameters is refused (its descriptors would not fit together)."""
    text = json.dumps(placecat.params(params), sort_keys=True)
    path = os.path.join(out, "params.json")
    if os.path.exists(path):
        with open(path) as f:
            old = f.read()
        if json.loads(old) != json.loads(text):
            raise placecat.PlacecatError(f"{path}: mismatch: this output was described with other parameters")
    else:
        with open(path + ".tmp", "w") as f:
            f.write(text)
        os.replace(path + ".tmp", path)
    return text


def described_files(out: str) -> set:
    """The files the parts under ``out`` hold a descriptor of."""
    import pyarrow.parquet as pq

    done = set()
    for p in _parts(out):
        t = pq.read_table(p, columns=["file", "descriptor"])
        for f, d in zip(t.column("file").to_pylist(), t.column("descriptor").to_pylist()):
            if d is not None:
                done.add(f)
    return done


def _write_part(out: str, index: int, rows: Sequence[Tuple[str, Optional[str], Optional[str]]]) -> None:
    import pyarrow as pa
    import pyarrow.parquet as pq

    table = pa.table(
        {
            "file": pa.array([r[0] for r in rows], pa.string()),
            "descriptor": pa.array([r[1] for r in rows], pa.string()),
            "error": pa.array([r[2] for r in rows], pa.string()),
        }
    )
    path = os.path.join(_parts_dir(out), f"part-{index:07d}.parquet")
    pq.write_table(table, path + ".tmp")
    os.replace(path + ".tmp", path)  # a stopped run leaves whole parts only


def _batches(files: Sequence[str], size: int) -> Iterator[List[str]]:
    for i in range(0, len(files), size):
        yield list(files[i : i + size])


def describe(
    source: Source,
    out: str,
    client: Any,
    params: Any = None,
    batch_size: int = 64,
    in_flight: Optional[int] = None,
    lenient: bool = False,
    quiet: bool = False,
) -> DescribeReport:
    """Describe every scan of ``source`` not yet described under ``out`` on
    the Dask ``client``'s cluster (see the module doc). Bad files are
    reported on stderr as the CLI reports them ("skipped FILE: error"),
    kept in the parts with their error, and tried again on a rerun."""
    from distributed import as_completed

    os.makedirs(_parts_dir(out), exist_ok=True)
    _check_params(out, params)
    params_dict = placecat.params(params)
    files = list_scans(source)
    done = described_files(out)
    todo = [f for f in files if f not in done]
    report = DescribeReport(files=len(files), skipped=len(files) - len(todo))
    if in_flight is None:
        threads = sum(client.nthreads().values()) or 1
        in_flight = 2 * threads
    next_part = len(_parts(out))
    batches = _batches(todo, batch_size)
    running = as_completed()
    for batch in batches:
        running.add(client.submit(describe_batch, batch, params_dict, lenient, pure=False))
        if running.count() >= in_flight:
            break
    for fut in running:
        rows = fut.result()
        fut.release()
        _write_part(out, next_part, rows)
        next_part += 1
        for f, d, e in rows:
            if e is None:
                report.described += 1
            else:
                report.errors.append((f, e))
                if not quiet:
                    print(f"skipped {e}", file=sys.stderr)
        batch = next(batches, None)
        if batch is not None:
            running.add(client.submit(describe_batch, batch, params_dict, lenient, pure=False))
    return report


def iter_descriptors(out: str) -> Iterator[Tuple[List[str], List[str]]]:
    """(files, descriptor JSONs) of each part, one part in memory at a
    time, without the files that failed (a file has one descriptor: a rerun
    describes only files without one)."""
    import pyarrow.parquet as pq

    for p in _parts(out):
        t = pq.read_table(p, columns=["file", "descriptor"])
        rows = [(f, d) for f, d in zip(t.column("file").to_pylist(), t.column("descriptor").to_pylist()) if d is not None]
        yield [f for f, _ in rows], [d for _, d in rows]


def load_collection(out: str, sample: Optional[int] = None, seed: int = 0) -> placecat.Collection:
    """The described scans under ``out`` as a Collection: all of them, or a
    seeded random sample of ``sample`` (reservoir sampling, one part in
    memory at a time)."""
    with open(os.path.join(out, "params.json")) as f:
        params_json = f.read()
    rng = random.Random(seed)
    kept: List[Tuple[str, str]] = []
    seen = 0
    for files, descs in iter_descriptors(out):
        for row in zip(files, descs):
            seen += 1
            if sample is None or len(kept) < sample:
                kept.append(row)
            else:
                j = rng.randrange(seen)
                if j < sample:
                    kept[j] = row
    kept.sort()
    ds = [placecat.Descriptor.from_parts(params_json, d) for _, d in kept]
    return placecat.Collection(ds, names=[f for f, _ in kept], params=json.loads(params_json))


@dataclass
class CategoriseReport:
    """What categorise did."""

    scans: int = 0
    clustered: int = 0
    categories: int = 0
    choice: Mapping[str, Any] = field(default_factory=dict)


def categorise(
    out: str,
    method: str = "hkmeans",
    categories: Union[int, str] = "auto",
    sample: Optional[int] = 100_000,
    seed: int = 0,
    restarts: int = 1,
) -> CategoriseReport:
    """Cluster the described scans under ``out`` (see the module doc):
    writes ``out/model.json`` and ``out/categories.parquet``."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    # Before the sample is loaded, and as placecat's error for any bad count.
    if isinstance(restarts, bool) or not isinstance(restarts, int) or not 1 <= restarts <= placecat.MAX_RESTARTS:
        raise placecat.PlacecatError(
            f"invalid parameter: restarts must be a whole number from 1 to {placecat.MAX_RESTARTS}, got {restarts!r}"
        )
    col = load_collection(out, sample=sample, seed=seed)
    if len(col) == 0:
        raise placecat.PlacecatError(f"{out}: invalid parameter: no described scans")
    choice: Mapping[str, Any] = {}
    if method == "hkmeans":
        tree = col.hkmeans(seed=seed, restarts=restarts)
        if categories == "auto":
            choice = col.choose_categories(tree, seed=seed)
            categories = choice["k"]
        labels = tree.cut_k(int(categories))["labels"]
    elif method == "kmeans":
        r = col.kmeans(categories, seed=seed, restarts=restarts)
        labels, choice = r["labels"], r.get("choice", {})
    else:
        raise placecat.PlacecatError(f"invalid parameter: unknown method {method!r} (hkmeans, kmeans)")
    model = col.build_model(labels)
    model.save(os.path.join(out, "model.json"))
    params_json = json.dumps(col.params)
    schema = pa.schema(
        [("file", pa.string()), ("descriptor", pa.string()), ("category", pa.int32()), ("distance", pa.float32())]
    )
    path = os.path.join(out, "categories.parquet")
    scans = 0
    with pq.ParquetWriter(path + ".tmp", schema) as w:
        for files, descs in iter_descriptors(out):
            answers = [model.classify(placecat.Descriptor.from_parts(params_json, d)) for d in descs]
            w.write_table(
                pa.table(
                    {
                        "file": files,
                        "descriptor": descs,
                        "category": pa.array([a["label"] for a in answers], pa.int32()),
                        "distance": pa.array([a["distance"] for a in answers], pa.float32()),
                    },
                    schema=schema,
                )
            )
            scans += len(files)
    os.replace(path + ".tmp", path)
    return CategoriseReport(scans=scans, clustered=len(col), categories=len(model.categories), choice=choice)


def read_categories(out: str) -> List[Tuple[str, int]]:
    """(file, category) of every scan of ``out/categories.parquet``, by file."""
    import pyarrow.parquet as pq

    t = pq.read_table(os.path.join(out, "categories.parquet"), columns=["file", "category"])
    return sorted(zip(t.column("file").to_pylist(), t.column("category").to_pylist()))


__all__: Iterable[str] = [
    "CategoriseReport",
    "DescribeReport",
    "categorise",
    "describe",
    "describe_batch",
    "described_files",
    "iter_descriptors",
    "list_scans",
    "load_collection",
    "read_categories",
]
