"""`fcvt field IN OUT.ply`: the PLY has the six field properties (nx ny nz rosy_x rosy_y rosy_z),
unit normals, unit directions orthogonal to them; the printed singularity index sum equals 6 chi
(chi also recomputed from the file). Usage: check_field.py FCVT WORK_DIR MESH EXPECTED_CHI [MESH CHI ...]"""
import os
import re
import sys

from fcvt_check import check, check_field_properties, euler_characteristic, finish, run_ok

fcvt, work = sys.argv[1], sys.argv[2]
cases = list(zip(sys.argv[3::2], (int(x) for x in sys.argv[4::2])))
os.makedirs(work, exist_ok=True)


def printed(text, key, label):
    match = re.search(rf"^{re.escape(key)}: (-?\d+)\b", text, re.MULTILINE)
    check(match is not None, f"{label}: no line '{key}: N' in {text!r}")
    return int(match.group(1)) if match else None


for source, expected_chi in cases:
    name = os.path.splitext(os.path.basename(source))[0]
    for field in ["extrinsic", "curvature-max"]:
        label = f"{name} {field}"
        out = os.path.join(work, f"{name}-{field}.ply")
        text = run_ok([fcvt, "field", source, out, "--field", field, "--seed", "3"])
        print(f"--- {label}\n{text}", end="")
        singularities = printed(text, "singularities", label)
        index_sum = printed(text, "index sum", label)
        chi = printed(text, "euler characteristic", label)
        rows, faces = check_field_properties(out, label)
        check(chi == expected_chi, f"{label}: euler characteristic {chi}, expected {expected_chi}")
        check(euler_characteristic(faces) == expected_chi, f"{label}: the file's V - E + F is {euler_characteristic(faces)}")
        check(index_sum == 6 * expected_chi, f"{label}: index sum {index_sum}, expected 6 chi = {6 * expected_chi}")
        check(singularities is not None and singularities >= abs(index_sum or 0),
              f"{label}: {singularities} singularities cannot sum to {index_sum} (indices are +-1 sixth or more)")

# --field user reads the field back from a written PLY: the same singularities.
first = os.path.splitext(os.path.basename(cases[0][0]))[0]
written = os.path.join(work, f"{first}-extrinsic.ply")
text = run_ok([fcvt, "field", written, os.path.join(work, "user.ply"), "--field", "user"])
again = run_ok([fcvt, "field", cases[0][0], os.path.join(work, "again.ply"), "--seed", "3"])
for key in ["singularities", "index sum"]:
    check(printed(text, key, "user") == printed(again, key, "extrinsic"), f"--field user read back: {key} differs")
check_field_properties(os.path.join(work, "user.ply"), "user")

# --quiet prints nothing and still writes the file.
quiet_out = os.path.join(work, "quiet.ply")
source = cases[0][0]
check(run_ok([fcvt, "field", source, quiet_out, "--quiet"]) == "", "--quiet printed something")
check_field_properties(quiet_out, "quiet")

finish()
