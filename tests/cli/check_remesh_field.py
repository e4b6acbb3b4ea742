"""`fcvt remesh` with a field: --field curvature-max on the cylinder writes the field at the
output vertices (rosy properties, unit and orthogonal to the unit normals); a default run's
report has an energy history with phases cvt and fcvt whose E_field decreases over the FCVT
iterations, the field's source and singularities, and params field/lambda; --field user takes
the field from the input PLY's rosy properties; lambda 0 writes no field.
Usage: check_remesh_field.py FCVT RESOURCES_DIR WORK_DIR"""
import json
import os
import sys

from fcvt_check import check, check_field_properties, finish, read_ply_vertex_properties, run_ok

fcvt, resources, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)


def remesh(source, name, vertices, *extra):
    out, report = os.path.join(work, name + ".ply"), os.path.join(work, name + ".json")
    print(run_ok([fcvt, "remesh", source, out, "--vertices", str(vertices), "--report", report, *extra]), end="")
    with open(report) as f:
        return out, json.load(f)


# --field curvature-max on the cylinder.
out, report = remesh(os.path.join(resources, "cylinder.off"), "cylinder-curvature-max", 300, "--field", "curvature-max")
rows, faces = check_field_properties(out, "cylinder curvature-max")
check(rows is not None and len(rows) == report["vertices"], "cylinder: vertex count of the file vs the report")
check(report["params"]["field"] == "curvature-max", f"params.field {report['params'].get('field')}")
check(report["field"]["source"] == "curvature-max" and report["field"]["computed"], f"field {report['field']}")

# A default run: CVT then FCVT, energies recorded.
torus = os.path.join(resources, "torus.obj")
out, report = remesh(torus, "torus-default", 400)
check_field_properties(out, "torus default")
params = report["params"]
check(params["field"] == "extrinsic" and params["lambda"] > 0 and params["fcvt_iterations"] > 0,
      f"default params {params}")
history = report["energy_history"]
check(len(history) > 0, "empty energy_history")
check(all(set(e) == {"phase", "e_cvt", "e_field"} for e in history), "energy_history entries need phase, e_cvt, e_field")
phases = [e["phase"] for e in history]
check("cvt" in phases and "fcvt" in phases, f"energy_history phases {sorted(set(phases))}")
fcvt_field = [e["e_field"] for e in history if e["phase"] == "fcvt"]
check(len(fcvt_field) >= 2 and fcvt_field[-1] < fcvt_field[0],
      f"E_field over the FCVT iterations: first {fcvt_field[:1]}, last {fcvt_field[-1:]}")
field = report["field"]
check(field["source"] == "extrinsic" and field["computed"], f"field {field}")
check(field["index_sum"] == 0, f"torus: singularity index sum {field['index_sum']}, expected 0")
check(field["singularities"] == 0 or len(field["singularity_positions"]) == min(1000, field["singularities"]),
      "singularity_positions: one per singularity (at most 1000)")
check(all(len(p) == 3 for p in field["singularity_positions"]), "singularity positions are [x, y, z]")

# --field user: the field of 'fcvt field' read back from the PLY.
with_field = os.path.join(work, "torus-field.ply")
run_ok([fcvt, "field", torus, with_field, "--quiet"])
out, report = remesh(with_field, "torus-user", 300, "--field", "user")
check_field_properties(out, "torus user")
check(report["field"]["source"] == "user" and report["params"]["field"] == "user", f"user field {report['field']}")

# lambda 0: a pure CVT, no field in the output.
out, report = remesh(torus, "torus-cvt", 300, "--lambda", "0", "--cvt-iterations", "60", "--fcvt-iterations", "0")
names = read_ply_vertex_properties(out)[0]
check(names == ["x", "y", "z"], f"pure CVT output has vertex properties {names}")
check(not report["field"]["computed"] and "fcvt" not in {e["phase"] for e in report["energy_history"]},
      "pure CVT: no field computed, no fcvt phase")

finish()
