"""pymeshlab_bad_parameter: a bad parameter raises pymeshlab.PyMeshLabException with the filter's
own message (the MLException the glue throws, which pymeshlab reports after "Details: "), and
the MeshSet is left as it was: a vertex count of 2, a negative seed (remeshing), 0 crosses (field),
a reference layer without faces (quality report). Then a good run still works."""
import sys

import numpy as np

from pml_common import FIELD, REMESH, REPORT, Test, fail

t = Test(sys.argv, needs_cli=False)
pymeshlab = t.pymeshlab
ms = t.meshset()
ms.load_new_mesh(t.resource("torus.ply"))
before = ms.current_mesh().vertex_matrix().copy()
bad = []


def expect_failure(what, message, filter_name, **params):
    try:
        figures = ms.apply_filter(filter_name, **params)
    except pymeshlab.PyMeshLabException as e:
        text = str(e)
        print("%s: %s" % (what, text.replace("\n", " | ")))
        if message not in text:
            bad.append("%s: the exception says %r, not %r" % (what, text, message))
    else:
        bad.append("%s: no exception (dict %r)" % (what, figures))
    if ms.mesh_number() != layers or not np.array_equal(ms.mesh(0).vertex_matrix(), before):
        bad.append("%s: the MeshSet changed (%d layers)" % (what, ms.mesh_number()))


layers = 1
expect_failure("vertexcount=2", "FCVT: 'Target vertices' (vertexCount) must be between 4 and 5000000, got 2",
               REMESH, vertexcount=2)
expect_failure("seed=-1", "(seed) must be 0 or more (got -1)", REMESH, vertexcount=300, seed=-1)
expect_failure("maxcrosses=0", "(maxCrosses) must be at least 1 (got 0)", FIELD, maxcrosses=0)
# A layer of points only (no faces) as the quality report's reference.
ms.add_mesh(pymeshlab.Mesh(vertex_matrix=np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]])), "points")
ms.set_current_mesh(0)
layers = 2
expect_failure("referencelayer without faces", "has no faces; choose a triangle mesh", REPORT, referencelayer=1)

figures = ms.apply_filter(REMESH, vertexcount=300, seed=1)
if ms.mesh_number() != 3 or not (250 <= figures.get("vertices", 0) <= 350):
    bad.append("a good run after the failures: %d layers, dict %r" % (ms.mesh_number(), figures))
if bad:
    fail("; ".join(bad))
print("PASS")
