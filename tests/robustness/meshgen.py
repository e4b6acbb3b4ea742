"""Small meshes, good and bad, and their files in every format fcvt reads (python3 only, no
numpy). Shared by the robustness corpus (corpus.py), the CLI fuzzing loop (fuzz_cli.py) and
the seed corpus of the libFuzzer targets (fuzz/make_seeds.py).

A mesh is (vertices, faces): vertices a list of [x, y, z] floats, faces a list of index lists
(triangles, or polygons for the quad cases)."""
import math
import struct


# --- base meshes -----------------------------------------------------------------------------

def icosphere(levels=1, radius=1.0):
    t = (1.0 + math.sqrt(5.0)) / 2.0
    v = [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t],
         [0, -1, -t], [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]]
    f = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4],
         [11, 10, 2], [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8],
         [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1]]

    def unit(p):
        n = math.sqrt(sum(c * c for c in p))
        return [c / n for c in p]

    v = [unit(p) for p in v]
    for _ in range(levels):
        mid = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                v.append(unit([(v[a][k] + v[b][k]) / 2 for k in range(3)]))
                mid[key] = len(v) - 1
            return mid[key]

        nf = []
        for a, b, c in f:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            nf += [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
        f = nf
    return [[c * radius for c in p] for p in v], f


def uv_sphere(rings=12, segments=24, radius=1.0):
    """A closed UV sphere: two poles and rings x segments quads split into triangles."""
    v = [[0.0, 0.0, radius]]
    for i in range(1, rings):
        t = math.pi * i / rings
        v += [[radius * math.sin(t) * math.cos(2 * math.pi * j / segments),
               radius * math.sin(t) * math.sin(2 * math.pi * j / segments), radius * math.cos(t)] for j in range(segments)]
    v.append([0.0, 0.0, -radius])
    south = len(v) - 1

    def ring(i, j):
        return 1 + (i - 1) * segments + j % segments

    f = [[0, ring(1, j), ring(1, j + 1)] for j in range(segments)]
    for i in range(1, rings - 1):
        for j in range(segments):
            f += [[ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)], [ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)]]
    f += [[south, ring(rings - 1, j + 1), ring(rings - 1, j)] for j in range(segments)]
    return v, f


def torus(n=16, m=8, R=1.0, r=0.35):
    v = []
    for i in range(n):
        for j in range(m):
            u, w = 2 * math.pi * i / n, 2 * math.pi * j / m
            v.append([(R + r * math.cos(w)) * math.cos(u), (R + r * math.cos(w)) * math.sin(u), r * math.sin(w)])

    def idx(i, j):
        return (i % n) * m + (j % m)

    f = []
    for i in range(n):
        for j in range(m):
            f.append([idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)])
            f.append([idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)])
    return v, f


def grid(cells=4, size=1.0):
    v = [[size * i / cells, size * j / cells, 0.0] for j in range(cells + 1) for i in range(cells + 1)]

    def idx(i, j):
        return j * (cells + 1) + i

    f = []
    for j in range(cells):
        for i in range(cells):
            f.append([idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)])
            f.append([idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)])
    return v, f


def tetrahedron():
    return [[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]


def quad_cube(cells=4):
    """A closed cube made of quads (each side cells x cells), vertices shared."""
    index = {}
    v, f = [], []

    def vid(p):
        key = tuple(round(c * cells) for c in p)
        if key not in index:
            index[key] = len(v)
            v.append([c * 2 - 1 for c in p])
        return index[key]

    for axis in range(3):
        for side in (0, 1):
            for i in range(cells):
                for j in range(cells):
                    quad = []
                    for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
                        p = [0.0, 0.0, 0.0]
                        p[axis] = float(side)
                        p[(axis + 1) % 3] = (i + di) / cells
                        p[(axis + 2) % 3] = (j + dj) / cells
                        quad.append(vid(p))
                    f.append(quad if side == 1 else quad[::-1])
    return v, f


def polygon_cube(cells=2):
    """A closed cube whose six faces are single polygons of 4 * cells corners: the square's corners
    and cells - 1 vertices on each of its edges (straight, 180-degree corners), shared with the
    neighbouring faces. A fan from a polygon's first corner makes zero-area triangles here."""
    v, quads = quad_cube(cells)
    used = set()
    f = []
    for axis in range(3):
        for side in (0, 1):
            ring = []
            # The border of this side's grid, walked once around (counter-clockwise from outside).
            for i, j in ([(i, 0) for i in range(cells)] + [(cells, j) for j in range(cells)] +
                         [(i, cells) for i in range(cells, 0, -1)] + [(0, j) for j in range(cells, 0, -1)]):
                p = [0.0, 0.0, 0.0]
                p[axis] = float(side)
                p[(axis + 1) % 3] = i / cells
                p[(axis + 2) % 3] = j / cells
                ring.append(next(k for k, q in enumerate(v) if q == [c * 2 - 1 for c in p]))
            f.append(ring if side == 1 else ring[::-1])
            used.update(ring)
    keep = sorted(used)
    index = {old: new for new, old in enumerate(keep)}
    return [v[k] for k in keep], [[index[c] for c in face] for face in f]



def c_outline(step=20):
    """Issue 30's C: an annulus cut open, outer radius 1, inner radius exactly 0.5, corners every
    `step` degrees from 0 to 300, counter-clockwise. Its reflex corners lie on diagonals between
    other corners (to rounding): inexact ear clipping folded it."""
    outer = [(math.cos(math.radians(d)), math.sin(math.radians(d))) for d in range(0, 301, step)]
    inner = [(0.5 * math.cos(math.radians(d)), 0.5 * math.sin(math.radians(d))) for d in range(300, -1, -step)]
    return outer + inner


def lobed_outline(n=300, lobes=6):
    """n corners on a lobed curve, counter-clockwise: concave between the lobes (a fan folds it)."""
    out = []
    for i in range(n):
        a = 2 * math.pi * i / n
        r = 1 + 0.4 * math.cos(lobes * a)
        out.append((r * math.cos(a), r * math.sin(a)))
    return out


def polygon_prism(outline, height=0.3):
    """A closed prism over a counter-clockwise outline: its two caps single polygon faces, its
    sides quads, oriented outward."""
    n = len(outline)
    v = [[x, y, 0.0] for x, y in outline] + [[x, y, height] for x, y in outline]
    f = [list(range(n - 1, -1, -1)), list(range(n, 2 * n))]
    f += [[i, (i + 1) % n, n + (i + 1) % n, n + i] for i in range(n)]
    return v, f


def polygon_prism_measures(outline, height=0.3):
    """(surface area, volume) of polygon_prism(outline, height), from the outline's shoelace area."""
    cap = 0.5 * sum(a[0] * b[1] - a[1] * b[0] for a, b in zip(outline, outline[1:] + outline[:1]))
    perimeter = sum(math.dist(a, b) for a, b in zip(outline, outline[1:] + outline[:1]))
    return 2 * cap + height * perimeter, cap * height

def cone(apex, direction, k=10, apex_index=None, v=None, f=None):
    """Appends a closed cone (apex, ring of k, cap centre) to (v, f); returns them."""
    v = [] if v is None else v
    f = [] if f is None else f
    if apex_index is None:
        apex_index = len(v)
        v.append(list(apex))
    ring = len(v)
    for i in range(k):
        a = 2 * math.pi * i / k
        v.append([apex[0] + 0.5 * math.cos(a), apex[1] + 0.5 * math.sin(a), apex[2] + direction])
    cap = len(v)
    v.append([apex[0], apex[1], apex[2] + direction])
    for i in range(k):
        p, q = ring + i, ring + (i + 1) % k
        if direction > 0:
            f += [[apex_index, q, p], [cap, p, q]]
        else:
            f += [[apex_index, p, q], [cap, q, p]]
    return v, f


def two_cones_at_apex(k=10):
    v, f = cone((0, 0, 0), 1.0, k)
    return cone((0, 0, 0), -1.0, k, apex_index=0, v=v, f=f)


def nonmanifold_edge():
    """A sphere with a fin: a third face on one of its edges."""
    v, f = icosphere(1)
    a, b = f[0][0], f[0][1]
    v.append([2 * c for c in v[a]])
    f.append([a, b, len(v) - 1])
    return v, f


def moebius(n=24, width=0.3):
    v = []
    for i in range(n):
        u = 2 * math.pi * i / n
        for s in (-width, width):
            v.append([(1 + s * math.cos(u / 2)) * math.cos(u), (1 + s * math.cos(u / 2)) * math.sin(u), s * math.sin(u / 2)])
    f = []
    for i in range(n):
        a, b = 2 * i, 2 * i + 1
        c, d = (2 * (i + 1), 2 * (i + 1) + 1) if i + 1 < n else (1, 0)
        f += [[a, c, d], [a, d, b]]
    return v, f


def every_face_twice(mesh):
    """Each face stored twice, in turn reversed and as it is (double-sided game assets)."""
    v, f = mesh
    return [list(p) for p in v], [list(t) for t in f] + [t[::-1] if i % 2 == 0 else list(t) for i, t in enumerate(f)]


def fin_of_three_sheets(rows=3):
    """Three rectangular sheets (rows x 1 quads, triangulated) hanging from one line of edges."""
    v = [[0.0, 0.0, j / rows] for j in range(rows + 1)]
    f = []
    for s in range(3):
        a = 2 * math.pi * s / 3
        o = len(v)
        v += [[math.cos(a), math.sin(a), j / rows] for j in range(rows + 1)]
        for j in range(rows):
            f += [[j, o + j, o + j + 1], [j, o + j + 1, j + 1]]
    return v, f


def two_shells_sharing_an_edge(cells=3):
    """Two closed quad cubes (triangulated) touching along one edge, vertices shared there."""
    v1, q1 = quad_cube(cells)
    v2 = [[p[0] + 2, p[1] + 2, p[2]] for p in v1]  # the cube [-1, 1]^3 and [1, 3]^2 x [-1, 1]
    v, f = combine((v1, triangulate(q1)), (v2, triangulate(q1)))
    return weld_exact((v, f))


def triangulate(polygons):
    return [[p[0], p[i], p[i + 1]] for p in polygons for i in range(1, len(p) - 1)]


def weld_exact(mesh):
    """Vertices at the same coordinates merged into the first."""
    v, f = mesh
    index, nv, remap = {}, [], []
    for p in v:
        key = tuple(p)
        if key not in index:
            index[key] = len(nv)
            nv.append(list(p))
        remap.append(index[key])
    return nv, [[remap[c] for c in t] for t in f]


def seam(gap=1e-12, cells=6, fine=False):
    """A unit square as two halves, the right one with its own vertices `gap` to the right of the
    left one's along x = 0.5 (fine: twice as many there, a T-junction crack)."""
    lv, lf = grid(cells)
    rv, rf = grid(2 * cells if fine else cells)
    lv = [[0.5 * p[0], p[1], p[2]] for p in lv]
    rv = [[0.5 + gap + 0.5 * p[0], p[1], p[2]] for p in rv]
    return combine((lv, lf), (rv, rf))


def floaters(main, count=1000, size=1e-3, at=(2.0, 0.0, 0.0)):
    """`main` and `count` tiny tetrahedra beside it."""
    parts = [main]
    for i in range(count):
        parts.append(transform(tetrahedron(), size, (at[0] + 0.01 * (i % 10), at[1] + 0.01 * (i // 10 % 10),
                                                    at[2] + 0.01 * (i // 100))))
    return combine(*parts)


def soup(mesh):
    """Every face with its own vertices (exact duplicates at shared corners)."""
    v, f = mesh
    nv, nf = [], []
    for face in f:
        nf.append([])
        for c in face:
            nf[-1].append(len(nv))
            nv.append(list(v[c]))
    return nv, nf


def combine(*meshes):
    v, f = [], []
    for mv, mf in meshes:
        o = len(v)
        v += [list(p) for p in mv]
        f += [[c + o for c in face] for face in mf]
    return v, f


def transform(mesh, scale=1.0, offset=(0.0, 0.0, 0.0)):
    v, f = mesh
    return [[p[k] * scale + offset[k] for k in range(3)] for p in v], [list(t) for t in f]


# --- writers (bytes) -------------------------------------------------------------------------

def fmt(x):
    return repr(float(x)) if math.isfinite(x) else ("nan" if x != x else ("inf" if x > 0 else "-inf"))


def obj_bytes(mesh):
    v, f = mesh
    lines = ["# fcvt robustness"]
    lines += ["v %s %s %s" % tuple(fmt(c) for c in p) for p in v]
    lines += ["f " + " ".join(str(c + 1) for c in face) for face in f]
    return ("\n".join(lines) + "\n").encode()


def off_bytes(mesh):
    v, f = mesh
    lines = ["OFF", "%d %d 0" % (len(v), len(f))]
    lines += ["%s %s %s" % tuple(fmt(c) for c in p) for p in v]
    lines += [" ".join(str(x) for x in [len(face)] + list(face)) for face in f]
    return ("\n".join(lines) + "\n").encode()


def ply_bytes(mesh, binary=True, scalar="double"):
    v, f = mesh
    head = ["ply", "format binary_little_endian 1.0" if binary else "format ascii 1.0",
            "element vertex %d" % len(v)]
    head += ["property %s %s" % (scalar, c) for c in "xyz"]
    head += ["element face %d" % len(f), "property list uchar int vertex_indices", "end_header"]
    out = ("\n".join(head) + "\n").encode()
    if binary:
        if scalar == "double":
            body = b"".join(struct.pack("<3d", *p) for p in v)
        else:
            body = b"".join(struct.pack("<3f", *map(f32, p)) for p in v)
        body += b"".join(struct.pack("<B%di" % len(face), len(face), *face) for face in f)
        return out + body
    lines = ["%s %s %s" % tuple(fmt(c) for c in p) for p in v]
    lines += [" ".join(str(x) for x in [len(face)] + list(face)) for face in f]
    return out + ("\n".join(lines) + "\n").encode()


def f32(x):
    """x as a float32 value (overflow to infinity, as a C cast would)."""
    try:
        return struct.unpack("<f", struct.pack("<f", x))[0]
    except OverflowError:
        return math.copysign(math.inf, x)


def stl_bytes(mesh, binary=True):
    v, f = mesh
    tris = [t for t in f if len(t) == 3 and all(0 <= c < len(v) for c in t)]  # STL has no indices
    if binary:
        out = b"fcvt robustness".ljust(80, b" ") + struct.pack("<I", len(tris))
        for t in tris:
            out += struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *map(f32, v[c])) for c in t) + b"\0\0"
        return out
    lines = ["solid fcvt"]
    for t in tris:
        lines += ["facet normal 0 0 0", "outer loop"] + ["vertex %s %s %s" % tuple(fmt(c) for c in v[c]) for c in t]
        lines += ["endloop", "endfacet"]
    lines.append("endsolid fcvt")
    return ("\n".join(lines) + "\n").encode()


def mesh_bytes(mesh, ext, variant=0):
    """File bytes for extension ext; variant picks ascii/binary (PLY, STL) and float/double."""
    if ext == "obj":
        return obj_bytes(mesh)
    if ext == "off":
        return off_bytes(mesh)
    if ext == "ply":
        return ply_bytes(mesh, binary=variant % 3 != 2, scalar="float" if variant % 3 == 1 else "double")
    if ext == "stl":
        return stl_bytes(mesh, binary=variant % 2 == 0)
    raise ValueError(ext)


# --- reading fcvt's output -------------------------------------------------------------------

def read_obj(path):
    v, f = [], []
    with open(path, "r", errors="replace") as fh:
        for line in fh:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                v.append([float(x) for x in parts[1:4]])
            elif parts[0] == "f":
                f.append([int(p.split("/")[0]) - 1 for p in parts[1:]])
    return v, f


def boundary_loops_and_components(mesh):
    """(boundary loops, connected components through shared edges) of a manifold triangle mesh."""
    v, f = mesh
    edges = {}
    for i, t in enumerate(f):
        for k in range(3):
            edges.setdefault((min(t[k], t[(k + 1) % 3]), max(t[k], t[(k + 1) % 3])), []).append(i)
    parent = list(range(len(v)))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    border = [e for e, faces in edges.items() if len(faces) == 1]
    for a, b in border:
        parent[find(a)] = find(b)
    loops = len({find(a) for a, _ in border})
    parent = list(range(len(f)))
    for faces in edges.values():
        for other in faces[1:]:
            parent[find(faces[0])] = find(other)
    return loops, len({find(i) for i in range(len(f))})



def area_and_volume(mesh):
    """(surface area, signed enclosed volume) of a mesh of triangles or polygons (fanned)."""
    v, f = mesh
    area = volume = 0.0
    for t in f:
        for k in range(1, len(t) - 1):
            a, b, c = v[t[0]], v[t[k]], v[t[k + 1]]
            u = [b[i] - a[i] for i in range(3)]
            w = [c[i] - a[i] for i in range(3)]
            n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
            area += 0.5 * math.sqrt(sum(x * x for x in n))
            volume += sum(a[i] * n[i] for i in range(3)) / 6
    return area, volume

def manifold_problems(mesh):
    """Why a mesh is not a valid manifold triangle mesh (empty list if it is one)."""
    v, f = mesh
    problems = []
    if not f:
        problems.append("no faces")
    for p in v:
        if not all(math.isfinite(c) for c in p):
            problems.append("non-finite vertex %r" % (p,))
            break
    edges = {}
    for i, t in enumerate(f):
        if len(t) != 3 or len(set(t)) != 3 or any(c < 0 or c >= len(v) for c in t):
            problems.append("bad face %d %r" % (i, t))
            continue
        for k in range(3):
            a, b = t[k], t[(k + 1) % 3]
            edges.setdefault((min(a, b), max(a, b)), []).append(i)
    bad_edges = [e for e, faces in edges.items() if len(faces) > 2]
    if bad_edges:
        problems.append("%d non-manifold edges, e.g. %r" % (len(bad_edges), bad_edges[0]))
    # Vertex fans: faces around a vertex joined across the edges they share.
    around = {}
    for i, t in enumerate(f):
        if len(t) == 3 and len(set(t)) == 3:
            for c in t:
                around.setdefault(c, []).append(i)
    bad_vertices = 0
    for c, faces in around.items():
        parent = {x: x for x in faces}

        def find(x):
            while parent[x] != x:
                parent[x] = parent[parent[x]]
                x = parent[x]
            return x

        for i in faces:
            for j in faces:
                if i < j and len(set(f[i]) & set(f[j])) >= 2:
                    parent[find(i)] = find(j)
        if len({find(x) for x in faces}) > 1:
            bad_vertices += 1
    if bad_vertices:
        problems.append("%d non-manifold vertices" % bad_vertices)
    return problems
