"""What the pymeshlab tests share: their arguments, pymeshlab with the plugin loaded, the CLI,
a PLY reader and the checks. Each test is run by run.sh as
    TEST.py PLUGIN SOURCE_DIR WORK_DIR [FCVT_CLI]
and exits 0 (PASS), 1 (FAIL: ...) or 77 (skipped: ...)."""
import json
import os
import re
import struct
import subprocess
import sys

import numpy as np

REMESH = "remeshing_field_aligned_cvt_fcvt"
FIELD = "compute_6_rosy_field"
REPORT = "remeshing_quality_report_fcvt"


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def skip(message):
    print("skipped: " + message)
    sys.exit(77)


class Test:
    def __init__(self, argv, needs_cli=True):
        if len(argv) < 4:
            sys.exit("usage: %s PLUGIN SOURCE_DIR WORK_DIR [FCVT_CLI]" % argv[0])
        self.plugin, self.source, self.work = argv[1:4]
        self.cli = argv[4] if len(argv) > 4 and argv[4] else None
        if needs_cli and self.cli is None:
            skip("no fcvt CLI in this build (FCVT_BUILD_CLI=OFF)")
        import pymeshlab  # on PYTHONPATH (run.sh): ../shared/pymeshlab

        self.pymeshlab = pymeshlab
        pymeshlab.load_plugin(self.plugin)
        for name in (REMESH, FIELD, REPORT):
            if name not in pymeshlab.filter_list():
                fail("pymeshlab lists no filter %s after load_plugin(%s)" % (name, self.plugin))

    def resource(self, name):
        return os.path.join(self.source, "resources", name)

    def path(self, name):
        return os.path.join(self.work, name)

    def meshset(self):
        return self.pymeshlab.MeshSet()

    def run_cli(self, *args):
        """`fcvt ARGS...`: its standard output."""
        done = subprocess.run([self.cli, *args], capture_output=True, text=True)
        if done.returncode != 0:
            fail("fcvt %s exited with %d: %s" % (" ".join(args), done.returncode, done.stderr.strip()))
        return done.stdout

    def cli_remesh(self, mesh, out_name, *options):
        """`fcvt remesh MESH OUT --report OUT.json OPTIONS`: (the output's path, the report)."""
        out = self.path(out_name)
        report = out + ".json"
        self.run_cli("remesh", mesh, out, "--report", report, "--quiet", *options)
        with open(report) as f:
            return out, json.load(f)

    def cli_metrics(self, mesh, reference=None):
        """`fcvt metrics MESH [--ref REFERENCE]`: its JSON figures and the topology of its table."""
        ref = ["--ref", reference] if reference else []
        figures = json.loads(self.run_cli("metrics", mesh, *ref, "--json"))
        table = self.run_cli("metrics", mesh, *ref)
        for key in ("genus", "boundary_loops", "components"):
            figures[key] = int(re.search(r"^%s\s+(-?\d+)$" % key, table, re.M).group(1))
        for key in ("manifold", "orientable"):
            figures[key] = re.search(r"^%s\s+(yes|no)$" % key, table, re.M).group(1) == "yes"
        return figures


def read_ply(path):
    """A PLY file's vertex properties (name -> float64 array) and faces (int array n x 3)."""
    data = open(path, "rb").read()
    end = data.index(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii").splitlines()
    fmt, elements = None, []
    for line in header:
        w = line.split()
        if w[:1] == ["format"]:
            fmt = w[1]
        elif w[:1] == ["element"]:
            elements.append([w[1], int(w[2]), []])
        elif w[:1] == ["property"]:
            elements[-1][2].append(w[1:])
    codes = {"char": "b", "uchar": "B", "int8": "b", "uint8": "B", "short": "h", "ushort": "H", "int16": "h",
             "uint16": "H", "int": "i", "uint": "I", "int32": "i", "uint32": "I", "float": "f", "float32": "f",
             "double": "d", "float64": "d"}
    if fmt not in ("ascii", "binary_little_endian"):
        fail("%s: PLY format %s not read here" % (path, fmt))
    vertices, faces = {}, []
    if fmt == "ascii":
        tokens = data[end:].split()
        pos = 0
    else:
        pos = end
    for name, count, props in elements:
        if name == "vertex":
            names = [p[-1] for p in props]
            if fmt == "ascii":
                rows = np.array(tokens[pos:pos + count * len(names)], dtype=np.float64).reshape(count, len(names))
                pos += count * len(names)
            else:
                st = struct.Struct("<" + "".join(codes[p[0]] for p in props))
                rows = np.array([st.unpack_from(data, pos + i * st.size) for i in range(count)], dtype=np.float64)
                pos += count * st.size
            vertices = {n: rows[:, i] for i, n in enumerate(names)}
        elif name == "face":
            for _ in range(count):
                for p in props:
                    if p[0] == "list":
                        if fmt == "ascii":
                            n = int(tokens[pos]); item = [int(t) for t in tokens[pos + 1:pos + 1 + n]]; pos += 1 + n
                        else:
                            cs, ci = struct.Struct("<" + codes[p[1]]), struct.Struct("<" + codes[p[2]])
                            n = cs.unpack_from(data, pos)[0]; pos += cs.size
                            item = [ci.unpack_from(data, pos + k * ci.size)[0] for k in range(n)]; pos += n * ci.size
                        if p[-1] in ("vertex_indices", "vertex_index"):
                            faces.append(item)
                    else:
                        if fmt == "ascii":
                            pos += 1
                        else:
                            pos += struct.calcsize("<" + codes[p[0]])
        else:
            fail("%s: element %s not read here" % (path, name))
    return vertices, np.array(faces, dtype=np.int64).reshape(-1, 3)


def points(vertices, prefix=""):
    return np.column_stack([vertices[prefix + "x"], vertices[prefix + "y"], vertices[prefix + "z"]])


def close(a, b, rel):
    return abs(a - b) <= rel * max(abs(a), abs(b), 1e-300)


def compare_figures(what, got, expected, keys, rel):
    """The keys' values of `got` (pymeshlab's dict) against `expected` (the CLI's JSON, where a figure not
    measured is null and the dict has no key); returns the mismatches as text."""
    bad = []
    for k in keys:
        e = expected.get(k)
        g = got.get(k)
        if e is None or g is None:
            if not (e is None and g is None):
                bad.append("%s %s: filter %r, CLI %r" % (what, k, g, e))
        elif isinstance(e, bool) or isinstance(g, bool):
            if bool(g) != bool(e):
                bad.append("%s %s: filter %r, CLI %r" % (what, k, g, e))
        elif not close(float(g), float(e), rel):
            bad.append("%s %s: filter %r, CLI %r" % (what, k, g, e))
    return bad
