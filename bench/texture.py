#!/usr/bin/env python3
"""Texture on the remeshed surface (issue 36, item 3): for each textured mesh and vertex count,
fcvt remesh with --texture keep and --texture bake (and the default auto's choice), then fcvt
texture-compare (6 unlit views, 512 px): the mean absolute colour difference to the input's
render, the half-pixel yardstick, their ratio (goal: at most 2), the share of output faces
across a seam of the input's atlas, and the texture step's time. One table, Markdown.
Usage: bench/texture.py FCVT [--meshes A.obj B.obj] [--counts 2000 5000] [--pictures DIR]"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("fcvt")
parser.add_argument("--meshes", nargs="+", default=[os.path.join(here, "..", "resources", "textured", m)
                                                     for m in ("bunny10k_textured.obj", "sub.obj")])
parser.add_argument("--counts", nargs="+", type=int, default=[2000, 5000])
parser.add_argument("--pictures", help="write each run's input/output renders (PNG) into this folder")
args = parser.parse_args()

work = tempfile.mkdtemp(prefix="fcvt-texture-")
print("| mesh | vertices | mode | auto picks | difference | half-pixel | ratio | faces across a seam | texture s |")
print("|---|---:|---|---|---:|---:|---:|---:|---:|")
for mesh in args.meshes:
    name = os.path.splitext(os.path.basename(mesh))[0]
    for count in args.counts:
        auto = os.path.join(work, f"{name}-{count}-auto.obj")
        subprocess.run([args.fcvt, "remesh", mesh, auto, "--vertices", str(count), "--quiet", "--report", auto + ".json"],
                       check=True, stderr=subprocess.DEVNULL)
        picked = json.load(open(auto + ".json"))["texture"]["mode"]
        for mode in ("keep", "bake"):
            out = os.path.join(work, f"{name}-{count}-{mode}.obj")
            subprocess.run([args.fcvt, "remesh", mesh, out, "--vertices", str(count), "--quiet", "--texture", mode,
                            "--report", out + ".json"], check=True, stderr=subprocess.DEVNULL)
            seconds = json.load(open(out + ".json"))["texture"]["time_s"]
            command = [args.fcvt, "texture-compare", mesh, out, "--json"]
            if args.pictures:
                os.makedirs(args.pictures, exist_ok=True)
                command += ["--pictures", os.path.join(args.pictures, f"{name}-{count}-{mode}.png")]
            r = json.loads(subprocess.run(command, check=True, capture_output=True, text=True).stdout)
            print(f"| {name} | {count} | {mode} | {picked} | {r['difference']:.2f} | {r['half_pixel']:.2f} | "
                  f"{r['ratio']:.2f} | {100 * r['seam_faces']:.1f} % | {seconds:.2f} |")
            sys.stdout.flush()
