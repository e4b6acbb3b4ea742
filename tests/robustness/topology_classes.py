"""Issue 52 ("topology first"): inputs whose topology a remesher at a few hundred vertices easily
breaks, and the measures that say whether an output kept it (python3 only, no numpy).

Generators (closed, manifold, oriented meshes, no two vertices at the same place):
  plate_with_holes(holes=30)   a thin closed plate with 30 narrow through-holes (genus 30)
  small_shells(count=100)      100 small closed spheres at scattered places, each about 1 % of
                               the area (each a part)
  chair()                      a seat, a back and 4 thin legs: 6 separate closed boxes, the
                               legs and the back a narrow gap away from the seat
  thin_handle_torus(genus=20)  the boundary of a 5 x 4 grid frame of thin bars (genus 20)
CLASSES maps each name to (generator, file extension, expected shells, genus of each shell).

Measures: read_mesh (OBJ, OFF, PLY, STL; exact duplicate vertices welded), shells (per connected
component: vertices, faces, area, boundary loops, genus, manifold, oriented), SurfaceIndex (the
closest input triangle to a point, for matching output pieces to input parts).

  python3 topology_classes.py [OUTDIR]   checks every generator (and writes them to OUTDIR)
"""
import math
import os
import random
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import meshgen  # noqa: E402


# --- generators ------------------------------------------------------------------------------

def segments(spans, max_cell):
    """Grid lines along one axis from (width, kind) spans, each cut into cells of at most
    max_cell: (coordinates, the kind of each cell)."""
    coords, kinds, x = [0.0], [], 0.0
    for width, kind in spans:
        cells = max(1, int(math.ceil(width / max_cell - 1e-9)))
        for c in range(cells):
            coords.append(x + width * (c + 1) / cells)
            kinds.append(kind)
        x += width
    return coords, kinds


def voxel_surface(xs, ys, zs, filled):
    """The boundary of a union of grid cells (cell (i, j, k) spans xs[i]..xs[i+1] and so on;
    filled(i, j, k) says whether it is solid): each cell side between a solid and an empty cell
    as two triangles, oriented outward, vertices shared through their grid indices. The caller
    keeps cells from touching along an edge or at a corner only (that would be non-manifold)."""
    lines = (xs, ys, zs)
    size = (len(xs) - 1, len(ys) - 1, len(zs) - 1)

    def solid(c):
        return all(0 <= c[a] < size[a] for a in range(3)) and filled(*c)

    index, v, f = {}, [], []

    def vid(g):
        if g not in index:
            index[g] = len(v)
            v.append([lines[a][g[a]] for a in range(3)])
        return index[g]

    for i in range(size[0]):
        for j in range(size[1]):
            for k in range(size[2]):
                c = (i, j, k)
                if not solid(c):
                    continue
                for a in range(3):
                    b, d = (a + 1) % 3, (a + 2) % 3
                    for side in (0, 1):
                        n = list(c)
                        n[a] += 1 if side else -1
                        if solid(tuple(n)):
                            continue
                        quad = []
                        for db, dd in ((0, 0), (1, 0), (1, 1), (0, 1)):  # counter-clockwise seen from +a
                            g = list(c)
                            g[a] += side
                            g[b] += db
                            g[d] += dd
                            quad.append(vid(tuple(g)))
                        if not side:
                            quad.reverse()
                        f += [[quad[0], quad[1], quad[2]], [quad[0], quad[2], quad[3]]]
    return v, f


def box(lo, hi, max_cell):
    """A closed box from corner lo to corner hi, its sides cut into cells of at most max_cell."""
    xs, ys, zs = (segments([(hi[a] - lo[a], 0)], max_cell)[0] for a in range(3))
    v, f = voxel_surface(xs, ys, zs, lambda i, j, k: True)
    return meshgen.transform((v, f), 1.0, lo)


def _factor(n):
    """(a, b) with a * b = n, a >= b, as close to square as n allows."""
    b = int(math.isqrt(n))
    while n % b:
        b -= 1
    return n // b, b


def plate_with_holes(holes=30, bar=1.0, hole=0.2, thickness=0.08, max_cell=0.25):
    """A closed plate (thickness `thickness`) with `holes` square through-holes of side `hole`
    in a grid, `bar` of solid plate between them and around them: genus `holes`. The area is
    about 2 (7 + 6 hole)(6 + 5 hole) bar^2 for 30 holes (about 110 with the defaults: an edge
    length of 0.65 at 300 vertices, 0.36 at 1000, 0.26 at 2000)."""
    nx, ny = _factor(holes)
    xs, kx = segments([(bar, 0), (hole, 1)] * nx + [(bar, 0)], max_cell)
    ys, ky = segments([(bar, 0), (hole, 1)] * ny + [(bar, 0)], max_cell)
    return voxel_surface(xs, ys, [0.0, thickness], lambda i, j, k: not (kx[i] and ky[j]))


def thin_handle_torus(genus=20, bar=0.1, opening=1.0, max_cell=0.1):
    """The boundary of a grid frame of square bars (side `bar`) around `genus` openings (5 x 4
    for 20) of side `opening`: genus `genus`, every handle a bar thinner than the edge length
    (the area is about 22 for 20 handles: an edge length of 0.29 at 300 vertices, 0.16 at 1000)."""
    nx, ny = _factor(genus)
    xs, kx = segments([(bar, 0), (opening, 1)] * nx + [(bar, 0)], max_cell)
    ys, ky = segments([(bar, 0), (opening, 1)] * ny + [(bar, 0)], max_cell)
    return voxel_surface(xs, ys, [0.0, bar], lambda i, j, k: not (kx[i] and ky[j]))


def small_shells(count=100, radius=0.1, spacing=0.5, seed=52):
    """`count` closed icospheres (162 vertices each) of radius `radius`
    (within +-10 %) at jittered grid places `spacing` apart: each about 1/count of the area."""
    rng = random.Random(seed)
    side = int(math.ceil(count ** (1 / 3)))
    sphere = meshgen.icosphere(2)
    parts = []
    for s in range(count):
        i, j, k = s % side, s // side % side, s // (side * side)
        r = radius * (0.9 + 0.2 * rng.random())
        centre = [spacing * (i + 0.3 * (rng.random() - 0.5)), spacing * (j + 0.3 * (rng.random() - 0.5)),
                  spacing * (k + 0.3 * (rng.random() - 0.5))]
        parts.append(meshgen.transform(sphere, r, centre))
    return meshgen.combine(*parts)


def chair(gap=0.02, leg=0.06, max_cell=0.1):
    """A chair as 6 separate closed boxes: a seat (1 x 1 x 0.08 at height 0.5), a back (1 x 0.08
    x 0.9) and 4 legs (leg x leg x 0.48), the back and the legs `gap` away from the seat (an asset
    of several objects). Area about 4.8: an edge length of 0.14 at 300 vertices (legs thinner
    than that, gaps far narrower), 0.074 at 1000."""
    seat_bottom, seat_top = 0.5, 0.58
    parts = [box((0.0, 0.0, seat_bottom), (1.0, 1.0, seat_top), max_cell),
             box((0.0, 0.92, seat_top + gap), (1.0, 1.0, seat_top + gap + 0.9), max_cell)]
    for x, y in ((0.05, 0.05), (0.89, 0.05), (0.05, 0.89), (0.89, 0.89)):
        parts.append(box((x, y, 0.0), (x + leg, y + leg, seat_bottom - gap), max_cell))
    return meshgen.combine(*parts)


# name -> (generator, file extension, expected closed shells, genus of each)
CLASSES = {
    "plate_with_holes": (plate_with_holes, "ply", 1, 30),
    "small_shells": (small_shells, "ply", 100, 0),
    "chair": (chair, "obj", 6, 0),
    "thin_handle_torus": (thin_handle_torus, "ply", 1, 20),
}


# --- measures --------------------------------------------------------------------------------

def weld(mesh):
    """Exact duplicate vertices merged, unreferenced vertices dropped, faces with a repeated
    corner dropped."""
    v, f = mesh
    index, nv, remap = {}, [], {}
    used = sorted({c for t in f for c in t})
    for c in used:
        key = tuple(v[c])
        if key not in index:
            index[key] = len(nv)
            nv.append(list(v[c]))
        remap[c] = index[key]
    nf = []
    for t in f:
        face = [remap[c] for c in t]
        if len(set(face)) == len(face):
            nf.append(face)
    return nv, nf


def weld_border(mesh, distance):
    """Border vertices (on an edge of one face) within `distance` of each other merged (a crack
    or seam closed, as fcvt's repair welds them); faces left with a repeated corner dropped."""
    v, f = mesh
    count = {}
    for t in f:
        for k in range(3):
            e = (min(t[k], t[(k + 1) % 3]), max(t[k], t[(k + 1) % 3]))
            count[e] = count.get(e, 0) + 1
    border = sorted({c for e, n in count.items() if n == 1 for c in e})
    if not border:
        return mesh
    parent = {c: c for c in border}

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    grid = {}
    for c in border:
        grid.setdefault(tuple(int(math.floor(x / distance)) for x in v[c]), []).append(c)
    for c in border:
        g = tuple(int(math.floor(x / distance)) for x in v[c])
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for o in grid.get((g[0] + dx, g[1] + dy, g[2] + dz), ()):
                        if o > c and math.dist(v[c], v[o]) <= distance:
                            parent[find(c)] = find(o)
    remap = {c: find(c) for c in border}
    nf = []
    for t in f:
        face = [remap.get(c, c) for c in t]
        if len(set(face)) == 3:
            nf.append(face)
    return weld(([list(p) for p in v], nf))


def split_fans(mesh):
    """A copy of the mesh with each non-manifold vertex split into one vertex per fan of faces
    (faces around it joined through the edges they share), as fcvt's repair does: the surface
    whose per-shell genus and loops a remesher can keep. Non-manifold edges stay."""
    v, f = mesh
    around = {}
    for i, t in enumerate(f):
        for c in t:
            around.setdefault(c, []).append(i)
    nv, nf = [list(p) for p in v], [list(t) for t in f]
    for c, fan in around.items():
        if len(fan) < 2:
            continue
        parent = {x: x for x in fan}

        def find(x):
            while parent[x] != x:
                parent[x] = parent[parent[x]]
                x = parent[x]
            return x

        by_other = {}
        for x in fan:
            for o in f[x]:
                if o != c:
                    by_other.setdefault(o, []).append(x)
        for faces in by_other.values():
            for y in faces[1:]:
                parent[find(faces[0])] = find(y)
        roots = {}
        for x in fan:
            roots.setdefault(find(x), []).append(x)
        for faces in list(roots.values())[1:]:
            nv.append(list(v[c]))
            for x in faces:
                nf[x] = [len(nv) - 1 if k == c else k for k in nf[x]]
    return nv, nf


def shells(mesh):
    """Per connected component (faces joined through shared edges), largest area first: a dict
    with faces (indices into mesh's faces), vertices (set), area, centre, loops (boundary loops), chi,
    genus (None unless manifold and oriented), manifold, oriented, closed. Faces must be
    triangles (polygons are fanned by the readers)."""
    v, f = mesh
    edges = {}
    directed = {}
    for i, t in enumerate(f):
        for k in range(3):
            a, b = t[k], t[(k + 1) % 3]
            edges.setdefault((min(a, b), max(a, b)), []).append(i)
            directed[(a, b)] = directed.get((a, b), 0) + 1
    parent = list(range(len(f)))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for faces in edges.values():
        for other in faces[1:]:
            ra, rb = find(faces[0]), find(other)
            if ra != rb:
                parent[ra] = rb
    groups = {}
    for i in range(len(f)):
        groups.setdefault(find(i), []).append(i)
    # Non-manifold vertices: faces around a vertex in more than one fan.
    around = {}
    for i, t in enumerate(f):
        for c in t:
            around.setdefault(c, []).append(i)
    out = []
    for faces in groups.values():
        verts = {c for i in faces for c in f[i]}
        comp_edges = {(min(f[i][k], f[i][(k + 1) % 3]), max(f[i][k], f[i][(k + 1) % 3])) for i in faces for k in range(3)}
        border = [e for e in comp_edges if len(edges[e]) == 1]
        manifold = all(len(edges[e]) <= 2 for e in comp_edges)
        oriented = all(directed.get(e, 0) <= 1 and directed.get(e[::-1], 0) <= 1 for e in comp_edges)
        if manifold:
            for c in verts:
                fan = around[c]
                if len(fan) < 2:
                    continue
                p = {x: x for x in fan}

                def fnd(x):
                    while p[x] != x:
                        p[x] = p[p[x]]
                        x = p[x]
                    return x

                for x in fan:
                    for k in range(3):
                        a, b = f[x][k], f[x][(k + 1) % 3]
                        if c in (a, b):
                            for y in edges[(min(a, b), max(a, b))]:
                                if y != x:
                                    p[fnd(x)] = fnd(y)
                if len({fnd(x) for x in fan}) > 1:
                    manifold = False
                    break
        bp = {}

        def bfind(x):
            while bp.setdefault(x, x) != x:
                bp[x] = bp[bp[x]]
                x = bp[x]
            return x

        for a, b in border:
            bp[bfind(a)] = bfind(b)
        loops = len({bfind(a) for e in border for a in e})
        chi = len(verts) - len(comp_edges) + len(faces)
        area = sum(triangle_area(v, f[i]) for i in faces)
        genus = (2 - chi - loops) // 2 if manifold and oriented and (2 - chi - loops) % 2 == 0 else None
        centre = [sum(v[c][k] for c in verts) / len(verts) for k in range(3)]
        out.append({"faces": faces, "vertices": verts, "area": area, "centre": centre, "loops": loops, "chi": chi, "genus": genus,
                    "manifold": manifold, "oriented": oriented, "closed": not border})
    out.sort(key=lambda s: -s["area"])
    return out


def triangle_area(v, t):
    a, b, c = v[t[0]], v[t[1]], v[t[2]]
    u = (b[0] - a[0], b[1] - a[1], b[2] - a[2])
    w = (c[0] - a[0], c[1] - a[1], c[2] - a[2])
    n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
    return 0.5 * math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2])


def closest_on_triangle(p, a, b, c):
    """Squared distance from p to the triangle abc (Ericson's regions)."""
    ab = (b[0] - a[0], b[1] - a[1], b[2] - a[2])
    ac = (c[0] - a[0], c[1] - a[1], c[2] - a[2])
    ap = (p[0] - a[0], p[1] - a[1], p[2] - a[2])
    d1 = ab[0] * ap[0] + ab[1] * ap[1] + ab[2] * ap[2]
    d2 = ac[0] * ap[0] + ac[1] * ap[1] + ac[2] * ap[2]
    if d1 <= 0 and d2 <= 0:
        q = a
    else:
        bp = (p[0] - b[0], p[1] - b[1], p[2] - b[2])
        d3 = ab[0] * bp[0] + ab[1] * bp[1] + ab[2] * bp[2]
        d4 = ac[0] * bp[0] + ac[1] * bp[1] + ac[2] * bp[2]
        cp = (p[0] - c[0], p[1] - c[1], p[2] - c[2])
        d5 = ab[0] * cp[0] + ab[1] * cp[1] + ab[2] * cp[2]
        d6 = ac[0] * cp[0] + ac[1] * cp[1] + ac[2] * cp[2]
        vc = d1 * d4 - d3 * d2
        vb = d5 * d2 - d1 * d6
        va = d3 * d6 - d5 * d4
        if d3 >= 0 and d4 <= d3:
            q = b
        elif d6 >= 0 and d5 <= d6:
            q = c
        elif vc <= 0 and d1 >= 0 and d3 <= 0:
            t = d1 / (d1 - d3)
            q = (a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2])
        elif vb <= 0 and d2 >= 0 and d6 <= 0:
            t = d2 / (d2 - d6)
            q = (a[0] + t * ac[0], a[1] + t * ac[1], a[2] + t * ac[2])
        elif va <= 0 and (d4 - d3) >= 0 and (d5 - d6) >= 0:
            t = (d4 - d3) / ((d4 - d3) + (d5 - d6))
            q = (b[0] + t * (c[0] - b[0]), b[1] + t * (c[1] - b[1]), b[2] + t * (c[2] - b[2]))
        else:
            s = va + vb + vc
            if s == 0:  # a degenerate triangle: its corners
                return min(sum((p[k] - x[k]) ** 2 for k in range(3)) for x in (a, b, c))
            vv, ww = vb / s, vc / s
            q = (a[0] + ab[0] * vv + ac[0] * ww, a[1] + ab[1] * vv + ac[1] * ww, a[2] + ab[2] * vv + ac[2] * ww)
    return (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2 + (p[2] - q[2]) ** 2


class SurfaceIndex:
    """The triangles of a mesh in a uniform grid; nearest(p) gives (distance, face index) of the
    closest triangle to p, exactly."""

    def __init__(self, mesh):
        self.v, self.f = mesh
        lo = [min(p[k] for p in self.v) for k in range(3)]
        hi = [max(p[k] for p in self.v) for k in range(3)]
        diag = math.dist(lo, hi) or 1.0
        extent = sum(max(self.v[c][k] for c in t) - min(self.v[c][k] for c in t) for t in self.f for k in range(3))
        h = max(extent / max(1, 3 * len(self.f)), diag / 400)
        # At most about 8 cells a face in all.
        volume = max(1e-300, (hi[0] - lo[0] + h) * (hi[1] - lo[1] + h) * (hi[2] - lo[2] + h))
        h = max(h, (volume / (8.0 * len(self.f) + 1)) ** (1 / 3))
        self.h, self.lo = h, lo
        self.cells = {}
        for i, t in enumerate(self.f):
            a = [int((min(self.v[c][k] for c in t) - lo[k]) / h) for k in range(3)]
            b = [int((max(self.v[c][k] for c in t) - lo[k]) / h) for k in range(3)]
            for x in range(a[0], b[0] + 1):
                for y in range(a[1], b[1] + 1):
                    for z in range(a[2], b[2] + 1):
                        self.cells.setdefault((x, y, z), []).append(i)
        self.size = [int((hi[k] - lo[k]) / h) + 1 for k in range(3)]

    def nearest(self, p):
        h = self.h
        c = [int(math.floor((p[k] - self.lo[k]) / h)) for k in range(3)]
        best, best_face, seen = math.inf, -1, set()
        # The cell grid's distance from p: rings until the next ring is farther than the best.
        outside = math.sqrt(sum(max(0.0, self.lo[k] - p[k], p[k] - (self.lo[k] + self.size[k] * h)) ** 2 for k in range(3)))
        start = max(0, int(outside / h) - 1)
        limit = max(self.size) + abs(c[0]) + abs(c[1]) + abs(c[2]) + 2
        r = start
        while r <= limit:
            if best_face >= 0 and (r - 1) * h > math.sqrt(best):
                break
            for x in range(c[0] - r, c[0] + r + 1):
                if x < 0 or x >= self.size[0]:
                    continue
                for y in range(c[1] - r, c[1] + r + 1):
                    if y < 0 or y >= self.size[1]:
                        continue
                    edge = abs(x - c[0]) == r or abs(y - c[1]) == r
                    zs = range(c[2] - r, c[2] + r + 1) if edge else (c[2] - r, c[2] + r)
                    for z in zs:
                        for i in self.cells.get((x, y, z), ()):
                            if i in seen:
                                continue
                            seen.add(i)
                            t = self.f[i]
                            d = closest_on_triangle(p, self.v[t[0]], self.v[t[1]], self.v[t[2]])
                            if d < best:
                                best, best_face = d, i
            r += 1
        return math.sqrt(best), best_face


# --- comparing an output with its input ------------------------------------------------------

PART_SHARE = 0.005  # a part: a connected component with at least this share of the input's area


def holes_closed(report, stderr=""):
    """How many holes fcvt closed by design: a report key (any key with "hole" and "closed" in
    its name holding a count) or else the warning "N holes under ... closed"."""
    found = []

    def walk(d):
        if isinstance(d, dict):
            for k, x in d.items():
                lk = k.lower()
                if "hole" in lk and "closed" in lk and isinstance(x, int) and not isinstance(x, bool):
                    found.append(x)
                else:
                    walk(x)

    walk(report or {})
    if found:
        return max(found)
    import re
    texts = list((report or {}).get("warnings", [])) + stderr.splitlines()
    counts = [int(m.group(1)) for t in texts for m in [re.search(r"(\d+) holes? under .* closed", t)] if m]
    return max(counts) if counts else 0


def added_vertices(report):
    """The vertices the report says were added beyond N: the sum of its "added_vertices" keys
    (thin_parts' and any other section's; the repair's vertex copies are not among them)."""
    total = 0

    def walk(d):
        nonlocal total
        if isinstance(d, dict):
            for k, x in d.items():
                if k == "added_vertices" and isinstance(x, (int, float)) and not isinstance(x, bool):
                    total += x
                else:
                    walk(x)

    walk(report or {})
    return int(total)


def zero_area_faces(mesh, mean_edge):
    """Faces with no area (to 1e-12 of the mean edge length squared)."""
    v, f = mesh
    limit = 1e-12 * mean_edge * mean_edge
    return sum(1 for t in f if triangle_area(v, t) <= limit)


def summary(parts):
    """(loops, pieces, genus) of a list of shells; genus the sum, "-" where one is undefined."""
    genus = [s["genus"] for s in parts]
    return (sum(s["loops"] for s in parts), len(parts),
            "-" if any(g is None for g in genus) else sum(genus))


_prepared = {}


def prepared_input(inp, weld_distance=0.0):
    """(the input as compared, its SurfaceIndex), kept for the next call with the same mesh."""
    key = (id(inp), weld_distance)
    if key not in _prepared or _prepared[key][0] is not inp:
        mesh = split_fans(weld_border(inp, weld_distance) if weld_distance > 0 else inp)
        _prepared[key] = (inp, mesh, SurfaceIndex(mesh))
    return _prepared[key][1:]


def compare(inp, out, closed_by_design=0, weld_distance=0.0):
    """Whether `out` kept the topology of `inp` (both welded meshes; the input's non-manifold
    vertices split, one per fan, as fcvt's repair does), issue 52 items 1-2: every
    part of the input (a shell with PART_SHARE of the area or more) comes back as exactly one
    output shell, with the input shell's genus (where the input shell is manifold and oriented)
    and its boundary loops (fewer only by holes closed by design, `closed_by_design` in all), and
    no two parts share an output shell. Output shells are matched to input shells through the
    closest input triangle of each output vertex (most votes wins: the shell's home); a part
    that is no shell's home is merged into a shell where 3 of its vertices (or 2 and a quarter
    of them) are closest to it, else lost. weld_distance > 0: the input's border vertices within
    it are welded first (the cracks fcvt's repair welds: repair.weld_distance in its report).
    The output's non-manifold vertices are split alike (their count: pinched; whether the output
    is manifold is the caller's check). Returns a dict: problems (list of messages), in_shells,
    out_shells, parts, matched (input shell -> output shells), deficit (boundary loops the parts
    lost), pinched."""
    inp, index = prepared_input(inp, weld_distance)
    in_shells = shells(inp)
    pinched = len(out[0])
    out = split_fans(out)
    pinched = len(out[0]) - pinched
    out_shells = shells(out)
    total = sum(s["area"] for s in in_shells) or 1.0
    shell_of_face = {}
    for k, s in enumerate(in_shells):
        for i in s["faces"]:
            shell_of_face[i] = k
    label = {}
    for s in out_shells:
        for c in s["vertices"]:
            if c not in label:
                label[c] = shell_of_face[index.nearest(out[0][c])[1]]
    parts = [k for k, s in enumerate(in_shells) if s["area"] >= PART_SHARE * total]
    is_part = set(parts)
    matched = {k: [] for k in range(len(in_shells))}
    covers = []
    for j, s in enumerate(out_shells):
        votes = {}
        for c in s["vertices"]:
            votes[label[c]] = votes.get(label[c], 0) + 1
        home = max(votes, key=lambda k: (votes[k], -k))
        matched[home].append(j)
        n = len(s["vertices"])
        covers.append({k for k, c in votes.items() if k in is_part and (c >= 3 or (c >= 2 and 4 * c >= n))})
    problems = []
    deficit = 0
    for k in parts:
        s, got = in_shells[k], matched[k]
        what = describe(s, total)
        if not got:
            into = [j for j, c in enumerate(covers) if k in c]
            if into:
                j = max(into, key=lambda j: out_shells[j]["area"])
                home = next(h for h, js in matched.items() if j in js)
                problems.append(f"part {what} merged into the output shell of part {describe(in_shells[home], total)}")
            else:
                problems.append(f"part {what} lost (no output shell)")
            continue
        if len(got) > 1:
            problems.append(f"part {what} in {len(got)} output shells")
        o = max((out_shells[j] for j in got), key=lambda x: x["area"])
        if s["genus"] is not None and o["genus"] != s["genus"]:
            problems.append(f"part {what}: output genus {o['genus']}, input {s['genus']}")
        if o["loops"] > s["loops"]:
            problems.append(f"part {what}: {o['loops']} boundary loops, input {s['loops']}" +
                            (" (a closed shell torn)" if s["closed"] else ""))
        elif o["loops"] < s["loops"]:
            deficit += s["loops"] - o["loops"]
    if deficit > closed_by_design:
        problems.append(f"{deficit} boundary loops of the parts lost, {closed_by_design} holes closed by design")
    return {"problems": problems, "in_shells": in_shells, "out_shells": out_shells, "parts": parts,
            "matched": matched, "deficit": deficit, "pinched": pinched}


def describe(s, total):
    """A shell, for messages: where it is, its share of the area, genus and loops."""
    return (f"at ({s['centre'][0]:.3g}, {s['centre'][1]:.3g}, {s['centre'][2]:.3g}) ({100 * s['area'] / total:.2g} % "
            f"of the area, genus {s['genus']}, {s['loops']} loops)")


# --- readers ---------------------------------------------------------------------------------

def _fan(face):
    return [[face[0], face[i], face[i + 1]] for i in range(1, len(face) - 1)]


def read_stl(path):
    data = open(path, "rb").read()
    corners = []
    if len(data) >= 84 and 84 + 50 * struct.unpack_from("<I", data, 80)[0] == len(data):
        for i in range(struct.unpack_from("<I", data, 80)[0]):
            vals = struct.unpack_from("<12f", data, 84 + 50 * i)
            corners += [list(vals[3 + 3 * k: 6 + 3 * k]) for k in range(3)]
    else:
        corners = [[float(x) for x in line.split()[1:4]] for line in data.decode(errors="replace").splitlines()
                   if line.strip().startswith("vertex")]
    return corners, [[i, i + 1, i + 2] for i in range(0, len(corners) - 2, 3)]


def read_off(path):
    words = open(path, errors="replace").read().split()
    i = 1 if words[0].upper().endswith("OFF") else 0
    nv, nf = int(words[i]), int(words[i + 1])
    i += 3
    v = [[float(x) for x in words[i + 3 * k: i + 3 * k + 3]] for k in range(nv)]
    i += 3 * nv
    f = []
    for _ in range(nf):
        k = int(words[i])
        f += _fan([int(w) for w in words[i + 1:i + 1 + k]])
        i += 1 + k
    return v, f


def read_obj(path):
    v, f = [], []
    with open(path, errors="replace") as fh:
        for line in fh:
            w = line.split()
            if not w:
                continue
            if w[0] == "v":
                v.append([float(x) for x in w[1:4]])
            elif w[0] == "f":
                face = [int(x.split("/")[0]) for x in w[1:]]
                f += _fan([x - 1 if x > 0 else len(v) + x for x in face])
    return v, f


_PLY = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h", "ushort": "H",
        "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I", "float": "f", "float32": "f",
        "double": "d", "float64": "d"}


def read_ply(path):
    """Any PLY (ascii or binary, either byte order): its vertex x y z and face index lists."""
    data = open(path, "rb").read()
    end = data.index(b"end_header") + len(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii", errors="replace").splitlines()
    fmt = header[1].split()[1]
    elements = []
    for line in header:
        w = line.split()
        if not w:
            continue
        if w[0] == "element":
            elements.append((w[1], int(w[2]), []))
        elif w[0] == "property":
            elements[-1][2].append(w[1:])
    v, f = [], []
    if fmt == "ascii":
        words = data[end:].split()
        i = 0
        for name, count, props in elements:
            for _ in range(count):
                row = {}
                for p in props:
                    if p[0] == "list":
                        k = int(words[i])
                        row[p[3]] = [int(x) for x in words[i + 1:i + 1 + k]]
                        i += 1 + k
                    else:
                        row[p[1]] = float(words[i])
                        i += 1
                if name == "vertex":
                    v.append([row["x"], row["y"], row["z"]])
                elif name == "face":
                    f += _fan(row.get("vertex_indices", row.get("vertex_index", [])))
        return v, f
    order = "<" if fmt == "binary_little_endian" else ">"
    offset = end
    for name, count, props in elements:
        if all(p[0] != "list" for p in props):
            fmt_row = order + "".join(_PLY[p[0]] for p in props)
            size = struct.calcsize(fmt_row)
            if name == "vertex":
                names = [p[1] for p in props]
                ix, iy, iz = names.index("x"), names.index("y"), names.index("z")
                for r in struct.iter_unpack(fmt_row, data[offset:offset + size * count]):
                    v.append([r[ix], r[iy], r[iz]])
            offset += size * count
            continue
        for _ in range(count):
            for p in props:
                if p[0] == "list":
                    k = struct.unpack_from(order + _PLY[p[1]], data, offset)[0]
                    offset += struct.calcsize(_PLY[p[1]])
                    items = struct.unpack_from(order + "%d%s" % (k, _PLY[p[2]]), data, offset)
                    offset += k * struct.calcsize(_PLY[p[2]])
                    if name == "face" and p[3] in ("vertex_indices", "vertex_index"):
                        f += _fan(list(items))
                else:
                    offset += struct.calcsize(_PLY[p[0]])
    return v, f


def read_mesh(path):
    """Any mesh file fcvt reads, exact duplicate vertices welded (STL's corners, seams)."""
    ext = path.rsplit(".", 1)[-1].lower()
    reader = {"stl": read_stl, "off": read_off, "obj": read_obj, "ply": read_ply}[ext]
    return weld(reader(path))


def write_mesh(path, mesh):
    ext = path.rsplit(".", 1)[-1].lower()
    with open(path, "wb") as fh:
        fh.write(meshgen.mesh_bytes(mesh, ext))
    return path


# --- self-check ------------------------------------------------------------------------------

def self_check(name, mesh, shells_expected, genus_expected):
    """Problems of a generated mesh (empty when it is as documented)."""
    v, f = mesh
    problems = []
    if len({tuple(p) for p in v}) != len(v):
        problems.append("two vertices at the same place")
    if len({c for t in f for c in t}) != len(v):
        problems.append("unreferenced vertices")
    problems += meshgen.manifold_problems(mesh)
    parts = shells(mesh)
    if len(parts) != shells_expected:
        problems.append(f"{len(parts)} shells, expected {shells_expected}")
    for s in parts:
        if not (s["closed"] and s["manifold"] and s["oriented"]) or s["genus"] != genus_expected:
            problems.append(f"a shell with genus {s['genus']}, {s['loops']} loops, manifold {s['manifold']}, "
                            f"oriented {s['oriented']} (expected closed, genus {genus_expected})")
            break
        _, volume = meshgen.area_and_volume((v, [f[i] for i in s["faces"]]))
        if volume <= 0:
            problems.append("a shell oriented inward")
            break
    total = sum(s["area"] for s in parts)
    if parts and parts[-1]["area"] < 0.005 * total:
        problems.append(f"the smallest shell has {100 * parts[-1]['area'] / total:.2f} % of the area (< 0.5 %)")
    return problems


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else None
    bad = 0
    for name, (make, ext, count, genus) in CLASSES.items():
        mesh = make()
        problems = self_check(name, mesh, count, genus)
        parts = shells(mesh)
        total = sum(s["area"] for s in parts)
        print(f"{name}: {len(mesh[0])} vertices, {len(mesh[1])} faces, {len(parts)} shells, genus "
              f"{sorted({s['genus'] for s in parts})}, area {total:.3g}, smallest shell "
              f"{100 * parts[-1]['area'] / total:.2f} %" + ("" if not problems else ": " + "; ".join(problems)))
        bad += bool(problems)
        if out:
            os.makedirs(out, exist_ok=True)
            write_mesh(os.path.join(out, f"{name}.{ext}"), mesh)
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
