"""The remeshed model rendered with its texture looks like the input (issue 36, items 1 and 3):
fcvt remesh with the default --texture auto, then fcvt texture-compare (6 unlit views, 512 px) on
bunny10k_textured (190 charts of a labelled pattern) and sub.obj (one chart per triangle) at 2000
and 5000 vertices. Both atlases have small charts against these faces, so auto bakes a new
image (OUT_texture.png, named by the .mtl and by a PLY's TextureFile); the render's difference
must stay within 2 times the half-pixel yardstick (the issue's goal; measured 0.3-1.45, see
docs/measurements.md), and below what keeping the atlas gives where that is worse. A generated torus with one chart of a checkerboard (cut open
along two circles: a chart that meets itself) keeps its atlas by default, within the same bar.
With --region (a textured PLY whose face quality marks the
faces to remesh) the kept faces keep their coordinates exactly and the new ones get a baked image
as a second texture. A missing image falls back to the kept atlas with a warning; an unknown
--texture mode is a usage error.
Usage: check_texture_render.py FCVT TEXTURED_DIR WORK_DIR"""
import json
import os
import shutil
import sys

from fcvt_check import check, finish, read_obj, run

fcvt, textured, work = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)  # a rerun's OUT.mtl and images would be numbered
os.makedirs(work)
# (mesh, vertices, largest ratio allowed)
CASES = [("bunny10k_textured.obj", 2000, 2.0), ("bunny10k_textured.obj", 5000, 2.0),
         ("sub.obj", 2000, 2.0), ("sub.obj", 5000, 2.0)]


def remesh(inp, out, vertices, *extra):
    report = out + ".json"
    code, _, err = run([fcvt, "remesh", inp, out, "--vertices", str(vertices), "--seed", "1", "--quiet", "--report", report,
                        *extra])
    check(code == 0, f"remesh {os.path.basename(inp)} exit {code}: {err.strip()[-300:]}")
    return (json.load(open(report)) if code == 0 else {}), err


def compare(inp, out):
    code, text, err = run([fcvt, "texture-compare", inp, out, "--json"])
    check(code == 0, f"texture-compare {os.path.basename(out)} exit {code}: {err.strip()[-300:]}")
    return json.loads(text) if code == 0 else {"ratio": float("inf"), "difference": float("inf"), "half_pixel": 0, "seam_faces": 0}


for name, vertices, bar in CASES:
    inp = os.path.join(textured, name)
    stem = f"{os.path.splitext(name)[0]}-{vertices}"
    out = os.path.join(work, stem + ".obj")
    report, _ = remesh(inp, out, vertices)
    tex = report.get("texture", {})
    check(tex.get("mode") == "bake" and tex.get("continued_share", 0) > 0.1, f"{stem}: auto should bake ({tex})")
    image = os.path.join(work, stem + "_texture.png")
    check(os.path.isfile(image) and tex.get("baked_image") == image, f"{stem}: baked image {tex.get('baked_image')}")
    mtl = os.path.join(work, stem + ".mtl")
    check(os.path.isfile(mtl) and f"map_Kd {stem}_texture.png" in open(mtl).read(), f"{stem}: the .mtl names the baked image")
    r = compare(inp, out)
    print(f"{stem}: difference {r['difference']:.3f}, half-pixel {r['half_pixel']:.3f}, ratio {r['ratio']:.2f} "
          f"(bar {bar}), faces across a seam of the input's atlas {100 * r['seam_faces']:.1f} %")
    check(r["ratio"] <= bar, f"{stem}: render difference {r['ratio']:.2f} x the half-pixel yardstick > {bar}")
    if name.startswith("bunny") and vertices == 5000:
        kept = os.path.join(work, stem + "-keep.obj")
        remesh(inp, kept, vertices, "--texture", "keep")
        k = compare(inp, kept)
        print(f"{stem} --texture keep: ratio {k['ratio']:.2f}")
        check(k["ratio"] > r["ratio"], f"{stem}: keeping the atlas ({k['ratio']:.2f}) should be worse than baking ({r['ratio']:.2f})")
        # A PLY output names the baked image in its TextureFile comment. The OBJ run's image has
        # the same name: --overwrite lets this run replace it (without, it would be numbered).
        ply = os.path.join(work, stem + ".ply")
        remesh(inp, ply, vertices, "--overwrite")
        header = open(ply, "rb").read().split(b"end_header")[0].decode()
        check(f"comment TextureFile {stem}_texture.png" in header and "texcoord" in header, f"{stem}.ply: TextureFile, texcoord")

# A torus in one chart (uv = its two angles; the chart meets itself along the cut circles): few
# faces cross its seams, so the atlas is kept, and the faces across them are continued.
def write_png(path, width, height, pixel):
    import struct
    import zlib
    raw = b"".join(b"\x00" + b"".join(bytes(pixel(x, y)) for x in range(width)) for y in range(height))
    chunk = lambda tag, data: (struct.pack(">I", len(data)) + tag + data +
                               struct.pack(">I", zlib.crc32(tag + data) & 0xffffffff))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


import math  # noqa: E402
torus_dir = os.path.join(work, "torus")
os.makedirs(torus_dir, exist_ok=True)
n, m = 96, 48
with open(os.path.join(torus_dir, "torus.obj"), "w") as f:
    f.write("mtllib torus.mtl\nusemtl checker\n")
    for i in range(n):
        for j in range(m):
            a, b = 2 * math.pi * i / n, 2 * math.pi * j / m
            f.write("v %r %r %r\n" % ((1 + 0.4 * math.cos(b)) * math.cos(a), 0.4 * math.sin(b), (1 + 0.4 * math.cos(b)) * math.sin(a)))
    for i in range(n + 1):
        for j in range(m + 1):
            f.write("vt %r %r\n" % (i / n, j / m))
    vi = lambda i, j: (i % n) * m + (j % m) + 1
    ti = lambda i, j: i * (m + 1) + j + 1
    for i in range(n):
        for j in range(m):
            f.write(f"f {vi(i, j)}/{ti(i, j)} {vi(i + 1, j)}/{ti(i + 1, j)} {vi(i + 1, j + 1)}/{ti(i + 1, j + 1)}\n")
            f.write(f"f {vi(i, j)}/{ti(i, j)} {vi(i + 1, j + 1)}/{ti(i + 1, j + 1)} {vi(i, j + 1)}/{ti(i, j + 1)}\n")
open(os.path.join(torus_dir, "torus.mtl"), "w").write("newmtl checker\nKd 1 1 1\nmap_Kd checker.png\n")
write_png(os.path.join(torus_dir, "checker.png"), 256, 256,
          lambda x, y: (220, 60, 40) if (x // 16 + y // 16) % 2 else (40, 90, 200))
for count in (1000, 3000):
    out = os.path.join(torus_dir, f"torus-{count}.obj")
    report, _ = remesh(os.path.join(torus_dir, "torus.obj"), out, count)
    tex = report.get("texture", {})
    r = compare(os.path.join(torus_dir, "torus.obj"), out)
    print(f"torus-{count}: {tex.get('mode')}, {tex.get('charts')} chart, {100 * tex.get('continued_share', -1):.1f} % of the "
          f"faces across a seam, ratio {r['ratio']:.2f}")
    check(tex.get("mode") == "keep_atlas" and tex.get("charts") == 1 and 0 < tex.get("continued_share", 0) < 0.1,
          f"torus-{count}: the atlas kept, the faces across its seams continued ({tex})")
    check(r["ratio"] <= 2.0, f"torus-{count}: render difference {r['ratio']:.2f} x the yardstick > 2")

# --region on a textured PLY: the faces above the bunny's middle (y) remeshed, the rest kept.
def read_ascii_ply_texture(path):
    """(vertices, [(corners, uv per corner, texnumber)], TextureFile names) of fcvt's PLY (binary little endian)."""
    import struct
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    files = [line.split(" ", 2)[2] for line in header if line.startswith("comment TextureFile ")]
    nv = int(next(line.split()[2] for line in header if line.startswith("element vertex")))
    nf = int(next(line.split()[2] for line in header if line.startswith("element face")))
    vprops = []
    fprops = []
    current = None
    for line in header:
        w = line.split()
        if w[:1] == ["element"]:
            current = w[1]
        elif w[:1] == ["property"]:
            (vprops if current == "vertex" else fprops).append(w[1:])
    codes = {"double": "d", "float": "f", "int": "i", "uchar": "B", "uint": "I"}
    vfmt = "<" + "".join(codes[p[0]] for p in vprops)
    size = struct.calcsize(vfmt)
    pos = end
    verts = []
    for _ in range(nv):
        verts.append(struct.unpack_from(vfmt, data, pos)[:3])
        pos += size
    faces = []
    for _ in range(nf):
        corners, uv, tex = None, None, 0
        for p in fprops:
            if p[0] == "list":
                n = struct.unpack_from("<B", data, pos)[0]
                pos += 1
                item = codes[p[2]]
                values = struct.unpack_from("<" + item * n, data, pos)
                pos += struct.calcsize(item) * n
                if p[-1] == "vertex_indices":
                    corners = values
                else:
                    uv = [(values[2 * k], values[2 * k + 1]) for k in range(n // 2)]
            else:
                value = struct.unpack_from("<" + codes[p[0]], data, pos)[0]
                pos += struct.calcsize(codes[p[0]])
                if p[-1] == "texnumber":
                    tex = value
        faces.append((corners, uv, tex))
    return verts, faces, files


bunny = os.path.join(textured, "bunny10k_textured.obj")
bv, bvt, bfaces, _, _ = read_obj(bunny)
middle = sorted(p[1] for p in bv)[len(bv) // 2]
region_dir = os.path.join(work, "region")
os.makedirs(region_dir, exist_ok=True)
shutil.copy(os.path.join(textured, "TextureDouble_A.png"), region_dir)
marked = os.path.join(region_dir, "marked.ply")
with open(marked, "w") as f:
    f.write("ply\nformat ascii 1.0\ncomment TextureFile TextureDouble_A.png\n")
    f.write(f"element vertex {len(bv)}\nproperty double x\nproperty double y\nproperty double z\n")
    f.write(f"element face {len(bfaces)}\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\n")
    f.write("property float quality\nend_header\n")
    for p in bv:
        f.write("%r %r %r\n" % p)
    for face in bfaces:
        selected = sum(bv[c[0]][1] for c in face) / 3 > middle
        uv = " ".join("%r %r" % bvt[c[1]] for c in face)
        f.write(f"3 {face[0][0]} {face[1][0]} {face[2][0]} 6 {uv} {1 if selected else 0}\n")
region_out = os.path.join(region_dir, "out.ply")
report, err = remesh(marked, region_out, 2500, "--region", "quality")
tex = report.get("texture", {})
check(tex.get("mode") == "bake", f"--region: the new faces baked ({tex})")
rv, rfaces, files = read_ascii_ply_texture(region_out)
check(files == ["TextureDouble_A.png", "out_texture.png"], f"--region: TextureFile {files}")
check(os.path.isfile(os.path.join(region_dir, "out_texture.png")), "--region: the baked image beside OUT")
# Kept faces: the same corners as an input face and its coordinates and texture 0 exactly.
by_corners = {}
for face in bfaces:
    key = frozenset(bv[c[0]] for c in face)
    by_corners[key] = {bv[c[0]]: bvt[c[1]] for c in face}
kept = exact = coinciding = 0
for corners, uv, texnumber in rfaces:
    key = frozenset(rv[i] for i in corners)
    if texnumber == 0:
        kept += 1
        expected = by_corners.get(key)
        exact += expected is not None and all(abs(uv[k][0] - expected[rv[corners[k]]][0]) < 1e-6 and
                                              abs(uv[k][1] - expected[rv[corners[k]]][1]) < 1e-6 for k in range(3))
    else:
        coinciding += key in by_corners  # a new face on three border vertices may repeat a selected input face
print(f"--region: {kept} faces in the input's texture, {exact} of them input faces with their coordinates; "
      f"{len(rfaces) - kept} new faces in the baked one ({coinciding} on an input face's corners)")
unselected = sum(1 for face in bfaces if sum(bv[c[0]][1] for c in face) / 3 <= middle)
check(kept == unselected and exact == kept, f"--region: {exact} of {kept} faces keep their coordinates, {unselected} unselected")
check(coinciding <= 0.01 * (len(rfaces) - kept), f"--region: {coinciding} new faces on input faces' corners")
r = compare(marked, region_out)
print(f"--region: difference {r['difference']:.3f}, half-pixel {r['half_pixel']:.3f}, ratio {r['ratio']:.2f}")
check(r["ratio"] <= 2.0, f"--region: render difference {r['ratio']:.2f} x the yardstick")

# Without its image the atlas is kept, with a warning: the image is never needed to remesh.
alone = os.path.join(work, "alone")
os.makedirs(alone, exist_ok=True)
shutil.copy(os.path.join(textured, "sub.obj"), alone)
shutil.copy(os.path.join(textured, "sub.mtl"), alone)
report, err = remesh(os.path.join(alone, "sub.obj"), os.path.join(alone, "out.obj"), 2000)
check(report.get("texture", {}).get("mode") == "keep_atlas" and "no texture to bake, the atlas is kept" in err,
      f"no image: kept with a warning ({report.get('texture')}, {err.strip()[-200:]})")
code, _, err = run([fcvt, "remesh", os.path.join(textured, "sub.obj"), os.path.join(work, "x.obj"), "--vertices", "500",
                    "--texture", "paint"])
check(code == 2 and "--texture must be auto, keep or bake" in err, f"--texture paint: exit {code}, {err.strip()}")
finish()
