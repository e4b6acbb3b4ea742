"""FCVT beside MMG's mmgs (../shared/anchors, the peer that keeps topology) on the real-world
meshes of ../shared/realworld, at N = max(500, V/4) and N = max(300, V/8) (V: the input's
vertices): smallest angle, zero-area faces, boundary loops, pieces and genus in and out, d_H (% of
the diagonal, `fcvt metrics OUT --ref IN`), output vertices, seconds (whole commands).

  python3 bench/realworld.py BUILD/cli/fcvt [--threads 2] [--divisors 4 8]
"""
import argparse
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from side_by_side import SHARED, metrics, timed  # noqa: E402

MMGS = os.path.join(SHARED, "anchors", "mmgs_remesh.py")


def read_obj(path):
    v, f = [], []
    with open(path) as fh:
        for line in fh:
            t = line.split()
            if t and t[0] == "v":
                v.append([float(x) for x in t[1:4]])
            elif t and t[0] == "f":
                f.append([int(x.split("/")[0]) - 1 for x in t[1:]])
    return v, f


def stl_to_obj(src, dst):
    """A binary or ASCII STL as OBJ, corners at the same coordinates welded (for mmgs, when
    `fcvt convert`, which checks the mesh as remesh --no-repair does, refuses it)."""
    import struct
    data = open(src, "rb").read()
    tris = []
    if len(data) >= 84 and 84 + 50 * struct.unpack_from("<I", data, 80)[0] == len(data):
        for i in range(struct.unpack_from("<I", data, 80)[0]):
            vals = struct.unpack_from("<12f", data, 84 + 50 * i)
            tris.append([tuple(vals[3 + 3 * k: 6 + 3 * k]) for k in range(3)])
    else:
        corners = [tuple(float(x) for x in line.split()[1:4]) for line in data.decode(errors="replace").splitlines()
                   if line.strip().startswith("vertex")]
        tris = [corners[i:i + 3] for i in range(0, len(corners) - 2, 3)]
    index = {}
    with open(dst, "w") as out:
        faces = []
        for t in tris:
            face = []
            for p in t:
                if p not in index:
                    index[p] = len(index) + 1
                    out.write("v %.9g %.9g %.9g\n" % p)
                face.append(index[p])
            faces.append(face)
        out.writelines("f %d %d %d\n" % tuple(f) for f in faces)


def zero_area_faces(mesh):
    v, f = mesh
    count = 0
    for t in f:
        a, b, c = v[t[0]], v[t[1]], v[t[2]]
        u = [b[i] - a[i] for i in range(3)]
        w = [c[i] - a[i] for i in range(3)]
        cross = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
        count += all(x == 0.0 for x in cross)
    return count


def row(fcvt, m, mesh, seconds):
    genus = m.get("genus")
    genus = f"{genus:g}" if isinstance(genus, float) else genus
    return (f"{m.get('theta_min', float('nan')):.1f} / {zero_area_faces(mesh)} / {int(m.get('boundary_loops', -1))} / "
            f"{int(m.get('components', -1))} / {genus} / {100 * m['d_h']:.2f} / {int(m['vertices'])} / {seconds:.1f}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("fcvt")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--divisors", type=int, nargs="+", default=[4, 8])
    a = ap.parse_args()
    floors = {4: 500, 8: 300}
    names = sorted(n for n in os.listdir(os.path.join(SHARED, "realworld")) if not n.endswith(".md"))
    print("| input (V; loops, pieces, genus) | N | FCVT θ_min / zero-area / loops / pieces / genus / d_H % / V / s "
          "| mmgs θ_min / zero-area / loops / pieces / genus / d_H % / V / s |")
    print("|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for name in names:
            path = os.path.join(SHARED, "realworld", name)
            obj = os.path.join(work, "in.obj")
            if subprocess.run([a.fcvt, "convert", path, obj, "--quiet"], stderr=subprocess.DEVNULL).returncode != 0:
                stl_to_obj(path, obj)
            ref = metrics(a.fcvt, path, path)
            v = int(ref["vertices"])
            for d in a.divisors:
                n = max(floors.get(d, 300), v // d)
                out_f, out_m = os.path.join(work, "fcvt.obj"), os.path.join(work, "mmgs.obj")
                try:
                    tf = timed([a.fcvt, "remesh", path, out_f, "--vertices", str(n), "--threads", str(a.threads), "--quiet"])[0]
                    fcvt_cell = row(a.fcvt, metrics(a.fcvt, out_f, path), read_obj(out_f), tf)
                except SystemExit as e:
                    fcvt_cell = "failed: " + str(e).splitlines()[-1][:80]
                try:
                    tm = timed(["/usr/bin/python3", MMGS, obj, out_m, str(n)])[0]
                    mmgs_cell = row(a.fcvt, metrics(a.fcvt, out_m, path), read_obj(out_m), tm)
                except SystemExit as e:
                    mmgs_cell = "failed: " + str(e).splitlines()[-1][:80]
                genus = ref["genus"] if isinstance(ref["genus"], str) else f"{ref['genus']:g}"
                print(f"| {name} ({v}; {int(ref['boundary_loops'])}, {int(ref['components'])}, {genus}) | {n} | "
                      f"{fcvt_cell} | {mmgs_cell} |", flush=True)


if __name__ == "__main__":
    main()
