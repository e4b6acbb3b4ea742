"""`fcvt field` works on the normalised surface, as remesh does (issue 14, items 1-2): a UV sphere
scaled by 1e-300 .. 1e300 gets the unit sphere's singularities (index sum 12 = 6 chi) and exits
well within the subprocess timeout (before: 958 singularities at 1e100, no exit in 200 s at
1e155 and beyond). `fcvt remesh` takes the same files (item 3: it said "the surface has no area"
at 1e100). Usage: check_field_scale.py FCVT WORK_DIR"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "robustness"))
import meshgen  # noqa: E402
from fcvt_check import check, finish, run  # noqa: E402

fcvt, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
sphere = meshgen.uv_sphere()


def field(scale):
    path = os.path.join(work, "uv-%g.ply" % scale)
    with open(path, "wb") as fh:
        fh.write(meshgen.ply_bytes(meshgen.transform(sphere, scale)))
    code, stdout, stderr = run([fcvt, "field", path, os.path.join(work, "field-%g.ply" % scale)], timeout=120)
    check(code == 0, "field at scale %g: exit %s, stderr %r" % (scale, code, stderr))
    counts = {key: re.search(r"^%s: (-?\d+)" % key, stdout, re.MULTILINE) for key in ("singularities", "index sum")}
    check(all(counts.values()), "field at scale %g: no singularity lines in %r" % (scale, stdout))
    return path, tuple(int(m.group(1)) if m else None for m in counts.values())


_, unit = field(1.0)
check(unit[1] == 12, "unit sphere: index sum %s, expected 12" % unit[1])
for scale in (1e-300, 1e-170, 1e-100, 1e100, 1e155, 1e160, 1e300):
    path, got = field(scale)
    print("scale %g: %d singularities, index sum %d" % ((scale,) + got))
    check(got == unit, "field at scale %g: (singularities, index sum) %s, the unit sphere has %s" % (scale, got, unit))
    code, _, stderr = run([fcvt, "remesh", path, os.path.join(work, "remesh-%g.obj" % scale), "--vertices", "100",
                           "--cvt-iterations", "5", "--fcvt-iterations", "5", "--quiet"], timeout=120)
    check(code == 0 and stderr == "", "remesh at scale %g: exit %s, stderr %r" % (scale, code, stderr))
finish()
