#!/usr/bin/env python3
"""Write the regression corpus of damaged (and borderline good) scans.

One small file per kind of damage the strict readers refuse; `expected.tsv`
beside this script holds, for each file, the exact message a user gets (and
what a lenient read gives). Run from anywhere: `python3 make_bad.py`. The
files are committed; rerunning must reproduce them byte for byte (no
randomness, no timestamps). Only the standard library is used, so the
corpus does not depend on placecat's own writers.
"""
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def write(name, data):
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data.encode() if isinstance(data, str) else data)


def mesh():
    """A small closed mesh (a UV sphere): vertices and triangles."""
    rings, segs = 8, 12
    verts = [(0.0, 0.0, 1.0)]
    for i in range(1, rings):
        t = math.pi * i / rings
        for j in range(segs):
            p = 2 * math.pi * j / segs
            verts.append((math.sin(t) * math.cos(p), math.sin(t) * math.sin(p), math.cos(t)))
    verts.append((0.0, 0.0, -1.0))
    faces = []
    for j in range(segs):
        faces.append((0, 1 + j, 1 + (j + 1) % segs))
    for i in range(rings - 2):
        a, b = 1 + i * segs, 1 + (i + 1) * segs
        for j in range(segs):
            k = (j + 1) % segs
            faces.append((a + j, b + j, b + k))
            faces.append((a + j, b + k, a + k))
    last = len(verts) - 1
    base = 1 + (rings - 2) * segs
    for j in range(segs):
        faces.append((base + j, last, base + (j + 1) % segs))
    return verts, faces


def binary_ply(verts, faces, face_count=None):
    n_faces = len(faces) if face_count is None else face_count
    head = (
        "ply\nformat binary_little_endian 1.0\ncomment made by make_bad.py\n"
        f"element vertex {len(verts)}\nproperty float x\nproperty float y\nproperty float z\n"
        f"element face {n_faces}\nproperty list uchar int vertex_indices\nend_header\n"
    ).encode()
    body = b"".join(struct.pack("<3f", *v) for v in verts)
    body += b"".join(struct.pack("<B3i", 3, *f) for f in faces)
    return head + body


def ascii_ply_head(n):
    return (
        f"ply\nformat ascii 1.0\nelement vertex {n}\n"
        "property float x\nproperty float y\nproperty float z\nend_header\n"
    )


def pcd_head(n, data, width=None, height=1, size="4 4 4", type_="F F F", count="1 1 1"):
    width = n if width is None else width
    return (
        "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z\n"
        f"SIZE {size}\nTYPE {type_}\nCOUNT {count}\nWIDTH {width}\nHEIGHT {height}\n"
        f"VIEWPOINT 0 0 0 1 0 0 0\nPOINTS {n}\nDATA {data}\n"
    )


verts, faces = mesh()
good = binary_ply(verts, faces)

# 1. An ascii PLY whose rows have 3, 2 and 4 values where 3 are declared:
#    read as one stream, the points shift (the first silent case).
write("ply_ascii_row_values.ply", ascii_ply_head(3) + "0 0 0\n1 1\n2 2 2 2\n")
# 2. The same in an ascii PCD.
write("pcd_ascii_row_values.pcd", pcd_head(3, "ascii") + "0 0 0\n1 1\n2 2 2 2\n")
# 3. A PCD header whose WIDTH x HEIGHT is not POINTS (PCL refuses it).
write("pcd_width_height_points.pcd", pcd_head(3, "ascii", width=2, height=2) + "0 0 0\n1 1 1\n2 2 2\n")
# 4. A binary PLY (vertices and faces) after a text round trip: every byte
#    sequence that is not UTF-8 replaced by U+FFFD (EF BF BD). The header is
#    intact, the body longer than declared, the faces no longer parse.
write("ply_text_round_trip.ply", good.decode("utf-8", errors="replace").encode("utf-8"))
# 5. A binary PLY whose face element runs past the end of the file (the last
#    face's list cut off): the vertices are whole, the file is not.
write("ply_face_past_end.ply", good[:-6])
# 6. A binary PLY with bytes after every declared element that are not padding.
write("ply_trailing_bytes.ply", good + b"garbage after the faces\n")
# 7. A binary PCD with more bytes than POINTS x record (a concatenation).
pts = b"".join(struct.pack("<3f", *v) for v in verts[:10])
write("pcd_binary_trailing_bytes.pcd", pcd_head(10, "binary").encode() + pts + pts[:24])
# 8. A PCD whose SIZE has fewer entries than FIELDS.
write("pcd_size_entries.pcd", pcd_head(1, "ascii", size="4 4") + "0 0 0\n")
# 9. A PCD with a TYPE that is not one letter.
write("pcd_type_word.pcd", pcd_head(1, "ascii", type_="F F F32") + "0 0 0\n")
# 10. A PCD whose SIZE does not fit 32 bits (on wasm32, `as usize` made it 4).
write("pcd_size_over_32_bits.pcd", pcd_head(1, "ascii", size="4 4 4294967300") + "0 0 0\n")
# 11. A PLY face list whose length (a double) is 2^32 + 3: on wasm32,
#     `as usize` made it 3 and the file read; natively it runs past the end.
head = (
    "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
    "property float y\nproperty float z\nelement face 1\n"
    "property list double int vertex_indices\nend_header\n"
).encode()
write("ply_list_length_over_32_bits.ply", head + struct.pack("<3f", 1, 2, 3) + struct.pack("<d3i", 2.0**32 + 3, 0, 0, 0))
# 12. An ascii PLY with a data line after the last declared element.
write("ply_ascii_extra_row.ply", ascii_ply_head(2) + "0 0 0\n1 1 1\n2 2 2\n")
# 12b. The same in an ascii PCD (POINTS 2, three rows).
write("pcd_ascii_extra_row.pcd", pcd_head(2, "ascii") + "0 0 0\n1 1 1\n2 2 2\n")
# 13. An ascii PLY whose header declares more faces than the body holds.
write(
    "ply_ascii_faces_missing.ply",
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
)

# Borderline files that must read (padding, CRLF, blank lines):
# a binary PLY ending in a newline, and a binary PCD padded with zeros.
write("ok_ply_trailing_newline.ply", good + b"\n")
write("ok_pcd_zero_padding.pcd", pcd_head(10, "binary").encode() + pts + bytes(100))
# An ascii PCD with CRLF line ends and a blank last line.
write("ok_pcd_ascii_crlf.pcd", (pcd_head(3, "ascii") + "0 0 0\n1 1 1\n2 2 2\n\n").replace("\n", "\r\n"))
