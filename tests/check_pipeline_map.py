"""Keeps docs/development.md's pipeline map true (issue 51 item 6): every row's function is
defined in the file the row names and declared in core/remesh_stages.h, its output type is
declared there (or is FeatureLines / a plain value), and every stage remesh() calls in
core/remesh.cpp has a row. Prints each fault; exits 1 on any.
Usage: check_pipeline_map.py SOURCE_DIR"""
import os
import re
import sys

root = sys.argv[1]
faults = []


def read(path):
    with open(os.path.join(root, path), encoding="utf-8") as f:
        return f.read()


doc = read("docs/development.md")
match = re.search(r"<!-- pipeline-map -->(.*?)<!-- /pipeline-map -->", doc, re.S)
if not match:
    print("FAIL: docs/development.md has no <!-- pipeline-map --> table")
    sys.exit(1)
rows = [line for line in match.group(1).splitlines() if line.startswith("| ") and not line.startswith("| stage")]
header = read("core/remesh_stages.h")
mapped = set()
for row in rows:
    cells = [c.strip() for c in row.strip().strip("|").split("|")]
    if len(cells) != 5:
        faults.append(f"a row without 5 cells: {row}")
        continue
    stage, function, _inputs, output, files = cells
    name = function.strip("`")
    mapped.add(name)
    path = re.match(r"`([^`]+)`", files)
    if not path or not os.path.isfile(os.path.join(root, path.group(1))):
        faults.append(f"{stage}: no file {files}")
        continue
    source = read(path.group(1))
    # A definition: the name at the start of a declarator, followed by its parameter list and a body.
    if not re.search(r"^[A-Za-z][\w:<>,\s&*]*\b" + re.escape(name) + r"\([^;{]*\)\s*\{", source, re.M):
        faults.append(f"{stage}: {name} is not defined in {path.group(1)}")
    if not re.search(r"\b" + re.escape(name) + r"\(", header):
        faults.append(f"{stage}: {name} is not declared in core/remesh_stages.h")
    produced = re.match(r"`(\w+)`", output)
    if produced and not re.search(r"\b(struct|class)\s+" + produced.group(1) + r"\b",
                                  header + read("core/feature_lines.h")):
        faults.append(f"{stage}: its output type {produced.group(1)} is not declared")

# Every stage remesh() calls: the free functions of remesh_stages.h called in remesh()'s body.
orchestration = read("core/remesh.cpp")
body = orchestration[orchestration.index("RemeshResult remesh("):]
declared = set(re.findall(r"^\w[\w:<>,\s&*]*?\b(\w+)\(", header, re.M)) - {"secondsSince", "phaseName"}  # helpers
for called in sorted(set(re.findall(r"\b(\w+)\(", body)) & declared):
    if called not in mapped:
        faults.append(f"remesh() calls {called}, which the pipeline map does not list")

for fault in faults:
    print("FAIL: " + fault)
print(f"{len(rows)} stages checked, {len(faults)} faults")
sys.exit(1 if faults else 0)
