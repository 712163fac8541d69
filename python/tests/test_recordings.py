"""placecat.scans: the scans of ROS bags and E57 surveys one at a time, as
the CLI reads them. The fixtures were written by other tools: the bags by
the Python rosbags package (tests/data/bags/make_bags.py), the survey by
pye57 (tests/data/survey/make_survey.py), whose recorded figures are in
their expected.json files."""

import json
import math

import numpy as np
import pytest

import placecat
from conftest import ROOT

BAGS = ROOT / "tests/data/bags"
SURVEY = ROOT / "tests/data/survey"


def test_an_e57_survey_gives_every_station_in_its_own_frame_with_its_pose():
    want = json.loads((SURVEY / "expected.json").read_text())["survey.e57"]["scans"]
    scans = placecat.scans(SURVEY / "survey.e57")
    assert (scans.total, scans.met, scans.topic) == (4, 0, None)
    got = list(scans)
    assert scans.met == 4 and scans.errors == []
    stations = ["hall", "office", "hall (scan 2)", "store"]
    # Named by the file's base name, as the page names them (errors name the path).
    assert [s["name"] for s in got] == [f"survey.e57:{n}" for n in stations]
    for s, w in zip(got, want):
        assert s["points"].dtype == np.float32 and s["points"].shape == (w["points"], 3)
        # The writer's float64 sums of the finite points, in the scan's own frame.
        finite = s["points"][np.isfinite(s["points"]).all(axis=1)].astype(np.float64)
        assert np.allclose(finite.sum(axis=0), w["sum"], atol=1e-3), s["name"]
        assert s["pose"]["position"] == w["translation"]
        assert math.isclose(s["pose"]["yaw"], w["yaw"], abs_tol=1e-9)
    # The scanner's invalid points (no return) are NaN: ten in the office.
    assert np.isnan(got[1]["points"][:, 0]).sum() == 10


def test_a_bag_gives_its_clouds_with_their_odometry_thinned_as_the_cli_thins():
    clouds = list(placecat.scans(BAGS / "ros1_corridor.bag"))
    # Named by the bag's base name, topic and index, as the page names them.
    assert [c["name"] for c in clouds] == [
        "ros1_corridor.bag:/points:000000",
        "ros1_corridor.bag:/points:000001",
    ]
    assert [c["points"].shape for c in clouds] == [(2700, 3), (2700, 3)]
    assert [c["pose"]["position"] for c in clouds] == [[0.0, 0.0, 0.0], [0.5, 0.25, 0.0]]
    # The second cloud is 0.56 m on: one a metre keeps the first only, as --every-metres 1.
    one = placecat.scans(BAGS / "ros1_corridor.bag", every_metres=1.0)
    assert one.topic == "/points"
    assert len(list(one)) == 1 and one.met == 2 and one.total == 2
    # The points describe as any array does.
    d = placecat.describe(clouds[0]["points"], "indoor")
    assert d.summary["points"] == 2700


def test_name_keeps_recordings_of_one_name_in_different_folders_apart(tmp_path):
    # Two runs saved as run.bag in their own folders: by base name their
    # clouds would share names; named by their paths under the fleet's
    # folder (as the CLI's describe names them), they do not.
    data = (BAGS / "ros1_corridor.bag").read_bytes()
    names = []
    for day in ("monday", "tuesday"):
        (tmp_path / day).mkdir()
        (tmp_path / day / "run.bag").write_bytes(data)
        clouds = list(placecat.scans(tmp_path / day / "run.bag", name=f"{day}/run.bag"))
        assert [c["pose"]["name"] for c in clouds] == [c["name"] for c in clouds]
        names += [c["name"] for c in clouds]
    assert names == [f"{d}/run.bag:/points:00000{i}" for d in ("monday", "tuesday") for i in (0, 1)]
    assert [c["name"] for c in placecat.scans(tmp_path / "monday" / "run.bag")] == ["run.bag:/points:000000", "run.bag:/points:000001"]
    # A survey's stations the same way.
    stations = list(placecat.scans(SURVEY / "survey.e57", name="site/a.e57"))
    assert [s["name"] for s in stations][:2] == ["site/a.e57:hall", "site/a.e57:office"]
    assert stations[1]["pose"]["name"] == "site/a.e57:office"
    # A skipped cloud is labelled by the name too; the message names the file.
    bad = placecat.scans(BAGS / "bad_no_xyz.bag", name="tuesday/bad.bag")
    with pytest.warns(UserWarning):
        list(bad)
    assert "(tuesday/bad.bag:" in bad.errors[0] and "bad_no_xyz.bag" in bad.errors[0]


def test_a_cloud_that_cannot_be_read_is_skipped_with_a_warning_and_listed():
    scans = placecat.scans(BAGS / "bad_no_xyz.bag")
    with pytest.warns(UserWarning, match=r"cloud 2 .*no field \"x\""):
        got = list(scans)
    # The writer's record of the bag: five clouds, the third without x.
    want = json.loads((BAGS / "expected.json").read_text())["bad_no_xyz.bag"]["clouds"]
    assert [c["no_xyz"] for c in want] == [False, False, True, False, False]
    assert [s["name"].rsplit(":", 1)[-1] for s in got] == ["000000", "000001", "000003", "000004"]
    assert [s["points"].shape[0] for s in got] == [c["count"] for c in want if not c["no_xyz"]]
    assert len(scans.errors) == 1 and "bad_no_xyz.bag" in scans.errors[0]


def test_what_is_not_a_recording_or_cannot_be_opened_raises_naming_the_file():
    with pytest.raises(placecat.PlacecatError, match=r"room_scan1\.pcd: invalid parameter: not a recording"):
        placecat.scans(ROOT / "tests/data/real/pcl_room/room_scan1.pcd")
    with pytest.raises(placecat.PlacecatError, match=r"truncated\.e57: E57: .*truncated"):
        placecat.scans(SURVEY / "truncated.e57")
    with pytest.raises(placecat.PlacecatError, match=r"survey\.e57: .*a topic, every and every_metres are a bag.s"):
        placecat.scans(SURVEY / "survey.e57", every=2)
    with pytest.raises(placecat.PlacecatError, match=r"las14_fmt6\.las: .*not a recording"):
        placecat.scans(SURVEY / "las14_fmt6.las")
    with pytest.raises(placecat.PlacecatError, match="/nope"):
        placecat.scans(BAGS / "two_cloud_topics.bag", topic="/nope")
