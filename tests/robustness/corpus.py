"""The corpus of bad meshes and bad parameters of issue 6, one case per documented problem, with
the documented outcome of each:

  expect "ok"      exit 0 and a manifold output (repaired or handled, and said so)
  expect "error"   exit code in `codes` (1 runtime, 2 usage) and exactly one stderr line
                   "fcvt: error: ..." (containing `fragment` if given)
  expect "either"  one of the two (e.g. a truncated OBJ may still hold whole triangles)

`meshlab` marks the well-formed OFF/PLY files MeshLab 2020.09's own importers load, run through
meshlabserver too. `same_as` = (case, scale, offset): after undoing the transform the output
must match that case's output. `closed`: the output (and, through MeshLab, the input the filter
sees) is one closed component, no boundary loop. `warning`: a fragment stderr must have (a
"fcvt: warning:" line). `early`: the error comes before any work (stderr is the error line
alone, no progress line). `out_ext` "@input" writes to the input file itself, "@link" to a
symbolic link to it; either must leave the input as it was. `measures` = (area, volume,
tolerance): the output's surface area and enclosed volume within that fraction of the given ones."""
import random

import meshgen as g

# Fast settings for every case unless it says otherwise: pure CVT, few iterations.
FAST = ["--vertices", "60", "--cvt-iterations", "5", "--fcvt-iterations", "0", "--lambda", "0"]


def case(name, ext, data, expect, args=None, codes=(1,), fragment="", meshlab=False, same_as=None, out_ext="obj",
         closed=False, warning="", early=False, measures=None):
    return {"name": name, "file": name + "." + ext if ext else None, "data": data, "expect": expect,
            "args": FAST if args is None else args, "codes": list(codes), "fragment": fragment,
            "meshlab": meshlab, "same_as": same_as, "out_ext": out_ext, "closed": closed, "warning": warning,
            "early": early, "measures": measures}


def truncate(data, fraction):
    return data[: int(len(data) * fraction)]


def cases():
    rng = random.Random(6)
    sphere = g.icosphere(2)
    torus = g.torus(16, 8)
    out = []

    # Unreadable files.
    for ext in ("off", "ply", "obj", "stl"):
        out.append(case("empty_" + ext, ext, b"", "error"))
    out.append(case("missing_file", "off", None, "error", fragment="no such file"))
    for ext in ("off", "ply", "obj", "stl"):
        out.append(case("garbage_" + ext, ext, bytes(rng.randrange(256) for _ in range(3000)), "error"))
    out.append(case("garbage_text_obj", "obj", b"hello world\nthis is not a mesh\n\x00\xff\n", "error"))
    out.append(case("ply_header_only", "ply", b"ply\nformat ascii 1.0\nelement vertex 3\n", "error"))
    out.append(case("ply_huge_count", "ply", b"ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
                    b"property float x\nproperty float y\nproperty float z\nelement face 1\n"
                    b"property list uchar int vertex_indices\nend_header\n\x00\x00\x00\x00", "error"))
    out.append(case("off_huge_count", "off", b"OFF\n2000000000 2000000000 0\n0 0 0\n", "error"))

    # Truncated files (a whole sphere cut at 60 %).
    out.append(case("truncated_ply_binary", "ply", truncate(g.ply_bytes(sphere, True), 0.6), "error"))
    out.append(case("truncated_ply_ascii", "ply", truncate(g.ply_bytes(sphere, False), 0.6), "error"))
    out.append(case("truncated_off", "off", truncate(g.off_bytes(sphere), 0.6), "error"))
    out.append(case("truncated_stl_binary", "stl", truncate(g.stl_bytes(sphere, True), 0.6), "error"))
    # An OBJ has no counts: cut between lines it is a smaller mesh, cut in a line it is malformed.
    out.append(case("truncated_obj", "obj", truncate(g.obj_bytes(sphere), 0.9), "either"))

    # No surface.
    pts = sphere[0]
    out.append(case("point_cloud_off", "off", g.off_bytes((pts, [])), "error", meshlab=True))
    out.append(case("point_cloud_ply", "ply", g.ply_bytes((pts, [])), "error", meshlab=True))
    out.append(case("point_cloud_obj", "obj", g.obj_bytes((pts, [])), "error"))
    out.append(case("all_degenerate_off", "off", g.off_bytes(([[0, 0, 0], [1, 0, 0], [2, 0, 0]], [[0, 1, 2]])),
                    "error", fragment="degenerate", meshlab=True))
    out.append(case("bad_index_off", "off", g.off_bytes(([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 7]])), "error"))
    out.append(case("negative_index_obj", "obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -7\n", "error"))

    # Non-finite coordinates.
    bad = [list(p) for p in sphere[0]]
    bad[5][1] = float("nan")
    out.append(case("nan_off", "off", g.off_bytes((bad, sphere[1])), "error", fragment="non-finite"))
    out.append(case("nan_ply_binary", "ply", g.ply_bytes((bad, sphere[1]), True), "error", fragment="non-finite",
                    meshlab=True))
    bad[5][1] = float("inf")
    out.append(case("inf_obj", "obj", g.obj_bytes((bad, sphere[1])), "error", fragment="non-finite"))
    bad[5][1] = float("-inf")
    out.append(case("inf_ply_float", "ply", g.ply_bytes((bad, sphere[1]), True, "float"), "error",
                    fragment="non-finite", meshlab=True))
    # Remeshed on the normalised surface (issue 14): was refused ("the surface has no area").
    out.append(case("huge_coordinates", "ply", g.ply_bytes(g.transform(sphere, 1e300)), "ok", closed=True))

    # Polygons: triangulated.
    cube = g.quad_cube(4)
    out.append(case("quads_obj", "obj", g.obj_bytes(cube), "ok"))
    out.append(case("quads_off", "off", g.off_bytes(cube), "ok", meshlab=True))
    out.append(case("quads_ply", "ply", g.ply_bytes(cube, False), "ok", meshlab=True))
    # Polygons with straight corners (a vertex on the polygon's edge): a fan makes zero-area
    # triangles whose removal tore the cube open (issue 14). MeshLab fans them itself.
    pcube = g.polygon_cube(2)
    out.append(case("polygon_cube_off", "off", g.off_bytes(pcube), "ok", meshlab=True, closed=True))
    out.append(case("polygon_cube_ply", "ply", g.ply_bytes(pcube, False), "ok", meshlab=True, closed=True))
    out.append(case("polygon_cube_obj", "obj", g.obj_bytes(pcube), "ok", closed=True))

    # Concave polygons (issue 30): inexact ear clipping folded the C's cap (reflex corners on
    # diagonals, to rounding) and a fan folded every polygon over 256 corners: the prism came out
    # 14 % too large, or in pieces. The edges kept as features so that the area is the polygons'.
    # MeshLab's OFF importer triangulates the caps itself: through the filter, closed in and out.
    prism_args = ["--vertices", "1500", "--feature-angle", "45", "--cvt-iterations", "20", "--fcvt-iterations", "0",
                  "--lambda", "0"]
    for name, outline in (("c_prism", g.c_outline()), ("lobed_prism_300", g.lobed_outline(300))):
        prism = g.polygon_prism(outline)
        measures = g.polygon_prism_measures(outline) + (0.02,)
        out.append(case(name + "_obj", "obj", g.obj_bytes(prism), "ok", args=prism_args, closed=True, measures=measures))
        out.append(case(name + "_off", "off", g.off_bytes(prism), "ok", args=prism_args, closed=True, measures=measures,
                        meshlab=True))
        # MeshLab's PLY importer fans the caps (the C folded, lobes lost): the filter takes the
        # readers' triangulation of the layer's file instead.
        out.append(case(name + "_ply", "ply", g.ply_bytes(prism, False), "ok", args=prism_args, closed=True,
                        measures=measures, meshlab=True))

    # Topology.
    # Repaired by default since issue 17 (README, "Bad input"); refused as before with --no-repair.
    strict = FAST + ["--no-repair"]
    out.append(case("nonmanifold_edge", "off", g.off_bytes(g.nonmanifold_edge()), "ok", meshlab=True))
    out.append(case("nonmanifold_edge_strict", "off", g.off_bytes(g.nonmanifold_edge()), "error", args=strict,
                    fragment="non-manifold edge", meshlab=True))
    out.append(case("nonmanifold_vertex", "off", g.off_bytes(g.two_cones_at_apex(12)), "ok", meshlab=True))
    flipped = [list(t) for t in torus[1]]
    for i in rng.sample(range(len(flipped)), len(flipped) // 3):
        flipped[i] = flipped[i][::-1]
    out.append(case("inconsistent_orientation", "off", g.off_bytes((torus[0], flipped)), "ok", meshlab=True))
    out.append(case("moebius", "off", g.off_bytes(g.moebius()), "ok", meshlab=True))
    out.append(case("moebius_strict", "off", g.off_bytes(g.moebius()), "error", args=strict, fragment="not orientable",
                    meshlab=True))

    # Real-world inputs (issue 17): repaired into a manifold, oriented mesh.
    out.append(case("every_face_twice", "off", g.off_bytes(g.every_face_twice(sphere)), "ok", meshlab=True))
    out.append(case("fin_of_three_sheets", "off", g.off_bytes(g.fin_of_three_sheets()), "ok", meshlab=True))
    out.append(case("two_shells_sharing_an_edge", "ply", g.ply_bytes(g.two_shells_sharing_an_edge()), "ok",
                    meshlab=True))
    out.append(case("moebius_among_others", "off",
                    g.off_bytes(g.combine(sphere, g.transform(g.moebius(), 1, (3, 0, 0)), g.transform(torus, 1, (-3, 0, 0)))),
                    "ok", meshlab=True))
    out.append(case("seam_1e-12", "ply", g.ply_bytes(g.seam(1e-12)), "ok", meshlab=True))
    out.append(case("t_junction_crack", "ply", g.ply_bytes(g.seam(1e-13, fine=True)), "ok", meshlab=True))
    out.append(case("floaters_1000", "off", g.off_bytes(g.floaters(sphere)), "ok", meshlab=True))
    # 1000 comparable tiny components at 300 vertices: nothing can be kept, a clear error (was a
    # 3-vertex "mesh" of two coincident faces with exit 0).
    tiny_ones = g.combine(*[g.transform(g.tetrahedron(), 0.1, (i % 10, i // 10 % 10, i // 100)) for i in range(1000)])
    out.append(case("thousand_tiny_components_300", "off", g.off_bytes(tiny_ones), "error",
                    args=["--vertices", "300"] + FAST[2:], fragment="too small", meshlab=True))
    tiny = g.transform(g.icosphere(1), 1e-3, (3, 0, 0))
    out.append(case("two_components_one_tiny", "off", g.off_bytes(g.combine(sphere, tiny)), "ok", meshlab=True))
    out.append(case("two_components", "ply", g.ply_bytes(g.combine(sphere, g.transform(torus, 1, (4, 0, 0)))),
                    "ok", meshlab=True))
    out.append(case("duplicate_vertices_soup", "off", g.off_bytes(g.soup(torus)), "ok", meshlab=True))
    out.append(case("stl_soup_binary", "stl", g.stl_bytes(sphere, True), "ok"))
    out.append(case("stl_soup_ascii", "stl", g.stl_bytes(sphere, False), "ok"))
    dup_faces = (sphere[0], sphere[1] + sphere[1][:10] + [t[::-1] for t in sphere[1][10:20]])
    out.append(case("duplicate_faces", "ply", g.ply_bytes(dup_faces), "ok", meshlab=True))
    unref = (sphere[0] + [[9, 9, 9], [float("nan")] * 3], sphere[1])
    out.append(case("unreferenced_vertices", "obj", g.obj_bytes(unref), "ok"))
    needle = ([[0, 0, 0], [1, 0, 0], [0.5, 1, 0], [0.5, -1e-9, 0]], [[0, 1, 2], [1, 0, 3]])
    out.append(case("needle_face", "off", g.off_bytes(needle), "either", args=["--vertices", "4"] + FAST[2:]))
    out.append(case("single_triangle", "off", g.off_bytes(([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])),
                    "either", meshlab=True))
    out.append(case("tetrahedron_more_vertices_than_input", "off", g.off_bytes(g.tetrahedron()), "either"))
    out.append(case("open_grid", "obj", g.obj_bytes(g.grid(6)), "ok"))

    # Scale: far from the origin or tiny, the unit-scale result.
    out.append(case("unit_sphere", "ply", g.ply_bytes(sphere), "ok", meshlab=True))
    out.append(case("offset_1e6", "ply", g.ply_bytes(g.transform(sphere, 1, (1e6, -1e6, 1e6))), "ok",
                    meshlab=True, same_as=("unit_sphere", 1.0, (1e6, -1e6, 1e6))))
    out.append(case("scale_1e-6", "ply", g.ply_bytes(g.transform(sphere, 1e-6)), "ok",
                    meshlab=True, same_as=("unit_sphere", 1e-6, (0, 0, 0))))

    # Scale (issue 14): huge and tiny models are remeshed on the normalised surface, with the
    # field too. Through MeshLab (float coordinates) 1e30, 1e-30.
    field = ["--vertices", "60", "--cvt-iterations", "3", "--fcvt-iterations", "3"]
    for scale, meshlab in ((1e100, False), (1e-100, False), (1e155, False), (1e30, True), (1e-30, True)):
        out.append(case("scale_%g" % scale, "ply", g.ply_bytes(g.transform(sphere, scale)), "ok", args=field,
                        meshlab=meshlab, closed=True))

    # Valid files our readers refused or read short (issue 14).
    ply = g.ply_bytes(sphere, False).replace(b"format ascii 1.0\n", b"format ascii 1.0\ncomment no end_header here\n")
    out.append(case("ply_comment_end_header", "ply", ply, "ok", closed=True))
    out.append(case("obj_bom", "obj", b"\xef\xbb\xbf" + g.obj_bytes(sphere), "ok", closed=True))
    obj = g.obj_bytes(sphere).replace(b"\nf ", b"\nf \\\n  ")
    out.append(case("obj_backslash_continuation", "obj", obj, "ok", closed=True))
    stl = g.stl_bytes(sphere, False)
    out.append(case("stl_ascii_no_endsolid", "stl", stl[:stl.rindex(b"endsolid")].rstrip(b"\n"), "ok", closed=True,
                    warning="endsolid"))
    v, f = sphere
    extra = g.ply_bytes((v, f[:-3]), False) + b"".join(b"3 %d %d %d\n" % tuple(t) for t in f[-3:])
    out.append(case("ply_faces_after_count", "ply", extra, "either", warning="3 lines ignored"))

    # Parameters.
    def with_args(**over):
        a = dict(zip(FAST[0::2], FAST[1::2]))
        for k, v in over.items():
            a["--" + k.rstrip("_").replace("_", "-")] = v
        return [x for kv in a.items() for x in kv]

    sphere_off = g.off_bytes(sphere)
    out.append(case("vertices_2", "off", sphere_off, "error", args=with_args(vertices="2"), codes=(2,),
                    fragment="--vertices", meshlab=True))
    out.append(case("vertices_1e9", "off", sphere_off, "error", args=with_args(vertices="1000000000"), codes=(1, 2),
                    fragment="vertices", meshlab=True))
    out.append(case("vertices_negative", "off", sphere_off, "error", args=with_args(vertices="-5"), codes=(2,)))
    # One limit, one wording (issue 14): was "between 4 and 2147483647", then "at most 50000000".
    out.append(case("vertices_6e6", "off", sphere_off, "error", args=with_args(vertices="6000000"), codes=(2,),
                    fragment="between 4 and 5000000", meshlab=True, early=True))
    out.append(case("target_length_tiny", "off", sphere_off, "error", args=["--target-length", "1e-6"] + FAST[2:],
                    codes=(2,), fragment="between 4 and 5000000"))
    out.append(case("lambda_negative", "off", sphere_off, "error", args=with_args(lambda_="-1"), codes=(2,),
                    fragment="--lambda", meshlab=True))
    out.append(case("cvt_iterations_negative", "off", sphere_off, "error", args=with_args(cvt_iterations="-1"),
                    codes=(2,), meshlab=True))
    out.append(case("zero_iterations", "off", sphere_off, "ok", args=with_args(cvt_iterations="0")))

    # The field term on (default lambda and FCVT iterations) over repaired inputs.
    out.append(case("field_on_nonmanifold_vertex", "off", g.off_bytes(g.two_cones_at_apex(12)), "ok", args=field))
    out.append(case("field_on_two_components", "off", g.off_bytes(g.combine(sphere, tiny)), "ok", args=field))
    out.append(case("field_on_open_grid", "obj", g.obj_bytes(g.grid(6)), "ok", args=field))

    # Output side.
    for ext in ("ply", "off", "stl"):
        out.append(case("write_" + ext, "off", sphere_off, "ok", out_ext=ext))
    out.append(case("unwritable_output", "off", sphere_off, "error", out_ext="/nonexistent-dir/out.obj", early=True))
    # Found before the work (issue 14), and the input never overwritten.
    out.append(case("unwritable_proc", "off", sphere_off, "error", out_ext="/proc/x.ply", fragment="cannot write",
                    early=True))
    out.append(case("output_is_directory", "off", sphere_off, "error", out_ext="/proc", fragment="is a directory",
                    early=True))
    out.append(case("output_is_input", "off", sphere_off, "error", out_ext="@input", fragment="is the input",
                    early=True))
    out.append(case("output_is_link_to_input", "off", sphere_off, "error", out_ext="@link", fragment="is the input",
                    early=True))
    return out
