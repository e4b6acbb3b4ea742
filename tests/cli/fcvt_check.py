"""Helpers shared by the end-to-end CLI tests: run fcvt, read its PLY output, and measure a
triangle mesh in pure Python, independently of the C++ metrics."""
import json
import os
import math
import struct
import subprocess
import sys

METRIC_KEYS = ["q_min", "q_avg", "theta_min", "theta_min_avg", "theta_max",
               "pct_lt30", "pct_gt90", "v6_pct", "d_rms", "d_h", "d_boundary", "boundary_v4_pct"]

failures = []


def check(condition, message):
    """Records a failed expectation (all are reported, not just the first)."""
    if not condition:
        failures.append(message)
        print("FAIL: " + message)
    return condition


def finish():
    if failures:
        print(f"{len(failures)} check(s) failed")
        sys.exit(1)
    print("all checks passed")


def run(args, timeout=900):
    """Runs a command; returns (exit code, stdout, stderr) as text."""
    p = subprocess.run(args, capture_output=True, text=True, timeout=timeout)
    return p.returncode, p.stdout, p.stderr


def write_file(directory, name, data):
    """Writes bytes `data` to directory/name; returns the path."""
    path = os.path.join(directory, name)
    with open(path, "wb") as f:
        f.write(data)
    return path


def bad_mesh_files(directory):
    """Broken inputs every command that reads a mesh must refuse with one error line (exit 1):
    name -> path, written into `directory`."""
    return {
        "garbage": write_file(directory, "garbage.obj", b"\x00\x01garbage\nf 1 2 3\n"),
        "truncated": write_file(directory, "truncated.off", b"OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n"),
        "truncated_ply": write_file(directory, "truncated.ply",
                                    b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                                    b"property float y\nproperty float z\nelement face 1\n"
                                    b"property list uchar int vertex_indices\nend_header\n\x00\x00"),
        "empty": write_file(directory, "empty.stl", b""),
        "cloud": write_file(directory, "cloud.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\n"),
        "nan": write_file(directory, "nan.obj",
                          b"v 0 0 0\nv 1 0 0\nv 0 nan 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n"),
    }


def expect_error(fcvt, args, code, fragment=""):
    """`fcvt ARGS` fails with exit code `code` and exactly one line "fcvt: error: ..." on stderr
    (mentioning `fragment`), nothing on stdout."""
    got, stdout, stderr = run([fcvt] + args, timeout=300)
    lines = stderr.splitlines()
    label = " ".join(args)
    check(got == code, f"'{label}': exit code {got}, expected {code}")
    check(len(lines) == 1 and lines[0].startswith("fcvt: error: "), f"'{label}': stderr is not one error line: {stderr!r}")
    check(fragment in stderr, f"'{label}': stderr {stderr!r} does not mention {fragment!r}")
    check(stdout == "", f"'{label}': unexpected stdout {stdout!r}")


def run_ok(args, timeout=900):
    code, out, err = run(args, timeout)
    if code != 0:
        print(err, file=sys.stderr)
        raise SystemExit(f"command failed with exit code {code}: {' '.join(args)}")
    return out


def metrics_json(fcvt, mesh, ref=None):
    args = [fcvt, "metrics", mesh, "--json"] + (["--ref", ref] if ref else [])
    return json.loads(run_ok(args))


_PLY_TYPES = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I", "float": "f",
              "double": "d"}


def _read_fcvt_ply(path):
    """The binary little-endian PLY that fcvt writes: vertex scalars (double x y z, float extras),
    faces with their vertex_indices triangle, other lists (texcoord) skipped, and at most one
    scalar face property (e.g. --region's). Returns (vertex property names, one tuple per vertex,
    faces, face values or None)."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    assert header[1] == "format binary_little_endian 1.0", header[1]
    names, vertex_format, face_properties, element, nv, nf = [], "<", [], None, 0, 0
    for line in header:
        words = line.split()
        if words[0] == "element":
            element = words[1]
            nv = int(words[2]) if element == "vertex" else nv
            nf = int(words[2]) if element == "face" else nf
        elif words[0] == "property" and element == "vertex":
            vertex_format += _PLY_TYPES[words[1]]
            names.append(words[2])
        elif words[0] == "property" and element == "face":
            face_properties.append(words[1:])
    size = struct.calcsize(vertex_format)
    rows = [struct.unpack_from(vertex_format, data, end + i * size) for i in range(nv)]
    offset, faces, values = end + nv * size, [], []
    for _ in range(nf):
        for p in face_properties:
            if p[0] == "list":
                count = struct.unpack_from("<" + _PLY_TYPES[p[1]], data, offset)[0]
                offset += struct.calcsize(_PLY_TYPES[p[1]])
                items = struct.unpack_from("<%d%s" % (count, _PLY_TYPES[p[2]]), data, offset)
                offset += count * struct.calcsize(_PLY_TYPES[p[2]])
                if p[3] == "vertex_indices":
                    assert count == 3
                    faces.append(tuple(items))
            else:
                value = struct.unpack_from("<" + _PLY_TYPES[p[0]], data, offset)[0]
                offset += struct.calcsize(_PLY_TYPES[p[0]])
                values.append(value)
    scalars = sum(1 for p in face_properties if p[0] != "list")
    assert scalars <= 1, "at most one scalar face property"
    return names, rows, faces, values if scalars else None


def read_ply(path):
    """Reads the binary little-endian PLY that fcvt writes. Returns (vertices, faces)."""
    _, rows, faces, _ = _read_fcvt_ply(path)
    return [r[:3] for r in rows], faces


def read_ply_face_values(path):
    """The same, with the scalar face property fcvt wrote (--region's). Returns (vertices, faces,
    face values or None)."""
    _, rows, faces, values = _read_fcvt_ply(path)
    return [r[:3] for r in rows], faces, values


def read_ply_vertex_properties(path):
    """Reads the binary little-endian PLY that fcvt writes; returns (property names, one tuple of
    values per vertex, faces)."""
    names, rows, faces, _ = _read_fcvt_ply(path)
    return names, rows, faces


def edge_counts(faces):
    """Undirected edge (sorted ends) -> how many faces have it."""
    counts = {}
    for f in faces:
        for k in range(3):
            e = tuple(sorted((f[k], f[(k + 1) % 3])))
            counts[e] = counts.get(e, 0) + 1
    return counts


def is_subsequence(part, whole):
    """Every item of `part` occurs in `whole`, in the same order."""
    it = iter(whole)
    return all(any(x == y for y in it) for x in part)


FIELD_PROPERTIES = ["nx", "ny", "nz", "rosy_x", "rosy_y", "rosy_z"]


def check_field_properties(path, label, tolerance=1e-6):
    """The PLY at `path` has x y z and the six field properties; normals and directions are unit
    and orthogonal (to `tolerance`). Returns (rows by name, faces)."""
    names, rows, faces = read_ply_vertex_properties(path)
    if not check(names[:3] == ["x", "y", "z"] and all(n in names for n in FIELD_PROPERTIES),
                 f"{label}: vertex properties {names}, expected x y z + {' '.join(FIELD_PROPERTIES)}"):
        return None, faces
    index = {n: names.index(n) for n in names}
    bad_normal = bad_direction = bad_dot = 0
    worst = 0.0
    for r in rows:
        n = tuple(r[index[k]] for k in ("nx", "ny", "nz"))
        d = tuple(r[index[k]] for k in ("rosy_x", "rosy_y", "rosy_z"))
        errors = (abs(_norm(n) - 1), abs(_norm(d) - 1), abs(n[0] * d[0] + n[1] * d[1] + n[2] * d[2]))
        worst = max(worst, *errors)
        bad_normal += errors[0] > tolerance
        bad_direction += errors[1] > tolerance
        bad_dot += errors[2] > tolerance
    check(bad_normal == 0, f"{label}: {bad_normal} of {len(rows)} normals not unit (worst error {worst:.2e})")
    check(bad_direction == 0, f"{label}: {bad_direction} of {len(rows)} directions not unit (worst error {worst:.2e})")
    check(bad_dot == 0, f"{label}: {bad_dot} of {len(rows)} directions not orthogonal to the normal (worst {worst:.2e})")
    return [{n: r[index[n]] for n in names} for r in rows], faces


def euler_characteristic(faces):
    """V - E + F over the referenced vertices."""
    edges = edge_counts(faces)
    vertices = {v for f in faces for v in f}
    return len(vertices) - len(edges) + len(faces)


def _sub(p, q):
    return (p[0] - q[0], p[1] - q[1], p[2] - q[2])


def _norm(v):
    return math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])


def _angle(u, v):
    c = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) / (_norm(u) * _norm(v))
    return math.degrees(math.acos(max(-1.0, min(1.0, c))))


def measure(vertices, faces):
    """Q_avg, theta_min, %<30, V6% and topology, computed the paper's way (Q = 2 sqrt(3) |t| / (s h))."""
    q_sum, theta_min, lt30 = 0.0, 180.0, 0
    edges = {}
    for f in faces:
        p = [vertices[i] for i in f]
        lengths = [_norm(_sub(p[(k + 1) % 3], p[k])) for k in range(3)]
        cross_u, cross_v = _sub(p[1], p[0]), _sub(p[2], p[0])
        cross = (cross_u[1] * cross_v[2] - cross_u[2] * cross_v[1],
                 cross_u[2] * cross_v[0] - cross_u[0] * cross_v[2],
                 cross_u[0] * cross_v[1] - cross_u[1] * cross_v[0])
        area = 0.5 * _norm(cross)
        s, h = 0.5 * sum(lengths), max(lengths)
        q_sum += 2 * math.sqrt(3) * area / (s * h)
        angles = [_angle(_sub(p[(k + 1) % 3], p[k]), _sub(p[(k + 2) % 3], p[k])) for k in range(3)]
        theta_min = min(theta_min, min(angles))
        lt30 += min(angles) < 30
        for k in range(3):
            e = tuple(sorted((f[k], f[(k + 1) % 3])))
            edges[e] = edges.get(e, 0) + 1
    used = sorted({v for f in faces for v in f})
    boundary_edges = [e for e, n in edges.items() if n == 1]
    boundary_vertices = {v for e in boundary_edges for v in e}
    valence = {}
    for a, b in edges:
        valence[a] = valence.get(a, 0) + 1
        valence[b] = valence.get(b, 0) + 1
    interior = [v for v in used if v not in boundary_vertices]
    # Boundary loops: connected components of the boundary edge graph (manifold boundaries).
    parent = {}

    def find(x):
        while parent.setdefault(x, x) != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for a, b in boundary_edges:
        parent[find(a)] = find(b)
    loops = len({find(v) for v in boundary_vertices})
    chi = len(used) - len(edges) + len(faces)
    return {
        "q_avg": q_sum / len(faces),
        "theta_min": theta_min,
        "pct_lt30": 100.0 * lt30 / len(faces),
        "v6_pct": 100.0 * sum(valence[v] == 6 for v in interior) / max(1, len(interior)),
        "edges_manifold": all(n <= 2 for n in edges.values()),
        "boundary_loops": loops,
        "genus_if_connected": (2 - chi - loops) // 2,
    }


def read_obj(path):
    """(vertices, vt, faces as [(v, vt)] * 3, mtllib names, usemtl count); negative indices resolved."""
    v, vt, faces, libs, usemtl = [], [], [], [], 0
    for line in open(path):
        w = line.split()
        if not w:
            continue
        if w[0] == "v":
            v.append(tuple(float(x) for x in w[1:4]))
        elif w[0] == "vt":
            vt.append(tuple(float(x) for x in w[1:3]))
        elif w[0] == "mtllib":
            libs += w[1:]
        elif w[0] == "usemtl":
            usemtl += 1
        elif w[0] == "f":
            corners = []
            for c in w[1:]:
                p = c.split("/")
                iv = int(p[0]); it = int(p[1]) if len(p) > 1 and p[1] else 0
                corners.append((iv - 1 if iv > 0 else len(v) + iv, (it - 1 if it > 0 else len(vt) + it) if it else None))
            for k in range(1, len(corners) - 1):
                faces.append((corners[0], corners[k], corners[k + 1]))
    return v, vt, faces, libs, usemtl
