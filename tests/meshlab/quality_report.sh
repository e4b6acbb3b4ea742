#!/usr/bin/env bash
# "Remeshing Quality Report (FCVT)" through meshlabserver (issue 5 item 6):
# 1. resources/fcvt-quality.mlx on the torus: the Table 2 figures in the log, no distances (the
#    reference is the layer itself), and the saved vertex colours are the valence palette with
#    as many blue / white / pink vertices as the log counts;
# 2. a short FCVT run with colorIrregular on, then the report against the input (layer 0):
#    d_RMS and d_H logged, the output coloured from the palette only.
# Usage: quality_report.sh SOURCE_DIR PLUGIN_SO WORK_DIR
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"

rm -rf "$work/out"; mkdir -p "$work/out"
server="$(stage_meshlab "$work/stage" "$plugin")"
"$FCVT_SOURCE_DIR/tests/meshlab/obj2off.sh" "$FCVT_SOURCE_DIR/resources/torus.obj" "$work/out/torus.off"

# Palette counts of an ASCII/binary PLY's vertex colours: "blue white pink other".
palette_counts() {
  python3 - "$1" <<'PY'
import struct, sys
data = open(sys.argv[1], "rb").read()
end = data.index(b"\n", data.index(b"end_header")) + 1
fmt, props, count = None, [], 0
for line in data[:end].decode("ascii", "replace").splitlines():
    w = line.split()
    if w[:1] == ["format"]: fmt = w[1]
    elif w[:2] == ["element", "vertex"]: count, cur = int(w[2]), True
    elif w[:1] == ["element"]: cur = False
    elif w[:1] == ["property"] and cur: props.append((w[1], w[-1]))
codes = {"float": "f", "double": "d", "uchar": "B", "int": "i", "uint": "I", "short": "h", "ushort": "H", "char": "b"}
names = [n for _, n in props]
if not {"red", "green", "blue"} <= set(names): sys.exit("no vertex colours in " + sys.argv[1])
rows = []
if fmt == "ascii":
    lines = data[end:].decode().splitlines()
    rows = [dict(zip(names, map(float, lines[i].split()))) for i in range(count)]
else:
    st = struct.Struct(("<" if fmt == "binary_little_endian" else ">") + "".join(codes[t] for t, _ in props))
    rows = [dict(zip(names, st.unpack_from(data, end + i * st.size))) for i in range(count)]
palette = {(30, 90, 235): 0, (255, 255, 255): 1, (235, 40, 175): 2}
n = [0, 0, 0, 0]
for r in rows:
    n[palette.get((int(r["red"]), int(r["green"]), int(r["blue"])), 3)] += 1
print(*n)
PY
}

# 1. The shipped script on the input itself.
run_meshlabserver "$server" "$work/out/log1.txt" -i "$work/out/torus.off" -o "$work/out/torus-q.ply" -m vc \
  -s "$FCVT_SOURCE_DIR/resources/fcvt-quality.mlx"
[ "$MLS_RC" -eq 0 ] || fail "meshlabserver exited with $MLS_RC"
log="$work/out/log1.txt"
grep -q "filter: Remeshing Quality Report (FCVT)" "$log" || fail "filter not run"
grep -Eq "FCVT quality: Q_min [0-9.]+, Q_avg [0-9.]+, theta_min [0-9.]+ deg, mean theta_min [0-9.]+ deg, theta_max [0-9.]+ deg, triangles with an angle under 30 deg [0-9.e-]+%, over 90 deg [0-9.e-]+%, V6% [0-9.]+" "$log" \
  || fail "no Table 2 figures in the log"
grep -q "FCVT quality: d_RMS and d_H not measured" "$log" || fail "distances claimed without a reference"
grep -q "FCVT quality topology: genus 1, 0 boundary loops, 1 components" "$log" || fail "topology of the torus"
line="$(grep -m1 "FCVT valence colours: interior vertices:" "$log")" || fail "no valence counts in the log"
read -r low reg high <<<"$(sed -n 's/.*interior vertices: \([0-9]*\) of valence under 6 (blue), \([0-9]*\) of valence 6 (white), \([0-9]*\) over 6 (pink).*/\1 \2 \3/p' <<<"$line")"
read -r b w p other <<<"$(palette_counts "$work/out/torus-q.ply")"
echo "log: $low blue, $reg white, $high pink; file: $b blue, $w white, $p pink, $other other"
[ "$other" -eq 0 ] || fail "$other vertices with colours outside the palette"
[ "$b" -eq "$low" ] && [ "$w" -eq "$reg" ] && [ "$p" -eq "$high" ] || fail "file colours do not match the logged counts"
[ $((b + p)) -gt 0 ] && [ "$w" -gt 0 ] || fail "expected both regular and irregular vertices on the torus input"

# 2. A short FCVT run coloured by the remeshing filter, then the report against layer 0.
mlx="$work/out/remesh-report.mlx"
python3 - "$FCVT_SOURCE_DIR/resources/fcvt-remesh.mlx" "$FCVT_SOURCE_DIR/resources/fcvt-quality.mlx" "$mlx" <<'PY'
import re, sys
remesh, quality = open(sys.argv[1]).read(), open(sys.argv[2]).read()
body = lambda s: s[s.index("<filter"):s.rindex("</filter>") + len("</filter>")]
r = body(remesh)
for name, value in [("vertexCount", "300"), ("cvtIterations", "10"), ("fcvtIterations", "10"), ("colorIrregular", "true")]:
    r, n = re.subn(r'(name="%s"[^>]*value=")[^"]*"' % name, r'\g<1>%s"' % value, r)
    assert n == 1, name
open(sys.argv[3], "w").write("<!DOCTYPE FilterScript>\n<FilterScript>\n " + r + "\n " + body(quality) + "\n</FilterScript>\n")
PY
run_meshlabserver "$server" "$work/out/log2.txt" -i "$work/out/torus.off" -o "$work/out/torus-fcvt.ply" -m vc -s "$mlx"
[ "$MLS_RC" -eq 0 ] || fail "meshlabserver exited with $MLS_RC"
log="$work/out/log2.txt"
grep -q "FCVT valence colours on 'torus_FCVT'" "$log" || fail "remeshing did not colour its output"
grep -q "FCVT quality of 'torus_FCVT'" "$log" || fail "report not run on the FCVT layer"
grep -Eq "FCVT quality: d_RMS [0-9.e-]+, d_H [0-9.e-]+ \(fractions of the bounding-box diagonal of 'torus.off'\)" "$log" \
  || fail "no distances against the input"
read -r b w p other <<<"$(palette_counts "$work/out/torus-fcvt.ply")"
echo "FCVT output: $b blue, $w white, $p pink, $other other"
[ "$other" -eq 0 ] && [ "$w" -gt 0 ] || fail "FCVT output not coloured from the palette"
! grep -Eq "Assertion|Aborted|terminate called" "$work/out/log2.txt.err" || fail "abort in stderr"
echo "PASS"
