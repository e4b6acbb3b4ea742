#!/usr/bin/env python3
"""FCVT and Instant Meshes side by side on the same inputs, one after the other (issue 12).

  bench/side_by_side.py BUILD/cli/fcvt [--im PATH] [--threads T] [--repeat K] [--peak]
                        [--fcvt-option OPT ...] [--baseline OLD/cli/fcvt] [MESH:N ...]

Each row: the whole `fcvt remesh IN OUT.ply --vertices N --threads T --quiet` command (issue 12's),
timed from start to exit (I/O included), then the whole `instant-meshes IN.obj -o OUT.obj
-r 6 -p 6 -v N -d -t T` command (OFF inputs are converted to OBJ first, outside the timed part).
With --repeat K both run K times, alternately, and the medians are printed. Both outputs are then
measured by the same code, `fcvt metrics OUT --ref IN` (Q_avg, θ_min, %θ<30°, V6%, d_H in % of
the diagonal, boundary loops). FCVT's per-stage times come from one more, untimed run with
--report R.json (which also computes the distances, 0.05-0.26 s more on these rows). --peak adds
each command's peak resident memory (from wait4).

--baseline runs a second fcvt build (e.g. before a change) in the same rounds, with the same
options, and adds its time and new/baseline (its output bytes must not differ for a change that
keeps the results: "same" or "differs" says which).

Instant Meshes is looked for at --im, else $FCVT_INSTANT_MESHES, else ../shared/anchors/instant-meshes
next to the source tree. When it is absent, FCVT's rows are printed alone and the output says so.
Without MESH:N, the rows of issue 12's table (../shared/meshes) are used."""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SHARED = os.path.normpath(os.path.join(HERE, "..", "..", "shared"))
DEFAULT_ROWS = ["torus.obj:1000", "cylinder.off:1000", "fertility.off:3000", "camelhead.off:3000", "mask.off:4000",
                "bunny.obj:5000", "fandisk.off:5000", "fertility.off:7000", "nefertiti.obj:10000"]


def off_to_obj(src, dst):
    """Plain OFF (as in ../shared/meshes) to OBJ, for Instant Meshes, which reads OBJ and PLY only."""
    with open(src) as f:
        tokens = []
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                tokens.extend(line.split())
    if not tokens[0].endswith("OFF"):
        raise SystemExit(f"{src}: not an OFF file")
    tokens = tokens[1:] if tokens[0] == "OFF" else [tokens[0][:-3]] + tokens[1:]
    nv, nf = int(tokens[0]), int(tokens[1])
    k = 3
    with open(dst, "w") as out:
        for _ in range(nv):
            out.write("v %s %s %s\n" % tuple(tokens[k:k + 3]))
            k += 3
        for _ in range(nf):
            n = int(tokens[k])
            idx = [int(t) + 1 for t in tokens[k + 1:k + 1 + n]]
            k += 1 + n
            out.write("f " + " ".join(map(str, idx)) + "\n")


def timed(cmd):
    """Runs cmd; returns (wall seconds, peak resident MB). Fails on a non-zero exit."""
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    seconds = time.perf_counter() - start
    err = proc.stderr.read().decode(errors="replace")
    proc.stderr.close()
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        raise SystemExit(f"{' '.join(cmd)} failed ({proc.returncode}):\n{err}")
    return seconds, usage.ru_maxrss / 1024.0


def metrics(fcvt, mesh, ref):
    text = subprocess.run([fcvt, "metrics", mesh, "--ref", ref], check=True, capture_output=True, text=True).stdout
    m = {}
    for line in text.splitlines():
        parts = line.split(None, 1)
        if len(parts) == 2:
            try:
                m[parts[0]] = float(parts[1])
            except ValueError:
                m[parts[0]] = parts[1]
    return m


def quality(m):
    def f(key, digits, scale=1.0):
        v = m.get(key)
        return "n/a" if not isinstance(v, float) else f"{scale * v:.{digits}f}"
    return (f"{f('q_avg', 3)} / {f('theta_min', 1)} / {f('pct_lt30', 2)} / {f('v6_pct', 1)} / {f('d_h', 2, 100)} / "
            f"{int(m.get('boundary_loops', -1))}")


def find_im(explicit):
    for candidate in (explicit, os.environ.get("FCVT_INSTANT_MESHES"), os.path.join(SHARED, "anchors", "instant-meshes")):
        if candidate and os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return candidate
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("fcvt")
    ap.add_argument("rows", nargs="*", help="MESH:N (a bare name is looked up in ../shared/meshes)")
    ap.add_argument("--im", help="the instant-meshes binary")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--peak", action="store_true", help="also print each command's peak resident memory")
    ap.add_argument("--fcvt-option", action="append", default=[], help="extra option for fcvt remesh (repeatable)")
    ap.add_argument("--baseline", help="a second fcvt build, timed in the same rounds")
    a = ap.parse_args()
    im = find_im(a.im)
    rows = a.rows or DEFAULT_ROWS
    print(f"# threads {a.threads}, repeat {a.repeat} (medians), fcvt {a.fcvt}"
          + (f" {' '.join(a.fcvt_option)}" if a.fcvt_option else "")
          + (f", Instant Meshes {im}" if im else ", Instant Meshes not found: FCVT's rows alone"))
    print("quality: Q_avg / θ_min / %θ<30° / V6% / d_H % / boundary loops, both by `fcvt metrics OUT --ref IN`;"
          " stages: FCVT's report (s)")
    print()
    head = "| mesh, N | FCVT s | " + ("baseline s | FCVT / baseline | output | " if a.baseline else "")
    head += ("IM s | FCVT / IM | " if im else "")
    head += ("FCVT MB | " + ("IM MB | " if im else "")) if a.peak else ""
    head += "FCVT quality | " + ("IM quality | " if im else "") + "FCVT stages | evals |"
    print(head)
    print("|" + "---|" * (head.count("|") - 1))
    ratios = []
    with tempfile.TemporaryDirectory() as work:
        for spec in rows:
            path, n = spec.rsplit(":", 1)
            if not os.path.exists(path) and os.path.exists(os.path.join(SHARED, "meshes", path)):
                path = os.path.join(SHARED, "meshes", path)
            name = os.path.basename(path)
            out_f, report = os.path.join(work, "fcvt.ply"), os.path.join(work, "report.json")
            fcvt_cmd = [a.fcvt, "remesh", path, out_f, "--vertices", n, "--threads", str(a.threads),
                        "--quiet"] + a.fcvt_option
            im_in, out_i = path, os.path.join(work, "im.obj")
            if im:
                if path.lower().endswith(".off"):
                    im_in = os.path.join(work, "in.obj")
                    off_to_obj(path, im_in)
                im_cmd = [im, im_in, "-o", out_i, "-r", "6", "-p", "6", "-v", n, "-d", "-t", str(a.threads)]
            out_b = os.path.join(work, "baseline.ply")
            base_cmd = [a.baseline] + fcvt_cmd[1:3] + [out_b] + fcvt_cmd[4:] if a.baseline else None
            tf, ti, tb, mf, mi = [], [], [], [], []
            for _ in range(a.repeat):
                s, mb = timed(fcvt_cmd)
                tf.append(s), mf.append(mb)
                if base_cmd:
                    tb.append(timed(base_cmd)[0])
                if im:
                    s, mb = timed(im_cmd)
                    ti.append(s), mi.append(mb)
            subprocess.run(fcvt_cmd + ["--report", report], check=True)  # the stage times, not timed
            with open(report) as f:
                r = json.load(f)
            stages = " ".join(f"{k} {v:.2f}" for k, v in r["time_s"].items()
                              if k != "total" and v >= 0.005)
            line = f"| {name} {n} | {statistics.median(tf):.2f} | "
            if base_cmd:
                with open(out_f, "rb") as f1, open(out_b, "rb") as f2:
                    same = f1.read() == f2.read()
                line += (f"{statistics.median(tb):.2f} | {statistics.median(tf) / statistics.median(tb):.2f} | "
                         f"{'same' if same else 'differs'} | ")
            if im:
                ratio = statistics.median(tf) / statistics.median(ti)
                ratios.append(ratio)
                line += f"{statistics.median(ti):.2f} | {ratio:.2f} | "
            if a.peak:
                line += f"{max(mf):.0f} | " + (f"{max(mi):.0f} | " if im else "")
            line += quality(metrics(a.fcvt, out_f, path)) + " | "
            if im:
                line += quality(metrics(a.fcvt, out_i, path)) + " | "
            line += f"{stages} | {r['evaluations']} |"
            print(line, flush=True)
    if ratios:
        print(f"\nFCVT / IM: max {max(ratios):.2f}, geometric mean "
              f"{statistics.geometric_mean(ratios):.2f} over {len(ratios)} rows")


if __name__ == "__main__":
    main()
