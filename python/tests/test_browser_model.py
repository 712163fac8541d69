"""A model named in the browser classifies in Python, and back: the page's
engine is the wasm build (pkg/node, built by npm test before this step);
its Model JSON loads in Python and Python's in it, with the same answers."""

import json
import os
import shutil
import subprocess

import pytest

import placecat
from conftest import ROOT

FILES = [
    "tests/data/real/pcl_room/room_scan1.pcd",
    "tests/data/real/pcl_room/room_scan2.pcd",
    "tests/data/real/velodyne_pair/251370668.pcd",
    "tests/data/real/velodyne_pair/251371071.pcd",
]

NODE = r"""
const fs = require('fs');
const { describeScan, DescriptorSet, Model } = require(process.argv[2]);
const [root, pyModelPath, outPath] = process.argv.slice(3);
const files = JSON.parse(process.argv[6]);
const set = new DescriptorSet(undefined, 'indoor');
const scans = files.map((f) => describeScan(fs.readFileSync(`${root}/${f}`), f, undefined, 'indoor'));
for (const s of scans) set.add(s);
const jsModel = set.buildModel([0, 0, 1, 1], { 0: 'room', 1: 'street' });
const pyModel = Model.fromJson(fs.readFileSync(pyModelPath, 'utf8'));
fs.writeFileSync(outPath, JSON.stringify({
  model: jsModel.toJson(),
  byPythonModel: scans.map((s) => pyModel.classify(s)),
}));
"""


def test_models_cross_between_the_page_engine_and_python(tmp_path):
    pkg = ROOT / "pkg/node/placecat.js"
    if not pkg.exists() or not shutil.which("node"):
        if os.environ.get("PLACECAT_REQUIRE_PKG"):
            raise AssertionError(f"{pkg} (the wasm build, scripts/build-pkg.sh) or node is missing")
        pytest.skip("no pkg/node build: run scripts/build-pkg.sh")
    ds = [placecat.describe_file(ROOT / f, "indoor") for f in FILES]
    py_model = placecat.Collection(ds, names=FILES).build_model([1, 1, 0, 0], {1: "hall", 0: "road"})
    py_model.save(tmp_path / "py-model.json")
    (tmp_path / "cross.js").write_text(NODE)
    subprocess.run(
        ["node", str(tmp_path / "cross.js"), str(pkg), str(ROOT), str(tmp_path / "py-model.json"), str(tmp_path / "out.json"), json.dumps(FILES)],
        check=True,
    )
    out = json.loads((tmp_path / "out.json").read_text())
    # The page's engine classifies with Python's model as Python does.
    for d, theirs in zip(ds, out["byPythonModel"]):
        ours = py_model.classify(d)
        assert theirs["name"] == ours["name"] and abs(theirs["distance"] - ours["distance"]) < 1e-6
    assert [c["name"] for c in out["byPythonModel"]] == ["hall", "hall", "road", "road"]
    # And Python classifies with the engine's model as the engine was taught.
    js_model = placecat.Model.from_json(out["model"])
    assert [js_model.classify(d)["name"] for d in ds] == ["room", "room", "street", "street"]
    same = placecat.Collection(ds).build_model([0, 0, 1, 1], {0: "room", 1: "street"})
    for d in ds:
        a, b = js_model.classify(d), same.classify(d)
        assert a["label"] == b["label"] and abs(a["distance"] - b["distance"]) < 1e-6
