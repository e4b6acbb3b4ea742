"""The presets (--preset fast|default|quality): the same bytes on 1, 2 and 3 threads for each; the
settings each one puts in the report's params; other options override the preset; a bad name is
a usage error; fast on bunny 5000 has the vertex count and at least the quality of the better of
pmp and CGAL in the README's peers table, with far fewer energy evaluations than the default.
Usage: check_presets.py FCVT RESOURCES WORK_DIR"""
import filecmp
import json
import os
import sys

from fcvt_check import check, finish, run, run_ok

fcvt, resources, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
fertility = os.path.join(resources, "fertility.off")
bunny = os.path.join(resources, "bunny.obj")


def remesh(name, source, vertices, *extra):
    path = os.path.join(work, name + ".ply")
    report = os.path.join(work, name + ".json")
    run_ok([fcvt, "remesh", source, path, "--vertices", str(vertices), "--quiet", "--report", report, *extra])
    with open(report) as fh:
        return path, json.load(fh)


# Item 5: the same bytes for the same seed and preset on 1, 2 and 3 threads.
outputs = {}
for preset, vertices in (("fast", 1000), ("default", 1000), ("quality", 600)):
    paths = [remesh(f"{preset}_t{t}", fertility, vertices, "--preset", preset, "--seed", "3", "--threads", str(t))[0]
             for t in (1, 2, 3)]
    for t, path in zip((2, 3), paths[1:]):
        check(filecmp.cmp(paths[0], path, shallow=False), f"--preset {preset}: --threads 1 and --threads {t} differ")
    outputs[preset] = paths[0]
check(not filecmp.cmp(outputs["fast"], outputs["default"], shallow=False), "fast and default give the same mesh")

# The settings each preset names (docs/cli.md's table), as the report's params give them.
expected = {
    "fast": {"cvt_iterations": 0, "fcvt_iterations": 5, "large_run_fcvt_iterations": 5, "boundary_iterations": 3,
             "field_smoothing_iterations": 8, "lattice_iterations": 2, "lattice_passes": 2, "optimisation_faces_per_sample": 2,
             "valence_rounds": 10, "valence_look_ahead": 2, "valence_relax_iterations": 3, "valence_local_smoothing": 1,
             "valence_sag_repair_rounds": 0, "simplify_block_faces": 16000},
    "default": {"lloyd_iterations": 10, "lattice_lloyd_iterations": 0, "cvt_iterations": 10, "fcvt_iterations": 40,
                "large_run_fcvt_iterations": 20, "boundary_iterations": 10, "field_smoothing_iterations": 20,
                "lattice_iterations": 4, "lattice_passes": 3, "optimisation_faces_per_sample": 4, "valence_rounds": 30,
                "valence_look_ahead": 8, "valence_relax_iterations": 20, "valence_local_smoothing": 3,
                "valence_sag_repair_rounds": 4, "simplify_block_faces": 250000},
    "quality": {"lloyd_iterations": 30, "lattice_lloyd_iterations": 30, "cvt_iterations": 65, "fcvt_iterations": 65,
                "large_run_fcvt_iterations": 65, "field_smoothing_iterations": 40, "lattice_iterations": 8,
                "optimisation_faces_per_sample": 0},
}
for preset, settings in expected.items():
    _, report = remesh(f"params_{preset}", os.path.join(resources, "torus.obj"), 300, "--preset", preset)
    for key, value in settings.items():
        check(report["params"].get(key) == value, f"--preset {preset}: params.{key} is {report['params'].get(key)}, not {value}")
_, plain = remesh("params_none", os.path.join(resources, "torus.obj"), 300)
_, named_default = remesh("params_default", os.path.join(resources, "torus.obj"), 300, "--preset", "default")
check(plain["params"] == named_default["params"], "no --preset and --preset default differ in params")

# Other options override the preset, before or after it on the line.
_, overridden = remesh("override", os.path.join(resources, "torus.obj"), 300, "--fcvt-iterations", "12", "--preset", "fast",
                       "--cvt-iterations", "3", "--full-surface")
for key, value in (("fcvt_iterations", 12), ("cvt_iterations", 3), ("optimisation_faces_per_sample", 0),
                   ("field_smoothing_iterations", 8)):
    check(overridden["params"][key] == value, f"override: params.{key} is {overridden['params'][key]}, not {value}")

code, out, err = run([fcvt, "remesh", bunny, os.path.join(work, "bad.ply"), "--vertices", "500", "--preset", "rapid"])
lines = [line for line in err.splitlines() if line.strip()]
check(code == 2 and len(lines) == 1 and "--preset must be fast, default or quality" in err,
      f"a bad preset: exit {code}, stderr {err!r}")

# Fast on bunny 5000 against the better of pmp and CGAL in the README's peers table (Q_avg 0.918,
# V6 75.1 %, θ_min 25.6°, d_H 0.99 % of the diagonal), with the same vertex count (± 3 %).
bunny_fast, fast = remesh("bunny_fast", bunny, 5000, "--preset", "fast", "--threads", "2")
# Bunny (70 000 faces) is simplified in blocks in parallel by the fast preset: still the same bytes.
for t in (1, 3):
    other, _ = remesh(f"bunny_fast_t{t}", bunny, 5000, "--preset", "fast", "--threads", str(t))
    check(filecmp.cmp(bunny_fast, other, shallow=False), f"fast bunny 5000: --threads 2 and --threads {t} differ")
_, default = remesh("bunny_default", bunny, 5000, "--threads", "2")
m = fast["metrics"]
check(abs(fast["vertices"] - 5000) <= 150, f"fast bunny: {fast['vertices']} vertices for 5000")
check(m["q_avg"] >= 0.918, f"fast bunny: Q_avg {m['q_avg']:.3f} under pmp's and CGAL's 0.918")
check(m["v6_pct"] >= 75.1, f"fast bunny: V6 {m['v6_pct']:.1f} % under pmp's 75.1 %")
check(m["theta_min"] >= 25.6, f"fast bunny: θ_min {m['theta_min']:.1f}° under CGAL's 25.6°")
check(m["d_h"] <= 1.1 * 0.0099, f"fast bunny: d_H {100 * m['d_h']:.2f} % over 1.1 times CGAL's 0.99 %")
check(fast["evaluations"] * 3 <= default["evaluations"],
      f"fast bunny: {fast['evaluations']} energy evaluations against the default's {default['evaluations']}")
print(f"fast bunny 5000: {fast['vertices']} vertices, Q_avg {m['q_avg']:.3f}, θ_min {m['theta_min']:.1f}, "
      f"V6 {m['v6_pct']:.1f} %, d_H {100 * m['d_h']:.2f} %, {fast['evaluations']} evaluations "
      f"(default {default['evaluations']})")

finish()
