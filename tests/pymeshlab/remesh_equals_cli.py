"""pymeshlab_remesh_equals_cli: "Remeshing: Field-Aligned CVT (FCVT)" through pymeshlab gives the
CLI's mesh and returns the top level of the CLI's --report as apply_filter's dict.
resources/bunny.ply (double coordinates; pymeshlab is double precision) at 5000 vertices, seed 1:
the same vertex and face counts, the same faces, the vertices within 1e-6 of the bounding-box
diagonal (in effect bit for bit: both are this machine's GCC on the same doubles), and the dict's
vertices, faces, evaluations, FCVT iterations, optimisation faces, mean edge length, stage times
and number of warnings those of `fcvt remesh --report`; resources/necked_ring.obj at 150 vertices
with exactcount: the CLI's vertex count and its number of warnings (2)."""
import sys

import numpy as np

from pml_common import REMESH, Test, compare_figures, fail, points, read_ply

t = Test(sys.argv)
bunny = t.resource("bunny.ply")
ms = t.meshset()
ms.load_new_mesh(bunny)
figures = ms.apply_filter(REMESH, vertexcount=5000, seed=1)
print("pymeshlab's dict:", figures)
if ms.mesh_number() != 2 or ms.current_mesh().label() != "bunny_FCVT":
    fail("expected the new layer bunny_FCVT as the current one, got %d layers, current %r"
         % (ms.mesh_number(), ms.current_mesh().label()))
mesh = ms.current_mesh()
v_filter, f_filter = mesh.vertex_matrix(), mesh.face_matrix()

cli_out, report = t.cli_remesh(bunny, "bunny-cli.ply", "--vertices", "5000", "--seed", "1")
vertices, f_cli = read_ply(cli_out)
v_cli = points(vertices)
print("filter: %d vertices, %d faces; CLI: %d vertices, %d faces" % (len(v_filter), len(f_filter), len(v_cli), len(f_cli)))
if v_filter.shape != v_cli.shape or f_filter.shape != f_cli.shape:
    fail("the filter's mesh has %d vertices, %d faces; the CLI's %d, %d"
         % (len(v_filter), len(f_filter), len(v_cli), len(f_cli)))
if not np.array_equal(f_filter, f_cli):
    fail("the faces differ (%d of %d)" % (int(np.any(f_filter != f_cli, axis=1).sum()), len(f_cli)))
diagonal = float(np.linalg.norm(v_cli.max(axis=0) - v_cli.min(axis=0)))
gap = float(np.abs(v_filter - v_cli).max())
print("largest coordinate difference: %.3g (%.3g of the diagonal)" % (gap, gap / diagonal))
if gap > 1e-6 * diagonal:
    fail("the vertices differ by up to %.3g of the diagonal" % (gap / diagonal))

bad = compare_figures("dict", figures, report,
                      ("vertices", "faces", "evaluations", "fcvt_iterations", "optimisation_faces"), 0)
bad += compare_figures("dict", figures, report, ("mean_edge_length",), 1e-6)
stages = [s for s in report["time_s"] if s not in ("read", "write")]
missing = [s for s in stages + ["total"] if not isinstance(figures.get("time_s_" + s), float)]
if missing:
    bad.append("no stage times time_s_%s in the dict (the CLI's: %s)" % (", time_s_".join(missing), ", ".join(stages)))
extra = sorted(k for k in figures if k.startswith("time_s_") and k[7:] not in stages + ["total"])
if extra:
    bad.append("stage times the CLI has not: %s" % ", ".join(extra))
if not (isinstance(figures.get("threads_used"), int) and figures["threads_used"] >= 1):
    bad.append("threads_used %r" % figures.get("threads_used"))
# The number of warnings (pymeshlab's dict holds no text): none on bunny, as the CLI's.
if figures.get("warnings") != len(report["warnings"]):
    bad.append("warnings: filter %r, the CLI's %r" % (figures.get("warnings"), report["warnings"]))
for key in ("vertices", "faces", "evaluations", "mean_edge_length", "time_s_total"):
    print("%-18s filter %-14s CLI %s" % (key, figures.get(key), report.get(key, report["time_s"]["total"])))
# A run with warnings: necked_ring.obj at 150 vertices with exactcount loses the handle, and
# both say so (and that one sample is in no triangle).
ring = t.resource("necked_ring.obj")
ms.load_new_mesh(ring)
ring_figures = ms.apply_filter(REMESH, vertexcount=150, seed=1, exactcount=True)
_, ring_report = t.cli_remesh(ring, "necked_ring-cli.ply", "--vertices", "150", "--seed", "1", "--exact-count")
print("necked_ring: filter %r vertices, %r warnings; CLI %d vertices, warnings %r"
      % (ring_figures.get("vertices"), ring_figures.get("warnings"), ring_report["vertices"], ring_report["warnings"]))
if not ring_report["warnings"] or ring_figures.get("warnings") != len(ring_report["warnings"]):
    bad.append("necked_ring: %r warnings, the CLI's %r" % (ring_figures.get("warnings"), ring_report["warnings"]))
if ring_figures.get("vertices") != ring_report["vertices"]:
    bad.append("necked_ring: %r vertices, the CLI's %d" % (ring_figures.get("vertices"), ring_report["vertices"]))
if bad:
    fail("; ".join(bad))
print("PASS")
