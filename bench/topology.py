"""Issue 52 ("topology first"): FCVT beside MMG's mmgs, the peer that keeps topology, on the
generated topology classes of tests/robustness/topology_classes.py (plate_with_holes,
small_shells, chair, thin_handle_torus; at the budgets tests/robustness/check_topology_classes.py
runs them with) and on the nine meshes of resources/realworld at N = max(500, V/4) and
N = max(300, V/8) (V: the input's vertices as `fcvt metrics` counts them). One markdown row per
input and N: the input's boundary loops, pieces (connected components) and genus (the sum over
its pieces; "-" where a piece is non-manifold), then for each tool its output vertices, loops,
pieces, genus, whether it kept the topology and seconds (whole command), and the ratio of
FCVT's vertices to mmgs's (issue 52's target: at most 0.5 where mmgs keeps the topology). Each
tool's triangles too: θ_min (degrees) / % of the triangles under 30° (`fcvt metrics OUT --json`),
issue 32's bars being θ_min ≥ 15 and at most 0.5 %: a vertex count says little without them.
"Kept" is topology_classes.compare: every part (a component with 0.5 % of the area) comes back
as one shell with its genus and loops, holes FCVT closes by design excepted, no parts merged;
the non-manifold vertices of both meshes are split one per fan first (the output's counted as
"pinched"). What broke: lost, merged, split (a part in several shells), genus, torn (more loops
than the part), holes (loops lost).

  python3 bench/topology.py BUILD/cli/fcvt [--threads 2] [--tools fcvt mmgs] [--fcvt-options "..."] [NAME ...]

--fcvt-options adds options to FCVT's runs (e.g. "--feature-angle 45").

NAME: a class name or a file of resources/realworld (default: all). mmgs runs as the anchors'
README says (`/usr/bin/python3 ../shared/anchors/mmgs_remesh.py IN.obj OUT.obj N`) on an OBJ copy
of the input (written outside the timed part); without ../shared/anchors its cells say
"skipped: ...". FCVT is timed on a plain run (`--quiet`); a second run writes the report that
says which holes it closed and which cracks its repair welded (the input compared with both
tools' outputs is welded alike).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, ".."))
sys.path.insert(0, os.path.join(ROOT, "tests", "robustness"))
sys.path.insert(0, HERE)
import topology_classes as tc  # noqa: E402
from check_topology_classes import PLAN  # noqa: E402
from realworld import stl_to_obj  # noqa: E402
from side_by_side import SHARED, timed  # noqa: E402

MMGS = os.path.join(SHARED, "anchors", "mmgs_remesh.py")
REALWORLD = os.path.join(ROOT, "resources", "realworld")


def input_vertices(fcvt, path):
    text = subprocess.run([fcvt, "metrics", path], capture_output=True, text=True, check=True).stdout
    return next(int(line.split()[1]) for line in text.splitlines() if line.split()[:1] == ["vertices"])


def topo(parts):
    loops, pieces, genus = tc.summary(parts)
    return f"{loops} / {pieces} / {genus}"


def verdict(result):
    """"yes", or "no" and what broke, in a few words; "(N pinched)": the output's non-manifold
    vertices (split before measuring)."""
    problems = result["problems"]
    pinched = f" ({result['pinched']} pinched)" if result["pinched"] else ""
    if not problems:
        return "yes" + pinched
    what = []
    for word, text in (("lost (no output shell)", "lost"), ("merged", "merged"), ("output shells", "split"),
                       ("output genus", "genus"), ("boundary loops, input", "torn"), ("loops of the parts lost", "holes")):
        n = sum(word in p for p in problems)
        if n:
            what.append(text if n == 1 else f"{n} {text}")
    return "no: " + ", ".join(what) + pinched


def triangles(fcvt, path):
    """'θ_min / % under 30' of a mesh file, and whether issue 32's bars hold."""
    m = json.loads(subprocess.run([fcvt, "metrics", path, "--json"], capture_output=True, text=True,
                                  check=True).stdout)
    return f"{m['theta_min']:.1f} / {m['pct_lt30']:.2f}", m["theta_min"] >= 15 and m["pct_lt30"] <= 0.5


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("fcvt")
    ap.add_argument("names", nargs="*", help="classes and resources/realworld files (default: all)")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--tools", nargs="+", default=["fcvt", "mmgs"], choices=["fcvt", "mmgs"])
    ap.add_argument("--fcvt-options", default="", help='more options for FCVT, e.g. "--feature-angle 45"')
    a = ap.parse_args()
    extra = a.fcvt_options.split()
    realworld = sorted(n for n in os.listdir(REALWORLD) if not n.endswith(".md"))
    names = a.names or list(tc.CLASSES) + realworld
    mmgs_missing = None
    if "mmgs" in a.tools and not os.path.isfile(MMGS):
        mmgs_missing = f"skipped: {os.path.dirname(MMGS)} absent"
    print("| input (V; loops, pieces, genus) | N | FCVT V | FCVT loops / pieces / genus | FCVT kept | FCVT s "
          "| FCVT θ_min / % < 30° | mmgs V | mmgs loops / pieces / genus | mmgs kept | mmgs s | mmgs θ_min / % < 30° "
          "| FCVT V / mmgs V |")
    print("|" + "---|" * 13)
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for name in names:
            obj = os.path.join(work, "in.obj")
            if name in tc.CLASSES:
                make, ext, _, _ = tc.CLASSES[name]
                mesh = make()
                path = tc.write_mesh(os.path.join(work, f"{name}.{ext}"), mesh)
                tc.write_mesh(obj, mesh)
                v = len(mesh[0])
                budgets = PLAN[name][0]
            else:
                path = os.path.join(REALWORLD, name)
                if not os.path.isfile(path):
                    raise SystemExit(f"{name}: neither a class ({', '.join(tc.CLASSES)}) nor a file of {REALWORLD}")
                if subprocess.run([a.fcvt, "convert", path, obj, "--quiet"], stderr=subprocess.DEVNULL).returncode != 0:
                    stl_to_obj(path, obj)
                mesh = tc.read_mesh(path)
                v = input_vertices(a.fcvt, path)
                budgets = [max(500, v // 4), max(300, v // 8)]
            for n in budgets:
                out = os.path.join(work, "fcvt.obj")
                report = os.path.join(work, "fcvt.json")
                closed, weld = 0, 0.0
                fcvt_cells = ["failed"] + [""] * 4
                f_bars = m_bars = False
                result = None
                f_v = m_v = None
                m_kept = False
                if "fcvt" in a.tools:
                    try:
                        seconds = timed([a.fcvt, "remesh", path, out, "--vertices", str(n), "--threads", str(a.threads),
                                         "--quiet"] + extra)[0]
                        run = subprocess.run([a.fcvt, "remesh", path, os.path.join(work, "fcvt2.obj"), "--vertices",
                                              str(n), "--threads", str(a.threads), "--report", report] + extra,
                                             capture_output=True, text=True)
                        r = json.load(open(report)) if run.returncode == 0 else {}
                        closed = tc.holes_closed(r, run.stderr)
                        repair = r.get("repair") or {}
                        weld = repair.get("weld_distance", 0.0) if repair.get("welded_vertices", 0) > 0 else 0.0
                        fm = tc.read_obj(out)  # as written: split copies of a vertex stay apart
                        result = tc.compare(mesh, fm, closed, weld_distance=weld)
                        f_v = len({c for t in fm[1] for c in t})
                        kept = verdict(result)
                        shape, f_bars = triangles(a.fcvt, out)
                        fcvt_cells = [str(f_v), topo(result["out_shells"]), kept, f"{seconds:.2f}", shape]
                    except (SystemExit, subprocess.CalledProcessError, OSError, ValueError) as e:
                        fcvt_cells = ["failed: " + (str(e).strip().splitlines() or ["?"])[-1][:60], "", "", "", ""]
                prepared = tc.prepared_input(mesh, weld)[0]
                in_parts = tc.shells(prepared)
                if mmgs_missing or "mmgs" not in a.tools:
                    mmgs_cells = [mmgs_missing or "not run", "", "", "", ""]
                else:
                    mout = os.path.join(work, "mmgs.obj")
                    if os.path.exists(mout):
                        os.remove(mout)
                    try:
                        seconds = timed(["/usr/bin/python3", MMGS, obj, mout, str(n)])[0]
                        mm = tc.read_obj(mout)
                        if not mm[1]:
                            raise SystemExit("no faces written")
                        res = tc.compare(mesh, mm, 0, weld_distance=weld)
                        m_v = len({c for t in mm[1] for c in t})
                        m_kept = not res["problems"]
                        kept = verdict(res)
                        shape, m_bars = triangles(a.fcvt, mout)
                        mmgs_cells = [str(m_v), topo(res["out_shells"]), kept, f"{seconds:.2f}", shape]
                    except (SystemExit, subprocess.CalledProcessError, OSError, ValueError) as e:
                        mmgs_cells = ["failed: " + (str(e).strip().splitlines() or ["?"])[-1][:60], "", "", "", ""]
                ratio = f"{f_v / m_v:.2f}" if f_v and m_v else "n/a"
                rows.append((name, n, result is not None and not result["problems"], m_kept, f_v, m_v, f_bars, m_bars))
                print(f"| {name} ({v}; {topo(in_parts).replace(' / ', ', ')}) | {n} | " + " | ".join(fcvt_cells) + " | "
                      + " | ".join(mmgs_cells) + f" | {ratio} |", flush=True)
    both = [r for r in rows if r[3] and r[4] and r[5]]
    if both:
        good = [r for r in both if r[2] and r[4] <= 0.5 * r[5]]
        print(f"\nWhere mmgs keeps the topology ({len(both)} rows): FCVT keeps it with at most half mmgs's vertices "
              f"on {len(good)}" + ("; not on " + ", ".join(f"{r[0]} {r[1]}" for r in both if r not in good)
                                   if len(good) < len(both) else ""))
    if rows:
        print(f"Triangle bars (θ_min ≥ 15°, ≤ 0.5 % under 30°): FCVT on {sum(r[6] for r in rows)} of {len(rows)} rows, "
              f"mmgs on {sum(r[7] for r in rows)}; where mmgs keeps the topology and meets them too "
              f"({sum(1 for r in both if r[7])} rows), FCVT has at most half its vertices on "
              f"{sum(1 for r in both if r[7] and r[2] and r[4] <= 0.5 * r[5])}")


if __name__ == "__main__":
    main()
