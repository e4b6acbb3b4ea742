"""FCVT at scale beside Instant Meshes (issue 35 item 3): nefertiti subdivided twice (1.6M faces,
bench/subdivide.py) remeshed to 25 000, 100 000 and 400 000 vertices. Per row: whole-command time
and peak resident memory of FCVT on 2 threads and on 1 (the 1 -> 2 thread speedup), of Instant
Meshes on 2 threads (`-r 6 -p 6 -v N -d -t 2`, as ../shared/anchors/README.md gives), the time and
memory per output vertex, and FCVT / IM. Medians of --repeat alternating rounds.

  python3 bench/scale.py BUILD/cli/fcvt [--repeat 1] [--counts 25000 100000 400000] [--input MESH]
                         [--levels 2] [--no-single-thread] [--preset P]

--levels 3 subdivides nefertiti three times (6.4M faces; issue 54 item 4: to 1 000 000 vertices in at
most half Instant Meshes' time and 3 GB); --no-single-thread skips FCVT's one-thread run.

The goal of issue 35: to 100 000 and 400 000 vertices at most half Instant Meshes' time, under
0.6 GB and 1.3 GB.
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from side_by_side import SHARED, find_im, timed  # noqa: E402


def vertex_count(fcvt, mesh):
    out = subprocess.run([fcvt, "metrics", mesh], capture_output=True, text=True, check=True).stdout
    for line in out.splitlines():
        words = line.split()
        if len(words) == 2 and words[0] == "vertices":
            return int(words[1])
    raise SystemExit(f"no vertex count in `fcvt metrics {mesh}`: {out[:200]}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("fcvt")
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--counts", type=int, nargs="+", default=[25000, 100000, 400000])
    ap.add_argument("--input", help="the input (default: nefertiti.obj of ../shared/meshes subdivided twice)")
    ap.add_argument("--im", help="the instant-meshes binary")
    ap.add_argument("--levels", type=int, default=2, help="subdivisions of nefertiti (default 2: 1.6M faces)")
    ap.add_argument("--no-single-thread", action="store_true", help="skip FCVT's run on one thread")
    ap.add_argument("--preset", help="FCVT's --preset")
    a = ap.parse_args()
    im = find_im(a.im)
    with tempfile.TemporaryDirectory() as work:
        source = a.input
        if not source:
            off = os.path.join(work, f"nefertiti{a.levels}.off")
            subprocess.run([sys.executable, os.path.join(HERE, "subdivide.py"), os.path.join(SHARED, "meshes", "nefertiti.obj"),
                            off, str(a.levels)], check=True, stdout=subprocess.DEVNULL)
            source = os.path.join(work, f"nefertiti{a.levels}.obj")  # Instant Meshes reads OBJ, not OFF
            subprocess.run([a.fcvt, "convert", off, source], check=True, stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL)
        print(f"# {os.path.basename(source)}; medians of {a.repeat}; time s / peak MB, then per output vertex (ms, kB)")
        print("| N | FCVT 2 thr | FCVT 1 thr | speedup 1 -> 2 | IM 2 thr | FCVT / IM time | FCVT / IM memory "
              "| FCVT per vertex | IM per vertex | V FCVT / IM |")
        print("|---|---|---|---|---|---|---|---|---|---|")
        for n in a.counts:
            out = {k: os.path.join(work, f"{k}.ply" if k != "im" else "im.obj") for k in ("fcvt2", "fcvt1", "im")}
            preset = ["--preset", a.preset] if a.preset else []
            cmds = {"fcvt2": [a.fcvt, "remesh", source, out["fcvt2"], "--vertices", str(n), "--threads", "2", "--quiet"] + preset}
            if not a.no_single_thread:
                cmds["fcvt1"] = [a.fcvt, "remesh", source, out["fcvt1"], "--vertices", str(n), "--threads", "1", "--quiet"] + preset
            if im:
                cmds["im"] = [im, source, "-o", out["im"], "-r", "6", "-p", "6", "-v", str(n), "-d", "-t", "2"]
            runs = {k: [] for k in cmds}
            for _ in range(a.repeat):
                for k, cmd in cmds.items():
                    runs[k].append(timed(cmd))
            med = {k: (statistics.median(t for t, _ in r), statistics.median(m for _, m in r)) for k, r in runs.items()}
            verts = {k: vertex_count(a.fcvt, out[k]) for k in cmds if k != "fcvt1"}
            cell = lambda k: f"{med[k][0]:.1f} / {med[k][1]:.0f}"  # noqa: E731
            per = lambda k: f"{1000 * med[k][0] / verts[k]:.3f} / {1024 * med[k][1] / verts[k]:.1f}"  # noqa: E731
            if "fcvt1" in med:
                line = f"| {n} | {cell('fcvt2')} | {cell('fcvt1')} | {med['fcvt1'][0] / med['fcvt2'][0]:.2f} | "
            else:
                line = f"| {n} | {cell('fcvt2')} | - | - | "
            if im:
                line += (f"{cell('im')} | {med['fcvt2'][0] / med['im'][0]:.2f} | {med['fcvt2'][1] / med['im'][1]:.2f} | "
                         f"{per('fcvt2')} | {per('im')} | {verts['fcvt2']} / {verts['im']} |")
            else:
                line += f"- | - | - | {per('fcvt2')} | - | {verts['fcvt2']} / - |"
            print(line, flush=True)


if __name__ == "__main__":
    main()
