"""Issue 50, items 4 and 5, through the `fcvt` command.
Item 4: `remesh --region` on a PLY whose selection holds a non-manifold edge (inside the selection,
on its border, a fin left out of it) or faces of the wrong orientation gives exit 0 and a manifold,
oriented output whose unselected faces are the input's, bit for bit; a non-manifold edge among the
kept faces stays, said by one warning; a selection no orientation of which agrees with the faces
around it is refused with one error line, and nothing is written.
Item 5: `convert` writes a non-manifold or non-orientable mesh as read (same vertices and faces)
with one warning line; `--strict` refuses it with one error line (exit 1).
Usage: check_region_convert_topology.py FCVT WORK_DIR"""
import json
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
import meshgen as g  # noqa: E402
from fcvt_check import read_ply, read_ply_face_values  # noqa: E402

fcvt, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
FAST = ["--seed", "1", "--threads", "2"]
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)
    return ok


def run(args, timeout=300):
    p = subprocess.run([fcvt] + args, capture_output=True, timeout=timeout)
    return p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace")


def path(name):
    return os.path.join(work, name)


def fresh(name):
    if os.path.exists(path(name)):
        os.remove(path(name))
    return path(name)


def faults(vertices, faces):
    """Non-manifold edges and vertices, edges two faces run the same way (counts, without examples)."""
    problems = [p.split(", e.g.")[0] for p in g.manifold_problems((vertices, [list(f) for f in faces]))
                if "non-manifold" in p]
    directed = {}
    for f in faces:
        for k in range(3):
            directed[(f[k], f[(k + 1) % 3])] = directed.get((f[k], f[(k + 1) % 3]), 0) + 1
    same = sum(1 for count in directed.values() if count > 1)
    return problems + ([f"{same} edges run the same way by two faces"] if same else [])


def centroid(vertices, face):
    return [sum(vertices[v][k] for v in face) / 3 for k in range(3)]


def write_marked_ply(name, vertices, faces, selected):
    """ASCII PLY with face quality 1 on the selected faces (MeshLab's way of marking them)."""
    lines = ["ply", "format ascii 1.0", f"element vertex {len(vertices)}", "property double x", "property double y",
             "property double z", f"element face {len(faces)}", "property list uchar int vertex_indices",
             "property float quality", "end_header"]
    lines += ["%r %r %r" % tuple(p) for p in vertices]
    lines += [f"3 {a} {b} {c} {1 if s else 0}" for (a, b, c), s in zip(faces, selected)]
    with open(path(name), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    return path(name)


def add_fin(vertices, faces, selected, a, b, rows, fin_selected):
    """A strip of `rows` pairs of faces standing out of the edge a-b: the edge gets three faces."""
    prev = (a, b)
    for r in range(1, rows + 1):
        vertices += [[c * (1 + 0.15 * r) for c in vertices[a]], [c * (1 + 0.15 * r) for c in vertices[b]]]
        na, nb = len(vertices) - 2, len(vertices) - 1
        faces += [[prev[0], prev[1], nb], [prev[0], nb, na]]
        selected += [fin_selected, fin_selected]
        prev = (na, nb)


def cap():
    """An icosphere (1280 faces) with the faces above z = 0.5 selected."""
    vertices, faces = g.icosphere(3)
    return vertices, faces, [centroid(vertices, f)[2] > 0.5 for f in faces]


def edge_toward(vertices, faces, z):
    face = min(faces, key=lambda f: abs(centroid(vertices, f)[2] / math.dist(centroid(vertices, f), [0, 0, 0]) - z))
    return face[0], face[1]


def border_edge(faces, selected):
    owners = {}
    for i, f in enumerate(faces):
        for k in range(3):
            owners.setdefault(tuple(sorted((f[k], f[(k + 1) % 3]))), []).append(i)
    return next(e for e, two in sorted(owners.items()) if len(two) == 2 and selected[two[0]] != selected[two[1]])


def region_run(name, vertices, faces, selected, vertices_asked=300):
    """Remeshes the marked faces; returns (exit code, stderr, output vertices, faces, values, the
    faces added to the selection)."""
    marked = write_marked_ply(name + ".ply", vertices, faces, selected)
    out, report = fresh(name + ".out.ply"), fresh(name + ".json")
    code, _, err = run(["remesh", marked, out, "--vertices", str(vertices_asked), "--region", "quality", "--report",
                        report] + FAST)
    if code != 0 or not os.path.exists(out):
        return code, err, None, None, None, 0
    with open(report) as fh:
        added = json.load(fh)["region"]["added_faces"]
    return (code, err) + tuple(read_ply_face_values(out)) + (added,)


def expect_clean(label, vertices, faces, selected, result):
    code, err, out_v, out_f, values, added = result
    warnings = [line for line in err.splitlines() if line.startswith("fcvt: warning:")]
    if not check(code == 0, f"{label}: exit 0" + (f" (exit {code}: {err.strip()[-300:]})" if code else "")):
        return
    check(not faults(out_v, out_f), f"{label}: manifold, oriented output ({faults(out_v, out_f)})")
    check(not any("kept as it is" in w or "not manifold" in w for w in warnings),
          f"{label}: no piece left broken ({warnings})")
    # The unselected input faces are in the output on the same coordinates bit for bit, but for
    # those the selection took in (around a non-manifold edge on its border, where it touched itself).
    kept_in = [tuple(tuple(vertices[v]) for v in f) for f, s in zip(faces, selected) if not s]
    kept_out = {tuple(tuple(out_v[v]) for v in f) for f, value in zip(out_f, values) if value == 0}
    missing = sum(1 for f in kept_in if f not in kept_out)
    check(missing == added, f"{label}: every unselected face kept bit for bit ({missing} missing, {added} taken in)")


# --- Item 4: --region -----------------------------------------------------------------------

for rows in (1, 3):  # a fin the repair drops as too small for the vertex count, and one it keeps
    v, f, sel = cap()
    a, b = edge_toward(v, f, 1.0)
    add_fin(v, f, sel, a, b, rows, True)
    expect_clean(f"non-manifold edge inside the selection ({rows} fin rows)", v, f, sel,
                 region_run(f"inside{rows}", v, f, sel))

v, f, sel = cap()
a, b = border_edge(f, sel)
add_fin(v, f, sel, a, b, 3, True)
expect_clean("non-manifold edge on the selection's border", v, f, sel, region_run("border", v, f, sel))

v, f, sel = cap()
a, b = edge_toward(v, f, 1.0)
add_fin(v, f, sel, a, b, 3, False)
# The fin's face on the edge joins the selection (and the faces around its corners): only the
# other fin faces must stay.
result = region_run("fin_out", v, f, sel)
code, err, out_v, out_f, values, _ = result
check(code == 0 and not faults(out_v, out_f), f"a fin left out of the selection: exit 0, manifold and oriented "
      f"(exit {code}, {faults(out_v, out_f) if code == 0 else err.strip()[-300:]})")
check("non-manifold edges (more than two faces)" in err, "a fin left out of the selection: the note says it was taken in")

v, f, sel = cap()
f = [list(reversed(t)) if s else t for t, s in zip(f, sel)]
expect_clean("a selection oriented against the rest", v, f, sel, region_run("flipped", v, f, sel))

v, f, sel = cap()
a, b = edge_toward(v, f, -1.0)  # far from the selection
add_fin(v, f, sel, a, b, 2, False)
code, err, out_v, out_f, values, _ = region_run("kept_fault", v, f, sel)
warnings = [line for line in err.splitlines() if line.startswith("fcvt: warning:")]
check(code == 0 and sum("the output keeps the input's own 1 non-manifold edge" in w for w in warnings) == 1,
      f"a non-manifold edge among the kept faces: exit 0, one warning (exit {code}, {warnings})")
if code == 0:
    check(faults(out_v, out_f) == faults(v, f), f"... and it is the only fault of the output ({faults(out_v, out_f)})")

# A Moebius band whose one orientation fault lies inside the selection: no orientation of the
# selection agrees with the kept half at both ends. One error line, nothing written.
band_v, band_f = g.moebius(48, 0.3)
band_sel = [i < 16 or i >= len(band_f) - 16 for i in range(len(band_f))]
code, err, *_ = region_run("band", band_v, band_f, band_sel, 120)
lines = [line for line in err.splitlines() if line.strip() and not line.startswith("fcvt: note")]
errors = [line for line in lines if line.startswith("fcvt: error: ")]
check(code == 1 and len(errors) == 1 and lines[-1] == errors[0] and "opposite orientation" in errors[0],
      f"a selection that cannot be oriented as its surroundings: one error line (exit {code}, {lines[-2:]})")
check(not os.path.exists(path("band.out.ply")), "... and no output written")

# --- Item 5: convert ------------------------------------------------------------------------

for name, mesh, what in [("fin", g.nonmanifold_edge(), "1 non-manifold edge"),
                         ("sheets", g.fin_of_three_sheets(), "3 non-manifold edges"),
                         ("band", g.moebius(), "1 non-orientable component")]:
    source = path(f"convert_{name}.off")
    with open(source, "wb") as fh:
        fh.write(g.off_bytes(mesh))
    out = fresh(f"convert_{name}.ply")
    code, stdout, err = run(["convert", source, out])
    lines = err.strip().splitlines()
    check(code == 0 and len(lines) == 1 and lines[0].startswith("fcvt: warning: ") and what in lines[0] and
          "--strict" in lines[0], f"convert {name}: exit 0, one warning naming {what!r} (exit {code}, {lines})")
    if code == 0:
        out_v, out_f = read_ply(out)
        check([list(t) for t in out_f] == [list(t) for t in mesh[1]] and
              all(math.dist(p, q) == 0 for p, q in zip(out_v, mesh[0])) and len(out_v) == len(mesh[0]),
              f"convert {name}: the output holds the input's vertices and faces, in order")
    code, _, err = run(["convert", source, out, "--quiet"])
    check(code == 0 and len(err.strip().splitlines()) == 1, f"convert {name} --quiet: the warning still said (exit {code})")
    strict_out = fresh(f"convert_{name}_strict.ply")
    code, _, err = run(["convert", source, strict_out, "--strict"])
    lines = err.strip().splitlines()
    check(code == 1 and len(lines) == 1 and lines[0].startswith("fcvt: error: ") and
          ("non-manifold edge" in lines[0] or "not orientable" in lines[0]),
          f"convert {name} --strict: one error line, exit 1 (exit {code}, {lines})")
    check(not os.path.exists(strict_out), f"convert {name} --strict: nothing written")

# A clean mesh is converted without a word, with or without --strict.
source = path("convert_sphere.off")
with open(source, "wb") as fh:
    fh.write(g.off_bytes(g.icosphere(2)))
for extra in ([], ["--strict"]):
    code, _, err = run(["convert", source, fresh("convert_sphere.ply")] + extra)
    check(code == 0 and err.strip() == "", f"convert a clean sphere {' '.join(extra)}: exit 0, no warning ({err.strip()!r})")

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("all checks passed")
