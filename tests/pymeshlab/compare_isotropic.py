"""MeshLab's own isotropic remesher and FCVT side by side in one pymeshlab script, at the same
vertex count, both measured by FCVT's quality report (its dict): the comparison the plugin is for.

As an example (docs/meshlab.md, "Packages: which MeshLab, which release"):
    PYTHONPATH=<pymeshlab> python3 compare_isotropic.py PLUGIN [MESH [TARGET_PERCENT]]
prints one row per remesher for MESH (default resources/bunny.ply; MeshLab's target edge length
TARGET_PERCENT % of the diagonal, default 1).
As CTest pymeshlab_compare_isotropic (run.sh: PLUGIN SOURCE_DIR WORK_DIR [CLI]) it runs that on
bunny.ply and checks that FCVT's vertex count is within 2 % of MeshLab's, that both outputs keep
bunny's topology and that FCVT's Q_avg, theta_min and V6% are above MeshLab's (the paper's
Table 2 claim)."""
import os
import sys

import pymeshlab

REMESH = "remeshing_field_aligned_cvt_fcvt"
REPORT = "remeshing_quality_report_fcvt"


def compare(plugin, mesh, target_percent=1.0):
    """The two remeshers on `mesh`: {name: the quality report's dict against the input}."""
    pymeshlab.load_plugin(plugin)
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(mesh)  # layer 0: the input, the reference of both reports
    ms.load_new_mesh(mesh)  # layer 1: MeshLab's remesher works in place, on this copy
    ms.meshing_isotropic_explicit_remeshing(iterations=10, targetlen=pymeshlab.PercentageValue(target_percent))
    count = ms.current_mesh().vertex_number()
    ms.set_current_mesh(0)
    ms.apply_filter(REMESH, vertexcount=count)  # layer 2: FCVT at MeshLab's vertex count
    reports = {}
    for layer, name in ((1, "isotropic explicit"), (2, "FCVT")):
        ms.set_current_mesh(layer)
        reports[name] = ms.apply_filter(REPORT, referencelayer=0, colorirregular=False)
    return reports


def print_table(reports):
    print("%-20s %8s %7s %7s %8s %7s %7s %8s" % ("remesher", "vertices", "Q_min", "Q_avg", "theta_min", "V6 %",
                                                   "genus", "d_H"))
    for name, q in reports.items():
        print("%-20s %8d %7.3f %7.3f %8.1f° %7.1f %7d %8.4f" % (name, q["vertices"], q["q_min"], q["q_avg"],
                                                               q["theta_min"], q["v6_pct"], q["genus"], q["d_h"]))


if __name__ == "__main__":
    if len(sys.argv) >= 4 and os.path.isdir(sys.argv[2]):  # CTest (run.sh)
        from pml_common import fail

        reports = compare(sys.argv[1], os.path.join(sys.argv[2], "resources", "bunny.ply"))
        print_table(reports)
        iso, fcvt = reports["isotropic explicit"], reports["FCVT"]
        bad = []
        if abs(fcvt["vertices"] - iso["vertices"]) > 0.02 * iso["vertices"]:
            bad.append("FCVT has %d vertices, MeshLab's %d" % (fcvt["vertices"], iso["vertices"]))
        for name, q in reports.items():
            if (q["genus"], q["boundary_loops"], q["components"]) != (0, 5, 1):
                bad.append("%s: genus %d, %d boundary loops, %d components (bunny: 0, 5, 1)"
                           % (name, q["genus"], q["boundary_loops"], q["components"]))
        for key in ("q_avg", "theta_min", "v6_pct"):
            if not fcvt[key] > iso[key]:
                bad.append("FCVT's %s %.4g is not above MeshLab's %.4g" % (key, fcvt[key], iso[key]))
        if bad:
            fail("; ".join(bad))
        print("PASS")
    elif len(sys.argv) >= 2:
        here = os.path.dirname(os.path.abspath(__file__))
        mesh = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "..", "..", "resources", "bunny.ply")
        print_table(compare(sys.argv[1], mesh, float(sys.argv[3]) if len(sys.argv) > 3 else 1.0))
    else:
        sys.exit("usage: compare_isotropic.py PLUGIN [MESH [TARGET_PERCENT]]")
