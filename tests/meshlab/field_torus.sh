#!/usr/bin/env bash
# End to end through meshlabserver: run resources/fcvt-field.mlx ("Compute 6-RoSy Field") on the
# torus, save the drawing layer (-l x: the last layer) and the input layer, and check the log and
# the drawing. MeshLab 2020.09 cannot save custom attributes like `rosy` from meshlabserver (the
# PLY exporter's PVA3F options default to off), so the checks are the log (singularity count,
# index sum 0 = 6 x chi on the torus, explained; the new layer) and the saved drawing, whose strips
# encode the field (issue 15 item 3): twice, with maxCrosses 10000 (a cross at every one of the
# 3072 vertices, cross i at vertex i) and with the script's 2000 (a subset of at most 2000).
# Per cross: three strips (4 vertices, 2 faces each) with one centre, lifted off its vertex along
# the normal by 0.15 x the segment length L, 60 degrees apart in the tangent plane, 0.12 L wide,
# L at least 0.6 x the vertex's mean edge length, faces facing away from the surface.
# Usage: field_torus.sh SOURCE_DIR PLUGIN_SO WORK_DIR
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"

rm -rf "$work/out"; mkdir -p "$work/out"
server="$(stage_meshlab "$work/stage" "$plugin")"
"$FCVT_SOURCE_DIR/tests/meshlab/obj2off.sh" "$FCVT_SOURCE_DIR/resources/torus.obj" "$work/out/torus.off"

for crosses in 10000 2000; do
  mlx="$work/out/field-$crosses.mlx"
  sed "s/\(name=\"maxCrosses\"[^>]*value=\"\)[^\"]*\"/\1$crosses\"/" "$FCVT_SOURCE_DIR/resources/fcvt-field.mlx" > "$mlx"
  [ "$(mlx_param "$mlx" maxCrosses)" = "$crosses" ] || fail "could not set maxCrosses in $mlx"
  drawing="$work/out/field-$crosses.ply"
  kept="$work/out/torus-after-$crosses.ply"
  log="$work/out/log-$crosses.txt"
  run_meshlabserver "$server" "$log" -i "$work/out/torus.off" -o "$drawing" -l x -o "$kept" -s "$mlx"

  [ "$MLS_RC" -eq 0 ] || fail "meshlabserver exited with $MLS_RC"
  grep -q "filter: Compute 6-RoSy Field" "$log" || fail "filter not run"
  grep -Eq "FCVT field: extrinsic 6-RoSy \(seed 1\) on layer 'torus.off': [0-9]+ singularities, index sum 0 \(indices in sixths of a turn; on a closed surface it is 6 x the Euler characteristic, here 6 x 0 = 0\)" \
    "$log" || fail "no singularity count with index sum 0 (6 * chi of the torus) in the log"
  line="$(grep -m1 "FCVT field: new layer '6-RoSy field': crosses at" "$log")" || fail "no new layer in the log"
  drawn="$(sed -n 's/.*crosses at \([0-9]*\) of 3072 vertices.*/\1/p' <<<"$line")"
  [ -n "$drawn" ] || fail "no cross count in: $line"
  ! grep -q "FCVT field: the layer 'torus.off' is unchanged; the field leaves out" "$log" || fail "the torus has nothing to leave out"
  grep -Eq "saved as .*/field-$crosses.ply \($((12 * drawn)) vn $((6 * drawn)) fn\)" "$log" || fail "drawing layer not saved with 12 vertices and 6 faces per cross"
  grep -Eq "Mesh .*torus.off saved as .*torus-after-$crosses.ply" "$log" || fail "input layer not saved"
  ! grep -Eq "Assertion|Aborted|terminate called" "$log.err" || fail "abort in stderr"

  python3 - "$work/out/torus.off" "$drawing" "$kept" "$crosses" "$drawn" <<'PY' || fail "the drawing does not show the field"
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

def read_ply(path):  # binary little endian: vertex x y z (+ scalars), face list uchar int
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    assert header[1].split()[1] == "binary_little_endian", header[1]
    sizes = {"float": "f", "float32": "f", "double": "d", "uchar": "B", "uint8": "B", "char": "b",
             "int": "i", "int32": "i", "uint": "I", "short": "h", "ushort": "H"}
    elements, cur = [], None
    for line in header:
        w = line.split()
        if w[0] == "element":
            cur = [w[1], int(w[2]), []]; elements.append(cur)
        elif w[0] == "property":
            cur[2].append(("list", w[2], w[3]) if w[1] == "list" else (w[2], w[1]))
    pos, pts, faces = end, [], []
    for name, count, props in elements:
        if name == "vertex":
            names = [p[0] for p in props]
            rec = "<" + "".join(sizes[p[1]] for p in props)
            size = struct.calcsize(rec)
            for i in range(count):
                row = struct.unpack_from(rec, data, pos); pos += size
                pts.append(tuple(row[names.index(c)] for c in "xyz"))
        elif name == "face":
            assert len(props) == 1 and props[0][0] == "list"
            cnt, idx = sizes[props[0][1]], sizes[props[0][2]]
            for i in range(count):
                (n,) = struct.unpack_from("<" + cnt, data, pos); pos += struct.calcsize(cnt)
                faces.append(struct.unpack_from("<%d%s" % (n, idx), data, pos)); pos += n * struct.calcsize(idx)
    return pts, faces

sub = lambda a, b: tuple(x - y for x, y in zip(a, b))
add = lambda a, b: tuple(x + y for x, y in zip(a, b))
mul = lambda s, a: tuple(s * x for x in a)
dot = lambda a, b: sum(x * y for x, y in zip(a, b))
norm = lambda a: math.sqrt(dot(a, a))
unit = lambda a: mul(1 / norm(a), a)
cross = lambda a, b: (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])

verts, faces = read_off(sys.argv[1])
pts, dfaces = read_ply(sys.argv[2])
kept, kept_faces = read_ply(sys.argv[3])
max_crosses, drawn = int(sys.argv[4]), int(sys.argv[5])
nv = len(verts)
print(f"input {nv} vertices, {len(faces)} faces; drawing {len(pts)} vertices, {len(dfaces)} faces, {drawn} crosses")
assert drawn <= max_crosses, f"{drawn} crosses, more than maxCrosses {max_crosses}"
assert drawn == min(nv, max_crosses) or (nv > max_crosses and drawn >= 0.5 * max_crosses), \
    f"{drawn} crosses for {nv} vertices and at most {max_crosses}"
assert len(pts) == 12 * drawn and len(dfaces) == 6 * drawn
assert len(kept) == nv and len(kept_faces) == len(faces), "the input layer changed size"
diag = norm(sub(tuple(max(p[k] for p in verts) for k in range(3)), tuple(min(p[k] for p in verts) for k in range(3))))
assert max(norm(sub(a, b)) for a, b in zip(verts, kept)) <= 1e-6 * diag, "the input geometry changed"

normals = [(0.0, 0.0, 0.0)] * nv
local = [[0.0, 0] for _ in range(nv)]
for f in faces:
    n = cross(sub(verts[f[1]], verts[f[0]]), sub(verts[f[2]], verts[f[0]]))
    for k, i in enumerate(f):
        normals[i] = add(normals[i], n)
        j = f[(k + 1) % 3]
        e = norm(sub(verts[i], verts[j]))
        local[i][0] += e; local[i][1] += 1; local[j][0] += e; local[j][1] += 1
normals = [unit(n) for n in normals]
local = [s / c for s, c in local]
# nearest input vertex of a point: a coarse grid
cell = 0.05 * diag
grid = {}
for i, p in enumerate(verts):
    grid.setdefault(tuple(int(math.floor(x / cell)) for x in p), []).append(i)
def nearest(q):
    k = tuple(int(math.floor(x / cell)) for x in q)
    best = None
    for dx in (-1, 0, 1):
        for dy in (-1, 0, 1):
            for dz in (-1, 0, 1):
                for i in grid.get((k[0] + dx, k[1] + dy, k[2] + dz), []):
                    d = norm(sub(verts[i], q))
                    if best is None or d < best[0]:
                        best = (d, i)
    return best[1]

tol = 1e-4 * diag
worst_tangent, lifts = 0.0, []
used = set()
for c in range(drawn):
    quads = [pts[12 * c + 4 * s: 12 * c + 4 * s + 4] for s in range(3)]
    centres = [mul(0.25, add(add(q[0], q[1]), add(q[2], q[3]))) for q in quads]
    centre = centres[0]
    assert all(norm(sub(x, centre)) <= tol for x in centres), f"cross {c}: strips not centred together"
    dirs, lengths, widths = [], [], []
    for q in quads:
        a_mid, b_mid = mul(0.5, add(q[0], q[3])), mul(0.5, add(q[1], q[2]))
        along = sub(b_mid, a_mid)
        lengths.append(norm(along)); dirs.append(unit(along))
        widths.append(norm(sub(q[3], q[0])))
    L = lengths[0]
    assert all(abs(x - L) <= 1e-3 * L for x in lengths), f"cross {c}: strips of different lengths"
    assert all(abs(w - 0.12 * L) <= 1e-3 * L for w in widths), f"cross {c}: strip width is not 0.12 L"
    for s in range(3):
        cs = abs(dot(dirs[s], dirs[(s + 1) % 3]))
        assert abs(cs - 0.5) <= 1e-3, f"cross {c}: strips {s}, {(s + 1) % 3} have |cos| {cs}"
    v = c if drawn == nv else nearest(centre)
    assert v not in used, f"two crosses at vertex {v}"
    used.add(v)
    lift = sub(centre, verts[v])
    h = norm(lift)
    lifts.append(h / L)
    assert abs(h - 0.15 * L) <= 0.01 * L, f"cross {c}: lifted {h / L:.3f} L off vertex {v}, want 0.15 L"
    assert dot(lift, normals[v]) >= 0.97 * h, f"cross {c}: not lifted along the normal"
    assert L >= 0.6 * local[v] * (1 - 1e-3), f"cross {c}: length {L} under 0.6 x the local edge {local[v]}"
    worst_tangent = max(worst_tangent, max(abs(dot(d, normals[v])) for d in dirs))
    for f in dfaces[6 * c: 6 * c + 6]:
        fn = cross(sub(pts[f[1]], pts[f[0]]), sub(pts[f[2]], pts[f[0]]))
        assert dot(fn, normals[v]) > 0, f"cross {c}: a strip faces into the surface"
assert worst_tangent <= math.sin(math.radians(10)), f"strips leave the tangent plane: |d.n| = {worst_tangent}"
print(f"{drawn} crosses: 3 strips each, centred, 60 deg apart, lifted {min(lifts):.3f}..{max(lifts):.3f} L along "
      f"the normal, max |d.n| {worst_tangent:.3g}")
PY
done
echo "PASS"
