#!/usr/bin/env bash
# Issue 38 items 4-7, read from meshlabserver's log (stderr: "LOG: <level> <text>", level 2 =
# information, 3 = warning) on the shipped example (resources/bunny.ply, the filter's defaults
# at 5000 vertices):
#   4. no warning: its 1113 unreferenced vertices are a note (information);
#   5. the lines in the order the stages ran: input, repair, field, optimisation (energies),
#      valence, the new layer and its figures, the times;
#   6. one singularity count per mesh: the field filter and `fcvt field` (the input) agree, and the
#      remesh log says which mesh its count is of and agrees with the CLI's report on that mesh;
#   7. the log says how d_RMS / d_H were sampled;
# and (issue 35 item 2) the filter's own time: one line after the stage times, its wall time at
# least the core's (3 significant digits each), with the output's normals the core's (the CLI's),
# not a search of the input.
# Usage: log_order.sh SOURCE_DIR PLUGIN_SO WORK_DIR FCVT_CLI
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"; cli="$4"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"

rm -rf "$work/out"; mkdir -p "$work/out"
server="$(stage_meshlab "$work/stage" "$plugin")"
cp "$FCVT_SOURCE_DIR/resources/bunny.ply" "$work/out/bunny.ply"
mlx="$work/out/remesh-5000.mlx"
sed 's/\(name="vertexCount"[^>]*value="\)[^"]*"/\15000"/' "$FCVT_SOURCE_DIR/resources/fcvt-remesh.mlx" > "$mlx"
run_meshlabserver "$server" "$work/out/remesh.txt" -i "$work/out/bunny.ply" -o "$work/out/remeshed.ply" -m vn -s "$mlx"
[ "$MLS_RC" -eq 0 ] || fail "remesh: meshlabserver exited with $MLS_RC"
run_meshlabserver "$server" "$work/out/field.txt" -i "$work/out/bunny.ply" -o "$work/out/field.ply" \
  -s "$FCVT_SOURCE_DIR/resources/fcvt-field.mlx"
[ "$MLS_RC" -eq 0 ] || fail "field: meshlabserver exited with $MLS_RC"
"$cli" remesh "$work/out/bunny.ply" "$work/out/cli.ply" --vertices 5000 --report "$work/out/cli.json" --quiet 2>/dev/null \
  || fail "fcvt remesh failed"
"$cli" field "$work/out/bunny.ply" "$work/out/cli-field.ply" > "$work/out/cli-field.txt" 2>&1 || fail "fcvt field failed"

python3 - "$work/out" <<'PY' || fail "the log's levels, order or figures"
import json, os, re, sys
out = sys.argv[1]
def log_lines(name):
    return [(int(m.group(1)), m.group(2)) for m in re.finditer(r"^LOG: (\d) (FCVT.*)$", open(os.path.join(out, name + ".txt.err")).read(), re.M)]
remesh, field = log_lines("remesh"), log_lines("field")
problems = []
# 4. Levels: information only on the shipped example, the unreferenced vertices as a note.
warnings = [t for level, t in remesh if level != 2]
if warnings:
    problems.append("warnings on the shipped example: %r" % warnings)
if not any(level == 2 and "FCVT note: repair: 1113 unreferenced vertices removed" in t for level, t in remesh):
    problems.append("no note on the 1113 unreferenced vertices")
# 5. Order: the first line of each stage, in the order the stages ran.
stages = ["FCVT input:", "FCVT repair:", "FCVT field:", "FCVT energy at the end", "FCVT valence optimisation:",
          "FCVT: new layer", "FCVT metrics:", "FCVT times ("]
first = [next((i for i, (_, t) in enumerate(remesh) if t.startswith(s)), None) for s in stages]
if None in first or first != sorted(first):
    problems.append("stages out of order: %r" % list(zip(stages, first)))
# 6. Singularities: the field filter = fcvt field (the input); the remesh log = the CLI's report,
# and it names the mesh.
count = lambda text: int(re.search(r"(\d+) singularities, index sum (-?\d+)", text).group(1))
field_line = next(t for _, t in field if " singularities, index sum" in t)
cli_field = int(re.search(r"singularities: (\d+)", open(os.path.join(out, "cli-field.txt")).read()).group(1))
if count(field_line) != cli_field:
    problems.append("field filter %d singularities, fcvt field %d" % (count(field_line), cli_field))
remesh_field = next(t for _, t in remesh if t.startswith("FCVT field:"))
report = json.load(open(os.path.join(out, "cli.json")))["field"]
if count(remesh_field) != report["singularities"] or report.get("mesh", "") not in remesh_field:
    problems.append("remesh log %r against the report's %d on %r" % (remesh_field, report["singularities"], report.get("mesh")))
# 7. The distances' sampling.
metrics = next(t for _, t in remesh if t.startswith("FCVT metrics:"))
if "50000 random points per mesh" not in metrics:
    problems.append("the metrics line does not say how d_H was sampled: %r" % metrics)
# The filter's time: after the stage times, wall >= the core's total, which is the times line's.
timing = [(i, t) for i, (_, t) in enumerate(remesh) if t.startswith("FCVT filter time:")]
times_at = next(i for i, (_, t) in enumerate(remesh) if t.startswith("FCVT times ("))
if len(timing) != 1 or timing[0][0] < times_at:
    problems.append("no one filter time line after the stage times: %r" % timing)
else:
    wall, core, rest = map(float, re.search(r"time: ([0-9.e+-]+) s .*stages ([0-9.e+-]+) s, .* data ([0-9.e+-]+) s",
                                          timing[0][1]).groups())
    total = float(re.search(r"total ([0-9.e+-]+) s", remesh[times_at][1]).group(1))
    if not (wall >= core > 0 and abs(core - total) <= 1e-3 * max(1.0, total) and abs(wall - core - rest) <= 0.006 * wall + 1e-3):
        problems.append("filter time %g, core %g (times line %g), the rest %g" % (wall, core, total, rest))
# The output's normals: the CLI's (the field's frames at the output vertices).
def ply_vertices(path):
    import struct
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    assert "format binary_little_endian 1.0" in header, header[:2]
    count, props, in_vertex = 0, [], False
    for line in header:
        w = line.split()
        if w[:2] == ["element", "vertex"]:
            count, in_vertex = int(w[2]), True
        elif w and w[0] == "element":
            in_vertex = False
        elif in_vertex and w[0] == "property":
            props.append((w[2], {"float": "f", "double": "d", "uchar": "B", "int": "i"}[w[1]]))
    fmt = "<" + "".join(t for _, t in props)
    size = struct.calcsize(fmt)
    names = [n for n, _ in props]
    return [dict(zip(names, struct.unpack_from(fmt, data, end + k * size))) for k in range(count)]
filt, cli = ply_vertices(os.path.join(out, "remeshed.ply")), ply_vertices(os.path.join(out, "cli.ply"))
if len(filt) != len(cli) or "nx" not in filt[0]:
    problems.append("filter output %d vertices (normals: %s), CLI %d" % (len(filt), "nx" in filt[0], len(cli)))
else:
    worst = max(abs(a[c] - b[c]) for a, b in zip(filt, cli) for c in ("nx", "ny", "nz"))
    if worst > 1e-5:
        problems.append("the filter's normals differ from the CLI's by up to %g" % worst)
print("\n".join(problems) if problems else "levels, order, singularities, sampling, time and normals as expected")
sys.exit(1 if problems else 0)
PY
echo "PASS"
