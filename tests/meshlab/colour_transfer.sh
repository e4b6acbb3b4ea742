#!/usr/bin/env bash
# Keep what the user had (issue 7 item 5) and size by edge length (item 2), through
# meshlabserver: a torus whose vertices carry colour (red = x, green = y, mapped to 0..255) and
# quality (= z) is remeshed with sizeMode "target edge length"; the saved output must carry
# colour and quality that follow the same smooth functions at its own vertices, and the log the
# achieved mean edge length, within 15 % of the target.
# Usage: colour_transfer.sh SOURCE_DIR PLUGIN_SO WORK_DIR
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"

rm -rf "$work/out"; mkdir -p "$work/out"
server="$(stage_meshlab "$work/stage" "$plugin")"
"$FCVT_SOURCE_DIR/tests/meshlab/obj2off.sh" "$FCVT_SOURCE_DIR/resources/torus.obj" "$work/out/torus.off"

# The coloured input: ASCII PLY with uchar red green blue alpha and float quality per vertex.
python3 - "$work/out/torus.off" "$work/out/torus-colour.ply" <<'PY'
import sys
tok = open(sys.argv[1]).read().split()
assert tok[0] == "OFF"
nv, nf = int(tok[1]), int(tok[2])
v = [tuple(map(float, tok[4 + 3 * i:7 + 3 * i])) for i in range(nv)]
pos = 4 + 3 * nv
faces = []
for _ in range(nf):
    n = int(tok[pos]); faces.append(tok[pos + 1:pos + 1 + n]); pos += 1 + n
lo = [min(p[k] for p in v) for k in range(3)]
hi = [max(p[k] for p in v) for k in range(3)]
with open(sys.argv[2], "w") as f:
    f.write("ply\nformat ascii 1.0\n")
    f.write(f"comment bbox {' '.join(map(str, lo + hi))}\n")
    f.write(f"element vertex {nv}\nproperty float x\nproperty float y\nproperty float z\n")
    f.write("property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n")
    f.write("property float quality\n")
    f.write(f"element face {nf}\nproperty list uchar int vertex_indices\nend_header\n")
    for p in v:
        r = round(255 * (p[0] - lo[0]) / (hi[0] - lo[0]))
        g = round(255 * (p[1] - lo[1]) / (hi[1] - lo[1]))
        f.write(f"{p[0]} {p[1]} {p[2]} {r} {g} 128 255 {p[2]}\n")
    for fc in faces:
        f.write(f"{len(fc)} {' '.join(fc)}\n")
PY

# The shipped script, switched to "target edge length" mode.
target=0.1
sed -e 's/\(name="sizeMode" value="\)[0-9]*"/\11"/' \
    -e "s/\(name=\"targetLength\" value=\"\)[^\"]*\"/\1$target\"/" \
    "$FCVT_SOURCE_DIR/resources/fcvt-remesh.mlx" > "$work/out/by-length.mlx"
[ "$(mlx_param "$work/out/by-length.mlx" sizeMode)" = 1 ] || fail "sizeMode not switched"

out="$work/out/torus-fcvt.ply"
run_meshlabserver "$server" "$work/out/log.txt" -i "$work/out/torus-colour.ply" -o "$out" -m vc vq \
  -s "$work/out/by-length.mlx"
[ "$MLS_RC" -eq 0 ] || fail "meshlabserver exited with $MLS_RC"
grep -q "FCVT: new layer" "$work/out/log.txt" || fail "filter not run"
grep -q "FCVT: per-vertex colour and quality of .* transferred" "$work/out/log.txt" \
  || fail "no transfer in the log"
mean="$(sed -n 's/^.*FCVT size: mean edge length \([0-9.eE+-]*\) .*/\1/p' "$work/out/log.txt" | head -n 1)"
awk -v m="$mean" -v t="$target" 'BEGIN { d = m - t; if (d < 0) d = -d; exit !(m != "" && d <= 0.15 * t) }' \
  || fail "logged mean edge length '$mean', target $target"
echo "mean edge length $mean (target $target)"
[ -s "$out" ] || fail "$out not written"

python3 - "$out" "$work/out/torus-colour.ply" <<'PY' || fail "colour or quality not transferred"
import struct, sys

def read_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header") + len(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii", "replace").splitlines()
    fmt, elements = None, []
    for line in header:
        w = line.split()
        if not w: continue
        if w[0] == "format": fmt = w[1]
        elif w[0] == "element": elements.append((w[1], int(w[2]), []))
        elif w[0] == "property": elements[-1][2].append(w[1:])
    codes = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
             "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
             "float": "f", "float32": "f", "double": "d", "float64": "d"}
    name, count, props = elements[0]
    assert name == "vertex"
    rows = []
    if fmt == "ascii":
        lines = data[end:].decode().splitlines()
        for i in range(count):
            vals = lines[i].split()
            rows.append({p[-1]: float(x) for p, x in zip(props, vals)})
    else:
        bo = "<" if fmt == "binary_little_endian" else ">"
        assert all(p[0] != "list" for p in props)
        st = struct.Struct(bo + "".join(codes[p[0]] for p in props))
        for i in range(count):
            vals = st.unpack_from(data, end + i * st.size)
            rows.append({p[-1]: float(x) for p, x in zip(props, vals)})
    return header, rows

header, rows = read_ply(sys.argv[1])
names = set(rows[0]) if rows else set()
print(f"output: {len(rows)} vertices, properties {sorted(names)}")
missing = {"red", "green", "blue", "quality"} - names
if missing:
    sys.exit(f"output lacks vertex properties {sorted(missing)}")
bbox = [float(x) for l in open(sys.argv[2]) if l.startswith("comment bbox") for x in l.split()[2:]]
lo, hi = bbox[:3], bbox[3:]
bad = 0
worst = [0.0, 0.0, 0.0, 0.0]
for r in rows:
    er = abs(r["red"] - 255 * (r["x"] - lo[0]) / (hi[0] - lo[0]))
    eg = abs(r["green"] - 255 * (r["y"] - lo[1]) / (hi[1] - lo[1]))
    eb = abs(r["blue"] - 128)
    eq = abs(r["quality"] - r["z"])
    worst = [max(a, b) for a, b in zip(worst, (er, eg, eb, eq))]
    # Linear along each input triangle: the closest point is within the chord error of the input.
    if er > 8 or eg > 8 or eb > 1 or eq > 0.05 * (hi[2] - lo[2]):
        bad += 1
print(f"worst errors: red {worst[0]:.2f}, green {worst[1]:.2f}, blue {worst[2]:.2f}, quality {worst[3]:.4f}")
reds = {r["red"] for r in rows}
qualities = {r["quality"] for r in rows}
if len(reds) < 50 or len(qualities) < 50:
    sys.exit(f"colour/quality nearly constant: {len(reds)} reds, {len(qualities)} qualities")
if bad:
    sys.exit(f"{bad} vertices off the input's colour/quality functions")
print("colour and quality follow the input")
PY
echo "PASS"
