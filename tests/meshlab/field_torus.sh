#!/usr/bin/env bash
# End to end through meshlabserver: run resources/fcvt-field.mlx ("Compute 6-RoSy Field") on the
# torus, save the drawing layer and the input layer, and check the log and the drawing.
# MeshLab 2020.09 cannot save the drawing's edges from meshlabserver (no -m option for
# IOM_EDGEINDEX) nor custom attributes like `rosy` (the PLY exporter's PVA3F options default to
# off), so the checks are: the log (singularity count, index sum 0 on the torus, the new layer),
# and the saved vertices of the drawing, which encode the segments (6 per drawn vertex: pairs
# symmetric about the mesh vertex, three directions 60 degrees apart, tangent, half the mean edge).
# Usage: field_torus.sh SOURCE_DIR PLUGIN_SO WORK_DIR
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"

rm -rf "$work/out"; mkdir -p "$work/out"
server="$(stage_meshlab "$work/stage" "$plugin")"
mlx="$FCVT_SOURCE_DIR/resources/fcvt-field.mlx"
"$FCVT_SOURCE_DIR/tests/meshlab/obj2off.sh" "$FCVT_SOURCE_DIR/resources/torus.obj" "$work/out/torus.off"
drawing="$work/out/field.ply"
kept="$work/out/torus-after.ply"
# -l x: the last layer (the drawing); the second output is the current layer, the input.
run_meshlabserver "$server" "$work/out/log.txt" -i "$work/out/torus.off" -o "$drawing" -l x \
  -o "$kept" -s "$mlx"

[ "$MLS_RC" -eq 0 ] || fail "meshlabserver exited with $MLS_RC"
grep -q "filter: Compute 6-RoSy Field" "$work/out/log.txt" || fail "filter not run"
grep -Eq "FCVT field: extrinsic 6-RoSy \(seed 1\) on layer 'torus.off': [0-9]+ singularities \(index sum 0/6\)" \
  "$work/out/log.txt" || fail "no singularity count with index sum 0 (6 * chi of the torus) in the log"
grep -q "FCVT field: new layer '6-RoSy field'" "$work/out/log.txt" || fail "no new layer in the log"
grep -Eq "saved as .*/field.ply \([0-9]+ vn 0 fn\)" "$work/out/log.txt" || fail "drawing layer not saved"
grep -Eq "Mesh .*torus.off saved as .*torus-after.ply" "$work/out/log.txt" || fail "input layer not saved"
! grep -Eq "Assertion|Aborted|terminate called" "$work/out/log.txt.err" || fail "abort in stderr"

python3 - "$work/out/torus.off" "$drawing" "$kept" <<'PY' || fail "the drawing does not show the field"
import math, struct, sys

def read_off(path):
    tok = open(path).read().split()
    assert tok[0] == "OFF"
    nv, nf = int(tok[1]), int(tok[2])
    vals = tok[4:]
    verts = [tuple(float(vals[3 * i + k]) for k in range(3)) for i in range(nv)]
    faces, at = [], 3 * nv
    for _ in range(nf):
        n = int(vals[at]); faces.append([int(x) for x in vals[at + 1: at + 1 + n]]); at += 1 + n
    return verts, faces

def read_ply(path):  # vertex x y z (+ anything), binary little endian or ascii
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    fmt = header[1].split()[1]
    elements, cur = [], None
    sizes = {"float": "f", "float32": "f", "double": "d", "uchar": "B", "uint8": "B", "char": "b",
             "int": "i", "int32": "i", "uint": "I", "short": "h", "ushort": "H"}
    for line in header:
        w = line.split()
        if w[0] == "element":
            cur = [w[1], int(w[2]), []]; elements.append(cur)
        elif w[0] == "property":
            if w[1] == "list":
                cur[2].append(("list", w[2], w[3], w[4]))
            else:
                cur[2].append((w[2], w[1]))
    counts = {e[0]: e[1] for e in elements}
    v = next(e for e in elements if e[0] == "vertex")
    assert all(p[0] != "list" for p in v[2])
    names = [p[0] for p in v[2]]
    pts = []
    if fmt == "ascii":
        lines = data[end:].decode().splitlines()
        for i in range(v[1]):
            row = lines[i].split()
            pts.append(tuple(float(row[names.index(c)]) for c in "xyz"))
    else:
        assert fmt == "binary_little_endian", fmt
        assert elements[0][0] == "vertex"
        rec = "<" + "".join(sizes[p[1]] for p in v[2])
        size = struct.calcsize(rec)
        for i in range(v[1]):
            row = struct.unpack_from(rec, data, end + i * size)
            pts.append(tuple(row[names.index(c)] for c in "xyz"))
    return pts, counts

sub = lambda a, b: tuple(x - y for x, y in zip(a, b))
add = lambda a, b: tuple(x + y for x, y in zip(a, b))
dot = lambda a, b: sum(x * y for x, y in zip(a, b))
norm = lambda a: math.sqrt(dot(a, a))
cross = lambda a, b: (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])

verts, faces = read_off(sys.argv[1])
pts, counts = read_ply(sys.argv[2])
kept, kept_counts = read_ply(sys.argv[3])
nv = len(verts)
print(f"input {nv} vertices, {len(faces)} faces; drawing {len(pts)} vertices, {counts.get('face', 0)} faces")
assert counts.get("face", 0) == 0, "the drawing layer has faces"
assert len(pts) == 6 * nv, f"expected 6 drawing vertices per input vertex ({6 * nv}), got {len(pts)}"
assert len(kept) == nv and kept_counts.get("face") == len(faces), "the input layer changed size"
diag = norm(sub(tuple(max(p[k] for p in verts) for k in range(3)), tuple(min(p[k] for p in verts) for k in range(3))))
assert max(norm(sub(a, b)) for a, b in zip(verts, kept)) <= 1e-6 * diag, "the input geometry changed"

edges = [norm(sub(verts[f[k]], verts[f[(k + 1) % len(f)]])) for f in faces for k in range(len(f))]
mean_edge = sum(edges) / len(edges)
normals = [(0.0, 0.0, 0.0)] * nv
for f in faces:
    n = cross(sub(verts[f[1]], verts[f[0]]), sub(verts[f[2]], verts[f[0]]))
    for i in f:
        normals[i] = add(normals[i], n)

tol = 1e-4 * diag
worst_tangent = 0.0
for i in range(nv):
    seg = [(pts[6 * i + 2 * s], pts[6 * i + 2 * s + 1]) for s in range(3)]
    dirs = []
    for a, b in seg:
        mid = tuple((x + y) / 2 for x, y in zip(a, b))
        assert norm(sub(mid, verts[i])) <= tol, f"vertex {i}: a segment is not centred on it"
        length = norm(sub(a, b))
        assert abs(length - 0.5 * mean_edge) <= 0.01 * mean_edge, \
            f"vertex {i}: segment length {length}, half the mean edge is {0.5 * mean_edge}"
        dirs.append(tuple(x / length for x in sub(a, b)))
    for s in range(3):  # the three segments are 60 degrees apart: |cos| = 1/2 for every pair
        c = abs(dot(dirs[s], dirs[(s + 1) % 3]))
        assert abs(c - 0.5) <= 1e-3, f"vertex {i}: segments {s}, {(s + 1) % 3} have |cos| {c}"
    n = normals[i]
    n = tuple(x / norm(n) for x in n)
    worst_tangent = max(worst_tangent, max(abs(dot(d, n)) for d in dirs))
# Field normal vs this script's angle-unweighted normal: close, not equal.
assert worst_tangent <= math.sin(math.radians(10)), f"segments leave the tangent plane: |d.n| = {worst_tangent}"
print(f"all {nv} vertices: 3 centred segments 60 deg apart, length 0.5 * mean edge "
      f"({0.5 * mean_edge:.4g}), max |d.n| {worst_tangent:.3g}")
PY
echo "PASS"
