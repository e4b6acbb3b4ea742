#!/usr/bin/env python3
"""The paper's Fig. 10 trade-off, measured: V6% and Q_avg (and θ_min, d_H, time) of FCVT
against λ, on meshes at given vertex counts, same seed. Usage:

  bench/lambda_sweep.py build/cli/fcvt [--lambdas 0,0.1,0.3,1] [--seed S] MESH:N [MESH:N ...]

Prints a Markdown table (one row per mesh and λ); λ = 0 runs the pure CVT schedule
(130 CVT iterations), λ > 0 the default schedule (65 CVT + 65 FCVT)."""
import argparse
import json
import os
import subprocess
import sys
import tempfile


def run(fcvt, mesh, vertices, lam, seed, workdir):
    out = os.path.join(workdir, "out.ply")
    report = os.path.join(workdir, "report.json")
    cmd = [fcvt, "remesh", mesh, out, "--vertices", str(vertices), "--seed", str(seed), "--quiet", "--report", report]
    if lam == 0:
        cmd += ["--lambda", "0", "--cvt-iterations", "130", "--fcvt-iterations", "0"]
    else:
        cmd += ["--lambda", str(lam)]
    subprocess.run(cmd, check=True)
    with open(report) as f:
        return json.load(f)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("fcvt")
    parser.add_argument("meshes", nargs="+", help="MESH:VERTICES")
    parser.add_argument("--lambdas", default="0,0.1,0.3,1")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    lambdas = [float(x) for x in args.lambdas.split(",")]
    print("| mesh | N | λ | V6% | Q_avg | θ_min | %θ<30° | d_H % | s |")
    print("|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as workdir:
        for spec in args.meshes:
            mesh, vertices = spec.rsplit(":", 1)
            for lam in lambdas:
                r = run(args.fcvt, mesh, int(vertices), lam, args.seed, workdir)
                m = r["metrics"]
                print("| %s | %s | %g | %.1f | %.3f | %.1f | %.2f | %.3f | %.2f |" % (
                    os.path.basename(mesh), vertices, lam, m["v6_pct"], m["q_avg"], m["theta_min"],
                    m["pct_lt30"], 100 * m["d_h"], r["time_s"]["total"]))
                sys.stdout.flush()


if __name__ == "__main__":
    main()
