#!/usr/bin/env python3
"""Categorise a fleet's scans on a Dask cluster (see docs/fleet.md).

    python python/examples/fleet.py SCANS... --out RUN [--scheduler tcp://host:8786 | --workers 2]

SCANS are folders (walked with their subfolders), files, or fsspec URLs
(s3://bucket/prefix/, file:///data/...). RUN gets descriptors/part-*.parquet,
params.json, model.json (load it in the page) and categories.parquet
(file, descriptor, category, distance). Run it again to go on after a stop:
files already described are skipped.
"""

import argparse
import json
import sys
import time

import placecat
from placecat import fleet


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("sources", nargs="+", help="folders, files or fsspec URLs of scans")
    ap.add_argument("--out", required=True, help="the run's folder (created; reused on a rerun)")
    ap.add_argument("--scheduler", help="address of a running dask scheduler (default: a LocalCluster)")
    ap.add_argument("--workers", type=int, default=2, help="LocalCluster workers (default 2)")
    ap.add_argument("--threads", type=int, default=1, help="threads per LocalCluster worker (default 1)")
    ap.add_argument("--preset", default="indoor", help=f"descriptor preset: {', '.join(placecat.presets())}")
    ap.add_argument("--params", help="JSON file of parameter overrides (as the CLI's --params)")
    ap.add_argument("--batch-size", type=int, default=64, help="files per task (default 64)")
    ap.add_argument("--method", default="hkmeans", choices=["hkmeans", "kmeans"])
    ap.add_argument("--categories", default="auto", help="number of categories, or auto (default)")
    ap.add_argument("--sample", type=int, default=100_000, help="descriptors clustered at most (default 100000)")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--restarts", type=int, default=1,
                    help="2-means++ trials a split of the tree, or k-means runs; the cheapest kept (default 1: the paper's)")
    ap.add_argument("--describe-only", action="store_true", help="stop after describing")
    a = ap.parse_args()
    if not 1 <= a.restarts <= placecat.MAX_RESTARTS:
        ap.error(f"--restarts must be from 1 to {placecat.MAX_RESTARTS}, got {a.restarts}")  # before describing

    params = {"preset": a.preset}
    if a.params:
        with open(a.params) as f:
            params.update(json.load(f))

    from distributed import Client, LocalCluster

    if a.scheduler:
        client = Client(a.scheduler)
    else:
        cluster = LocalCluster(n_workers=a.workers, threads_per_worker=a.threads, processes=True)
        client = Client(cluster)
    try:
        t = time.perf_counter()
        r = fleet.describe(a.sources, a.out, client, params=params, batch_size=a.batch_size)
        print(
            f"described {r.described} of {r.files} files ({r.skipped} already described, "
            f"{len(r.errors)} skipped) in {time.perf_counter() - t:.1f} s",
            file=sys.stderr,
        )
    finally:
        client.close()
    if a.describe_only:
        return 0
    t = time.perf_counter()
    categories = a.categories if a.categories == "auto" else int(a.categories)
    c = fleet.categorise(a.out, method=a.method, categories=categories, sample=a.sample, seed=a.seed, restarts=a.restarts)
    print(
        f"{c.categories} categories from {c.clustered} scans; {c.scans} scans categorised "
        f"-> {a.out}/categories.parquet, {a.out}/model.json in {time.perf_counter() - t:.1f} s",
        file=sys.stderr,
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
