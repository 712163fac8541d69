#!/usr/bin/env python3
"""Write walk.bag (ROS 1, lz4 chunks) and walk.mcap (rosbag2 MCAP, zstd),
the bags the page's e2e test drops (tests/e2e/bags.test.mjs): a robot walks
make_bags.py's path (x = t - T0, y = (t - T0) / 2, 0.56 m between clouds)
through a corridor (clouds 0-3: floor and walls 1 m either side) into a hall
(clouds 4-7: walls 4 m away, a ceiling), with odometry at 10 Hz. Clouds with
structure (points on a 1 cm grid), so that each one gets a descriptor.
Uses make_bags.py's helpers; run as it says (the venv with rosbags):

    /tmp/venv-bags/bin/python tests/data/bags/make_walk_bags.py
"""

import numpy as np
from rosbags.rosbag1 import Writer as Ros1Writer

from make_bags import F32, OUT, ROS1, ROS2, T0, header, odometry, stamp_of, write_ros1, write_rosbags_mcap

N = 8


def room(store, i, rng, half_width, height):
    n = 600
    floor = np.c_[rng.uniform(-3, 3, n), rng.uniform(-half_width, half_width, n), np.full(n, -1.0)]
    walls = [np.c_[rng.uniform(-3, 3, n), np.full(n, s * half_width), rng.uniform(-1, height, n)] for s in (-1.0, 1.0)]
    parts = [floor] + walls
    if half_width > 2:
        parts.append(np.c_[rng.uniform(-3, 3, n), rng.uniform(-half_width, half_width, n), np.full(n, height)])
    xyz = np.round(np.vstack(parts), 2).astype("<f4")
    T = store.types
    fields = [T["sensor_msgs/msg/PointField"](name=c, offset=4 * k, datatype=F32, count=1) for k, c in enumerate("xyz")]
    return T["sensor_msgs/msg/PointCloud2"](
        header=header(store, stamp_of(i), "velodyne"), height=1, width=len(xyz), fields=fields, is_bigendian=False,
        point_step=12, row_step=12 * len(xyz), data=np.frombuffer(xyz.tobytes(), np.uint8), is_dense=True)


def walk(store):
    rng = np.random.default_rng(8)
    msgs = [("/points", "sensor_msgs/msg/PointCloud2", stamp_of(i) + 0.01,
             room(store, i, rng, 1.0, 1.5) if i < N // 2 else room(store, i, rng, 4.0, 3.0)) for i in range(N)]
    ticks = int(round((stamp_of(N - 1) - T0) / 0.1)) + 2
    msgs += [("/odom", "nav_msgs/msg/Odometry", T0 - 0.1 + 0.1 * k, odometry(store, T0 - 0.1 + 0.1 * k)) for k in range(ticks + 1)]
    return sorted(msgs, key=lambda m: m[2])


if __name__ == "__main__":
    (OUT / "walk.bag").unlink(missing_ok=True)
    write_ros1(OUT / "walk.bag", walk(ROS1), compression=Ros1Writer.CompressionFormat.LZ4)
    (OUT / "walk.mcap").unlink(missing_ok=True)
    write_rosbags_mcap(OUT / "walk.mcap", walk(ROS2), zstd=True)
