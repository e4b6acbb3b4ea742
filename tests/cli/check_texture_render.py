"""The remeshed model rendered with its texture looks like the input (issue 36, items 1 and 3):
fcvt remesh with the default --texture auto, then fcvt texture-compare (6 unlit views, 512 px) on
bunny10k_textured (190 charts of a labelled pattern) and sub.obj (one chart per triangle) at 2000
and 5000 vertices. Both atlases have small charts against these faces, so auto bakes a new
image (OUT_texture.png, named by the .mtl and by a PLY's TextureFile); the render's difference
must stay within 2 times the half-pixel yardstick (the issue's goal; measured 0.3-1.45, see
docs/measurements.md), and below what keeping the atlas gives where that is worse. A missing image falls back to the kept atlas with a warning;
an unknown --texture mode is a usage error.
Usage: check_texture_render.py FCVT TEXTURED_DIR WORK_DIR"""
import json
import os
import shutil
import sys

from fcvt_check import check, finish, run

fcvt, textured, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
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
        # A PLY output names the baked image in its TextureFile comment.
        ply = os.path.join(work, stem + ".ply")
        remesh(inp, ply, vertices)
        header = open(ply, "rb").read().split(b"end_header")[0].decode()
        check(f"comment TextureFile {stem}_texture.png" in header and "texcoord" in header, f"{stem}.ply: TextureFile, texcoord")

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
