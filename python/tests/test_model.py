"""A model made in Python classifies like the same model through the CLI,
and a model made by the CLI (the page's format too) loads in Python."""

import csv
import io
import json

import numpy as np

import placecat
from conftest import cli_describe, run_cli, simulate


def test_python_model_classifies_like_the_cli(tmp_path):
    scans = simulate(tmp_path / "train", seed=41, scans=3)
    new = simulate(tmp_path / "new", seed=42, scans=1)
    ds = [placecat.describe_file(p, "indoor") for p, _ in scans]
    c = placecat.Collection(ds, names=[p.name for p, _ in scans])
    kinds = sorted({k for _, k in scans})
    labels = [kinds.index(k) for _, k in scans]
    model = c.build_model(labels, {i: k for i, k in enumerate(kinds)})
    model.save(tmp_path / "model.json")
    assert placecat.Model.load(tmp_path / "model.json") == model

    out = run_cli("classify", tmp_path / "model.json", *[p for p, _ in new], "-o", "-").stdout
    rows = list(csv.DictReader(io.StringIO(out)))
    assert len(rows) == len(new)
    for (path, _), row in zip(new, rows):
        ours = model.classify_file(path)
        assert ours["name"] == row["category"], path
        assert abs(ours["distance"] - float(row["distance"])) < 1e-6
        assert ours == model.classify(placecat.describe(placecat.read(path), model.params))
    right = sum(model.classify_file(p)["name"] == k for p, k in new)
    assert right >= len(new) - 1, right  # simulated kinds are well apart

    # And back: the CLI's model of the same names is the same model.
    cli_describe([p for p, _ in scans], tmp_path / "d.json")
    (tmp_path / "names.csv").write_text("file,name\n" + "".join(f"{p.name},{k}\n" for p, k in scans))
    run_cli("model", tmp_path / "d.json", "--names", tmp_path / "names.csv", "-o", tmp_path / "cli-model.json")
    cli_model = placecat.Model.load(tmp_path / "cli-model.json")
    assert sorted(c_["name"] for c_ in cli_model.categories) == kinds
    for p, _ in new:
        a, b = cli_model.classify_file(p), model.classify_file(p)
        assert a["name"] == b["name"]
        np.testing.assert_allclose(a["distance"], b["distance"], atol=1e-6)


def test_a_bad_model_file_is_named(tmp_path):
    bad = tmp_path / "m.json"
    bad.write_text(json.dumps({"format": "placecat-model/9", "params": placecat.params(), "rows": 11, "cols": 7, "categories": []}))
    try:
        placecat.Model.load(bad)
    except placecat.PlacecatError as e:
        assert str(e).startswith(f"{bad}: mismatch: not a placecat model"), str(e)
    else:
        raise AssertionError("no error")
