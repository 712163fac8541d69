#!/usr/bin/env python3
"""A big ROS bag for bench/bag-memory.mjs (never committed): a robot at 1 m/s
records a cloud every 0.1 s (0.1 m apart) walking through rooms whose width
changes every 10 m (floor, two walls, a ceiling: structure every cloud can be
described by), with odometry at 50 Hz. Each cloud is P points of float32
x, y, z, intensity (16 bytes). ROS 1 with lz4 chunks (.bag) or rosbag2 MCAP
with zstd chunks (.mcap), written by the `rosbags` package.

    python3 -m venv /tmp/venv-bags && /tmp/venv-bags/bin/pip install rosbags numpy
    /tmp/venv-bags/bin/python bench/make_walk_bag.py /tmp/big.bag 560 120000   # ~1 GB
"""

import math
import shutil
import sys
import tempfile
from pathlib import Path

import numpy as np
from rosbags.rosbag1 import Writer
from rosbags.rosbag2 import StoragePlugin, Writer as Writer2
from rosbags.rosbag2.enums import CompressionFormat, CompressionMode
from rosbags.typesys import Stores, get_typestore

out = sys.argv[1]
n = int(sys.argv[2]) if len(sys.argv) > 2 else 560
p = int(sys.argv[3]) if len(sys.argv) > 3 else 120_000
ros2 = out.endswith(".mcap")
Path(out).unlink(missing_ok=True)
ts = get_typestore(Stores.ROS2_HUMBLE if ros2 else Stores.ROS1_NOETIC)
T = ts.types
rng = np.random.default_rng(0)
if ros2:
    tmp = Path(tempfile.mkdtemp()) / "bag"
    w = Writer2(tmp, version=9, storage_plugin=StoragePlugin.MCAP)
    w.set_compression(CompressionMode.STORAGE, CompressionFormat.ZSTD)
    ser = ts.serialize_cdr
else:
    w = Writer(out)
    w.set_compression(Writer.CompressionFormat.LZ4)
    ser = ts.serialize_ros1


def header(t, frame):
    sec = int(math.floor(t))
    stamp = T["builtin_interfaces/msg/Time"](sec=sec, nanosec=int(round((t - sec) * 1e9)))
    if ros2:
        return T["std_msgs/msg/Header"](stamp=stamp, frame_id=frame)
    return T["std_msgs/msg/Header"](seq=0, stamp=stamp, frame_id=frame)


def cloud(i):
    """A room around the robot: half width 1.5 m to 6 m, changing every 100 clouds."""
    half = [1.5, 4.0, 2.5, 6.0][(i // 100) % 4]
    height = 2.5 if half < 3 else 4.0
    k = p // 4
    u = lambda lo, hi, m: rng.uniform(lo, hi, m)
    floor = np.c_[u(-15, 15, k), u(-half, half, k), np.full(k, -1.0)]
    ceiling = np.c_[u(-15, 15, k), u(-half, half, k), np.full(k, height - 1.0)]
    left = np.c_[u(-15, 15, k), np.full(k, half), u(-1, height - 1.0, k)]
    right = np.c_[u(-15, 15, p - 3 * k), np.full(p - 3 * k, -half), u(-1, height - 1.0, p - 3 * k)]
    xyz = np.round(np.vstack([floor, ceiling, left, right]), 2)
    pts = np.c_[xyz, rng.uniform(0, 100, p)].astype("<f4")
    return pts


def odometry(t):
    x = t - 100.0
    q = T["geometry_msgs/msg/Quaternion"](x=0.0, y=0.0, z=0.0, w=1.0)
    pose = T["geometry_msgs/msg/Pose"](position=T["geometry_msgs/msg/Point"](x=x, y=0.0, z=0.0), orientation=q)
    v = T["geometry_msgs/msg/Vector3"](x=1.0, y=0.0, z=0.0)
    return T["nav_msgs/msg/Odometry"](
        header=header(t, "odom"), child_frame_id="base_link",
        pose=T["geometry_msgs/msg/PoseWithCovariance"](pose=pose, covariance=np.zeros(36)),
        twist=T["geometry_msgs/msg/TwistWithCovariance"](twist=T["geometry_msgs/msg/Twist"](linear=v, angular=v), covariance=np.zeros(36)))


with w:
    pc = w.add_connection("/points", "sensor_msgs/msg/PointCloud2", typestore=ts)
    od = w.add_connection("/odom", "nav_msgs/msg/Odometry", typestore=ts)
    fields = [T["sensor_msgs/msg/PointField"](name=c, offset=4 * j, datatype=7, count=1) for j, c in enumerate(["x", "y", "z", "intensity"])]
    for i in range(n):
        t = 100.0 + 0.1 * i
        for j in range(5):  # odometry at 50 Hz, the first one before the cloud
            to = t + 0.02 * j
            w.write(od, int(round(to * 1e9)), ser(odometry(to), "nav_msgs/msg/Odometry"))
        pts = cloud(i)
        msg = T["sensor_msgs/msg/PointCloud2"](header=header(t, "velodyne"), height=1, width=p, fields=fields, is_bigendian=False,
                                             point_step=16, row_step=16 * p, data=np.frombuffer(pts.tobytes(), np.uint8), is_dense=True)
        w.write(pc, int(round(t * 1e9)) + 1, ser(msg, "sensor_msgs/msg/PointCloud2"))
if ros2:
    (mcap,) = tmp.glob("*.mcap")
    shutil.move(str(mcap), out)
    shutil.rmtree(tmp.parent)
