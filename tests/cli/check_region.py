"""fcvt remesh --region (issue 34) end to end: a disk of faces marked through a PLY face property
(MeshLab's face quality, written after the vertex list as MeshLab does) is remeshed; the rest of
the mesh is identical bit for bit and in order, the seam is watertight (every edge keeps the
input's face count), no vertex is duplicated, and the new faces meet the quality bars.
Usage: check_region.py FCVT MESH|sphere VERTICES WORKDIR RADIUS THETA_MIN Q_AVG V6
(RADIUS: the disk's radius as a fraction of the bounding-box diagonal)."""
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fcvt_check import (check, edge_counts, expect_error, finish, is_subsequence, measure,  # noqa: E402
                        read_ply_face_values, run, run_ok)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "robustness"))
from meshgen import icosphere  # noqa: E402


def write_marked_ply(path, vertices, faces, selected):
    """ASCII PLY with face quality 1 on the selected faces (after the list, as MeshLab writes it)."""
    lines = ["ply", "format ascii 1.0", f"element vertex {len(vertices)}", "property double x", "property double y",
             "property double z", f"element face {len(faces)}", "property list uchar int vertex_indices",
             "property float quality", "end_header"]
    lines += ["%r %r %r" % tuple(p) for p in vertices]
    lines += [f"3 {a} {b} {c} {1 if s else 0}" for (a, b, c), s in zip(faces, selected)]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    fcvt, mesh, vertex_count, work = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
    radius_share, theta_bar, q_bar, v6_bar = (float(x) for x in sys.argv[5:9])
    os.makedirs(work, exist_ok=True)
    if mesh == "sphere":
        vertices, faces = icosphere(4)
        vertices, faces = [tuple(p) for p in vertices], [tuple(f) for f in faces]
    else:
        converted = os.path.join(work, "input.ply")
        run_ok([fcvt, "convert", mesh, converted])
        vertices, faces, _ = read_ply_face_values(converted)
    lo = [min(p[k] for p in vertices) for k in range(3)]
    hi = [max(p[k] for p in vertices) for k in range(3)]
    diagonal = math.dist(lo, hi)
    centre = vertices[faces[len(faces) // 3][0]]
    centroid = lambda f: [sum(vertices[v][k] for v in f) / 3 for k in range(3)]  # noqa: E731
    selected = [math.dist(centroid(f), centre) < radius_share * diagonal for f in faces]
    marked = os.path.join(work, "marked.ply")
    write_marked_ply(marked, vertices, faces, selected)
    out, report = os.path.join(work, "out.ply"), os.path.join(work, "report.json")
    print(run_ok([fcvt, "remesh", marked, out, "--region", "quality", "--vertices", str(vertex_count), "--seed", "1",
                  "--report", report]))
    new_vertices, new_faces, values = read_ply_face_values(out)
    region = json.load(open(report))["region"]

    # The kept faces: the unselected input faces, in order, on the same coordinates bit for bit.
    kept_in = [tuple(vertices[v] for v in f) for f, s in zip(faces, selected) if not s]
    kept_out = [tuple(new_vertices[v] for v in f) for f, value in zip(new_faces, values) if value == 0]
    # Faces the selection gained where it touched itself at a vertex (closePinches) are remeshed too.
    check(is_subsequence(kept_out, kept_in) and len(kept_in) - len(kept_out) == region["added_faces"],
          f"kept faces differ: {len(kept_in)} input, {len(kept_out)} output, {region['added_faces']} added")
    check(values is not None and sum(1 for x in values if x == 1) == region["new_faces"],
          "the output's quality marks the new faces")
    # The seam: every edge has the face count it had in the input (closed stays closed).
    position = {p: i for i, p in enumerate(vertices)}
    input_edges = edge_counts(faces)
    bad = 0
    for (a, b), count in edge_counts(new_faces).items():
        if count == 2:
            continue
        pa, pb = position.get(new_vertices[a]), position.get(new_vertices[b])
        bad += count != 1 or pa is None or pb is None or input_edges.get((min(pa, pb), max(pa, pb))) != 1
    check(bad == 0, f"{bad} edges are cracks, T-junctions or non-manifold")
    check(len(set(new_vertices)) == len(new_vertices), "duplicate vertices")
    unreferenced_in = len(vertices) - len({v for f in faces for v in f})
    unreferenced_out = len(new_vertices) - len({v for f in new_faces for v in f})
    check(unreferenced_out == unreferenced_in, f"{unreferenced_out} unreferenced vertices, the input had {unreferenced_in}")
    # The new faces' figures, measured here and by the report.
    inside = [f for f, value in zip(new_faces, values) if value == 1]
    m = measure(new_vertices, inside)
    print(f"region: {region['pieces']} piece(s), {region['new_vertices']} new vertices, {region['new_faces']} new faces, "
          f"border ratio {region['worst_border_ratio']:.2f}; measured here Q_avg {m['q_avg']:.3f}, "
          f"theta_min {m['theta_min']:.1f}; report V6 {region['metrics']['v6_pct']:.1f} %, "
          f"interior theta_min {region['interior_metrics']['theta_min']:.1f}")
    check(region["kept_pieces"] == 0, "a piece was kept instead of remeshed")
    check(m["theta_min"] >= theta_bar, f"theta_min {m['theta_min']:.1f} < {theta_bar}")
    check(m["q_avg"] >= q_bar, f"Q_avg {m['q_avg']:.3f} < {q_bar}")
    check(region["metrics"]["v6_pct"] >= v6_bar, f"V6 {region['metrics']['v6_pct']:.1f} < {v6_bar}")

    # Edge cases: an empty region, a missing property, a non-PLY input, everything selected.
    write_marked_ply(os.path.join(work, "none.ply"), vertices, faces, [False] * len(faces))
    expect_error(fcvt, ["remesh", os.path.join(work, "none.ply"), out, "--region", "quality", "--vertices", "100"], 1,
                 "the region is empty")
    expect_error(fcvt, ["remesh", marked, out, "--region", "red", "--vertices", "100"], 1,
                 "no scalar property 'red' (they have: quality)")
    expect_error(fcvt, ["remesh", mesh if mesh != "sphere" else "x.obj", out, "--region", "quality", "--vertices", "100"],
                 2, "--region takes the region from a face property of a PLY input")
    if mesh == "sphere":
        everything = os.path.join(work, "all.ply")
        write_marked_ply(everything, vertices, faces, [True] * len(faces))
        a, b = os.path.join(work, "all_region.ply"), os.path.join(work, "all_plain.ply")
        run_ok([fcvt, "remesh", everything, a, "--region", "quality", "--vertices", "400", "--seed", "1", "--quiet"])
        run_ok([fcvt, "remesh", everything, b, "--vertices", "400", "--seed", "1", "--quiet"])
        check(open(a, "rb").read() == open(b, "rb").read(), "everything selected differs from the plain remesh")
    finish()


if __name__ == "__main__":
    main()
