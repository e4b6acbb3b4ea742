"""Adaptive remeshing (issue 5, item 5) through the CLI: `fcvt remesh --adaptive curvature` keeps
the vertex count and the quality, and output edge lengths follow the target 1/sqrt(mu).

mu is recomputed here in pure Python from the input, the way core/density.cpp defines it (per
vertex: a least-squares fit of the shape operator S from the 1-ring, kappa = |S|_F =
sqrt(k1^2 + k2^2) in units of the uniform target edge length, mu = (1 + G kappa)^2, clamped to 25x
its minimum, Laplacian-smoothed over about one target edge). Each output edge gets mu of the
input vertex nearest to its midpoint; the bar is on the Pearson correlation between edge length
and 1/sqrt(mu), and edges where mu is high (top 10 %) must be shorter than where it is low
(bottom half).
With MESH.ply (an 8th argument), that mesh is checked instead of running fcvt remesh (e.g. the
MeshLab filter's output with Vertex density 'curvature', tests/meshlab/log_density.sh).
Usage: check_adaptive.py FCVT INPUT.obj VERTICES WORK_DIR GRADATION MIN_CORRELATION MIN_Q_AVG [MESH.ply]"""
import json
import math
import os
import sys

from fcvt_check import check, finish, metrics_json, read_ply, run_ok

fcvt, source, target, work = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
gradation, min_correlation, min_q_avg = float(sys.argv[5]), float(sys.argv[6]), float(sys.argv[7])
os.makedirs(work, exist_ok=True)
out = os.path.join(work, "adaptive.ply")
report_path = os.path.join(work, "adaptive.json")
report = None
if len(sys.argv) > 8:
    out = sys.argv[8]
else:
    print(run_ok([fcvt, "remesh", source, out, "--vertices", str(target), "--adaptive", "curvature",
                  "--gradation", str(gradation), "--report", report_path]))
    with open(report_path) as f:
        report = json.load(f)


def read_obj(path):
    vertices, faces = [], []
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "v":
                vertices.append(tuple(float(w) for w in words[1:4]))
            elif words[0] == "f":
                corners = [int(w.split("/")[0]) for w in words[1:]]
                corners = [c - 1 if c > 0 else len(vertices) + c for c in corners]
                for k in range(1, len(corners) - 1):
                    faces.append((corners[0], corners[k], corners[k + 1]))
    return vertices, faces


def sub(p, q):
    return (p[0] - q[0], p[1] - q[1], p[2] - q[2])


def dot(p, q):
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]


def cross(p, q):
    return (p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0])


def unit(p):
    n = math.sqrt(dot(p, p))
    return (p[0] / n, p[1] / n, p[2] / n) if n > 1e-300 else (0.0, 0.0, 1.0)


def input_density(vertices, faces, samples):
    n = len(vertices)
    normal_sum = [(0.0, 0.0, 0.0)] * n
    area = 0.0
    for a, b, c in faces:
        fn = cross(sub(vertices[b], vertices[a]), sub(vertices[c], vertices[a]))
        area += 0.5 * math.sqrt(dot(fn, fn))
        for v in (a, b, c):
            s = normal_sum[v]
            normal_sum[v] = (s[0] + fn[0], s[1] + fn[1], s[2] + fn[2])
    normals = [unit(s) for s in normal_sum]
    tangents = []
    for nv in normals:
        u = unit(cross(nv, (1.0, 0.0, 0.0) if abs(nv[0]) < 0.9 else (0.0, 1.0, 0.0)))
        tangents.append((u, cross(nv, u)))
    # Normal equations of dn = S e per vertex, S = [[L, M], [M, N]], weight 1/(2|e|^2).
    ata = [[0.0] * 6 for _ in range(n)]  # xx, xy, yy-part: a00 a01 a11 a12 a22 (a02 = 0)
    atb = [[0.0] * 3 for _ in range(n)]
    edge_sum = 0.0
    neighbours = [set() for _ in range(n)]
    for f in faces:
        for k in range(3):
            i = f[k]
            for s in (1, 2):
                j = f[(k + s) % 3]
                neighbours[i].add(j)
                e = sub(vertices[j], vertices[i])
                len2 = dot(e, e)
                if s == 1:
                    edge_sum += math.sqrt(len2)
                if not len2 > 0:
                    continue
                dn = sub(normals[j], normals[i])
                u, v = tangents[i]
                x, y, p, q = dot(e, u), dot(e, v), dot(dn, u), dot(dn, v)
                w = 0.5 / len2
                m = ata[i]
                m[0] += w * x * x
                m[1] += w * x * y
                m[2] += w * (x * x + y * y)
                m[3] += w * x * y
                m[4] += w * y * y
                r = atb[i]
                r[0] += w * x * p
                r[1] += w * (y * p + x * q)
                r[2] += w * y * q
    scale = math.sqrt(samples / area)  # the working scale of core/remesh.cpp
    h = math.sqrt(2 / math.sqrt(3))    # uniform target edge length there
    mu = []
    for i in range(n):
        a00, a01, a11, a12, a22 = ata[i][:5]
        b0, b1, b2 = atb[i]
        trace = a00 + a11 + a22
        det = a00 * (a11 * a22 - a12 * a12) - a01 * (a01 * a22)
        kappa = 0.0
        if trace > 0 and det > 1e-10 * trace ** 3:
            L = (b0 * (a11 * a22 - a12 * a12) - a01 * (b1 * a22 - a12 * b2)) / det
            M = (a00 * (b1 * a22 - a12 * b2) - b0 * (a01 * a22)) / det
            N = (a00 * (a11 * b2 - b1 * a12) - a01 * (a01 * b2) + b0 * (a01 * a12)) / det
            kappa = math.sqrt(L * L + 2 * M * M + N * N) / scale * h
        mu.append((1 + gradation * kappa) ** 2)
    lowest = min(mu)
    mu = [min(m, 25 * lowest) for m in mu]
    mean_edge = edge_sum / (3 * len(faces)) * scale
    steps = int(min(50, max(3, round(2 * (h / mean_edge) ** 2))))
    neighbours = [list(s) for s in neighbours]
    for _ in range(steps):
        mu = [0.5 * mu[v] + 0.5 * sum(mu[w] for w in neighbours[v]) / len(neighbours[v]) if neighbours[v] else mu[v]
              for v in range(n)]
    return mu, edge_sum / (3 * len(faces))


class Grid:
    """Nearest input vertex by a uniform grid."""

    def __init__(self, points, cell):
        self.points, self.cell, self.cells = points, cell, {}
        for index, p in enumerate(points):
            self.cells.setdefault(self.key(p), []).append(index)

    def key(self, p):
        return tuple(int(math.floor(c / self.cell)) for c in p)

    def nearest(self, p):
        kx, ky, kz = self.key(p)
        best, best_d = -1, float("inf")
        radius = 1
        while True:
            for dx in range(-radius, radius + 1):
                for dy in range(-radius, radius + 1):
                    for dz in range(-radius, radius + 1):
                        for index in self.cells.get((kx + dx, ky + dy, kz + dz), ()):
                            d = dot(sub(self.points[index], p), sub(self.points[index], p))
                            if d < best_d:
                                best, best_d = index, d
            # Every point within radius cells is covered: done when the best is that near.
            if best >= 0 and math.sqrt(best_d) <= radius * self.cell:
                return best
            radius += 1


def pearson(xs, ys):
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxy = sum((x - mx) * (y - my) for x, y in zip(xs, ys))
    sxx = sum((x - mx) ** 2 for x in xs)
    syy = sum((y - my) ** 2 for y in ys)
    return sxy / math.sqrt(sxx * syy)


in_vertices, in_faces = read_obj(source)
referenced = sorted({v for f in in_faces for v in f})
mu, mean_input_edge = input_density(in_vertices, in_faces, target)
grid = Grid([in_vertices[v] for v in referenced], 2 * mean_input_edge)

out_vertices, out_faces = read_ply(out)
edges = sorted({(min(a, b), max(a, b)) for f in out_faces for a, b in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0]))})
lengths, targets, mus = [], [], []
for a, b in edges:
    pa, pb = out_vertices[a], out_vertices[b]
    mid = tuple(0.5 * (pa[k] + pb[k]) for k in range(3))
    m = mu[referenced[grid.nearest(mid)]]
    lengths.append(math.sqrt(dot(sub(pa, pb), sub(pa, pb))))
    targets.append(1 / math.sqrt(m))
    mus.append(m)
correlation = pearson(lengths, targets)
order = sorted(range(len(mus)), key=lambda e: mus[e])
low = [lengths[e] for e in order[: len(order) // 2]]
high = [lengths[e] for e in order[len(order) * 9 // 10:]]
ratio = (sum(high) / len(high)) / (sum(low) / len(low))
measured = metrics_json(fcvt, out)
print(f"mu max/min on the input: {max(mu) / min(mu):.2f}; output vertices {len(out_vertices)} (target {target}), "
      f"{len(edges)} edges")
print(f"Pearson correlation(edge length, 1/sqrt(mu)) = {correlation:.3f}")
print(f"mean edge length: top 10 % mu {sum(high) / len(high):.6g}, bottom half {sum(low) / len(low):.6g}, ratio {ratio:.3f}")
print(f"Q_avg {measured['q_avg']:.4f}, theta_min {measured['theta_min']:.2f}, V6 {measured['v6_pct']:.1f} %")

check(abs(len(out_vertices) - target) <= 0.02 * target, f"{len(out_vertices)} vertices, target {target} +- 2 %")
if report is not None:
    check(report["vertices"] == len(out_vertices), "report vertex count vs file")
check(measured["q_avg"] >= min_q_avg, f"Q_avg {measured['q_avg']:.4f} < {min_q_avg}")
check(correlation >= min_correlation, f"correlation {correlation:.3f} < {min_correlation}")
check(ratio < 0.8, f"edges where mu is high are not shorter: length ratio {ratio:.3f}")
finish()
