"""placecat.fleet on a Dask LocalCluster: 200 simulated scans and one bad
file give the CLI's descriptors, the bad file reported and skipped; a rerun
describes nothing again; the results are Parquet and a model the CLI (and
the page) reads."""

import json
import shutil

import pytest

import placecat
from placecat import fleet
from conftest import ROOT, cli_describe, run_cli, simulate

BAD = "ply_trailing_bytes.ply"


@pytest.fixture(scope="module")
def scans(tmp_path_factory):
    d = tmp_path_factory.mktemp("fleet")
    sim = simulate(d / "scans", seed=21, scans=40)  # 5 kinds x 40 = 200 files
    shutil.copy(ROOT / "tests/data/bad" / BAD, d / "scans" / BAD)
    return d, sim


@pytest.fixture(scope="module")
def client():
    from distributed import Client, LocalCluster

    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with Client(cluster) as c:
            yield c


def test_dask_run_gives_the_clis_descriptors_and_skips_the_bad_file(scans, client, capsys):
    d, sim = scans
    out = d / "run"
    assert len(sim) == 200
    r = fleet.describe(str(d / "scans"), str(out), client, params="indoor", batch_size=16)
    assert (r.files, r.skipped, r.described) == (201, 0, 200)
    assert [f for f, _ in r.errors] == [str(d / "scans" / BAD)]
    assert f"skipped {d / 'scans' / BAD}: PLY: " in capsys.readouterr().err

    cli = cli_describe([d / "scans"], d / "cli.json")
    assert len(cli["files"]) == 200 and [e["file"] for e in cli["errors"]] == [str(d / "scans" / BAD)]
    assert r.errors[0][1] == cli["errors"][0]["error"]  # the same message
    ours = {f: json.loads(desc) for files, descs in fleet.iter_descriptors(str(out)) for f, desc in zip(files, descs)}
    theirs = {f["path"]: f["descriptor"] for f in cli["files"]}
    assert ours.keys() == theirs.keys()
    assert all(ours[k] == theirs[k] for k in theirs)

    # Categories of all 200 without an n x n matrix: the CLI's K (same
    # descriptors, order and seed), and each scan in the category of the
    # nearest centre (the CLI's tree cut has accuracy 0.945 here).
    cli_cut = json.loads(run_cli("cluster", d / "cli.json", "--method", "hkmeans", "-o", "-").stdout)
    c = fleet.categorise(str(out), sample=None, seed=0)
    assert (c.scans, c.clustered, c.categories) == (200, 200, cli_cut["categories"])
    truth = {str(p): k for p, k in sim}
    cats = fleet.read_categories(str(out))
    ev = placecat.evaluate([truth[f] for f, _ in cats], [l for _, l in cats])
    assert ev["accuracy"] > 0.8, ev["accuracy"]
    # Trial splits reach the tree and its choice, as the CLI's --restarts.
    cli10 = json.loads(run_cli("cluster", d / "cli.json", "--method", "hkmeans", "--restarts", "10", "-o", "-").stdout)
    c10 = fleet.categorise(str(out), sample=None, seed=0, restarts=10)
    assert c10.categories == cli10["categories"]
    scores = [(k, s) for k, s in c10.choice["scores"]]
    assert [k for k, _ in scores] == [k for k, _ in cli10["choice"]["scores"]]
    assert all(abs(s - t) < 1e-9 for (_, s), (_, t) in zip(scores, cli10["choice"]["scores"]))
    assert cli10["choice"]["scores"] != cli_cut["choice"]["scores"], "the trials change the tree here"
    for bad in (0, -1, 1001, 2.5, True):
        with pytest.raises(placecat.PlacecatError, match="restarts must be a whole number from 1 to 1000"):
            fleet.categorise(str(out), sample=None, seed=0, restarts=bad)

    # Restartable: a rerun describes nothing already described (the bad
    # file is tried again), and a new file only.
    again = fleet.describe(str(d / "scans"), str(out), client, params="indoor", batch_size=16, quiet=True)
    assert (again.skipped, again.described, len(again.errors)) == (200, 0, 1)
    extra = simulate(d / "extra", seed=43, scans=1)[0]
    shutil.copy(extra[0], d / "scans" / "extra.ply")
    more = fleet.describe(str(d / "scans"), str(out), client, params="indoor", batch_size=16, quiet=True)
    assert (more.files, more.skipped, more.described) == (202, 200, 1)
    with pytest.raises(placecat.PlacecatError, match="other parameters"):
        fleet.describe(str(d / "scans"), str(out), client, params="outdoor")

    # A sample: Parquet of every described scan all the same, and a model
    # that the CLI classifies with as Python does.
    c = fleet.categorise(str(out), sample=150, seed=0)
    assert (c.scans, c.clustered) == (201, 150) and c.categories >= 2
    cats = fleet.read_categories(str(out))
    assert len(cats) == 201
    model = placecat.Model.load(out / "model.json")
    rows = run_cli("classify", out / "model.json", d / "scans" / "extra.ply", "-o", "-").stdout.splitlines()
    assert rows[1].split(",")[1] == model.classify_file(d / "scans" / "extra.ply")["name"]
    label = dict(cats)[str(d / "scans" / "extra.ply")]
    assert model.classify_file(d / "scans" / "extra.ply")["label"] == label


def test_fsspec_urls_describe_like_paths(scans):
    d, sim = scans
    url = "file://" + str(d / "scans")
    listed = fleet.list_scans(url)
    assert listed == ["file://" + f for f in fleet.list_scans(str(d / "scans"))]
    local = fleet.describe_batch([str(sim[0][0])], "indoor")
    remote = fleet.describe_batch(["file://" + str(sim[0][0]), "file://" + str(d / "scans" / BAD)], "indoor")
    assert remote[0][1] == local[0][1] and remote[0][2] is None
    assert remote[1][1] is None and remote[1][2].startswith("file://" + str(d / "scans" / BAD) + ": PLY: ")


def test_the_example_script_runs_and_restarts(tmp_path):
    """python/examples/fleet.py as docs/fleet.md runs it (a LocalCluster)."""
    import subprocess
    import sys

    sim = simulate(tmp_path / "scans", seed=44, scans=1)
    cmd = [sys.executable, str(ROOT / "python/examples/fleet.py"), str(tmp_path / "scans"), "--out", str(tmp_path / "run"),
           "--workers", "1", "--categories", "2", "--batch-size", "2", "--restarts", "2"]
    first = subprocess.run(cmd, capture_output=True, text=True)
    assert first.returncode == 0, first.stderr
    assert "described 5 of 5 files (0 already described, 0 skipped)" in first.stderr
    assert "2 categories from 5 scans; 5 scans categorised" in first.stderr
    assert len(fleet.read_categories(str(tmp_path / "run"))) == len(sim)
    assert len(placecat.Model.load(tmp_path / "run" / "model.json").categories) == 2
    again = subprocess.run(cmd + ["--describe-only"], capture_output=True, text=True)
    assert again.returncode == 0, again.stderr
    assert "described 0 of 5 files (5 already described, 0 skipped)" in again.stderr


def test_list_scans_skips_hidden_entries_as_the_cli_does(tmp_path):
    # macOS leaves ._name files beside each scan; editors leave .folders.
    for rel in ["a.ply", "._a.ply", ".cache/b.ply", "sub/c.PCD", "sub/._c.pcd", "notes.txt"]:
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_bytes(b"")
    want = [str(tmp_path / "a.ply"), str(tmp_path / "sub/c.PCD")]
    assert fleet.list_scans(str(tmp_path)) == want
    assert fleet.list_scans("file://" + str(tmp_path)) == ["file://" + f for f in want]
