#!/usr/bin/env python3
"""Write the E57 and LAS/LAZ fixtures of tests/it/survey.rs with tools that are
not placecat (pye57 over libE57Format, laspy with lazrs), and the figures the
tests check against in expected.json.

    python3 -m venv /tmp/venv-survey
    /tmp/venv-survey/bin/pip install pye57 laspy lazrs numpy
    /tmp/venv-survey/bin/python tests/data/survey/make_survey.py

The output is deterministic for a given set of tool versions (fixed seed;
E57 GUIDs differ from run to run, which the tests do not look at). Sums are
float64 sums of the coordinates as the writer stored them: after scale and
offset for LAS, after the origin shift where one is given, and of the float32
values that pye57 stores for E57 (single precision).
"""

import json
import math
import os
import sys
from importlib import metadata

import laspy
import numpy as np
import pye57
from pye57 import libe57

HERE = os.path.dirname(os.path.abspath(__file__))
rng = np.random.default_rng(20261130)
expected = {"tools": {t: metadata.version(t) for t in ("pye57", "laspy", "lazrs", "numpy")}}


def room(n, half=(4.0, 3.0), height=2.6, sensor_z=1.2):
    """Points on the walls, floor and ceiling of a box around a sensor at
    the origin (sensor frame: z up, floor at -sensor_z)."""
    hx, hy = half
    face = rng.integers(0, 6, n)
    u, v = rng.uniform(-1, 1, n), rng.uniform(0, 1, n)
    x = np.where(face == 0, hx, np.where(face == 1, -hx, u * hx))
    y = np.where(face == 2, hy, np.where(face == 3, -hy, np.where(face < 2, u * hy, rng.uniform(-hy, hy, n))))
    z = np.where(face == 4, -sensor_z, np.where(face == 5, height - sensor_z, v * height - sensor_z))
    return np.stack([x, y, z], axis=1)


def sums(xyz):
    """Count and float64 sums of the finite points."""
    ok = np.isfinite(xyz).all(axis=1)
    s = xyz[ok].astype(np.float64).sum(axis=0)
    return {"points": int(len(xyz)), "finite": int(ok.sum()), "sum": [float(v) for v in s]}


def yaw_quaternion(yaw):
    """(w, x, y, z) of a rotation by yaw about z."""
    return np.array([math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2)])


# ---------------------------------------------------------------- E57
def write_spherical(e57, rae, name, rotation, translation):
    """A scan in spherical coordinates only (pye57's write_scan_raw needs
    Cartesian ones), through pye57's libE57Format bindings."""
    imf = e57.image_file
    scan = libe57.StructureNode(imf)
    scan.set("guid", libe57.StringNode(imf, "{5e57a1d0-0000-4000-8000-000000000002}"))
    scan.set("name", libe57.StringNode(imf, name))
    pose = libe57.StructureNode(imf)
    rot = libe57.StructureNode(imf)
    for k, v in zip("wxyz", rotation):
        rot.set(k, libe57.FloatNode(imf, float(v)))
    pose.set("rotation", rot)
    tr = libe57.StructureNode(imf)
    for k, v in zip("xyz", translation):
        tr.set(k, libe57.FloatNode(imf, float(v)))
    pose.set("translation", tr)
    scan.set("pose", pose)
    proto = libe57.StructureNode(imf)
    proto.set("sphericalRange", libe57.FloatNode(imf, 0.0, libe57.E57_DOUBLE, 0.0, 100.0))
    proto.set("sphericalAzimuth", libe57.FloatNode(imf, 0.0, libe57.E57_DOUBLE, -math.pi, math.pi))
    proto.set("sphericalElevation", libe57.FloatNode(imf, 0.0, libe57.E57_DOUBLE, -math.pi / 2, math.pi / 2))
    points = libe57.CompressedVectorNode(imf, proto, libe57.VectorNode(imf, True))
    scan.set("points", points)
    e57.data3d.append(scan)
    fields = ["sphericalRange", "sphericalAzimuth", "sphericalElevation"]
    arrays, buffers = e57.make_buffers(fields, len(rae))
    for i, f in enumerate(fields):
        arrays[f][:] = rae[:, i]
    writer = points.writer(buffers)
    writer.write(len(rae))
    writer.close()


def make_e57():
    stations = [
        # name, points (sensor frame), yaw, translation
        ("hall", room(900, (6.0, 2.0)), 0.0, (0.0, 0.0, 0.0)),
        ("office", room(700, (3.0, 3.0)), math.pi / 2, (10.0, 2.0, 0.5)),
        ("hall", room(500, (6.0, 2.0)), -math.pi / 6, (-4.0, 6.0, 1.2)),
    ]
    path = os.path.join(HERE, "survey.e57")
    scans = []
    with pye57.E57(path, mode="w") as e57:
        for i, (name, xyz, yaw, t) in enumerate(stations):
            q = yaw_quaternion(yaw)
            data = {"cartesianX": xyz[:, 0], "cartesianY": xyz[:, 1], "cartesianZ": xyz[:, 2]}
            stored = xyz.astype(np.float32).astype(np.float64)
            if i == 1:
                # Ten points the scanner marks invalid (no return): readers keep them as NaN.
                state = np.zeros(len(xyz), dtype=np.int8)
                state[::70] = 2
                data["cartesianInvalidState"] = state
                stored[state != 0] = np.nan
            e57.write_scan_raw(data, name=name, rotation=q, translation=np.array(t))
            scans.append({"name": name, "yaw": yaw, "translation": list(t), **sums(stored)})
        # A fourth station in spherical coordinates (range, azimuth, elevation).
        xyz = room(400, (2.5, 2.0))
        r = np.linalg.norm(xyz, axis=1)
        rae = np.stack([r, np.arctan2(xyz[:, 1], xyz[:, 0]), np.arcsin(xyz[:, 2] / r)], axis=1)
        yaw, t = math.pi, (3.0, -7.0, 0.0)
        write_spherical(e57, rae, "store", yaw_quaternion(yaw), t)
        back = np.stack([rae[:, 0] * np.cos(rae[:, 2]) * np.cos(rae[:, 1]),
                         rae[:, 0] * np.cos(rae[:, 2]) * np.sin(rae[:, 1]),
                         rae[:, 0] * np.sin(rae[:, 2])], axis=1)
        scans.append({"name": "store", "yaw": yaw, "translation": list(t), "spherical": True, **sums(back)})
    expected["survey.e57"] = {"scans": scans}
    data = open(path, "rb").read()
    # Damaged: the same file cut at two thirds.
    open(os.path.join(HERE, "truncated.e57"), "wb").write(data[: len(data) * 2 // 3])


# ---------------------------------------------------------------- LAS / LAZ
def write_las(name, version, point_format, xyz, scale, offset, compressed=False, origin=None):
    header = laspy.LasHeader(version=version, point_format=point_format)
    header.scales = np.array(scale)
    header.offsets = np.array(offset)
    las = laspy.LasData(header)
    las.x, las.y, las.z = xyz[:, 0], xyz[:, 1], xyz[:, 2]
    n = len(xyz)
    las.intensity = rng.integers(0, 65535, n, dtype=np.uint16)
    if "gps_time" in las.point_format.dimension_names:
        las.gps_time = np.linspace(1000.0, 1001.0, n)
    if "red" in las.point_format.dimension_names:
        las.red = las.green = las.blue = rng.integers(0, 65535, n, dtype=np.uint16)
    path = os.path.join(HERE, name)
    las.write(path, do_compress=compressed, laz_backend=laspy.LazBackend.Lazrs if compressed else None)
    back = laspy.read(path)
    stored = np.stack([np.asarray(back.x), np.asarray(back.y), np.asarray(back.z)], axis=1)
    entry = {"version": version, "point_format": point_format, "compressed": compressed, **sums(stored)}
    if origin is not None:
        local = stored - np.array(origin)
        entry["origin"] = list(origin)
        entry["centred"] = sums(local)
        entry["first_centred"] = [float(v) for v in local[0]]
    expected[name] = entry
    return path


def make_las():
    # Sensor-frame scans: the sensor is at the file's origin.
    write_las("las12_fmt0.las", "1.2", 0, room(800), (0.001,) * 3, (0.0,) * 3)
    write_las("las12_fmt1.las", "1.2", 1, room(600), (0.01, 0.01, 0.001), (0.0, 0.0, 0.0))
    write_las("las12_fmt3.las", "1.2", 3, room(700), (0.0001,) * 3, (-2.0, 1.0, 0.5))
    write_las("las14_fmt6.las", "1.4", 6, room(1000), (0.001,) * 3, (0.0,) * 3)
    write_las("laz12_fmt1.laz", "1.2", 1, room(3000), (0.001,) * 3, (0.0,) * 3, compressed=True)
    write_las("laz14_fmt6.laz", "1.4", 6, room(3000), (0.001,) * 3, (0.0,) * 3, compressed=True)
    # Georeferenced (UTM-like): a station at 512345.678 E, 6123456.789 N, 98.765 m.
    station = (512345.678, 6123456.789, 98.765)
    world = room(1200, (8.0, 5.0)) + np.array(station)
    write_las("geo14_fmt6.las", "1.4", 6, world, (0.001,) * 3, (500000.0, 6000000.0, 0.0), origin=station)

    # Damaged: a LAS cut in its point records; a LAZ whose chunks are overwritten.
    data = open(os.path.join(HERE, "las12_fmt3.las"), "rb").read()
    open(os.path.join(HERE, "truncated.las"), "wb").write(data[: len(data) - 1000])
    data = bytearray(open(os.path.join(HERE, "laz12_fmt1.laz"), "rb").read())
    offset_to_points = int.from_bytes(data[96:100], "little")
    # The 8 bytes at the start of the point data point to the chunk table
    # (lazrs writes one); garble the compressed points between them.
    start, end = offset_to_points + 8, int.from_bytes(data[offset_to_points:offset_to_points + 8], "little")
    garbage = np.random.default_rng(7).integers(0, 256, end - start - 200, dtype=np.uint8).tobytes()
    data[start + 100:end - 100] = garbage
    open(os.path.join(HERE, "corrupt_chunk.laz"), "wb").write(bytes(data))


def make_single_e57():
    """A survey of one station: what `read_scan` takes as one scan."""
    xyz = room(300, (2.0, 2.0))
    with pye57.E57(os.path.join(HERE, "single.e57"), mode="w") as e57:
        e57.write_scan_raw({"cartesianX": xyz[:, 0], "cartesianY": xyz[:, 1], "cartesianZ": xyz[:, 2]})
    expected["single.e57"] = sums(xyz.astype(np.float32).astype(np.float64))


def main():
    make_e57()
    make_las()
    make_single_e57()
    with open(os.path.join(HERE, "expected.json"), "w") as f:
        json.dump(expected, f, indent=1, sort_keys=True)
        f.write("\n")
    total = sum(os.path.getsize(os.path.join(HERE, n)) for n in os.listdir(HERE))
    print(f"wrote {len(os.listdir(HERE))} files, {total} bytes", file=sys.stderr)


if __name__ == "__main__":
    main()
