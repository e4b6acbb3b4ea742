"""FCVT beside the peers of ../shared/anchors on the same inputs: Instant Meshes (N vertices), and
the edge-length-driven pmp-library uniform_remeshing and CGAL isotropic_remeshing (one thread
each, 10 iterations, as that README gives). Their edge length starts at L = sqrt(2 A / (sqrt(3) N))
from the input's area A and is corrected, in untimed runs before the rounds, by the square root
of their output's vertex count over N until it is within 3 % of N (issue 35 item 1: the same output
size; at the README's L they give 16-63 % more vertices).
Whole commands, one after the other, medians of --repeat alternating rounds; every output
measured by `fcvt metrics OUT --ref IN` (Q_avg / theta_min / %theta<30 / V6% / d_H % / loops).
FCVT runs twice in each round: with the default preset and with --preset fast (column "fast"),
and the last table checks fast against the faster of pmp and CGAL (issue 54 item 1).

  python3 bench/peers.py BUILD/cli/fcvt [--threads 2] [--repeat 5] [MESH:N ...]
"""
import argparse
import math
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from side_by_side import DEFAULT_ROWS, SHARED, metrics, off_to_obj, quality, timed  # noqa: E402

ANCHORS = os.path.join(SHARED, "anchors")


def obj_area(path):
    v, area = [], 0.0
    with open(path) as fh:
        for line in fh:
            t = line.split()
            if not t:
                continue
            if t[0] == "v":
                v.append([float(x) for x in t[1:4]])
            elif t[0] == "f":
                c = [v[int(x.split("/")[0]) - 1] for x in t[1:]]
                for k in range(1, len(c) - 1):
                    a = [c[k][i] - c[0][i] for i in range(3)]
                    b = [c[k + 1][i] - c[0][i] for i in range(3)]
                    area += 0.5 * math.sqrt((a[1] * b[2] - a[2] * b[1]) ** 2 + (a[2] * b[0] - a[0] * b[2]) ** 2
                                            + (a[0] * b[1] - a[1] * b[0]) ** 2)
    return area


def obj_vertex_count(path):
    with open(path) as fh:
        return sum(1 for line in fh if line.startswith("v "))


def matched_length(cmd_for, out, n, length, tries=8):
    """The edge length at which the tool's output has N vertices within 3 %, and that count."""
    best = None
    for _ in range(tries):
        timed(cmd_for(length))
        count = obj_vertex_count(out)
        if best is None or abs(count - n) < abs(best[1] - n):
            best = (length, count)
        if abs(count - n) <= 0.03 * n or count == 0:
            break
        length *= math.sqrt(count / n)
    return best


def fast_verdict(row, n, med, measured):
    """One line of the fast-preset check, or None without both pmp and CGAL."""
    peers = [k for k in ("pmp", "CGAL") if k in med]
    if len(peers) < 2:
        return None
    faster = min(peers, key=lambda k: med[k])
    fast = measured["fast"]

    def best(key, larger_is_better=True):
        values = [measured[k].get(key) for k in peers if isinstance(measured[k].get(key), float)]
        return (max(values) if larger_is_better else min(values)) if values else None

    def mark(ok):
        return "yes" if ok else "**no**"
    cells, oks = [], []
    ratio = med["fast"] / med[faster]
    oks.append(ratio <= 1.0)
    cells.append(f"{med['fast']:.2f} / {med[faster]:.2f} ({faster}) = {ratio:.2f} {mark(oks[-1])}")
    for key, limit in (("q_avg", best("q_avg")), ("v6_pct", best("v6_pct"))):
        oks.append(limit is None or fast.get(key, 0) >= limit)
        cells.append(f"{fast.get(key, 0):.3g} vs {limit if limit is None else f'{limit:.3g}'} {mark(oks[-1])}")
    theta = min(30.0, best("theta_min") or 0.0)
    oks.append(fast.get("theta_min", 0) >= theta)
    cells.append(f"{fast.get('theta_min', 0):.1f} vs {theta:.1f} {mark(oks[-1])}")
    dh = best("d_h", larger_is_better=False)
    oks.append(dh is None or fast.get("d_h", 1) <= 1.1 * dh)
    cells.append(f"{100 * fast.get('d_h', 1):.2f} vs 1.1 × {100 * dh:.2f} {mark(oks[-1])}")
    count = int(fast.get("vertices", 0))
    oks.append(abs(count - n) <= 0.03 * n)
    cells.append(f"{count} {mark(oks[-1])}")
    return f"| {row} | " + " | ".join(cells) + f" | {mark(all(oks))} |"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("fcvt")
    ap.add_argument("rows", nargs="*")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--repeat", type=int, default=5)
    a = ap.parse_args()
    tools = {"IM": os.path.join(ANCHORS, "instant-meshes"), "pmp": os.path.join(ANCHORS, "pmp_remesh"),
             "CGAL": os.path.join(ANCHORS, "cgal_remesh")}
    tools = {k: p for k, p in tools.items() if os.access(p, os.X_OK)}
    print(f"# FCVT {a.threads} threads; peers: {', '.join(tools) or 'none found'}; medians of {a.repeat}")
    print("quality: Q_avg / θ_min / %θ<30° / V6% / d_H % / boundary loops (`fcvt metrics OUT --ref IN`); V: output vertices")
    print()
    head = "| mesh, N | FCVT s | fast s | " + " | ".join(f"{k} s | FCVT / {k}" for k in tools)
    head += " | FCVT quality, V | fast quality, V | "
    head += " | ".join(f"{k} quality, V" for k in tools) + " |"
    print(head)
    print("|" + "---|" * (head.count("|") - 1))
    verdicts = []
    with tempfile.TemporaryDirectory() as work:
        for spec in a.rows or DEFAULT_ROWS:
            path, n = spec.rsplit(":", 1)
            if not os.path.exists(path):
                path = os.path.join(SHARED, "meshes", path)
            obj = path
            if path.lower().endswith(".off"):
                obj = os.path.join(work, "in.obj")
                off_to_obj(path, obj)
            length = math.sqrt(2 * obj_area(obj) / (math.sqrt(3) * int(n)))
            out = {k: os.path.join(work, k + ".obj") for k in tools}
            out["FCVT"] = os.path.join(work, "fcvt.ply")
            out["fast"] = os.path.join(work, "fast.ply")
            cmds = {"FCVT": [a.fcvt, "remesh", path, out["FCVT"], "--vertices", n, "--threads", str(a.threads), "--quiet"],
                    "fast": [a.fcvt, "remesh", path, out["fast"], "--vertices", n, "--threads", str(a.threads), "--quiet",
                             "--preset", "fast"]}
            if "IM" in tools:
                cmds["IM"] = [tools["IM"], obj, "-o", out["IM"], "-r", "6", "-p", "6", "-v", n, "-d", "-t", str(a.threads)]
            for k in ("pmp", "CGAL"):
                if k in tools:
                    def cmd_for(edge, tool=tools[k], target=out[k]):
                        return [tool, obj, target, "%.9g" % edge, "10"]
                    edge, _ = matched_length(cmd_for, out[k], int(n), length)
                    cmds[k] = cmd_for(edge)
            times = {k: [] for k in cmds}
            for _ in range(a.repeat):
                for k, cmd in cmds.items():
                    times[k].append(timed(cmd)[0])
            med = {k: statistics.median(t) for k, t in times.items()}
            line = f"| {os.path.basename(path)} {n} | {med['FCVT']:.2f} | {med['fast']:.2f} | "
            line += " | ".join(f"{med[k]:.2f} | {med['FCVT'] / med[k]:.2f}" for k in tools) + " | "
            cells, measured = [], {}
            for k in ["FCVT", "fast"] + list(tools):
                measured[k] = m = metrics(a.fcvt, out[k], path)
                cells.append(f"{quality(m)}, {int(m.get('vertices', 0))}")
            print(line + " | ".join(cells) + " |", flush=True)
            verdicts.append(fast_verdict(f"{os.path.basename(path)} {n}", int(n), med, measured))
    if verdicts and verdicts[0] is not None:
        print()
        print("fast against the faster of pmp and CGAL (time) and the better of the two (quality; θ_min against "
              "min(30°, theirs), d_H against 1.1 times theirs):")
        print()
        print("| mesh, N | fast s / peer s | Q_avg | V6 | θ_min | d_H | V within 3 % | all |")
        print("|---|---|---|---|---|---|---|---|")
        for v in verdicts:
            print(v)


if __name__ == "__main__":
    main()
