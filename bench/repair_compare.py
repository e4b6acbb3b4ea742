"""Real-world-like inputs (issue 17), made from the bundled meshes, through `fcvt remesh` (repair
on) and, when it is found, Instant Meshes, both measured by `fcvt metrics --ref INPUT`.

Usage: repair_compare.py FCVT RESOURCES WORK [--instant-meshes PATH] [--vertices N] [--only NAME,...]
                         [--strict-timeout S]

Inputs (OBJ, written to WORK/in):
  bunny_twice        bunny.obj, every face stored twice (every other copy reversed)
  bunny_floaters     bunny.obj (5 holes) and 1000 tiny tetrahedra beside it (a raw scan's floaters)
  fandisk_soup       fandisk.off as a triangle soup, every corner moved by up to 1e-12 (an STL export)
  fertility_fins     fertility.off with a fin standing out of 50 of its edges (non-manifold edges)
  torus_moebius      torus.obj beside a Moebius band (a non-orientable component)
  cubes_edge         two cubes touching along an edge (two shells sharing one)
  mask_tjunctions    mask.off, its right half re-triangulated on a finer grid along a seam (T-junctions)

d_H and d_RMS in % of the reference's bounding-box diagonal: the whole input, but bunny.obj for
bunny_floaters (the surface the user wants; the floaters are what the repair drops). Each input
also goes through `fcvt remesh --no-repair` (the strict check alone, as before issue 17)."""
import argparse
import json
import math
import os
import random
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "robustness"))
import meshgen as g  # noqa: E402


def read_off(path):
    words = open(path).read().split()
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    pos = 4
    v = []
    for _ in range(nv):
        v.append([float(x) for x in words[pos:pos + 3]])
        pos += 3
    f = []
    for _ in range(nf):
        k = int(words[pos])
        f.append([int(x) for x in words[pos + 1:pos + 1 + k]])
        pos += 1 + k
    return v, f


def read(path):
    return read_off(path) if path.endswith(".off") else g.read_obj(path)


def fins(mesh, count, rng):
    """A third face on `count` edges, standing out along the normal (an edge length high)."""
    v, f = [list(p) for p in mesh[0]], [list(t) for t in mesh[1]]
    for t in rng.sample(f, count):
        a, b, c = t
        u = [v[b][k] - v[a][k] for k in range(3)]
        w = [v[c][k] - v[a][k] for k in range(3)]
        n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
        scale = math.sqrt(sum(x * x for x in u)) / math.sqrt(sum(x * x for x in n))
        v.append([(v[a][k] + v[b][k]) / 2 + scale * n[k] for k in range(3)])
        f.append([a, b, len(v) - 1])
    return v, f


def jittered_soup(mesh, size, rng):
    v, f = g.soup(mesh)
    return [[c + rng.uniform(-size, size) for c in p] for p in v], f


def cubes_edge():
    return g.two_shells_sharing_an_edge(8)


def inputs(resources):
    rng = random.Random(17)
    bunny = read(os.path.join(resources, "bunny.obj"))
    lo = [min(p[k] for p in bunny[0]) for k in range(3)]
    hi = [max(p[k] for p in bunny[0]) for k in range(3)]
    size = max(hi[k] - lo[k] for k in range(3))
    return {
        "bunny_twice": g.every_face_twice(bunny),
        "bunny_floaters": g.floaters(bunny, 1000, 1e-3 * size, (hi[0] + 0.05 * size, lo[1], lo[2])),
        "fandisk_soup": jittered_soup(read(os.path.join(resources, "fandisk.off")), 1e-12, rng),
        "fertility_fins": fins(read(os.path.join(resources, "fertility.off")), 50, rng),
        "torus_moebius": g.combine(read(os.path.join(resources, "torus.obj")), g.transform(g.moebius(48), 1.0, (4, 0, 0))),
        "cubes_edge": cubes_edge(),
        "mask_tjunctions": mask_tjunctions(read(os.path.join(resources, "mask.off"))),
    }


def mask_tjunctions(mask):
    """Every face of the right half (centroid x > median) split at the midpoints of its edges
    that face a left-half face: the left side keeps whole edges, the right side has a vertex at
    their middle (a T-junction crack along the seam)."""
    v, f = [list(p) for p in mask[0]], [list(t) for t in mask[1]]
    xs = sorted(p[0] for p in v)
    median = xs[len(xs) // 2]
    right = [sum(v[c][0] for c in t) / 3 > median for t in f]
    owner = {}
    for i, t in enumerate(f):
        for k in range(3):
            owner.setdefault((min(t[k], t[(k + 1) % 3]), max(t[k], t[(k + 1) % 3])), []).append(i)
    mids = {}

    def split(t, edges):
        """Splits triangle t at the midpoints of `edges` (sorted vertex pairs), one at a time."""
        for k in range(3):
            a, b, c = t[k], t[(k + 1) % 3], t[(k + 2) % 3]
            key = (min(a, b), max(a, b))
            if key in edges:
                if key not in mids:
                    v.append([(v[a][m] + v[b][m]) / 2 for m in range(3)])
                    mids[key] = len(v) - 1
                rest = edges - {key}
                return split([a, mids[key], c], rest) + split([mids[key], b, c], rest)
        return [t]

    out = []
    for i, t in enumerate(f):
        seam = {key for key in ((min(t[k], t[(k + 1) % 3]), max(t[k], t[(k + 1) % 3])) for k in range(3))
                if right[i] and any(not right[j] for j in owner[key])}
        out += split(t, seam)
    return v, out


def metrics(fcvt, mesh, ref):
    p = subprocess.run([fcvt, "metrics", mesh, "--ref", ref, "--json"], capture_output=True, text=True)
    if p.returncode != 0:
        return None
    return json.loads(p.stdout)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("fcvt")
    ap.add_argument("resources")
    ap.add_argument("work")
    ap.add_argument("--instant-meshes", default="")
    ap.add_argument("--vertices", type=int, default=3000)
    ap.add_argument("--only", default="")
    ap.add_argument("--strict-timeout", type=float, default=300)
    a = ap.parse_args()
    os.makedirs(os.path.join(a.work, "in"), exist_ok=True)
    os.makedirs(os.path.join(a.work, "out"), exist_ok=True)
    rows = []
    references = {"bunny_floaters": read(os.path.join(a.resources, "bunny.obj"))}
    for name, mesh in inputs(a.resources).items():
        if a.only and name not in a.only.split(","):
            continue
        inp = os.path.join(a.work, "in", name + ".obj")
        with open(inp, "wb") as fh:
            fh.write(g.obj_bytes(mesh))
        ref = inp
        if name in references:  # distances to the surface meant, without the floaters
            ref = os.path.join(a.work, "in", name + "-ref.obj")
            with open(ref, "wb") as fh:
                fh.write(g.obj_bytes(references[name]))
        out = os.path.join(a.work, "out", name + "-fcvt.obj")
        rep = os.path.join(a.work, "out", name + "-fcvt.json")
        p = subprocess.run([a.fcvt, "remesh", inp, out, "--vertices", str(a.vertices), "--report", rep, "--quiet"],
                           capture_output=True, text=True)
        row = {"input": name, "faces_in": len(mesh[1])}
        # The strict check alone (as before issue 17): refused, or what it made of the input.
        strict = os.path.join(a.work, "out", name + "-strict.obj")
        try:
            q = subprocess.run([a.fcvt, "remesh", inp, strict, "--vertices", str(a.vertices), "--quiet", "--no-repair"],
                               capture_output=True, text=True, timeout=a.strict_timeout)
        except subprocess.TimeoutExpired:
            q = None
        if q is None:
            row["fcvt_no_repair"] = "no result within %g s" % a.strict_timeout
        elif q.returncode != 0:
            row["fcvt_no_repair"] = "exit %d: %s" % (q.returncode, q.stderr.strip()[-120:])
        else:
            m = metrics(a.fcvt, strict, ref)
            row["fcvt_no_repair"] = {"theta_min": m["theta_min"], "d_h": 100 * m["d_h"], "d_rms": 100 * m["d_rms"]}
        if p.returncode != 0:
            row["fcvt"] = "exit %d: %s" % (p.returncode, p.stderr.strip()[-200:])
        else:
            r = json.load(open(rep))
            m = metrics(a.fcvt, out, ref)
            row["fcvt"] = {"vertices": r["vertices"], "manifold": r["output"]["manifold"],
                           "orientable": r["output"]["orientable"], "components": r["output"]["components"],
                           "theta_min": m["theta_min"], "d_h": 100 * m["d_h"], "d_rms": 100 * m["d_rms"],
                           "repair": {k: x for k, x in r["repair"].items() if x not in (0, 0.0, False) or k == "enabled"}}
        if a.instant_meshes:
            im = os.path.join(a.work, "out", name + "-im.obj")
            p = subprocess.run([a.instant_meshes, inp, "-o", im, "-r", "6", "-p", "6", "-v", str(a.vertices), "-d", "-t", "2"],
                               capture_output=True, text=True)
            empty = not os.path.exists(im) or os.path.getsize(im) == 0
            m = metrics(a.fcvt, im, ref) if p.returncode == 0 and not empty else None
            if m is None:
                row["instant_meshes"] = "exit %d%s" % (p.returncode, ", empty output" if empty else "")
            else:
                result = g.read_obj(im)
                row["instant_meshes"] = {"vertices": len(result[0]), "manifold": not g.manifold_problems(result),
                                         "theta_min": m["theta_min"], "d_h": 100 * m["d_h"], "d_rms": 100 * m["d_rms"]}
        print(json.dumps(row), flush=True)
        rows.append(row)


if __name__ == "__main__":
    main()
