#!/usr/bin/env python3
"""Bad input raises ValueError with the CLI's message (issue 53 item 4)."""
import os
import warnings

import numpy as np

import fcvt
from common import BUNNY, check, cli_error, main, octahedron, temp_dir

warnings.simplefilter("ignore", UserWarning)


def value_error(*args, **keywords):
    """The message of the ValueError fcvt.remesh(*args, **keywords) raises."""
    try:
        fcvt.remesh(*args, **keywords)
    except ValueError as e:
        check("\n" not in str(e), f"more than one line: {e!r}")
        return str(e)
    raise AssertionError(f"no ValueError for {keywords}")


def test_empty_arrays():
    check(value_error(np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int32), vertices=100) == "the mesh is empty", "empty")


def test_wrong_shapes_and_types():
    V, F = octahedron()
    check("V must have shape (n, 3)" in value_error(V[:, :2], F, vertices=100), "V shape")
    check("F must have shape (n, 3)" in value_error(V, F[:, :2], vertices=100), "F shape")
    check("F must have shape (n, 3)" in value_error(V, F.ravel(), vertices=100), "F 1-D")
    check("expected integers" in value_error(V, F.astype(float), vertices=100), "F of floats")
    check("refers to vertex" in value_error(V, F + 10, vertices=100), "index out of range")


def test_nan():
    V, F = octahedron()
    V[2, 1] = np.nan
    check("non-finite" in value_error(V, F, vertices=100), "NaN")


def test_non_manifold_edge_as_the_cli_says():
    V, F = octahedron()
    V = np.vstack([V, [[0, 0, 2]]])
    F = np.vstack([F, [[0, 2, 6]]])  # a third face on the edge 0-2
    message = value_error(V, F, vertices=100, no_repair=True)
    with temp_dir() as tmp:
        path = os.path.join(tmp, "nm.off")
        fcvt.write(path, V, F)
        check(cli_error("remesh", path, os.path.join(tmp, "o.ply"), "--vertices", 100, "--no-repair") == f"{path}: {message}",
              f"CLI and module differ: {message}")
    r = fcvt.remesh(V, F, vertices=100)  # repaired by default, as by the CLI
    check(r.report["repair"]["non_manifold_edges"] == 1, "the repair counts the edge")


def test_bad_options_as_the_cli_says():
    V, F = octahedron()
    with temp_dir() as tmp:
        out = os.path.join(tmp, "o.ply")
        cases = [
            ({"vertices": -1}, ["--vertices", -1]),
            ({"vertices": 100, "lambda_": -1}, ["--vertices", 100, "--lambda", -1]),
            ({"vertices": 100, "adaptive": "x"}, ["--vertices", 100, "--adaptive", "x"]),
            ({"vertices": 100, "field": "nope"}, ["--vertices", 100, "--field", "nope"]),
            ({"vertices": 100, "seed": -3}, ["--vertices", 100, "--seed", -3]),
            ({"vertices": 100, "gradation": 2}, ["--vertices", 100, "--gradation", 2]),
            ({}, []),
            ({"vertices": 100, "target_length": 0.1}, ["--vertices", 100, "--target-length", 0.1]),
            ({"vertices": 100, "texture": "x"}, ["--vertices", 100, "--texture", "x"]),
            ({"vertices": 100, "bogus_option": 1}, ["--vertices", 100, "--bogus-option", 1]),
        ]
        for keywords, options in cases:
            expected = cli_error("remesh", BUNNY, out, *options)
            got = value_error(V, F, **keywords)
            check(got == expected, f"{keywords}: {got!r} != CLI's {expected!r}")
    check("is a flag" in value_error(V, F, vertices=100, no_valence="yes"), "flag given a string")
    check("unknown option '--help'" in value_error(V, F, vertices=100, help=True), "help is no keyword")


def test_field_and_metrics_errors():
    V, F = octahedron()
    for call in (lambda: fcvt.field(V, F, seed=-1), lambda: fcvt.field(V, F, bogus=1),
                 lambda: fcvt.field(V[:, :2], F), lambda: fcvt.metrics(V, F[:, :1]),
                 lambda: fcvt.metrics(V, F, reference=(V,))):
        try:
            call()
            raise AssertionError("no ValueError")
        except ValueError:
            pass


if __name__ == "__main__":
    main([test_empty_arrays, test_wrong_shapes_and_types, test_nan, test_non_manifold_edge_as_the_cli_says,
          test_bad_options_as_the_cli_says, test_field_and_metrics_errors])
