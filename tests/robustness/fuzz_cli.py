"""A bounded random fuzzing loop through `fcvt remesh`: small meshes, perturbed and broken at
the mesh level (flipped, missing, duplicated or extra faces, merged or split vertices, NaN/Inf,
huge or tiny coordinates, bad indices) and at the byte level (truncated, flipped or inserted
bytes), in every format, with small and odd parameters. Fixed seed: the same cases every run.
Each must end as documented: exit 0 with a manifold output, or exit 1/2 with exactly one
stderr line "fcvt: error: ..." -- never a signal, never a hang.
A failing case is kept in WORK_DIR/findings/ with the command that reproduces it.
Usage: fuzz_cli.py FCVT WORK_DIR [--seed S] [--count N] [--timeout S] [--jobs N]"""
import argparse
import concurrent.futures
import os
import random
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import meshgen as g  # noqa: E402

BASES = [
    lambda r: g.icosphere(1),
    lambda r: g.torus(r.randint(6, 12), r.randint(4, 6)),
    lambda r: g.grid(r.randint(1, 5)),
    lambda r: g.tetrahedron(),
    lambda r: g.two_cones_at_apex(r.randint(3, 8)),
    lambda r: g.moebius(r.randint(6, 12)),
    lambda r: g.quad_cube(r.randint(1, 3)),
    lambda r: g.nonmanifold_edge(),
    lambda r: g.combine(g.icosphere(0), g.transform(g.tetrahedron(), 10 ** r.uniform(-6, 0), (3, 0, 0))),
]

SPECIAL = [float("nan"), float("inf"), float("-inf"), 1e308, -1e308, 1e-308, 5e-324, 0.0, -0.0, 1e30]


def mutate_mesh(r, mesh):
    v, f = [list(p) for p in mesh[0]], [list(t) for t in mesh[1]]
    for _ in range(r.randint(1, 3)):
        op = r.randrange(13)
        if op == 0 and v:    # jitter
            s = 10 ** r.uniform(-9, -1)
            v = [[c + r.uniform(-s, s) for c in p] for p in v]
        elif op == 1 and f:  # flip faces
            for i in r.sample(range(len(f)), r.randint(1, len(f))):
                f[i] = f[i][::-1]
        elif op == 2 and f:  # delete faces
            for i in sorted(r.sample(range(len(f)), r.randint(1, len(f))), reverse=True):
                del f[i]
        elif op == 3 and f:  # duplicate faces
            f += [list(r.choice(f)) for _ in range(r.randint(1, 5))]
        elif op == 4 and len(v) >= 3:  # random extra faces
            f += [r.sample(range(len(v)), 3) for _ in range(r.randint(1, 4))]
        elif op == 5 and v:  # a special coordinate
            r.choice(v)[r.randrange(3)] = r.choice(SPECIAL)
        elif op == 6 and f:  # a bad index
            t = r.choice(f)
            t[r.randrange(len(t))] = r.choice([-1, len(v), len(v) + 7, 2 ** 31 - 1])
        elif op == 7 and len(v) >= 2:  # collapse a vertex onto another
            a, b = r.sample(range(len(v)), 2)
            v[a] = list(v[b])
        elif op == 8:  # scale / translate
            k = 10 ** r.uniform(-8, 8)
            o = [r.choice([0.0, 10 ** r.uniform(0, 7)]) for _ in range(3)]
            v = [[p[i] * k + o[i] for i in range(3)] for p in v]
        elif op == 9:  # triangle soup
            v, f = g.soup((v, [t for t in f if all(0 <= c < len(v) for c in t)]))
        elif op == 10 and f:  # degenerate faces
            t = r.choice(f)
            f.append([t[0], t[0], t[-1]])
        elif op == 11:  # flatten (all on a plane or a line)
            axis = r.randrange(3)
            for p in v:
                p[axis] = 0.0
                if r.random() < 0.3:
                    p[(axis + 1) % 3] = 0.0
        elif op == 12:  # unreferenced vertices
            v += [[r.uniform(-1, 1) for _ in range(3)] for _ in range(r.randint(1, 5))]
    return v, f


def mutate_bytes(r, data):
    data = bytearray(data)
    op = r.randrange(4)
    if op == 0 and data:
        del data[r.randrange(len(data)):]
    elif op == 1 and data:
        for _ in range(r.randint(1, 8)):
            data[r.randrange(len(data))] = r.randrange(256)
    elif op == 2:
        at = r.randrange(len(data) + 1)
        data[at:at] = bytes(r.randrange(256) for _ in range(r.randint(1, 16)))
    elif op == 3 and data:
        a = r.randrange(len(data))
        b = min(len(data), a + r.randint(1, 64))
        data[a:a] = data[a:b]  # repeat a chunk
    return bytes(data)


def make_case(seed, i):
    r = random.Random(seed * 1000003 + i)
    mesh = mutate_mesh(r, r.choice(BASES)(r))
    ext = r.choice(["obj", "off", "ply", "stl"])
    data = g.mesh_bytes(mesh, ext, r.randrange(3))
    if r.random() < 0.3:
        data = mutate_bytes(r, data)
    vertices = r.choice([4, 5, 8, 12, 20, 30, 40, r.choice([3, 0, 100000000])])
    args = ["--vertices", str(vertices), "--cvt-iterations", str(r.randint(0, 5)), "--seed", str(r.randint(0, 9))]
    if r.random() < 0.2:
        args += ["--lambda", "0.3", "--fcvt-iterations", str(r.randint(1, 3))]
    else:
        args += ["--lambda", "0", "--fcvt-iterations", "0"]
    return ext, data, args


def run_one(fcvt, work, seed, i, timeout):
    ext, data, args = make_case(seed, i)
    inp = os.path.join(work, "case%03d.%s" % (i, ext))
    out = os.path.join(work, "case%03d-out.obj" % i)
    with open(inp, "wb") as fh:
        fh.write(data)
    if os.path.exists(out):
        os.remove(out)
    cmd = [fcvt, "remesh", inp, out] + args + ["--quiet", "--threads", "1"]
    problems = []
    try:
        p = subprocess.run(cmd, capture_output=True, timeout=timeout)
        rc, stderr = p.returncode, p.stderr.decode("utf-8", "replace")
        lines = stderr.splitlines()
        if "Sanitizer" in stderr or "runtime error:" in stderr:
            problems.append("sanitizer report")
        if rc < 0:
            problems.append("killed by signal %d" % -rc)
        elif rc == 0:
            # --quiet keeps the warnings (the output differs from what was asked), nothing else.
            if any(not line.startswith("fcvt: warning: ") for line in lines):
                problems.append("stderr other than warnings on success with --quiet")
            problems += ["output: " + x for x in g.manifold_problems(g.read_obj(out))]
        elif rc in (1, 2):
            if len(lines) != 1 or not lines[0].startswith("fcvt: error: "):
                problems.append("stderr is not exactly one 'fcvt: error:' line")
        else:
            problems.append("unexpected exit code %d" % rc)
    except subprocess.TimeoutExpired:
        rc, stderr = None, ""
        problems.append("hang: no exit within %g s" % timeout)
    return i, cmd, rc, stderr, problems, inp


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("fcvt")
    ap.add_argument("work")
    ap.add_argument("--seed", type=int, default=20240606)
    ap.add_argument("--count", type=int, default=200)
    ap.add_argument("--timeout", type=float, default=20)
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    findings = os.path.join(a.work, "findings")
    shutil.rmtree(findings, ignore_errors=True)
    counts = {}
    failed = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        for i, cmd, rc, stderr, problems, inp in pool.map(lambda i: run_one(a.fcvt, a.work, a.seed, i, a.timeout),
                                                          range(a.count)):
            counts[rc] = counts.get(rc, 0) + 1
            if problems:
                failed += 1
                os.makedirs(findings, exist_ok=True)
                kept = os.path.join(findings, os.path.basename(inp))
                shutil.copy(inp, kept)
                print("FAIL case %d: %s\n  reproduce: %s\n  stderr: %s" % (
                    i, "; ".join(problems), " ".join([cmd[0], cmd[1], kept] + cmd[3:]), stderr.strip()[-600:]), flush=True)
    print("%d cases (seed %d), exit codes %s, %d failed" % (
        a.count, a.seed, ", ".join("%s: %d" % (k, n) for k, n in sorted(counts.items(), key=str)), failed))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
