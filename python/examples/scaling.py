#!/usr/bin/env python3
"""Measure placecat on Dask against a plain process, and the clustering of
100,000 descriptors; prints JSON (docs/scaling.md's "Fleet scale" section
is written from it by hand, with the machine's load).

    python python/examples/scaling.py --cli target/release/placecat [--work /tmp/placecat-scaling]

1. 2,000 simulated indoor scans (`placecat simulate --scene indoor --scans 400 --seed 2`,
   a development seed) written under --work (never in the repository).
2. Describe them: one plain Python process (`describe_file` in a loop),
   the same with a thread per core (the GIL is released), a LocalCluster of
   2 single-threaded worker processes through `placecat.fleet.describe`,
   and the CLI (rayon, every core) for reference.
3. 100,000 descriptors: the 2,000 reused 50 times, 0..2 added to every
   count (as the core's `sim::reused_descriptors` does), written as fleet
   parts; `fleet.categorise(sample=None)` in a fresh process: time of each
   stage and the peak resident memory.
"""

import argparse
import json
import os
import resource
import shutil
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import placecat
from placecat import fleet


def load() -> str:
    with open("/proc/loadavg") as f:
        return " ".join(f.read().split()[:3])


def simulate(cli: str, work: str) -> list:
    scans = os.path.join(work, "scans")
    if not os.path.exists(os.path.join(scans, "labels.csv")):
        subprocess.run([cli, "simulate", "--scene", "indoor", "--scans", "400", "--seed", "2", "-o", scans], check=True)
    return fleet.list_scans(scans)


def timed(f):
    t = time.perf_counter()
    out = f()
    return out, time.perf_counter() - t


def describe_stage(cli: str, work: str, files: list, rounds: int) -> dict:
    """Each way of describing, `rounds` times in turn (the machine is shared:
    alternating spreads its load over all of them); the fastest of each."""
    from distributed import Client, LocalCluster

    run = os.path.join(work, "run")
    times = {"single_process_s": [], "threads_s": [], "dask_2_workers_s": [], "cli_s": []}
    # CPU seconds, which the other sessions' load does not inflate (wall
    # time does: a process gets a share of a core).
    cpu = {"single_process_cpu_s": [], "dask_workers_cpu_s": [], "cli_cpu_s": []}
    out = {"files": len(files), "rounds": rounds, "load_before": load()}
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    client = Client(cluster)
    for _ in range(rounds):
        c = time.process_time()
        times["single_process_s"].append(timed(lambda: [placecat.describe_file(f) for f in files])[1])
        cpu["single_process_cpu_s"].append(time.process_time() - c)
        with ThreadPoolExecutor(os.cpu_count()) as pool:
            times["threads_s"].append(timed(lambda: list(pool.map(placecat.describe_file, files)))[1])
        shutil.rmtree(run, ignore_errors=True)
        before = sum(client.run(time.process_time).values())
        r, t = timed(lambda: fleet.describe(files, run, client, batch_size=64, quiet=True))
        cpu["dask_workers_cpu_s"].append(sum(client.run(time.process_time).values()) - before)
        assert r.described == len(files), r
        times["dask_2_workers_s"].append(t)
        cmd = [cli, "describe", *files, "-o", os.path.join(work, "cli.json")]
        c = resource.getrusage(resource.RUSAGE_CHILDREN)
        times["cli_s"].append(timed(lambda: subprocess.run(cmd, check=True, capture_output=True))[1])
        c2 = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu["cli_cpu_s"].append(c2.ru_utime + c2.ru_stime - c.ru_utime - c.ru_stime)
    # A rerun: every file skipped (the restart cost).
    _, out["dask_rerun_s"] = timed(lambda: fleet.describe(files, run, client, batch_size=64, quiet=True))
    client.close()
    cluster.close()
    out["all_s"] = times
    out["all_cpu_s"] = cpu
    out.update({k: min(v) for k, v in times.items()})
    out.update({k: min(v) for k, v in cpu.items()})
    out["per_scan_cpu_s"] = out["single_process_cpu_s"] / len(files)
    out["dask_cpu_overhead"] = out["dask_workers_cpu_s"] / out["single_process_cpu_s"]
    single = out["single_process_s"]
    out["per_scan_core_s"] = single / len(files)
    out["dask_vs_single"] = single / out["dask_2_workers_s"]
    out["threads_vs_single"] = single / out["threads_s"]
    out["cli_vs_single"] = single / out["cli_s"]
    sizes = [len(d) for _, descs in fleet.iter_descriptors(run) for d in descs]
    out["descriptor_json_bytes_mean"] = sum(sizes) / len(sizes)
    out["scan_file_bytes_mean"] = sum(os.path.getsize(f) for f in files) / len(files)
    out["load_after"] = load()
    return out


def make_100k(work: str, n: int = 100_000, part: int = 2000, seed: int = 5) -> str:
    """n descriptors from the described 2,000, with 0..2 added to every count."""
    big = os.path.join(work, "big")
    shutil.rmtree(big, ignore_errors=True)
    os.makedirs(os.path.join(big, "descriptors"))
    shutil.copy(os.path.join(work, "run", "params.json"), big)
    base = [(f, json.loads(d)) for files, descs in fleet.iter_descriptors(os.path.join(work, "run")) for f, d in zip(files, descs)]
    rng = np.random.default_rng(seed)
    rows = []
    index = 0
    for i in range(n):
        f, d = base[i % len(base)]
        m = np.asarray(d["matrices"], dtype=np.uint32)
        m = m + rng.integers(0, 3, size=m.shape, dtype=np.uint32)
        rows.append((f"{f}#{i // len(base)}", json.dumps({**d, "matrices": m.tolist()}), None))
        if len(rows) == part:
            fleet._write_part(big, index, rows)
            index += 1
            rows = []
    if rows:
        fleet._write_part(big, index, rows)
    return big


CLUSTER_CHILD = r"""
import json, resource, sys, time
import placecat
from placecat import fleet
out, method = sys.argv[1], sys.argv[2]
t = {}
t0 = time.perf_counter()
col = fleet.load_collection(out)
t["load_s"] = time.perf_counter() - t0
rss_loaded = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
t1 = time.perf_counter()
if method == "hkmeans":
    tree = col.hkmeans(seed=0)
    t["hkmeans_s"] = time.perf_counter() - t1
    t2 = time.perf_counter()
    k = col.choose_categories(tree)["k"]
    t["choose_k_s"] = time.perf_counter() - t2
    labels = tree.cut_k(k)["labels"]
else:
    r = col.kmeans()
    k, labels = r["k"], r["labels"]
    t["kmeans_auto_s"] = time.perf_counter() - t1
t["categories"] = k
t3 = time.perf_counter()
model = col.build_model(labels)
del col
t4 = time.perf_counter()
t["model_s"] = t4 - t3
# categorise's last stage: classify every scan, streamed, and write Parquet.
import os, pyarrow as pa, pyarrow.parquet as pq
params_json = open(os.path.join(out, "params.json")).read()
n = 0
for files, descs in fleet.iter_descriptors(out):
    for d in descs:
        model.classify(placecat.Descriptor.from_parts(params_json, d))
    n += len(files)
t["classify_all_s"] = time.perf_counter() - t4
t["scans"] = n
t["peak_rss_mib"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
t["rss_after_load_mib"] = rss_loaded / 1024
print(json.dumps(t))
"""


def cluster_stage(big: str, method: str) -> dict:
    t = time.perf_counter()
    r = subprocess.run([sys.executable, "-c", CLUSTER_CHILD, big, method], check=True, capture_output=True, text=True)
    out = json.loads(r.stdout)
    out["total_s"] = time.perf_counter() - t
    out["load_before"] = load()
    return out


def baseline_rss() -> float:
    r = subprocess.run(
        [sys.executable, "-c", "import resource, placecat, pyarrow.parquet; print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)"],
        check=True,
        capture_output=True,
        text=True,
    )
    return int(r.stdout) / 1024


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", required=True)
    ap.add_argument("--work", default="/tmp/placecat-scaling")
    ap.add_argument("--skip-describe", action="store_true")
    ap.add_argument("--skip-cluster", action="store_true")
    ap.add_argument("--rounds", type=int, default=3)
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    files = simulate(a.cli, a.work)
    res = {"cores": os.cpu_count()}
    if not a.skip_describe:
        res["describe"] = describe_stage(a.cli, a.work, files, a.rounds)
        print(json.dumps(res["describe"]), file=sys.stderr)
    if a.skip_cluster:
        print(json.dumps(res, indent=1))
        return 0
    big = make_100k(a.work)
    res["python_baseline_rss_mib"] = baseline_rss()
    for method in ("hkmeans", "kmeans"):
        res[f"cluster_100k_{method}"] = cluster_stage(big, method)
        print(json.dumps(res[f"cluster_100k_{method}"]), file=sys.stderr)
    print(json.dumps(res, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
