#!/usr/bin/env python3
"""Compares two builds of fcvt_bench on a shared, noisy machine: runs them alternately
(A B A B ...) for ROUNDS rounds on the same benchmarks and prints the median real time of each
benchmark and the ratio B/A. Usage:
  bench/compare.py BASE/fcvt_bench NEW/fcvt_bench [--filter REGEX] [--rounds N] [--min-time S]"""
import argparse
import json
import statistics
import subprocess


def run(binary, pattern, min_time):
    out = subprocess.run([binary, "--benchmark_filter=" + pattern, "--benchmark_format=json",
                          "--benchmark_min_time=%g" % min_time], check=True, capture_output=True, text=True).stdout
    return {b["name"]: b["real_time"] for b in json.loads(out)["benchmarks"] if b.get("run_type") != "aggregate"}, \
        {b["name"]: b["time_unit"] for b in json.loads(out)["benchmarks"]}


parser = argparse.ArgumentParser()
parser.add_argument("base")
parser.add_argument("new")
parser.add_argument("--filter", default="Dense")
parser.add_argument("--rounds", type=int, default=5)
parser.add_argument("--min-time", type=float, default=0.5)
args = parser.parse_args()
times = {"base": {}, "new": {}}
units = {}
for r in range(args.rounds):
    for label, binary in (("base", args.base), ("new", args.new)):
        result, unit = run(binary, args.filter, args.min_time)
        units.update(unit)
        for name, t in result.items():
            times[label].setdefault(name, []).append(t)
print("%-40s %12s %12s %8s" % ("benchmark (median of %d)" % args.rounds, "base", "new", "new/base"))
for name in times["base"]:
    if name not in times["new"]:
        continue
    a, b = statistics.median(times["base"][name]), statistics.median(times["new"][name])
    print("%-40s %9.1f %s %9.1f %s %8.3f" % (name, a, units[name], b, units[name], b / a))
