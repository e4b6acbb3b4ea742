#!/usr/bin/env bash
# Issue 34 through meshlabserver: a script selects a disk of bunny's faces (Conditional Face
# Selection), runs FCVT with "Remesh only selected faces" and writes the
# new layer with face quality = its selection (the new faces). The kept faces are the input's
# unselected ones, in order, on the same (single-precision) coordinates; the seam is watertight;
# no vertex is duplicated; the new faces clear the quality floors; the log has the region line.
# Usage: remesh_selected.sh SOURCE_DIR PLUGIN_SO WORK_DIR
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"

rm -rf "$work/out"; mkdir -p "$work/out"
server="$(stage_meshlab "$work/stage" "$plugin")"
cp "$FCVT_SOURCE_DIR/resources/bunny.ply" "$work/out/bunny.ply"
out="$work/out/bunny-selected.ply"
# The script: MeshLab's own filters around the shipped FCVT script (every parameter: meshlabserver
# 2020.09 asserts that a script has them all) with vertexCount 3000, seed 1, selectedOnly true.
mlx="$work/out/selected.mlx"
{ echo '<!DOCTYPE FilterScript>'; echo '<FilterScript>'
  echo ' <filter name="Conditional Face Selection">'
  echo '  <Param type="RichString" name="condSelect" value="(((x0+x1+x2)/3+0.025969)^2+((y0+y1+y2)/3-0.156664)^2+((z0+z1+z2)/3+0.002607)^2 &lt; 0.0014)" description="boolean function" tooltip="a disk of faces"/>'
  echo ' </filter>'
  sed -n '/<filter /,/<\/filter>/p' "$FCVT_SOURCE_DIR/resources/fcvt-remesh.mlx" \
    | sed -e 's/\(name="vertexCount"[^>]*value="\)[^"]*"/\13000"/' -e 's/\(name="seed"[^>]*value="\)[^"]*"/\11"/' \
          -e 's/\(name="selectedOnly"[^>]*value="\)[^"]*"/\1true"/'
  echo ' <filter name="Per Face Quality Function">'
  echo '  <Param type="RichString" name="q" value="fsel" description="func q0 = " tooltip="the selection: the new faces"/>'
  echo '  <Param type="RichBool" name="normalize" value="false" description="normalize" tooltip=""/>'
  echo '  <Param type="RichBool" name="map" value="false" description="map into color" tooltip=""/>'
  echo '  <Param type="RichBool" name="onselected" value="false" description="only on selection" tooltip=""/>'
  echo ' </filter>'; echo '</FilterScript>'; } > "$mlx"
grep -q 'name="selectedOnly" value="true"' "$mlx" || fail "no selectedOnly in the script"
run_meshlabserver "$server" "$work/out/log.txt" -i "$work/out/bunny.ply" -o "$out" -m fq -s "$mlx"
[ "$MLS_RC" -eq 0 ] || fail "meshlabserver exited with $MLS_RC"
grep -q "FCVT region: [1-9][0-9]* piece(s) of the selection remeshed (0 kept" "$work/out/log.txt" || fail "no region line in the log"
added="$(sed -n 's/.*the selection touched itself at a vertex: \([0-9]*\) faces.*/\1/p' "$work/out/log.txt" | head -n 1)"
python3 - "$work/out/bunny.ply" "$out" "$FCVT_SOURCE_DIR/tests/cli" "${added:-0}" <<'PY' || fail "the region remesh broke a guarantee"
import math, struct, sys
sys.path.insert(0, sys.argv[3])
from fcvt_check import edge_counts, is_subsequence, measure

TYPES = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I", "float": "f", "double": "d",
         "int8": "b", "uint8": "B", "int16": "h", "uint16": "H", "int32": "i", "uint32": "I", "float32": "f", "float64": "d"}

def read_ply(path):
    """Binary little-endian PLY: (vertices, faces, face quality or None)."""
    data = open(path, "rb").read()
    end = data.index(b"end_header") + len(b"end_header")
    end = data.index(b"\n", end) + 1
    elements = []
    for line in data[:end].decode("ascii").splitlines():
        w = line.split()
        if w and w[0] == "element":
            elements.append((w[1], int(w[2]), []))
        elif w and w[0] == "property":
            elements[-1][2].append(w[1:])
    off, vertices, faces, quality = end, [], [], []
    for name, count, props in elements:
        for _ in range(count):
            record = {}
            for p in props:
                if p[0] == "list":
                    n = struct.unpack_from("<" + TYPES[p[1]], data, off)[0]
                    off += struct.calcsize(TYPES[p[1]])
                    record[p[3]] = struct.unpack_from("<%d%s" % (n, TYPES[p[2]]), data, off)
                    off += n * struct.calcsize(TYPES[p[2]])
                else:
                    record[p[1]] = struct.unpack_from("<" + TYPES[p[0]], data, off)[0]
                    off += struct.calcsize(TYPES[p[0]])
            if name == "vertex":
                vertices.append((record["x"], record["y"], record["z"]))
            elif name == "face":
                faces.append(tuple(record["vertex_indices"]))
                quality.append(record.get("quality"))
    return vertices, faces, quality

f32 = lambda x: struct.unpack("<f", struct.pack("<f", x))[0]
iv, ifaces, _ = read_ply(sys.argv[1])
iv = [tuple(f32(c) for c in p) for p in iv]  # the layer's single precision
ov, ofaces, oq = read_ply(sys.argv[2])
centre, r2 = (-0.025969, 0.156664, -0.002607), 0.0014
selected = [sum((sum(iv[v][k] for v in f) / 3 - centre[k]) ** 2 for k in range(3)) < r2 for f in ifaces]
kept_in = [tuple(iv[v] for v in f) for f, s in zip(ifaces, selected) if not s]
kept_out = [tuple(ov[v] for v in f) for f, q in zip(ofaces, oq) if q == 0]
new = [f for f, q in zip(ofaces, oq) if q == 1]
bad = []
# Faces the selection gained where it touched itself at a vertex (logged) are remeshed too.
if not is_subsequence(kept_out, kept_in) or len(kept_in) - len(kept_out) != int(sys.argv[4]):
    bad.append("kept faces differ (%d input, %d output, %s added)" % (len(kept_in), len(kept_out), sys.argv[4]))
position = {p: i for i, p in enumerate(iv)}
input_edges = edge_counts(ifaces)
seam = 0
for (a, b), n in edge_counts(ofaces).items():
    if n == 2:
        continue
    pa, pb = position.get(ov[a]), position.get(ov[b])
    seam += n != 1 or pa is None or pb is None or input_edges.get((min(pa, pb), max(pa, pb))) != 1
if seam:
    bad.append("%d seam edges are cracks, T-junctions or non-manifold" % seam)
if len(set(ov)) != len(ov):
    bad.append("duplicate vertices")
m = measure(ov, new)
print("kept %d faces; %d new faces: Q_avg %.3f, theta_min %.1f" % (len(kept_out), len(new), m["q_avg"], m["theta_min"]))
if not new or m["q_avg"] < 0.9 or m["theta_min"] < 15:
    bad.append("new faces: Q_avg %.3f, theta_min %.1f" % (m["q_avg"], m["theta_min"]))
print("\n".join(bad))
sys.exit(1 if bad else 0)
PY
echo "PASS"
