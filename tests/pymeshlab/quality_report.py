"""pymeshlab_quality_report: "Remeshing Quality Report (FCVT)" returns its figures as apply_filter's
dict, by the keys of `fcvt metrics --json` and of the CLI report's "metrics" and "output".
1. The CLI's remeshed bunny loaded into pymeshlab, measured against bunny.ply (reference layer 0):
   the Table 2 figures equal `fcvt metrics OUT --ref bunny.ply` (the same code on the same
   doubles: to 1e-9), d_RMS and d_H within 3 % (each samples its own random points), the topology
   (genus, boundary loops, components, manifold, orientable) that of the CLI report's output;
2. no reference (the default, the layer itself): no distances in the dict;
3. the torus remeshed by the filter carries its field (the attribute rosy): the dict counts its
   singularities, whose index sum is 6 chi = 0 on the closed torus; a layer without rosy has no
   singularities key."""
import sys

from pml_common import REMESH, REPORT, Test, compare_figures, fail

TABLE2 = ("q_min", "q_avg", "theta_min", "theta_min_avg", "theta_max", "pct_lt30", "pct_gt90", "v6_pct",
          "boundary_v4_pct")
TOPOLOGY = ("genus", "boundary_loops", "components", "manifold", "orientable")

t = Test(sys.argv)
bunny = t.resource("bunny.ply")
cli_out, report = t.cli_remesh(bunny, "bunny-cli.ply", "--vertices", "5000", "--seed", "1")
expected = t.cli_metrics(cli_out, bunny)

ms = t.meshset()
ms.load_new_mesh(bunny)     # id 0
ms.load_new_mesh(cli_out)   # id 1, current
figures = ms.apply_filter(REPORT, referencelayer=0, colorirregular=False)
print("pymeshlab's dict:", figures)
bad = compare_figures("report", figures, expected, TABLE2, 1e-9)
bad += compare_figures("report", figures, expected, ("d_rms", "d_h"), 0.03)
bad += compare_figures("report", figures, report["output"], TOPOLOGY, 0)
bad += compare_figures("report", figures, expected, TOPOLOGY, 0)
if figures.get("vertices") != report["vertices"] or figures.get("faces") != report["faces"]:
    bad.append("counts %r / %r, the CLI's %r / %r" % (figures.get("vertices"), figures.get("faces"),
                                                      report["vertices"], report["faces"]))
for key in ("q_avg", "theta_min", "v6_pct", "d_rms", "d_h", "genus", "boundary_loops"):
    print("%-15s report %-22r fcvt metrics %r" % (key, figures.get(key), expected.get(key)))
if "singularities" in figures:
    bad.append("singularities counted on a layer without the attribute rosy")

ms.set_current_mesh(0)
alone = ms.apply_filter(REPORT, colorirregular=False)
if any(k in alone for k in ("d_rms", "d_h", "d_boundary")):
    bad.append("distances without a reference: %r" % alone)
if alone.get("vertices") is None or alone.get("components") is None:
    bad.append("no figures for bunny.ply itself: %r" % alone)

torus = t.meshset()
torus.load_new_mesh(t.resource("torus.ply"))
torus.apply_filter(REMESH, vertexcount=600, seed=1)
own = torus.apply_filter(REPORT, referencelayer=0)
print("torus remeshed, its report:", own)
if own.get("genus") != 1 or own.get("boundary_loops") != 0:
    bad.append("torus topology %r" % own)
if not isinstance(own.get("singularities"), int) or own.get("index_sum") != 0:
    bad.append("the remeshed torus's field: singularities %r, index sum %r (6 chi = 0)"
               % (own.get("singularities"), own.get("index_sum")))
if bad:
    fail("; ".join(bad))
print("PASS")
