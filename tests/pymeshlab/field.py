"""pymeshlab_field: "Compute 6-RoSy Field" through pymeshlab gives `fcvt field`'s field.
resources/bunny.ply (1113 of its vertices on no face): the dict's singularity count and index sum
are those `fcvt field` prints; the layer's per-vertex attribute rosy (pymeshlab's
vertex_custom_point_attribute_matrix) is (0,0,0) on the 1113 vertices on no face and, on the
others in order, the CLI's rosy_x/y/z (written as floats: to 1e-6), at the CLI's vertices; the
layer's geometry is unchanged and the drawing layer "6-RoSy field" is added; the quality report on
the layer counts the field's singularities as the CLI does (from rosy, projected again)."""
import re
import sys

import numpy as np

from pml_common import FIELD, REPORT, Test, fail, points, read_ply

t = Test(sys.argv)
bunny = t.resource("bunny.ply")
ms = t.meshset()
ms.load_new_mesh(bunny)
before = ms.current_mesh().vertex_matrix().copy()
figures = ms.apply_filter(FIELD, seed=1)
print("pymeshlab's dict:", figures)
bad = []
if ms.mesh_number() != 2:
    bad.append("%d layers, expected the input and the drawing" % ms.mesh_number())
layer = ms.mesh(0)
if not np.array_equal(layer.vertex_matrix(), before):
    bad.append("the input layer's vertices changed")
rosy = layer.vertex_custom_point_attribute_matrix("rosy")

out = t.path("bunny-field.ply")
printed = t.run_cli("field", bunny, out, "--seed", "1")
count = int(re.search(r"^singularities: (\d+)$", printed, re.M).group(1))
index_sum = int(re.search(r"^index sum: (-?\d+)$", printed, re.M).group(1))
print("CLI: %d singularities, index sum %d" % (count, index_sum))
if figures.get("singularities") != count or figures.get("index_sum") != index_sum:
    bad.append("dict %r / %r singularities / index sum, the CLI's %d / %d"
               % (figures.get("singularities"), figures.get("index_sum"), count, index_sum))

vertices, _ = read_ply(out)
cli_rosy = points(vertices, "rosy_")
used = np.any(rosy != 0, axis=1)
print("rosy: %d vertices, %d (0,0,0); the CLI's field: %d vertices" % (len(rosy), int((~used).sum()), len(cli_rosy)))
if int((~used).sum()) != 1113 or int(used.sum()) != len(cli_rosy):
    bad.append("rosy on %d vertices, (0,0,0) on %d; the CLI's field has %d" % (int(used.sum()), int((~used).sum()), len(cli_rosy)))
else:
    gap = float(np.abs(rosy[used] - cli_rosy).max())
    print("largest rosy difference: %.3g" % gap)
    if gap > 1e-6:
        bad.append("rosy differs from the CLI's by up to %.3g" % gap)
    if float(np.abs(before[used] - points(vertices)).max()) > 1e-12:
        bad.append("the CLI's field is not on the layer's vertices")
# The quality report counts the singularities of the layer's field rosy: the same.
ms.set_current_mesh(0)
report = ms.apply_filter(REPORT, colorirregular=False)
print("the report on the layer: %r singularities, index sum %r" % (report.get("singularities"), report.get("index_sum")))
if report.get("singularities") != count or report.get("index_sum") != index_sum:
    bad.append("the report counts %r / %r singularities / index sum on the layer's rosy, the CLI %d / %d"
               % (report.get("singularities"), report.get("index_sum"), count, index_sum))
if figures.get("field_vertices") != len(cli_rosy):
    bad.append("field_vertices %r, the CLI's %d" % (figures.get("field_vertices"), len(cli_rosy)))
if bad:
    fail("; ".join(bad))
print("PASS")
