#!/usr/bin/env python3
# Writes the seed corpora of the fuzz harnesses: OUTDIR/<target>/<seed>.
# Small, valid (or nearly valid) inputs made here, so that the fuzzer starts
# from the structure of each format; no copy of real data files.
import os
import struct
import sys


def tetra_points():
    return [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 1)]


def seeds():
    s = {}
    s["fuzz_pts"] = {
        "xyz.pts": b"0 0 0\n1 0 0\n0 1 0.5\n",
        "normals.pts": b"# points with normals\n0 0 0 0 0 1\n1 2 3 1 0 0\n-1.5e2 +2 3 0 -1 0\n",
        "a3d.pts": b"p 0 0 0\nn 0 0 1\nc 1 0 0\np 1 1 1\nn 1 0 0\n",
        "crlf.pts": b"1 2 3\r\n4 5 6\r\n",
    }
    s["fuzz_tris"] = {
        "one.tris": b"0 0 1\n0 0 0\n1 0 0\n0 1 0\n",
        "two.tris": b"0 0 1\n0 0 0\n1 0 0\n0 1 0\n0 0 0\n1 1 1\n1 1 1\n1 1 1\n",
    }
    pts = tetra_points()
    verts = "".join("%g %g %g 0\n" % p for p in pts)
    s["fuzz_medit"] = {
        "one.mesh": ("MeshVersionFormatted 2\nDimension 3\nVertices\n4\n" + "".join(
            "%g %g %g 0\n" % p for p in pts[:4]) + "Tetrahedra\n1\n1 2 3 4 0\nEnd\n").encode(),
        "two.mesh": ("MeshVersionFormatted 1\nDimension\n3\nVertices 5\n" + verts +
                     "Triangles\n1\n1 2 3 0\n# comment\nTetrahedra 2\n1 2 3 4 1\n2 3 4 5 2\n").encode(),
        "tets_first.mesh": ("Tetrahedra\n1\n1 2 3 4 0\nVertices\n4\n" + "".join(
            "%g %g %g 0\n" % p for p in pts[:4]) + "End\n").encode(),
    }
    node = "5 3 0 0\n" + "".join("%d %g %g %g\n" % ((i,) + p) for i, p in enumerate(pts))
    node1 = "# one-based\n4 3 1 1\n" + "".join("%d %g %g %g 7 1\n" % ((i + 1,) + p) for i, p in enumerate(pts[:4]))
    s["fuzz_tetgen"] = {
        "zero.node_ele": (node + "\0" + "2 4 0\n0 0 1 2 3\n1 1 2 3 4\n").encode(),
        "one.node_ele": (node1 + "\0" + "1 10 1\n1 1 2 3 4 1 2 3 4 1 2 5\n").encode(),
    }
    s["fuzz_scalar_fields_text"] = {
        "two.txt": b"2\n# v0\n-1 0.5\n2.5e-3 -0\n1 1\n",
        "one.txt": b"1\n0\n-1\n3\n",
    }
    raw = {}
    for name, n, fields, ext, fmt in [("f64.bin", 3, 2, 0, "<d"), ("f32.bin", 4, 1, 2, "<f"),
                                      ("f64b.bin", 2, 3, 1, "<d")]:
        body = b"".join(struct.pack(fmt, (i * 0.75 - 1.0)) for i in range(n * fields))
        raw[name] = bytes([n & 255, n >> 8, fields, ext]) + body
    raw["hint0.bin"] = bytes([2, 0, 0, 0]) + struct.pack("<4d", 1, 2, 3, 4)
    s["fuzz_scalar_fields_raw"] = raw

    header = ("ply\nformat %s 1.0\ncomment fuzz seed\nelement vertex 4\nproperty double x\nproperty double y\n"
              "property double z\nelement face 4\nproperty list uchar int vertex_indices\nproperty int field\n"
              "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n")
    faces = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
    ascii = header % "ascii" + "".join("%g %g %g\n" % p for p in pts[:4]) + "".join(
        "3 %d %d %d %d 200 10 10\n" % (f + (k - 1,)) for k, f in enumerate(faces))
    binary = (header % "binary_little_endian").encode() + b"".join(struct.pack("<3d", *p) for p in pts[:4]) + \
        b"".join(struct.pack("<B3ii3B", 3, *f, k - 1, 1, 2, 3) for k, f in enumerate(faces))
    big = ("ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
           "property float z\nproperty uchar extra\nelement edge 1\nproperty int a\nelement face 1\n"
           "property list uchar uint vertex_index\nproperty short field\nend_header\n").encode() + \
        b"".join(struct.pack(">3fB", *p, 9) for p in pts[:3]) + struct.pack(">i", 5) + struct.pack(">B3Ih", 3, 0, 1, 2, 0)
    s["fuzz_ply_with_fields"] = {"ascii.ply": ascii.encode(), "binary.ply": binary, "big.ply": big}

    s["fuzz_expression_letters"] = {
        "union.txt": b"A | B", "difference.txt": b"A - B - C", "mixed.txt": b"(A & !B) | ~(C & D) - (E | 1)",
        "constants.txt": b"true & (A | false) | 0", "deep.txt": b"((A | (B & (C | !D))) & Z)",
    }
    s["fuzz_expression_f"] = {
        "union.txt": b"f0 | f1", "difference.txt": b"f0 - f1 - f2", "mixed.txt": b"(f0 & !f1) | ~(f2 & f63) - f10",
        "constants.txt": b"1 & (f3 | false)", "deep.txt": b"((f0 | (f1 & (f2 | !f3))) & f25)",
    }

    off = b"OFF\n4 4 0\n" + "".join("%g %g %g\n" % p for p in pts[:4]).encode() + \
        b"".join(b"3 %d %d %d\n" % f for f in faces)
    obj = "".join("v %g %g %g\n" % p for p in pts[:4]).encode() + b"".join(
        b"f %d %d %d\n" % tuple(i + 1 for i in f) for f in faces)
    ply = ("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
           "element face 4\nproperty list uchar int vertex_indices\nend_header\n" +
           "".join("%g %g %g\n" % p for p in pts[:4]) + "".join("3 %d %d %d\n" % f for f in faces)).encode()
    stl = b"solid t\n" + b"".join(
        b"facet normal 0 0 0\nouter loop\n" + b"".join(b"vertex %g %g %g\n" % pts[i] for i in f) +
        b"endloop\nendfacet\n" for f in faces) + b"endsolid t\n"
    s["fuzz_closed_triangle_mesh"] = {"off": b"\x00" + off, "obj": b"\x01" + obj, "ply": b"\x02" + ply,
                                      "stl": b"\x03" + stl, "off_inward": b"\x04" + off}
    return s


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "corpus"
    for target, files in seeds().items():
        d = os.path.join(out, target)
        os.makedirs(d, exist_ok=True)
        for name, data in files.items():
            with open(os.path.join(d, name), "wb") as f:
                f.write(data)


if __name__ == "__main__":
    main()
