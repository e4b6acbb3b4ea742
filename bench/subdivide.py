#!/usr/bin/env python3
"""Midpoint (1-to-4) subdivision of a triangle mesh, for the scale benchmark: makes a ~1M-face
input from nefertiti.obj (100k faces) in two steps. Reads OBJ/OFF (v/f or OFF lists), writes OFF.
Usage: bench/subdivide.py IN OUT.off LEVELS"""
import sys


def read(path):
    verts, faces = [], []
    with open(path) as f:
        if path.lower().endswith(".off"):
            tokens = f.read().split()
            nv, nf = int(tokens[1]), int(tokens[2])
            pos = 4
            for _ in range(nv):
                verts.append(tuple(float(t) for t in tokens[pos:pos + 3]))
                pos += 3
            for _ in range(nf):
                k = int(tokens[pos])
                idx = [int(t) for t in tokens[pos + 1:pos + 1 + k]]
                pos += 1 + k
                faces += [(idx[0], idx[i], idx[i + 1]) for i in range(1, k - 1)]
        else:
            for line in f:
                p = line.split()
                if not p:
                    continue
                if p[0] == "v":
                    verts.append(tuple(float(t) for t in p[1:4]))
                elif p[0] == "f":
                    idx = [int(t.split("/")[0]) - 1 for t in p[1:]]
                    faces += [(idx[0], idx[i], idx[i + 1]) for i in range(1, len(idx) - 1)]
    return verts, faces


def subdivide(verts, faces):
    verts = list(verts)
    mid = {}

    def m(a, b):
        key = (a, b) if a < b else (b, a)
        if key not in mid:
            va, vb = verts[a], verts[b]
            verts.append(((va[0] + vb[0]) / 2, (va[1] + vb[1]) / 2, (va[2] + vb[2]) / 2))
            mid[key] = len(verts) - 1
        return mid[key]

    out = []
    for a, b, c in faces:
        ab, bc, ca = m(a, b), m(b, c), m(c, a)
        out += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
    return verts, out


verts, faces = read(sys.argv[1])
for _ in range(int(sys.argv[3])):
    verts, faces = subdivide(verts, faces)
with open(sys.argv[2], "w") as f:
    f.write("OFF\n%d %d 0\n" % (len(verts), len(faces)))
    f.writelines("%.9g %.9g %.9g\n" % v for v in verts)
    f.writelines("3 %d %d %d\n" % t for t in faces)
print("%d vertices, %d faces" % (len(verts), len(faces)))
