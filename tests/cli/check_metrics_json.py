"""`fcvt metrics --json` prints exactly the report's metrics keys, distances null without --ref
and numbers with it, plus the input's part coverage with --ref; the table form works too. Usage: check_metrics_json.py FCVT RESOURCES_DIR"""
import math
import os
import sys

from fcvt_check import METRIC_KEYS, check, finish, metrics_json, run_ok

fcvt, resources = sys.argv[1], sys.argv[2]
mesh = os.path.join(resources, "fandisk.off")

plain = metrics_json(fcvt, mesh)
check(list(plain.keys()) == METRIC_KEYS, f"keys {list(plain.keys())}, expected {METRIC_KEYS}")
check(plain["d_rms"] is None and plain["d_h"] is None, "distances must be null without --ref")
for key in METRIC_KEYS[:8]:
    check(isinstance(plain[key], (int, float)) and math.isfinite(plain[key]), f"{key} = {plain[key]!r}")
check(0 < plain["q_min"] <= plain["q_avg"] <= 1, f"q_min {plain['q_min']} q_avg {plain['q_avg']}")

# A mesh against itself: distances are (nearly) zero, its one part kept whole.
PART_KEYS = ["parts", "part_gap", "part_pieces", "small_parts", "small_parts_area_pct", "small_parts_gap"]
with_ref = metrics_json(fcvt, mesh, ref=mesh)
check(list(with_ref.keys()) == METRIC_KEYS + PART_KEYS, f"keys with --ref: {list(with_ref.keys())}")
check(isinstance(with_ref["d_h"], float) and 0 <= with_ref["d_rms"] <= with_ref["d_h"] < 1e-6,
      f"self distances d_rms {with_ref['d_rms']} d_h {with_ref['d_h']}")
check((with_ref["parts"], with_ref["part_pieces"], with_ref["small_parts"]) == (1, 1, 0) and with_ref["part_gap"] < 1e-6,
      f"self parts {[with_ref[k] for k in PART_KEYS]}")

table = run_ok([fcvt, "metrics", mesh])
for word in METRIC_KEYS + ["vertices", "faces", "genus", "boundary_loops", "manifold"]:
    check(word in table, f"table lacks {word}")
table = run_ok([fcvt, "metrics", mesh, "--ref", mesh])
for word in PART_KEYS + ["part 1: 100 % of the area"]:
    check(word in table, f"table with --ref lacks {word}")

finish()
