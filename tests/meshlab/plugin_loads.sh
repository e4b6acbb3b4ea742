#!/usr/bin/env bash
# The staged meshlabserver loads libfilter_fcvt.so with its three filters, and every .mlx script in
# resources/ lists exactly the parameters its filter declares (meshlabserver 2020.09 asserts on
# a script missing one, and refuses a script with more), under the frozen names. In any order:
# MeshLab matches a script's parameters by name (issue 15: the dialog puts the common ones
# first, the scripts keep the old order with new parameters appended; meshlab_log_density runs
# an old-order script).
# Usage: plugin_loads.sh SOURCE_DIR PLUGIN_SO WORK_DIR
set -euo pipefail
FCVT_SOURCE_DIR="$1"; plugin="$2"; work="$3"
source "$FCVT_SOURCE_DIR/tests/meshlab/common.sh"

rm -rf "$work/out"; mkdir -p "$work/out"
server="$(stage_meshlab "$work/stage" "$plugin")"
run_meshlabserver "$server" "$work/out/log.txt" -d "$work/out/filters.txt"
[ "$MLS_RC" -eq 0 ] || fail "meshlabserver -d exited with $MLS_RC"
grep -q "Current Plugins Dir is: $work/stage/lib/x86_64-linux-gnu/meshlab/plugins" "$work/out/log.txt.err" \
  || fail "meshlabserver did not search the staged plugin directory"

# The dump (-d) has one "\section fN NAME" per filter followed by one row per parameter:
#   <TR><TD> \c TYPE  </TD> <TD> DESCRIPTION </TD> <TD><i> TOOLTIP -- </i></TD> </TR>
# It does not print parameter names, so a script's <Param> is matched to a declared parameter
# by (type, description, tooltip); the names are checked against the frozen lists below.
python3 - "$work/out/filters.txt" "$FCVT_SOURCE_DIR/resources" <<'PY' || fail "filters or .mlx scripts do not match"
import glob, os, re, sys
import xml.etree.ElementTree as ET

dump_path, resources = sys.argv[1], sys.argv[2]
frozen = {  # filter name -> parameter names, in the scripts' order (frozen API)
    "Remeshing: Field-Aligned CVT (FCVT)":
        ["vertexCount", "lambda", "cvtIterations", "fcvtIterations", "fieldSource", "seed",
         "sizeMode", "targetLength", "valenceOptimization", "featureAngle", "featureSelection",
         "adaptive", "colorIrregular", "gradation", "repair", "selectedOnly",
         "exactCount", "preset"],
    "Compute 6-RoSy Field": ["fieldSource", "seed", "maxCrosses"],
    "Remeshing Quality Report (FCVT)": ["referenceLayer", "colorIrregular"],
}
declared, current = {}, None
for line in open(dump_path, encoding="utf-8", errors="replace"):
    m = re.match(r"\\section f\d+ (.*?)\s*$", line)
    if m:
        current = m.group(1)
        declared.setdefault(current, [])
        continue
    m = re.match(r"<TR><TD> \\c (\S+)  </TD> <TD> (.*) </TD> <TD><i> (.*) -- </i></TD> </TR>", line)
    if m and current is not None:
        declared[current].append(m.groups())

bad = []
for name in frozen:
    if name not in declared:
        bad.append(f"filter '{name}' not loaded")
    else:
        print(f"filter '{name}' declares {len(declared[name])} parameters")
scripts = sorted(glob.glob(os.path.join(resources, "*.mlx")))
covered = set()
for path in scripts:
    root = ET.parse(path).getroot()
    for f in root.iter("filter"):
        name = f.get("name")
        covered.add(name)
        params = f.findall("Param")
        names = [p.get("name") for p in params]
        rows = [(p.get("type", "").removeprefix("Rich"), p.get("description"), p.get("tooltip"))
                for p in params]
        where = f"{os.path.basename(path)} '{name}'"
        print(f"{where}: {', '.join(names)}")
        if name not in declared:
            if os.environ.get("FCVT_MESHLAB_HOST") and name not in frozen:
                # fcvt-meshlab-host (MeshLab 2022.02) dumps only libfilter_fcvt.so's filters.
                print(f"{where}: MeshLab's own filter, not in the host's dump")
                continue
            bad.append(f"{where}: no such filter loaded")
            continue
        if name in frozen and sorted(names) != sorted(frozen[name]):
            bad.append(f"{where}: parameters {names}, frozen list {frozen[name]}")
        if sorted(rows) != sorted(declared[name]):
            missing = [r for r in declared[name] if r not in rows]
            extra = [r for r in rows if r not in declared[name]]
            bad.append(f"{where}: does not list exactly the declared parameters "
                       f"(missing {missing}, not declared {extra})")
        for p in params:
            if p.get("type") == "RichEnum":
                n = int(p.get("enum_cardinality", "-1"))
                labels = [p.get(f"enum_val{i}") for i in range(max(n, 0))]
                if n <= 0 or None in labels or not 0 <= int(p.get("value", "-1")) < n:
                    bad.append(f"{where}: enum {p.get('name')} malformed")
for name in frozen:
    if name not in covered:
        bad.append(f"no .mlx script in resources/ for '{name}'")
if bad:
    print("\n".join("MISMATCH: " + b for b in bad))
    sys.exit(1)
print(f"{len(scripts)} scripts match their filters")
PY
echo "PASS"
