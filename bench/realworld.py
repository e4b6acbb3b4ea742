"""FCVT beside Instant Meshes and MMG's mmgs (../shared/anchors; mmgs is the peer that keeps
topology) on the real-world meshes of ../shared/realworld, at N = max(500, V/4) and
N = max(300, V/8) (V: the input's vertices), one row per tool: θ_min, % of triangles under 30°,
V6 %, Q_avg, d_H (% of the diagonal), zero-area faces, boundary loops (holes), pieces, genus,
the input parts' largest gap to the output (in its edge lengths) and most pieces (issue 32 item 3:
at most 2 and 1), output vertices and seconds (whole commands), all measured by `fcvt metrics OUT --ref IN`.
Issue 32 item 4: FCVT's d_H at most Instant Meshes' wherever Instant Meshes returns a mesh.

  python3 bench/realworld.py BUILD/cli/fcvt [--threads 2] [--divisors 4 8] [--tools fcvt im mmgs]
                             [--fcvt-option OPT ...] [NAME ...]

Instant Meshes runs as the anchors' README says (`-r 6 -p 6 -v N -d -t T`) on an OBJ copy (STL
and OFF converted outside the timed part); "failed" means it exited non-zero or wrote no faces.
"""
import argparse
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from side_by_side import SHARED, metrics, timed  # noqa: E402

MMGS = os.path.join(SHARED, "anchors", "mmgs_remesh.py")
IM = os.path.join(SHARED, "anchors", "instant-meshes")


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


def cells(m, mesh, seconds):
    """The table's figures for one output, measured against the input."""
    genus = m.get("genus")
    genus = f"{genus:g}" if isinstance(genus, float) else genus

    def f(key, digits, scale=1.0):
        v = m.get(key)
        return "n/a" if not isinstance(v, float) else f"{scale * v:.{digits}f}"
    return (f"{f('theta_min', 1)} | {f('pct_lt30', 2)} | {f('v6_pct', 1)} | {f('q_avg', 3)} | {f('d_h', 2, 100)} | "
            f"{zero_area_faces(mesh)} | {int(m.get('boundary_loops', -1))} | {int(m.get('components', -1))} | "
            f"{genus} | {f('part_gap', 2)} / {int(m.get('part_pieces', -1))} | {int(m['vertices'])} | {seconds:.2f}")


def run_tool(tool, a, path, obj, out, n):
    """Runs one tool to about n vertices; returns its seconds (whole command)."""
    if tool == "fcvt":
        return timed([a.fcvt, "remesh", path, out, "--vertices", str(n), "--threads", str(a.threads), "--quiet"]
                     + a.fcvt_option)[0]
    if tool == "im":
        return timed([IM, obj, "-o", out, "-r", "6", "-p", "6", "-v", str(n), "-d", "-t", str(a.threads)])[0]
    return timed(["/usr/bin/python3", MMGS, obj, out, str(n)])[0]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("fcvt")
    ap.add_argument("names", nargs="*", help="meshes of ../shared/realworld (default: all)")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--divisors", type=int, nargs="+", default=[4, 8])
    ap.add_argument("--tools", nargs="+", default=["fcvt", "im", "mmgs"], choices=["fcvt", "im", "mmgs"])
    ap.add_argument("--fcvt-option", action="append", default=[], help="extra option for fcvt remesh (repeatable)")
    a = ap.parse_args()
    floors = {4: 500, 8: 300}
    names = a.names or sorted(n for n in os.listdir(os.path.join(SHARED, "realworld")) if not n.endswith(".md"))
    names_of = {"fcvt": "FCVT", "im": "Instant Meshes", "mmgs": "mmgs"}
    print("| input (V; loops, pieces, genus) | N | tool | θ_min | % < 30° | V6 % | Q_avg | d_H % | zero-area "
          "| holes | pieces | genus | part gap / pieces | V | s |")
    print("|" + "---|" * 15)
    d_h = {}
    with tempfile.TemporaryDirectory() as work:
        for name in names:
            path = os.path.join(SHARED, "realworld", name)
            obj = os.path.join(work, "in.obj")
            if subprocess.run([a.fcvt, "convert", path, obj, "--quiet"], stderr=subprocess.DEVNULL).returncode != 0:
                stl_to_obj(path, obj)
            ref = metrics(a.fcvt, path, path)
            v = int(ref["vertices"])
            genus = ref["genus"] if isinstance(ref["genus"], str) else f"{ref['genus']:g}"
            for d in a.divisors:
                n = max(floors.get(d, 300), v // d)
                for tool in a.tools:
                    out = os.path.join(work, tool + ".obj")
                    if os.path.exists(out):
                        os.remove(out)
                    try:
                        seconds = run_tool(tool, a, path, obj, out, n)
                        mesh = read_obj(out)
                        if not mesh[1]:
                            raise SystemExit("no faces written")
                        m = metrics(a.fcvt, out, path)
                        d_h[(name, n, tool)] = m["d_h"]
                        cell = cells(m, mesh, seconds)
                    except (SystemExit, subprocess.CalledProcessError) as e:
                        cell = "failed: " + (str(e).strip().splitlines() or ["?"])[-1][:70] + " |" * 11
                    print(f"| {name} ({v}; {int(ref['boundary_loops'])}, {int(ref['components'])}, {genus}) | {n} "
                          f"| {names_of[tool]} | {cell} |", flush=True)
    pairs = [(k, d_h[k], d_h[(k[0], k[1], "im")]) for k in d_h if k[2] == "fcvt" and (k[0], k[1], "im") in d_h]
    if pairs:
        worse = [f"{k[0]} {k[1]} ({100 * f:.2f} % > {100 * i:.2f} %)" for k, f, i in pairs if f > i]
        print(f"\nd_H: FCVT at most Instant Meshes' on {len(pairs) - len(worse)} of {len(pairs)} rows where both "
              "return a mesh" + ("; above it on " + ", ".join(worse) if worse else ""))


if __name__ == "__main__":
    main()
