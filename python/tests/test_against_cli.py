#!/usr/bin/env python3
"""The module against the CLI (issue 53 item 4): the same bytes, report, field and metrics."""
import json
import os
import warnings

import numpy as np

import fcvt
from common import BUNNY, check, main, run_cli, temp_dir

warnings.simplefilter("ignore", UserWarning)


def remesh_both(tmp, name, cli_options, **keywords):
    """fcvt remesh BUNNY OUT.ply CLI_OPTIONS --report, and fcvt.remesh(**keywords) written with fcvt.write."""
    cli_ply, cli_json, py_ply = (os.path.join(tmp, f"{name}{s}") for s in ("-cli.ply", "-cli.json", "-py.ply"))
    run_cli("remesh", BUNNY, cli_ply, *cli_options, "--report", cli_json, "--quiet")
    V, F = fcvt.read(BUNNY)
    r = fcvt.remesh(V, F, **keywords)
    fcvt.write(py_ply, r.vertices, r.faces, normals=r.normals, rosy=r.rosy)
    with open(cli_ply, "rb") as a, open(py_ply, "rb") as b, open(cli_json) as j:
        return a.read(), b.read(), json.load(j), r


def test_bunny_1000_same_bytes_and_report():
    with temp_dir() as tmp:
        cli, py, report, r = remesh_both(tmp, "bunny", ["--vertices", 1000], vertices=1000)
        check(py == cli, f"PLY bytes differ ({len(py)} vs {len(cli)})")
        check(r.vertices.dtype == np.float64 and r.vertices.shape[1] == 3, "vertices n x 3 float64")
        check(r.faces.dtype in (np.int32, np.int64) and r.faces.shape[1] == 3, "faces m x 3 int")
        check(r.report["metrics"] == report["metrics"], f"metrics {r.report['metrics']} != {report['metrics']}")
        check(list(r.report) == list(report), f"report keys {list(r.report)} != {list(report)}")
        # threads_used is the cores no other task held as each run started (threads 0): it moves
        # with the machine's load, the output does not (the bytes above are the same).
        for key in report:
            if key not in ("input_file", "output_file", "time_s", "threads_used"):
                check(r.report[key] == report[key], f"report[{key!r}] differs")
        check(list(r.report["time_s"]) == list(report["time_s"]), "time_s keys")
        check(r.report["input_file"] is None and r.report["output_file"] is None, "no files")


def test_keywords_pass_through():
    with temp_dir() as tmp:
        base_cli, base_py, _, _ = remesh_both(tmp, "base", ["--vertices", 600], vertices=600)
        cli, py, report, r = remesh_both(tmp, "cvt", ["--vertices", 600, "--lambda", 0, "--feature-angle", 45],
                                         vertices=600, lambda_=0, feature_angle=45)
        check(py == cli, "lambda_=0, feature_angle=45: PLY bytes differ from the CLI's")
        check(py != base_py, "lambda_=0, feature_angle=45 changed nothing")
        check(r.report["params"]["lambda"] == 0 and r.report["params"]["feature_angle"] == 45, "params in the report")
        cli, py, report, r = remesh_both(tmp, "flags", ["--vertices", 600, "--no-valence", "--seed", 7],
                                         vertices=600, no_valence=True, seed=7)
        check(py == cli and r.report["valence"] == report["valence"], "no_valence=True, seed=7 differ from the CLI's")
        cli, py, report, r = remesh_both(tmp, "fast", ["--vertices", 600, "--preset", "fast"], vertices=600, preset="fast")
        check(py == cli and py != base_py, "preset='fast' differs from the CLI's --preset fast, or changes nothing")
        check(r.report["params"] == report["params"] and r.report["params"]["fcvt_iterations"] == 5, "fast's params")


def test_target_length():
    with temp_dir() as tmp:
        cli, py, report, r = remesh_both(tmp, "length", ["--target-length", 0.004], target_length=0.004)
        check(py == cli, "target_length: PLY bytes differ")
        check(r.report["vertex_count"] == report["vertex_count"], "vertex_count differs")


def test_field_against_cli():
    with temp_dir() as tmp:
        out = os.path.join(tmp, "field-cli.ply")
        done = run_cli("field", BUNNY, out, "--seed", 3)
        V, F = fcvt.read(BUNNY)
        f = fcvt.field(V, F, seed=3)
        mine = os.path.join(tmp, "field-py.ply")
        fcvt.write(mine, f.vertices, f.faces, normals=f.normals, rosy=f.rosy)
        with open(out, "rb") as a, open(mine, "rb") as b:
            check(a.read() == b.read(), "field PLY bytes differ from fcvt field's")
        lines = dict(line.split(": ", 1) for line in done.stdout.splitlines() if ": " in line)
        check(int(lines["singularities"]) == len(f.singularities) == len(f.indices), "singularity count")
        check(int(lines["index sum"]) == f.index_sum, "index sum")
        check(int(lines["euler characteristic"]) == f.euler_characteristic, "euler characteristic")
        g = fcvt.field(V, F, field="curvature-max")
        check(not np.array_equal(g.rosy, f.rosy), "field='curvature-max' changed nothing")


def test_metrics_against_cli():
    with temp_dir() as tmp:
        out = os.path.join(tmp, "m.ply")
        run_cli("remesh", BUNNY, out, "--vertices", 500, "--quiet")
        with_ref = json.loads(run_cli("metrics", out, "--ref", BUNNY, "--json").stdout)
        alone = json.loads(run_cli("metrics", out, "--json").stdout)
        V, F = fcvt.read(out)
        V0, F0 = fcvt.read(BUNNY)
        check(fcvt.metrics(V, F, reference=(V0, F0)) == with_ref, "metrics with reference differ from fcvt metrics --ref")
        check(fcvt.metrics(V, F) == alone, "metrics differ from fcvt metrics --json")
        check(alone["d_h"] is None, "no distance without a reference")


def test_read_write_round_trip():
    V, F = fcvt.read(BUNNY)
    check(V.dtype == np.float64 and V.shape == (V.shape[0], 3) and F.shape[1] == 3, "read shapes")
    with temp_dir() as tmp:
        for ext in ("ply", "obj", "off"):
            path = os.path.join(tmp, f"round.{ext}")
            fcvt.write(path, V, F)
            V2, F2 = fcvt.read(path)
            check(np.array_equal(F, F2), f"{ext}: faces differ")
            check(np.array_equal(V, V2) if ext == "ply" else np.allclose(V, V2, rtol=1e-6, atol=1e-9), f"{ext}: vertices")
        # int64 faces and a list of lists are taken as well
        path = os.path.join(tmp, "list.ply")
        fcvt.write(path, V.tolist(), F.astype(np.int64))
        check(np.array_equal(fcvt.read(path)[1], F), "int64 faces")
    try:
        fcvt.read(os.path.join(RES_MISSING, "nothing.ply"))
        raise AssertionError("reading a missing file did not raise")
    except OSError:
        pass


RES_MISSING = "/nonexistent-fcvt"

if __name__ == "__main__":
    main([test_bunny_1000_same_bytes_and_report, test_keywords_pass_through, test_target_length, test_field_against_cli,
          test_metrics_against_cli, test_read_write_round_trip])
