"""fcvt convert IN OUT (issue 15 item 8): every supported format to every other keeps the
triangles (PLY, OBJ, OFF: also the vertex and face order; STL stores a triangle soup), bad input
gets the same single error line and exit code as fcvt remesh, what remesh would repair is a
warning and is written as read (a non-manifold edge too, issue 50; --strict refuses it), and the
shipped resources/bunny.ply and torus.ply are what convert makes of the OBJ files.
Usage: check_convert.py FCVT RESOURCES_DIR WORK_DIR"""
import filecmp
import math
import os
import sys

import fcvt_check
from fcvt_check import bad_mesh_files, check, finish, run, write_file

fcvt, resources, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
torus_obj = os.path.join(resources, "torus.obj")
formats = ["ply", "obj", "off", "stl"]


def read_off(path):
    tok = open(path).read().split()
    assert tok[0] == "OFF", path
    nv, nf = int(tok[1]), int(tok[2])
    verts = [tuple(float(tok[4 + 3 * i + k]) for k in range(3)) for i in range(nv)]
    faces, at = [], 4 + 3 * nv
    for _ in range(nf):
        n = int(tok[at]); faces.append(tuple(int(x) for x in tok[at + 1: at + 1 + n])); at += 1 + n
    return verts, faces


def triangles(verts, faces, scale):
    """Each face as the rotation of its corner coordinates (rounded) that starts lowest."""
    out = []
    for f in faces:
        c = [tuple(round(x / scale) for x in verts[i]) for i in f]
        k = c.index(min(c))
        out.append(tuple(c[k:] + c[:k]))
    return sorted(out)


def convert(src, dst, expect=0):
    code, stdout, stderr = run([fcvt, "convert", src, dst])
    check(code == expect, f"convert {os.path.basename(src)} -> {os.path.basename(dst)}: exit {code}: {stderr.strip()}")
    return code, stdout, stderr


# The reference: torus.obj as OFF.
ref_off = os.path.join(work, "ref.off")
convert(torus_obj, ref_off)
ref_v, ref_f = read_off(ref_off)
lo = [min(v[k] for v in ref_v) for k in range(3)]
hi = [max(v[k] for v in ref_v) for k in range(3)]
diag = math.dist(lo, hi)
scale = 1e-5 * diag
ref_tris = triangles(ref_v, ref_f, scale)
check(len(ref_v) == 3072 and len(ref_f) == 6144, f"torus.obj as OFF: {len(ref_v)} vertices, {len(ref_f)} faces")

# Every format to every other, then back to OFF for the comparison.
for a in formats:
    first = os.path.join(work, f"torus.{a}")
    convert(torus_obj, first)
    for b in formats:
        second = os.path.join(work, f"torus-{a}-to.{b}")
        convert(first, second)
        back = os.path.join(work, f"torus-{a}-{b}.off")
        convert(second, back)
        v, f = read_off(back)
        label = f"obj -> {a} -> {b} -> off"
        check(len(f) == len(ref_f), f"{label}: {len(f)} faces, expected {len(ref_f)}")
        check(triangles(v, f, scale) == ref_tris, f"{label}: the triangles changed")
        if "stl" not in (a, b):
            check(len(v) == len(ref_v) and f == ref_f, f"{label}: vertex or face order changed")
            check(max(math.dist(p, q) for p, q in zip(v, ref_v)) <= 1e-6 * diag, f"{label}: vertices moved")

# Polygons are triangulated (a note), and what remesh would repair is a warning, written as read.
quads = os.path.join(work, "quads.obj")
with open(quads, "w") as fh:
    fh.write("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nv 5 5 5\n"
             "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n")
code, stdout, stderr = convert(quads, os.path.join(work, "quads.off"))
v, f = read_off(os.path.join(work, "quads.off"))
check(len(v) == 9 and len(f) == 12, f"quads.obj: {len(v)} vertices, {len(f)} faces (expected 9, 12)")
check("1 unreferenced vertices" in stderr and "convert writes the mesh as read" in stderr,
      f"quads.obj: no warning on the unreferenced vertex: {stderr!r}")
check(all(line.startswith("fcvt: warning: ") for line in stderr.splitlines()), f"quads.obj: stderr {stderr!r}")

# The shipped PLY examples are what convert makes of the OBJ files.
for name in ["bunny", "torus"]:
    made = os.path.join(work, f"{name}.ply")
    code, stdout, stderr = convert(os.path.join(resources, f"{name}.obj"), made)
    check(filecmp.cmp(made, os.path.join(resources, f"{name}.ply"), shallow=False),
          f"resources/{name}.ply is not 'fcvt convert resources/{name}.obj'")
    if name == "bunny":
        check("removed 1113 unreferenced vertices" in stderr, f"bunny.obj: no warning on its 1113 unreferenced vertices")


def expect_error(args, code, fragment):
    fcvt_check.expect_error(fcvt, args, code, fragment)


out = os.path.join(work, "out.ply")
bad = bad_mesh_files(work)
garbage, truncated, truncated_ply, empty, cloud, nan_mesh = (
    bad[k] for k in ["garbage", "truncated", "truncated_ply", "empty", "cloud", "nan"])
bad_index = write_file(work, "bad-index.off", b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n")
fin = write_file(work, "fin.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n")
missing = os.path.join(work, "missing.ply")
for args, code, fragment in [
    (["convert"], 2, "input and an output"),
    (["convert", torus_obj], 2, "input and an output"),
    (["convert", torus_obj, out, "--bogus"], 2, "--bogus"),
    (["convert", missing, out], 1, missing),
    (["convert", garbage, out], 1, garbage),
    (["convert", truncated, out], 1, truncated),
    (["convert", truncated_ply, out], 1, truncated_ply),
    (["convert", empty, out], 1, empty),
    (["convert", cloud, out], 1, cloud),
    (["convert", nan_mesh, out], 1, nan_mesh),
    (["convert", bad_index, out], 1, bad_index),
    (["convert", fin, out, "--strict"], 1, "non-manifold edge"),
    (["convert", torus_obj, os.path.join(work, "out.xyz")], 1, "out.xyz"),
    (["convert", torus_obj, os.path.join(work, "no", "such", "dir", "out.ply")], 1, "out.ply"),
]:
    expect_error(args, code, fragment)
    check(not os.path.exists(out), f"'{' '.join(args)}': wrote {out}")
    if os.path.exists(out):
        os.remove(out)

# A non-manifold edge is written as read, with one warning (issue 50, item 5).
fin_off = os.path.join(work, "fin.off")
code, stdout, stderr = convert(fin, fin_off)
v, f = read_off(fin_off)
check(len(v) == 5 and len(f) == 3, f"fin.obj: {len(v)} vertices, {len(f)} faces (expected 5, 3)")
check(stderr.strip().splitlines() == [f"fcvt: warning: {fin}: 1 non-manifold edge, written as read (remesh repairs it; "
                                      "--strict refuses)"], f"fin.obj: stderr {stderr!r}")

code, stdout, stderr = run([fcvt, "convert", "--help"])
check(code == 0 and "Usage: fcvt convert IN OUT" in stdout, "convert --help")
code, stdout, stderr = run([fcvt, "--help"])
check(code == 0 and "convert IN OUT" in stdout, "fcvt --help lists convert")
finish()
