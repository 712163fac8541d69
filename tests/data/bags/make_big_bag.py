#!/usr/bin/env python3
"""A large bag for measuring throughput and peak memory (not committed data):
N clouds of P points (float32 x/y/z/intensity) with odometry, written by
rosbags: OUT.bag is ROS 1 with lz4 chunks, OUT.mcap rosbag2 MCAP with zstd
chunks. Usage: make_big_bag.py OUT.bag|OUT.mcap [N=200] [P=100000] [--rooms]

The robot moves 0.1 m a cloud along x. Points are uniform in a 60 m cube
(z whole metres), which the descriptor finds too sparse to describe; with
--rooms each cloud is the floor, ceiling and two walls of a room (a
quarter of the points each, on a 1 cm grid) whose half width changes every
100 clouds (1.5, 4, 2.5, 6 m), so that every cloud is described and the
rooms fall into categories (bench/bag-memory.mjs, the page's memory)."""

import shutil
import sys
import tempfile
from pathlib import Path

import numpy as np
from rosbags.rosbag1 import Writer
from rosbags.rosbag2 import StoragePlugin, Writer as Writer2
from rosbags.rosbag2.enums import CompressionFormat, CompressionMode
from rosbags.typesys import Stores, get_typestore

rooms = "--rooms" in sys.argv
args = [a for a in sys.argv[1:] if a != "--rooms"]
out, n, p = args[0], int(args[1]) if len(args) > 1 else 200, int(args[2]) if len(args) > 2 else 100_000
ros2 = out.endswith(".mcap")
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


def room(i):
    half = [1.5, 4.0, 2.5, 6.0][(i // 100) % 4]
    top = 1.5 if half < 3 else 3.0  # the ceiling, over the floor at -1 m
    k = p // 4
    u = rng.uniform
    floor = np.c_[u(-15, 15, k), u(-half, half, k), np.full(k, -1.0)]
    ceiling = np.c_[u(-15, 15, k), u(-half, half, k), np.full(k, top)]
    left = np.c_[u(-15, 15, k), np.full(k, half), u(-1, top, k)]
    right = np.c_[u(-15, 15, p - 3 * k), np.full(p - 3 * k, -half), u(-1, top, p - 3 * k)]
    xyz = np.round(np.vstack([floor, ceiling, left, right]), 2)
    return np.c_[xyz, u(0, 100, p)].astype("<f4")


def header(i, sec, ns):
    stamp = T["builtin_interfaces/msg/Time"](sec=sec, nanosec=ns)
    if ros2:
        return T["std_msgs/msg/Header"](stamp=stamp, frame_id="velodyne")
    return T["std_msgs/msg/Header"](seq=i, stamp=stamp, frame_id="velodyne")


with w:
    pc = w.add_connection("/points", "sensor_msgs/msg/PointCloud2", typestore=ts)
    od = w.add_connection("/odom", "nav_msgs/msg/Odometry", typestore=ts)
    fields = [T["sensor_msgs/msg/PointField"](name=c, offset=4 * i, datatype=7, count=1) for i, c in enumerate("xyzi")]
    for i in range(n):
        t = 100.0 + 0.1 * i
        sec, ns = int(t), int(round((t - int(t)) * 1e9))
        hdr = header(i, sec, ns)
        if rooms:
            pts = room(i)
        else:
            pts = rng.uniform(-30, 30, size=(p, 4)).astype("<f4")
            pts[:, 2] = np.round(pts[:, 2])  # some redundancy for the compressor, as real scans have
        msg = T["sensor_msgs/msg/PointCloud2"](header=hdr, height=1, width=p, fields=fields, is_bigendian=False,
                                             point_step=16, row_step=16 * p, data=np.frombuffer(pts.tobytes(), np.uint8), is_dense=True)
        w.write(pc, sec * 10**9 + ns, ser(msg, "sensor_msgs/msg/PointCloud2"))
        q = T["geometry_msgs/msg/Quaternion"](x=0.0, y=0.0, z=0.0, w=1.0)
        pose = T["geometry_msgs/msg/Pose"](position=T["geometry_msgs/msg/Point"](x=0.1 * i, y=0.0, z=0.0), orientation=q)
        v = T["geometry_msgs/msg/Vector3"](x=0.0, y=0.0, z=0.0)
        odo = T["nav_msgs/msg/Odometry"](header=hdr, child_frame_id="base_link",
                                         pose=T["geometry_msgs/msg/PoseWithCovariance"](pose=pose, covariance=np.zeros(36)),
                                         twist=T["geometry_msgs/msg/TwistWithCovariance"](twist=T["geometry_msgs/msg/Twist"](linear=v, angular=v), covariance=np.zeros(36)))
        w.write(od, sec * 10**9 + ns, ser(odo, "nav_msgs/msg/Odometry"))
if ros2:
    (mcap,) = tmp.glob("*.mcap")
    shutil.move(str(mcap), out)
    shutil.rmtree(tmp.parent)
