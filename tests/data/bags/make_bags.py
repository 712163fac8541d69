#!/usr/bin/env python3
"""Write the ROS bag fixtures of tests/it/bags.rs with tools independent of
placecat: the `rosbags` package (ROS 1 bags, rosbag2 MCAP, and the ROS 1 / CDR
serialisation) and `mcap-ros2-support` (rosbag2 MCAP with its own CDR
encoder). Also writes expected.json: per bag, its topics and, per cloud, the
point count, the finite-point count, the float64 sums of x, y, z over the
finite points, the stamp, and the poses the reader should interpolate.

    python3 -m venv /tmp/venv-bags
    /tmp/venv-bags/bin/pip install rosbags mcap-ros2-support numpy
    /tmp/venv-bags/bin/python tests/data/bags/make_bags.py

Every cloud topic cycles through five layouts (see `LAYOUTS`): float32
x/y/z + intensity; float64 x/y/z with padding; big-endian; an organised
8 x 32 cloud with NaN rows and row padding; fields out of order with padding.
The robot drives x = t - T0, y = 0.5 (t - T0), yaw = 0.1 (t - T0): linear in
time, so interpolating poses at a cloud's stamp is exact.
"""

import json
import math
import shutil
import struct
import sys
import tempfile
from pathlib import Path

import numpy as np
from mcap_ros2.writer import Writer as McapRos2Writer
from mcap.writer import CompressionType
from rosbags.rosbag1 import Writer as Ros1Writer
from rosbags.rosbag2 import StoragePlugin, Writer as Ros2Writer
from rosbags.rosbag2.enums import CompressionFormat, CompressionMode
from rosbags.typesys import Stores, get_types_from_msg, get_typestore

OUT = Path(__file__).resolve().parent
T0 = 100.0
CLOUD_DT = 0.5  # clouds at 2 Hz
ODOM_DT = 0.1  # odometry and tf at 10 Hz
N_CLOUDS = 5
SENSOR = (0.5, 0.0, 1.0)  # base_link -> velodyne, fixed (tf_static)

ROS1 = get_typestore(Stores.ROS1_NOETIC)
# Noetic's store lacks tf2_msgs; its definition is one line.
ROS1.register(get_types_from_msg("geometry_msgs/TransformStamped[] transforms", "tf2_msgs/msg/TFMessage"))
ROS2 = get_typestore(Stores.ROS2_HUMBLE)

F32, F64, U8 = 7, 8, 2

# name: (fields as (name, offset, datatype), point_step, bigendian, height, width, row pad)
LAYOUTS = [
    ("float32", [("x", 0, F32), ("y", 4, F32), ("z", 8, F32), ("intensity", 12, F32)], 16, False, 1, 300, 0),
    ("float64", [("x", 0, F64), ("y", 8, F64), ("z", 16, F64), ("intensity", 24, F32)], 32, False, 1, 250, 0),
    ("bigendian", [("x", 0, F32), ("y", 4, F32), ("z", 8, F32)], 12, True, 1, 200, 0),
    ("organised_nan", [("x", 0, F32), ("y", 4, F32), ("z", 8, F32), ("ring", 12, U8)], 16, False, 8, 32, 16),
    ("reordered", [("intensity", 0, F32), ("z", 4, F32), ("y", 8, F32), ("x", 12, F32)], 20, False, 1, 150, 0),
]


def stamp_of(i):
    return T0 + i * CLOUD_DT


def base_pose(t):
    s = t - T0
    return (s, 0.5 * s, 0.0), 0.1 * s


def sensor_pose(t):
    (x, y, z), yaw = base_pose(t)
    c, s = math.cos(yaw), math.sin(yaw)
    return (x + c * SENSOR[0] - s * SENSOR[1], y + s * SENSOR[0] + c * SENSOR[1], z + SENSOR[2]), yaw


def cloud_bytes(i, layout_index, rng):
    """Point bytes of one cloud and its expected figures."""
    _, fields, step, big, height, width, pad = LAYOUTS[layout_index]
    n = height * width
    xyz = rng.uniform(-20.0, 20.0, size=(n, 3))
    if layout_index == 3:
        xyz[rng.random(n) < 0.2] = np.nan  # organised: missing returns stay as NaN
    row_step = width * step + pad
    data = bytearray(row_step * height)
    order = ">" if big else "<"
    written = np.zeros((n, 3))
    for p in range(n):
        r, c = divmod(p, width)
        base = r * row_step + c * step
        for name, off, dt in fields:
            if name in "xyz":
                v = xyz[p, "xyz".index(name)]
                fmt = order + ("d" if dt == F64 else "f")
                struct.pack_into(fmt, data, base + off, v)
                # what the reader sees: float32 values, float64 narrowed by it
                written[p, "xyz".index(name)] = struct.unpack(fmt, struct.pack(fmt, v))[0]
            elif dt == F32:
                struct.pack_into(order + "f", data, base + off, 7.0)
            else:
                struct.pack_into("B", data, base + off, r)
    finite = np.isfinite(written).all(axis=1)
    expect = {
        "layout": LAYOUTS[layout_index][0],
        "count": n,
        "finite": int(finite.sum()),
        "sum": [float(written[finite, k].sum()) for k in range(3)],
        "stamp": stamp_of(i),
    }
    return bytes(data), fields, step, big, height, width, row_step, expect


def make_cloud(store, i, layout_index, rng, frame="velodyne", drop_xyz=False):
    data, fields, step, big, height, width, row_step, expect = cloud_bytes(i, layout_index, rng)
    PF = store.types["sensor_msgs/msg/PointField"]
    PC2 = store.types["sensor_msgs/msg/PointCloud2"]
    names = {"x": "a", "y": "b", "z": "c"} if drop_xyz else {}
    pfs = [PF(name=names.get(n, n), offset=o, datatype=d, count=1) for n, o, d in fields]
    msg = PC2(
        header=header(store, stamp_of(i), frame),
        height=height,
        width=width,
        fields=pfs,
        is_bigendian=big,
        point_step=step,
        row_step=row_step,
        data=np.frombuffer(data, dtype=np.uint8),
        is_dense=layout_index != 3,
    )
    return msg, expect


def header(store, t, frame):
    Time = store.types["builtin_interfaces/msg/Time"]
    Header = store.types["std_msgs/msg/Header"]
    sec = int(math.floor(t))
    stamp = Time(sec=sec, nanosec=int(round((t - sec) * 1e9)))
    if "seq" in Header.__dataclass_fields__:
        return Header(seq=0, stamp=stamp, frame_id=frame)
    return Header(stamp=stamp, frame_id=frame)


def quat_z(yaw):
    return (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))


def odometry(store, t):
    T = store.types
    (x, y, z), yaw = base_pose(t)
    q = quat_z(yaw)
    pose = T["geometry_msgs/msg/Pose"](
        position=T["geometry_msgs/msg/Point"](x=x, y=y, z=z),
        orientation=T["geometry_msgs/msg/Quaternion"](x=q[0], y=q[1], z=q[2], w=q[3]),
    )
    zeros = np.zeros(36)
    v = T["geometry_msgs/msg/Vector3"](x=0.0, y=0.0, z=0.0)
    return T["nav_msgs/msg/Odometry"](
        header=header(store, t, "odom"),
        child_frame_id="base_link",
        pose=T["geometry_msgs/msg/PoseWithCovariance"](pose=pose, covariance=zeros),
        twist=T["geometry_msgs/msg/TwistWithCovariance"](
            twist=T["geometry_msgs/msg/Twist"](linear=v, angular=v), covariance=zeros
        ),
    )


def transform(store, t, parent, child, xyz, yaw):
    T = store.types
    q = quat_z(yaw)
    return T["geometry_msgs/msg/TransformStamped"](
        header=header(store, t, parent),
        child_frame_id=child,
        transform=T["geometry_msgs/msg/Transform"](
            translation=T["geometry_msgs/msg/Vector3"](x=xyz[0], y=xyz[1], z=xyz[2]),
            rotation=T["geometry_msgs/msg/Quaternion"](x=q[0], y=q[1], z=q[2], w=q[3]),
        ),
    )


def tf_message(store, transforms):
    return store.types["tf2_msgs/msg/TFMessage"](transforms=transforms)


def timeline(store, layouts, *, odom=True, tf=True, static=True, no_xyz_at=None, seed=1):
    """Messages (topic, type, t, msg) in time order, and the expected clouds."""
    rng = np.random.default_rng(seed)
    msgs, clouds = [], []
    if tf and static:
        st = tf_message(store, [transform(store, T0 - 1.0, "base_link", "velodyne", SENSOR, 0.0)])
        msgs.append(("/tf_static", "tf2_msgs/msg/TFMessage", T0 - 1.0, st))
    t = T0 - 1.0
    while t <= stamp_of(len(layouts) - 1) + 1.0 + 1e-9:
        if odom:
            msgs.append(("/odom", "nav_msgs/msg/Odometry", t, odometry(store, t)))
        if tf:
            (x, y, z), yaw = base_pose(t)
            tr = transform(store, t, "odom", "base_link", (x, y, z), yaw)
            msgs.append(("/tf", "tf2_msgs/msg/TFMessage", t, tf_message(store, [tr])))
        t = round(t + ODOM_DT, 6)
    for i, li in enumerate(layouts):
        msg, expect = make_cloud(store, i, li, rng, drop_xyz=(i == no_xyz_at))
        (bp, byaw), (sp, syaw) = base_pose(stamp_of(i)), sensor_pose(stamp_of(i))
        expect["odom_pose"] = list(bp) + [byaw]
        expect["tf_pose"] = list(sp) + [syaw]
        expect["no_xyz"] = i == no_xyz_at
        clouds.append(expect)
        # logged a little after the stamp, as a real driver would
        msgs.append(("/points", "sensor_msgs/msg/PointCloud2", stamp_of(i) + 0.01, msg))
    msgs.sort(key=lambda m: m[2])
    return msgs, clouds


def ns(t):
    return int(round(t * 1e9))


def write_ros1(path, msgs, compression=None, chunk_threshold=None):
    w = Ros1Writer(path)
    if compression:
        w.set_compression(compression)
    if chunk_threshold:
        w.chunk_threshold = chunk_threshold
    with w:
        conns = {}
        for topic, typ, t, msg in msgs:
            if topic not in conns:
                conns[topic] = w.add_connection(topic, typ, typestore=ROS1)
            w.write(conns[topic], ns(t), ROS1.serialize_ros1(msg, typ))


def write_rosbags_mcap(path, msgs, zstd=False, little_endian=True):
    tmp = Path(tempfile.mkdtemp()) / "bag"
    w = Ros2Writer(tmp, version=9, storage_plugin=StoragePlugin.MCAP)
    if zstd:
        w.set_compression(CompressionMode.STORAGE, CompressionFormat.ZSTD)
    with w:
        conns = {}
        for topic, typ, t, msg in msgs:
            if topic not in conns:
                conns[topic] = w.add_connection(topic, typ, typestore=ROS2)
            w.write(conns[topic], ns(t), ROS2.serialize_cdr(msg, typ, little_endian=little_endian))
    (mcap,) = tmp.glob("*.mcap")
    shutil.copy(mcap, path)
    shutil.rmtree(tmp.parent)


def to_dict(msg):
    """rosbags message object -> plain dict for mcap-ros2-support's encoder."""
    if isinstance(msg, np.ndarray):
        return msg.tolist() if msg.dtype != np.uint8 else bytes(msg)
    if hasattr(msg, "__dataclass_fields__"):
        return {k: to_dict(getattr(msg, k)) for k in msg.__dataclass_fields__ if k != "__msgtype__"}
    if isinstance(msg, list):
        return [to_dict(m) for m in msg]
    return msg


def write_mcap_ros2(path, msgs, compression):
    with open(path, "wb") as f:
        w = McapRos2Writer(f, chunk_size=16 * 1024, compression=compression)
        schemas = {}
        for topic, typ, t, msg in msgs:
            if typ not in schemas:
                text, _ = ROS2.generate_msgdef(typ, ros_version=2)
                schemas[typ] = w.register_msgdef(typ, text)
            w.write_message(topic, schemas[typ], to_dict(msg), log_time=ns(t), publish_time=ns(t))
        w.finish()


# ---- ROS 1 record surgery for the broken bags ----

def ros1_records(b):
    """(offset, header bytes, data bytes) of each top-level record."""
    out, at = [], 13
    while at < len(b):
        hl = struct.unpack_from("<I", b, at)[0]
        h = b[at + 4 : at + 4 + hl]
        dl = struct.unpack_from("<I", b, at + 4 + hl)[0]
        out.append((at, h, b[at + 8 + hl : at + 8 + hl + dl]))
        at += 8 + hl + dl
    return out


def fields(h):
    f, i = {}, 0
    while i < len(h):
        n = struct.unpack_from("<I", h, i)[0]
        k, v = h[i + 4 : i + 4 + n].split(b"=", 1)
        f[k.decode()] = v
        i += 4 + n
    return f


def pack_fields(f):
    return b"".join(struct.pack("<I", len(k) + 1 + len(v)) + k.encode() + b"=" + v for k, v in f.items())


def rebuild_ros1(b, edit):
    """Re-serialise a ROS 1 bag after `edit(index, header fields, data)` on
    each record, fixing chunk_pos and index_pos for the moved bytes."""
    recs = ros1_records(b)
    out = bytearray(b[:13])
    moved = {}
    index_pos = None
    for i, (at, h, d) in enumerate(recs):
        f = fields(h)
        f, d = edit(i, f, d)
        moved[at] = len(out)
        if f["op"] == b"\x07" and index_pos is None and i > 0:
            index_pos = len(out)
        if f["op"] == b"\x06":
            f["chunk_pos"] = struct.pack("<Q", moved[struct.unpack("<Q", f["chunk_pos"])[0]])
        hb = pack_fields(f)
        out += struct.pack("<I", len(hb)) + hb + struct.pack("<I", len(d)) + d
    # the bag header is padded to a fixed size, so its index_pos patches in place
    at, h, d = recs[0]
    f = fields(h)
    f["index_pos"] = struct.pack("<Q", index_pos)
    hb = pack_fields(f)
    assert len(hb) == len(h)
    out[13 + 4 : 13 + 4 + len(hb)] = hb
    return bytes(out)


def chunk_indices(b):
    return [i for i, (_, h, _) in enumerate(ros1_records(b)) if fields(h)["op"] == b"\x05"]


def main():
    out = {}
    every = list(range(len(LAYOUTS)))
    tmp = Path(tempfile.mkdtemp())

    def ros1(name, msgs, clouds, **kw):
        p = OUT / name
        p.unlink(missing_ok=True)
        write_ros1(p, msgs, **kw)
        out[name] = {"clouds": clouds, "topics": topics_of(msgs, ros1=True)}

    def topics_of(msgs, ros1):
        t = {}
        for topic, typ, _, _ in msgs:
            typ = typ.replace("/msg/", "/") if ros1 else typ
            t.setdefault(topic, [typ, 0])[1] += 1
        return t

    msgs, clouds = timeline(ROS1, every)
    ros1("ros1_plain.bag", msgs, clouds)
    ros1("ros1_bz2.bag", msgs, clouds, compression=Ros1Writer.CompressionFormat.BZ2, chunk_threshold=8000)
    ros1("ros1_lz4.bag", msgs, clouds, compression=Ros1Writer.CompressionFormat.LZ4, chunk_threshold=8000)

    msgs2, clouds2 = timeline(ROS2, every, seed=2)
    # The last: every message in big-endian CDR (CDR_BE encapsulation).
    for name, zstd, le in [
        ("ros2_rosbags.mcap", False, True),
        ("ros2_rosbags_zstd.mcap", True, True),
        ("ros2_rosbags_cdr_be.mcap", True, False),
    ]:
        p = OUT / name
        p.unlink(missing_ok=True)
        write_rosbags_mcap(p, msgs2, zstd=zstd, little_endian=le)
        out[name] = {"clouds": clouds2, "topics": topics_of(msgs2, ros1=False)}
    for name, comp in [("ros2_mcap_lz4.mcap", CompressionType.LZ4), ("ros2_mcap_none.mcap", CompressionType.NONE)]:
        p = OUT / name
        write_mcap_ros2(p, msgs2, comp)
        out[name] = {"clouds": clouds2, "topics": topics_of(msgs2, ros1=False)}

    # Clouds with structure (a corridor: floor and two walls, points on a 1 cm
    # grid), so that the CLI test gets descriptors, not only points.
    def corridor(store, i, rng):
        n = 900
        floor = np.c_[rng.uniform(-3, 3, n), rng.uniform(-1, 1, n), np.full(n, -1.0)]
        walls = [np.c_[rng.uniform(-3, 3, n), np.full(n, s), rng.uniform(-1, 1.5, n)] for s in (-1.0, 1.0)]
        xyz = np.round(np.vstack([floor] + walls), 2).astype("<f4")
        PF, PC2 = store.types["sensor_msgs/msg/PointField"], store.types["sensor_msgs/msg/PointCloud2"]
        fields = [PF(name=c, offset=4 * k, datatype=F32, count=1) for k, c in enumerate("xyz")]
        msg = PC2(header=header(store, stamp_of(i), "velodyne"), height=1, width=len(xyz), fields=fields,
                  is_bigendian=False, point_step=12, row_step=12 * len(xyz),
                  data=np.frombuffer(xyz.tobytes(), np.uint8), is_dense=True)
        x = xyz.astype(np.float64)
        expect = {"layout": "corridor", "count": len(xyz), "finite": len(xyz), "stamp": stamp_of(i),
                  "sum": [float(x[:, k].sum()) for k in range(3)]}
        return msg, expect

    rng = np.random.default_rng(6)
    scene, scene_clouds = [], []
    for i in range(2):
        msg, expect = corridor(ROS1, i, rng)
        expect["odom_pose"] = list(base_pose(stamp_of(i))[0]) + [base_pose(stamp_of(i))[1]]
        scene.append(("/points", "sensor_msgs/msg/PointCloud2", stamp_of(i) + 0.01, msg))
        scene_clouds.append(expect)
    scene += [("/odom", "nav_msgs/msg/Odometry", t, odometry(ROS1, t)) for t in (T0 - 1.0, T0 + 1.0)]
    scene.sort(key=lambda m: m[2])
    ros1("ros1_corridor.bag", scene, scene_clouds, compression=Ros1Writer.CompressionFormat.BZ2)

    # Two cloud topics: the reader must be told which (small clouds).
    rng = np.random.default_rng(7)
    two, two_clouds = [], []
    for i, topic in enumerate(["/front/points", "/rear/points"]):
        msg, expect = make_cloud(ROS1, i, 2, rng)
        two.append((topic, "sensor_msgs/msg/PointCloud2", stamp_of(i), msg))
        expect["topic"] = topic
        two_clouds.append(expect)
    ros1("two_cloud_topics.bag", two, two_clouds)

    # ---- bad bags ----
    # No PointCloud2 at all.
    msgs_nc = [m for m in msgs if m[0] != "/points"]
    ros1("bad_no_cloud.bag", msgs_nc, [])

    # A cloud without x/y/z (cloud 2) among good ones.
    m, c = timeline(ROS1, every, no_xyz_at=2, seed=3)
    ros1("bad_no_xyz.bag", m, c)

    # tf without the cloud's frame: no /tf_static base_link -> velodyne.
    m, c = timeline(ROS1, every, odom=False, static=False, seed=4)
    ros1("bad_tf.bag", m, c)

    # Chunks of about one cloud each, then break one of them.
    src = tmp / "chunky.bag"
    m, c = timeline(ROS1, every, odom=False, tf=False, seed=5)
    write_ros1(src, m, compression=Ros1Writer.CompressionFormat.LZ4, chunk_threshold=1000)
    b = src.read_bytes()
    chunks = chunk_indices(b)
    assert len(chunks) == len(c), (len(chunks), len(c))

    # A truncated chunk: cloud 1's compressed data cut in half.
    def cut(i, f, d):
        return (f, d[: len(d) // 2]) if i == chunks[1] else (f, d)

    (OUT / "bad_truncated.bag").write_bytes(rebuild_ros1(b, cut))
    out["bad_truncated.bag"] = {"clouds": c, "topics": topics_of(m, ros1=True), "bad_cloud": 1}

    # An unknown compression: cloud 3's chunk says "zip".
    def rename(i, f, d):
        if i == chunks[3]:
            f["compression"] = b"zip"
        return f, d

    (OUT / "bad_compression.bag").write_bytes(rebuild_ros1(b, rename))
    out["bad_compression.bag"] = {"clouds": c, "topics": topics_of(m, ros1=True), "bad_cloud": 3}

    # MCAP whose second chunk claims an unknown compression (same length, patched in place).
    b = (OUT / "ros2_mcap_lz4.mcap").read_bytes()
    at, seen = 8, 0
    patched = bytearray(b)
    while at < len(b):
        op, n = b[at], struct.unpack_from("<Q", b, at + 1)[0]
        if op == 0x06:
            seen += 1
            if seen == 2:
                s = at + 9 + 8 + 8 + 8 + 4
                ln = struct.unpack_from("<I", b, s)[0]
                assert b[s + 4 : s + 4 + ln] == b"lz4"
                patched[s + 4 : s + 4 + ln] = b"lz5"
                break
        at += 9 + n
    (OUT / "bad_compression.mcap").write_bytes(bytes(patched))
    out["bad_compression.mcap"] = {"clouds": clouds2, "topics": topics_of(msgs2, ros1=False)}

    shutil.rmtree(tmp)
    (OUT / "expected.json").write_text(json.dumps(out, indent=1, sort_keys=True) + "\n")
    total = sum(p.stat().st_size for p in OUT.iterdir())
    print(f"wrote {len(out)} bags, {total} bytes in {OUT}", file=sys.stderr)


if __name__ == "__main__":
    main()
