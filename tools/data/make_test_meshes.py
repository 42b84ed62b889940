#!/usr/bin/env python3
"""Writes tests/data/meshes/tetra-be.ply: the test tetrahedron (the same vertices and faces as
tetra.ply, tetra.off, ...) as binary big-endian PLY with float coordinates, the layout of the
Scalable CCD dataset's larger scenes. Run from the repository root:
    python3 tools/data/make_test_meshes.py
"""
import struct

VERTICES = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]

header = (
    "ply\n"
    "format binary_big_endian 1.0\n"
    "comment exactccd test mesh (tools/data/make_test_meshes.py)\n"
    f"element vertex {len(VERTICES)}\n"
    "property float x\nproperty float y\nproperty float z\n"
    f"element face {len(FACES)}\n"
    "property list uchar int vertex_indices\n"
    "end_header\n"
)
body = b"".join(struct.pack(">fff", *v) for v in VERTICES)
body += b"".join(struct.pack(">Biii", 3, *f) for f in FACES)
with open("tests/data/meshes/tetra-be.ply", "wb") as out:
    out.write(header.encode("ascii") + body)
