"""Shared fixtures: the repository, the release CLI (the reference every
Python result is checked against) and simulated scans made by it."""

import csv
import json
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def cli_path() -> Path:
    """The CLI built by `cargo build --release` (scripts/test-4-python.sh
    builds it and passes it as PLACECAT_CLI)."""
    target = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    return Path(os.environ.get("PLACECAT_CLI", target / "release" / "placecat"))


def run_cli(*args, check=True) -> subprocess.CompletedProcess:
    exe = cli_path()
    assert exe.exists(), f"{exe}: build the CLI first (cargo build --release)"
    return subprocess.run([str(exe), *map(str, args)], capture_output=True, text=True, check=check)


def simulate(out: Path, scene="indoor", seed=0, scans=2) -> list:
    """Simulated PLY scans in the simulator's order (labels.csv's rows):
    [(path, label)]."""
    run_cli("simulate", "--scene", scene, "--seed", seed, "--scans", scans, "-o", out)
    with open(out / "labels.csv") as f:
        rows = list(csv.reader(f))[1:]
    return [(out / name, label) for name, label in rows]


def cli_describe(files, out: Path, preset="indoor") -> dict:
    run_cli("describe", "--preset", preset, *files, "-o", out)
    return json.loads(out.read_text())


PARITY_REAL = [
    ROOT / "tests/data/real/ouster_os0_sequence/scan_000.bin",
    ROOT / "tests/data/real/ouster_os0_sequence/scan_005.bin",
    ROOT / "tests/data/real/ouster_os0_sequence/scan_009.bin",
    ROOT / "tests/data/real/pcl_room/room_scan1.pcd",
    ROOT / "tests/data/real/pcl_room/room_scan2.pcd",
    ROOT / "tests/data/real/velodyne_pair/251370668.pcd",
]


@pytest.fixture(scope="session")
def parity_files(tmp_path_factory):
    """The scans of tests/common/parity_case.rs in its order: six real
    files, then the indoor simulation of seed 7 with 2 scans a kind."""
    sim = simulate(tmp_path_factory.mktemp("parity"), seed=7, scans=2)
    return PARITY_REAL + [p for p, _ in sim]


@pytest.fixture(scope="session")
def parity_truth(parity_files):
    """A ground truth of the parity files: "real" for the real ones, the
    simulator's kinds for the others."""
    with open(parity_files[-1].parent / "labels.csv") as f:
        kinds = [label for _, label in list(csv.reader(f))[1:]]
    return ["real"] * len(PARITY_REAL) + kinds


@pytest.fixture(scope="session")
def parity_fixture():
    return json.loads((ROOT / "tests/fixtures/parity.json").read_text())
