"""fcvt remesh --texture keep keeps the input's texture atlas (issue 36): per-corner texture coordinates on the
output OBJ (one finite vt per corner, `f v/vt`), no face stretched across the atlas, the copied
material library and its image resolving from the output's folder, the chart count and the share
of seam-crossing faces in the report, MeshLab's PLY texcoord / TextureFile, --no-texture; and an
atlas of one chart per triangle (sub.obj, when given) handled and reported. The default
(--texture auto) and the baked texture: check_texture_render.py.
Usage: check_texture.py FCVT TEXTURED_OBJ CHARTS VERTICES WORK_DIR [ONE_CHART_PER_FACE_OBJ]"""
import json
import math
import os
import shutil
import sys

from fcvt_check import check, finish, read_obj, run

fcvt, textured, charts, vertices, work = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4], sys.argv[5]
per_face = sys.argv[6] if len(sys.argv) > 6 else None
shutil.rmtree(work, ignore_errors=True)  # a rerun's OUT.mtl and images would be numbered
os.makedirs(work)


def stretch(v, vt, face):
    """UV perimeter / 3D perimeter of a face: large when its corners are in distant charts."""
    uv = [vt[c[1]] for c in face]
    p = [v[c[0]] for c in face]
    return sum(math.dist(uv[k], uv[(k + 1) % 3]) for k in range(3)) / max(sum(math.dist(p[k], p[(k + 1) % 3]) for k in range(3)), 1e-300)


def remesh(inp, out, *extra):
    report = out + ".json"
    code, _, err = run([fcvt, "remesh", inp, out, "--vertices", vertices, "--seed", "1", "--report", report, "--texture", "keep",
                        *extra])
    check(code == 0, f"remesh {os.path.basename(inp)} -> {os.path.basename(out)} exit {code}: {err.strip()[-400:]}")
    return json.load(open(report)) if code == 0 else {}, err


iv, ivt, ifaces, ilibs, _ = read_obj(textured)
input_stretch = sorted(stretch(iv, ivt, f) for f in ifaces)
out_dir = os.path.join(work, "elsewhere")  # another folder than the input's: the .mtl must be copied
os.makedirs(out_dir, exist_ok=True)
out = os.path.join(out_dir, "out.obj")
report, err = remesh(textured, out)
ov, ovt, ofaces, olibs, ousemtl = read_obj(out)
check(len(ofaces) > 0 and len(ovt) == 3 * len(ofaces), f"{len(ovt)} vt for {len(ofaces)} faces (one per corner expected)")
check(all(c[1] is not None for f in ofaces for c in f), "every corner has a vt")
check(len({c[1] for f in ofaces for c in f}) == 3 * len(ofaces), "each corner its own vt")
check(all(math.isfinite(x) for t in ovt for x in t), "all vt finite")
out_stretch = sorted(stretch(ov, ovt, f) for f in ofaces)
bound = 2 * input_stretch[-1]
worst = out_stretch[-1]
print(f"stretch (UV / 3D perimeter): input median {input_stretch[len(input_stretch) // 2]:.4g} max {input_stretch[-1]:.4g}; "
      f"output median {out_stretch[len(out_stretch) // 2]:.4g} max {worst:.4g}")
check(worst <= bound, f"an output face spans the atlas: stretch {worst:.4g} > 2 x the input's largest {input_stretch[-1]:.4g}")


def closest_on_triangle(p, a, b, c):
    """(squared distance, barycentric) of p's closest point on triangle abc (Ericson's regions)."""
    sub = lambda u, v: (u[0] - v[0], u[1] - v[1], u[2] - v[2])
    dot = lambda u, v: u[0] * v[0] + u[1] * v[1] + u[2] * v[2]
    ab, ac, ap = sub(b, a), sub(c, a), sub(p, a)
    d1, d2 = dot(ab, ap), dot(ac, ap)
    if d1 <= 0 and d2 <= 0:
        w = (1, 0, 0)
    else:
        bp = sub(p, b); d3, d4 = dot(ab, bp), dot(ac, bp)
        cp = sub(p, c); d5, d6 = dot(ab, cp), dot(ac, cp)
        vc, vb, va = d1 * d4 - d3 * d2, d5 * d2 - d1 * d6, d3 * d6 - d5 * d4
        if d3 >= 0 and d4 <= d3:
            w = (0, 1, 0)
        elif d6 >= 0 and d5 <= d6:
            w = (0, 0, 1)
        elif vc <= 0 and d1 >= 0 and d3 <= 0:
            t = d1 / (d1 - d3); w = (1 - t, t, 0)
        elif vb <= 0 and d2 >= 0 and d6 <= 0:
            t = d2 / (d2 - d6); w = (1 - t, 0, t)
        elif va <= 0 and d4 - d3 >= 0 and d5 - d6 >= 0:
            t = (d4 - d3) / ((d4 - d3) + (d5 - d6)); w = (0, 1 - t, t)
        else:
            den = va + vb + vc
            w = (va / den, vb / den, vc / den)
    q = tuple(w[0] * a[k] + w[1] * b[k] + w[2] * c[k] for k in range(3))
    return dot(sub(p, q), sub(p, q)), w


def input_uv_at(points):
    """The input's interpolated coordinates at each point (closest input face, through a grid)."""
    cell = 2 * max(max(math.dist(iv[f[k][0]], iv[f[(k + 1) % 3][0]]) for k in range(3)) for f in ifaces)
    grid = {}
    for n, f in enumerate(ifaces):
        lo = [min(iv[c[0]][k] for c in f) for k in range(3)]
        hi = [max(iv[c[0]][k] for c in f) for k in range(3)]
        for i in range(int(lo[0] // cell), int(hi[0] // cell) + 1):
            for j in range(int(lo[1] // cell), int(hi[1] // cell) + 1):
                for k in range(int(lo[2] // cell), int(hi[2] // cell) + 1):
                    grid.setdefault((i, j, k), []).append(n)
    result = []
    for p in points:
        key = tuple(int(p[k] // cell) for k in range(3))
        best = None
        for n in grid.get(key, []):
            f = ifaces[n]
            d, w = closest_on_triangle(p, *(iv[c[0]] for c in f))
            if best is None or d < best[0]:
                best = (d, tuple(sum(w[k] * ivt[f[k][1]][m] for k in range(3)) for m in range(2)))
        result.append(best[1] if best else None)
    return result


# Independently of fcvt: the corners not continued across a seam have the input's coordinates at
# their position, so the faces with a corner that has not are at most the continued ones.
expected = input_uv_at(ov)
off_faces = sum(1 for f in ofaces
                if any(expected[c[0]] is None or math.dist(expected[c[0]], ovt[c[1]]) > 1e-5 for c in f))
tex = report.get("texture", {})
continued = tex.get("continued_faces", -1)
print(f"faces with a corner off the input's coordinates at its position: {off_faces}; continued: {continued}")
check(off_faces <= 1.02 * continued + 5, f"{off_faces} faces have corners off the input's map, {continued} continued")
check(tex.get("kept") is True and tex.get("charts") == charts, f"report texture {tex}, expected {charts} charts")
share = tex.get("continued_share", -1)
check(0 <= share < 0.5, f"seam-crossing share {share}")
print(f"{os.path.basename(textured)} at {vertices} vertices: {tex.get('charts')} charts, "
      f"{100 * share:.2f} % of output faces continued across a seam")
check("across a seam, continued there" in err, "the seam figure is printed")
# The material library was copied next to the output, and its image resolves from there.
check(len(olibs) == len(ilibs) and all(os.path.isfile(os.path.join(out_dir, lib)) for lib in olibs), f"mtllib {olibs}")
images = []
for lib in olibs:
    for line in open(os.path.join(out_dir, lib)):
        if line.split()[:1] == ["map_Kd"]:
            images.append(line.split()[-1])
check(images and all(os.path.isfile(os.path.join(out_dir, i)) for i in images), f"images {images} resolve from {out_dir}")
check(ousemtl >= 1, "usemtl written")

# The same bytes on 1 and 3 threads.
remesh(textured, os.path.join(out_dir, "threads1.obj"), "--threads", "1")
remesh(textured, os.path.join(out_dir, "threads3.obj"), "--threads", "3")
def without_mtllib(name):
    """An OBJ output's bytes but its mtllib line (each output names its own library), and that library's."""
    obj = open(os.path.join(out_dir, name + ".obj"), "rb").read()
    body = b"".join(line for line in obj.splitlines(True) if not line.startswith(b"mtllib "))
    return body, open(os.path.join(out_dir, name + ".mtl"), "rb").read()


check(without_mtllib("threads1") == without_mtllib("threads3"), "same output on 1 and 3 threads")

# PLY: MeshLab's texcoord face list and the TextureFile comment, resolving as well.
ply = os.path.join(out_dir, "out.ply")
remesh(textured, ply)
header = open(ply, "rb").read().split(b"end_header")[0].decode()
check("property list uchar float texcoord" in header, "PLY texcoord list")
files = [line.split(" ", 2)[2] for line in header.splitlines() if line.startswith("comment TextureFile ")]
check(files and all(os.path.isfile(os.path.join(out_dir, f)) for f in files), f"TextureFile {files}")

# --no-texture: no texture coordinates, nothing copied.
plain = os.path.join(work, "plain.obj")
plain_report, _ = remesh(textured, plain, "--no-texture")
check(plain_report.get("texture", {}).get("kept") is False, f"--no-texture report {plain_report.get('texture')}")
pv, pvt, pfaces, plibs, _ = read_obj(plain)
check(not pvt and not plibs and len(pfaces) == len(ofaces), "--no-texture drops the texture, same faces")
check([c[0] for f in pfaces for c in f] == [c[0] for f in ofaces for c in f], "--no-texture: same triangles")

# Broken coordinates: dropped with a warning, the mesh remeshed. A missing .mtl or image: a
# warning, the coordinates kept (the image is never needed).
lines = open(textured).read().splitlines(True)
first_vt = next(i for i, line in enumerate(lines) if line.startswith("vt"))
broken_dir = os.path.join(work, "broken")
os.makedirs(broken_dir, exist_ok=True)
broken = os.path.join(broken_dir, "nan.obj")
open(broken, "w").write("".join(lines[:first_vt] + ["vt nan 0.5\n"] + lines[first_vt + 1:]))
_, err = remesh(broken, os.path.join(work, "nan_out.obj"))
_, nvt, nfaces, nlibs, _ = read_obj(os.path.join(work, "nan_out.obj"))
check("texture coordinates dropped" in err and not nvt and len(nfaces) > 0, f"NaN vt: dropped with a warning ({err.strip()[-300:]})")
alone = os.path.join(broken_dir, "alone.obj")  # no .mtl, no image next to it
open(alone, "w").write("".join(lines))
_, err = remesh(alone, os.path.join(work, "alone_out.obj"))
_, avt, afaces, _, _ = read_obj(os.path.join(work, "alone_out.obj"))
check("cannot be read" in err and len(avt) == 3 * len(afaces), f"missing .mtl: a warning, coordinates kept ({err.strip()[-300:]})")

if per_face:
    # One chart per triangle: every output face crosses seams; the atlas is kept, the share reported.
    sub_out = os.path.join(work, "sub.obj")
    sub_report, _ = remesh(per_face, sub_out)
    sv, svt, sfaces, _, _ = read_obj(sub_out)
    st = sub_report.get("texture", {})
    check(len(svt) == 3 * len(sfaces) and all(math.isfinite(x) for t in svt for x in t), "sub: one finite vt per corner")
    check(st.get("kept") is True and st.get("charts", 0) > 1000, f"sub report {st}")
    print(f"{os.path.basename(per_face)} at {vertices} vertices: {st.get('charts')} charts, "
          f"{100 * st.get('continued_share', -1):.2f} % of output faces continued across a seam")
finish()
