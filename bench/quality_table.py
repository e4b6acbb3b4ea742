#!/usr/bin/env python3
"""The default pipeline's quality, measured: one `fcvt remesh` per mesh (same seed), one
Markdown row each with the Table 2 figures, V6% before and after the valence optimisation,
the boundary figures (distance to the input's boundary, % of boundary vertices of valence 4)
and the time. Usage:

  bench/quality_table.py build/cli/fcvt MESH:N[:OPTION,OPTION...] ...

e.g. resources/fandisk.off:5000:--feature-angle,60 ; options go to `fcvt remesh` as given."""
import json
import os
import subprocess
import sys
import tempfile


def fmt(x, digits):
    return "–" if x is None else f"{x:.{digits}f}"


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    fcvt = sys.argv[1]
    print("| mesh | options | \\|X\\| | \\|t\\| | Q_min | Q_avg | θ_min | %θ<30° | V6% (before valence) | d_H % "
          "| d_boundary % | boundary V4% | genus, loops in/out | s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for spec in sys.argv[2:]:
            parts = spec.split(":")
            mesh, vertices = parts[0], parts[1]
            options = parts[2].split(",") if len(parts) > 2 and parts[2] else []
            out, report_path = os.path.join(work, "out.ply"), os.path.join(work, "report.json")
            subprocess.run([fcvt, "remesh", mesh, out, "--vertices", vertices, "--quiet", "--report", report_path] + options,
                           check=True)
            with open(report_path) as f:
                r = json.load(f)
            m, v = r["metrics"], r.get("valence") or {}
            pct = lambda x: None if x is None else 100 * x
            before = v.get("v6_before")
            v6 = fmt(m["v6_pct"], 1) + (f" ({before:.1f})" if before else "")
            topo = f"{r['input']['genus']}/{r['output']['genus']}, {r['input']['boundary_loops']}/{r['output']['boundary_loops']}"
            print(f"| {os.path.basename(mesh)} | {' '.join(options) or 'defaults'} | {r['vertices']} | {r['faces']} "
                  f"| {fmt(m['q_min'], 3)} | {fmt(m['q_avg'], 3)} | {fmt(m['theta_min'], 1)} | {fmt(m['pct_lt30'], 2)} | {v6} "
                  f"| {fmt(pct(m['d_h']), 3)} | {fmt(pct(m.get('d_boundary')), 3)} | {fmt(m.get('boundary_v4_pct'), 1)} "
                  f"| {topo} | {r['time_s']['total']:.1f} |", flush=True)


if __name__ == "__main__":
    main()
