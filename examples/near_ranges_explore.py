"""Issue 14, seventh round, before its development run: range intervals of
the outdoor descriptor tried on the outdoor site through the CLI, on
development seeds only (docs/seeds.md, seventh round). Its figures are
docs/near-ranges-explore.json; examples/near_ranges.rs then compared the
chosen one (outdoor_near) with outdoor and outdoor_hellinger.

    cargo build --release
    SEEDS=1,2,3 ONLY=hn20,paper python3 examples/near_ranges_explore.py

For each seed and variant: `placecat simulate --scene outdoor --seed S`,
`placecat describe --params VARIANT.json`, stride k-means at 3, and
hierarchical k-means++ with ten trial splits cut at 3 for tree seeds 0-9
(`placecat evaluate` against labels.csv). Work files go to $WORK (default
a temporary folder). Prints each variant's accuracies per seed.
"""
import json
import os
import statistics
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CLI = os.environ.get("PLACECAT", str(ROOT / "target/release/placecat"))
WORK = Path(os.environ.get("WORK") or tempfile.mkdtemp(prefix="near-ranges-"))
# Development seeds of the seventh round only (the test seeds 801-805 were
# run once by examples/near_ranges.rs).
DEV = set(range(1, 11)) | set(range(501, 506)) | set(range(601, 606)) | set(range(701, 706))
SEEDS = [int(s) for s in os.environ.get("SEEDS", "1,2,3,4,5,6,7,8,9,10").split(",")]
assert all(s in DEV for s in SEEDS), "development seeds only"
TREES = 10

PAPER = [[5, 8], [7, 10], [9, 12], [11, 15], [14, 20]]
VARIANTS = {
    "paper": {"preset": "outdoor"},
    "hell": {"preset": "outdoor_hellinger"},
    "r15": {"preset": "outdoor", "ranges": PAPER[:4]},
    "r12": {"preset": "outdoor", "ranges": PAPER[:3]},
    "n20": {"preset": "outdoor", "ranges": [[2, 5], [4, 8]] + PAPER[1:]},
    "n15": {"preset": "outdoor", "ranges": [[2, 5], [4, 8]] + PAPER[1:4]},
    "n12": {"preset": "outdoor", "ranges": [[2, 5], [4, 8]] + PAPER[1:3]},
    # outdoor_near is hn20.
    "hn20": {"preset": "outdoor_hellinger", "ranges": [[2, 5], [4, 8]] + PAPER[1:]},
    "hn20b": {"preset": "outdoor_hellinger", "ranges": [[2, 5], [4, 7], [6, 9], [8, 12]] + PAPER[3:]},
    "hn20c": {"preset": "outdoor_hellinger", "ranges": [[3, 6]] + PAPER},
    "hn20d": {"preset": "outdoor_hellinger", "ranges": [[2, 5]] + PAPER},
    "hn1": {"preset": "outdoor_hellinger", "ranges": [[1, 4], [3, 6]] + PAPER},
}
only = os.environ.get("ONLY")
if only:
    VARIANTS = {k: v for k, v in VARIANTS.items() if k in only.split(",")}


def run(*args):
    return subprocess.run([CLI, *map(str, args)], check=True, capture_output=True, text=True).stdout


def simulated(seed):
    d = WORK / f"sim/outdoor-{seed}"
    if not (d / "labels.csv").exists():
        run("simulate", "--scene", "outdoor", "--seed", seed, "-o", d)
    return d


def accuracy(out, d):
    return json.loads(run("evaluate", out, "--truth", d / "labels.csv"))["accuracy"]


def one(seed, name, params):
    d = simulated(seed)
    w = WORK / f"w/{name}-{seed}"
    w.mkdir(parents=True, exist_ok=True)
    (w / "params.json").write_text(json.dumps(params))
    run("describe", "--params", w / "params.json", d, "-o", w / "d.json")
    run("cluster", w / "d.json", "--method", "kmeans", "--seeding", "stride", "--k", 3, "-o", w / "s.json")
    trees = []
    for t in range(TREES):
        out = w / f"h{t}.json"
        run("cluster", w / "d.json", "--method", "hkmeans", "--categories", 3, "--restarts", 10, "--seed", t, "-o", out)
        trees.append(accuracy(out, d))
    return seed, name, accuracy(w / "s.json", d), statistics.mean(trees), min(trees)


with ThreadPoolExecutor(2) as pool:
    list(pool.map(simulated, SEEDS))
    res = list(pool.map(lambda a: one(*a), [(s, n, p) for n, p in VARIANTS.items() for s in SEEDS]))
for n in VARIANTS:
    rows = [r for r in res if r[1] == n]
    print(f"{n:6s} stride", " ".join(f"{r[2] * 100:5.1f}" for r in rows),
          f"| mean {statistics.mean(r[2] for r in rows) * 100:5.2f} lowest {min(r[2] for r in rows) * 100:5.1f}")
    print(f"{'':6s} tree  ", " ".join(f"{r[3] * 100:5.1f}" for r in rows),
          f"| mean {statistics.mean(r[3] for r in rows) * 100:5.2f} lowest tree {min(r[4] for r in rows) * 100:5.1f}")
