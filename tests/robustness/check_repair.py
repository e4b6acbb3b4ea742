"""The repair stage (issue 17) end to end: generated inputs of each kind real meshes come in, through
`fcvt remesh --report` and through meshlabserver (resources/fcvt-remesh.mlx on a staged MeshLab
with our plugin, under xvfb-run). Each must give a manifold, oriented output, keep every
component that holds over 1 % of the area, and count its repairs in the report's "repair" object
and, with the same numbers, in the filter's log; with --no-repair (the checkbox off) the strict
check refuses what it refused before.
Usage: check_repair.py FCVT WORK_DIR [--source DIR --plugin SO]   (no plugin: CLI only)"""
import argparse
import json
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import meshgen as g  # noqa: E402

FAST = ["--vertices", "300", "--cvt-iterations", "10", "--fcvt-iterations", "0", "--lambda", "0", "--threads", "1"]
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL: " + message, flush=True)
    return condition


def cases():
    sphere = g.icosphere(2)
    torus = g.torus(16, 8)
    edge = 1.0 / 6  # the seam grids' edge length
    return [
        # name, mesh, expected repair counts, expected output components, strict refusal fragment
        ("every_face_twice", g.every_face_twice(sphere),
         {"removed_opposite_faces": 160, "removed_duplicate_faces": 160}, 1, None),
        ("fin_of_three_sheets", g.fin_of_three_sheets(), {"non_manifold_edges": 3}, None, "non-manifold edge"),
        ("two_shells_sharing_an_edge", g.two_shells_sharing_an_edge(), {"non_manifold_edges": 3}, 2,
         "non-manifold edge"),
        ("moebius_among_others",
         g.combine(sphere, g.transform(g.moebius(), 1, (3, 0, 0)), g.transform(torus, 1, (-3, 0, 0))),
         {"non_orientable_components": 1}, 3, "not orientable"),
        ("seam_1e-12", g.seam(1e-12), {"welded_vertices": 7}, 1, None),
        ("t_junction_crack", g.seam(1e-13, fine=True), {"welded_vertices": 7, "t_junctions": 6}, 1, None),
        ("narrow_real_gap", g.seam(0.01 * edge), {"welded_vertices": 0, "t_junctions": 0}, 2, None),
        ("floaters_1000", g.floaters(sphere), {"dropped_components": 1000}, 1, None),
    ]


def run_cli(fcvt, work, name, data, extra):
    inp = os.path.join(work, name + ".off")
    with open(inp, "wb") as fh:
        fh.write(g.off_bytes(data))
    tag = name + ("-strict" if extra else "")
    out, rep = os.path.join(work, tag + ".obj"), os.path.join(work, tag + ".json")
    for path in (out, rep):
        if os.path.exists(path):
            os.remove(path)
    p = subprocess.run([fcvt, "remesh", inp, out, "--report", rep, "--quiet"] + FAST + extra,
                       capture_output=True, text=True, timeout=300)
    return inp, p, (json.load(open(rep)) if p.returncode == 0 else None), out


def cli_checks(fcvt, work):
    for name, mesh, counts, components, refusal in cases():
        inp, p, report, out = run_cli(fcvt, work, name, mesh, [])
        print("%-28s exit %d" % (name, p.returncode), flush=True)
        if not check(p.returncode == 0, "%s: exit %d: %s" % (name, p.returncode, p.stderr.strip())):
            continue
        repair = report["repair"]
        check(repair["enabled"] is True, name + ": repair not enabled in the report")
        for key, value in counts.items():
            check(repair.get(key) == value, "%s: repair.%s = %r, expected %r" % (name, key, repair.get(key), value))
        topo = report["output"]
        check(topo["manifold"] and topo["orientable"], "%s: output not manifold and oriented: %r" % (name, topo))
        check(not g.manifold_problems(g.read_obj(out)), "%s: output file not manifold" % name)
        if components is not None:
            check(topo["components"] == components, "%s: %d output components, expected %d" % (name, topo["components"], components))
        check(report["params"]["repair"] is True, name + ": params.repair not true")
        # The strict behaviour: today's refusal, or (no refusal) the same run without repairs.
        _, p, report, _ = run_cli(fcvt, work, name, mesh, ["--no-repair"])
        if refusal:
            check(p.returncode == 1 and refusal in p.stderr, "%s --no-repair: expected the refusal %r, got exit %d %s"
                  % (name, refusal, p.returncode, p.stderr.strip()[-300:]))
        elif p.returncode == 0:
            check(report["repair"] == {"enabled": False}, name + " --no-repair: repair object %r" % report["repair"])
    # Nothing can be kept: a clear error, no output (was a 3-vertex "mesh" with exit 0).
    tiny = g.combine(*[g.transform(g.tetrahedron(), 0.1, (i % 10, i // 10 % 10, i // 100)) for i in range(1000)])
    _, p, _, out = run_cli(fcvt, work, "thousand_tiny", tiny, [])
    check(p.returncode == 1 and "all 1000 connected components are too small for 300 vertices" in p.stderr
          and "use at least 8000 vertices" in p.stderr and not os.path.exists(out),
          "thousand_tiny: expected the too-small error, got exit %d %s" % (p.returncode, p.stderr.strip()[-300:]))


def meshlab_checks(source, plugin, work, fcvt):
    stage = subprocess.run([os.path.join(source, "scripts", "stage-meshlab.sh"), os.path.join(work, "stage"), plugin],
                           capture_output=True, text=True)
    if not check(stage.returncode == 0, "staging MeshLab: " + stage.stderr[-400:]):
        return
    server = stage.stdout.strip().splitlines()[-1]
    template = open(os.path.join(source, "resources", "fcvt-remesh.mlx")).read()
    values = {"vertexCount": "300", "cvtIterations": "10", "fcvtIterations": "0", "lambda": "0"}
    for repair in ("true", "false"):
        text = template
        for name, value in dict(values, repair=repair).items():
            text, n = re.subn(r'(name="%s"[^>]*value=")[^"]*"' % name, r'\g<1>%s"' % value, text)
            check(n == 1, "no parameter %s in fcvt-remesh.mlx" % name)
        with open(os.path.join(work, "repair-%s.mlx" % repair), "w") as fh:
            fh.write(text)
    for name, mesh, counts, components, refusal in cases():
        inp = os.path.join(work, name + ".off")
        with open(inp, "wb") as fh:
            fh.write(g.off_bytes(mesh))
        for repair in ("true", "false"):
            out = os.path.join(work, "%s-ml-%s.ply" % (name, repair))
            if os.path.exists(out):
                os.remove(out)
            for attempt in range(2):  # once more when the X server did not start (no FCVT line at all)
                p = subprocess.run(["timeout", "-k", "5", "300", "xvfb-run", "-a", server, "-i", inp, "-o", out, "-s",
                                    os.path.join(work, "repair-%s.mlx" % repair)], capture_output=True, text=True)
                if "FCVT" in p.stdout:
                    break
                print("  meshlabserver exit %d without an FCVT line: %s" % (p.returncode, p.stderr.strip()[-300:]))
            log = p.stdout
            print("%-28s meshlab repair=%s exit %d" % (name, repair, p.returncode), flush=True)
            if repair == "false":
                check("FCVT repair: off" in log or (refusal and refusal in log),
                      "%s: meshlab without repair: neither 'FCVT repair: off' nor the refusal in the log" % name)
                if refusal:
                    check(p.returncode == 255 and not os.path.exists(out),
                          "%s: meshlab without repair: exit %d, expected the refusal (255)" % (name, p.returncode))
                continue
            if not check(p.returncode == 0 and os.path.exists(out), "%s: meshlab exit %d\n%s" % (name, p.returncode, log[-1500:])):
                continue
            expected = "FCVT repair: done" if any(counts.values()) else "FCVT repair: nothing to repair"
            check(expected in log, "%s: no %r in the log" % (name, expected))
            # The counts of the CLI's report, in the log's warnings (MeshLab's float coordinates
            # may make a near seam exact: the two welding counts are summed).
            said = dict((m.group(2), int(m.group(1))) for m in re.finditer(r"FCVT (?:warning|note): repair: (\d+) ([a-z -]+)", log))
            total = lambda *words: sum(v for k, v in said.items() if any(k.startswith(w) for w in words))
            if "non_manifold_edges" in counts:
                check(total("non-manifold edges") == counts["non_manifold_edges"], "%s: log counts %r" % (name, said))
            if "non_orientable_components" in counts:
                check(total("non-orientable") == counts["non_orientable_components"], "%s: log counts %r" % (name, said))
            if "dropped_components" in counts:
                check(total("connected components too small") == counts["dropped_components"], "%s: log counts %r" % (name, said))
            if "removed_opposite_faces" in counts:
                check(total("opposite duplicate", "duplicate faces") == 320, "%s: log counts %r" % (name, said))
            if counts.get("welded_vertices"):
                check(total("border vertices welded", "vertices merged") >= counts["welded_vertices"],
                      "%s: log counts %r" % (name, said))
            if counts.get("t_junctions"):
                check(total("border vertices inserted") == counts["t_junctions"], "%s: log counts %r" % (name, said))
            # meshlabserver writes PLY; the CLI's metrics read it: manifold, components.
            m = subprocess.run([fcvt, "metrics", out], capture_output=True, text=True)
            check(m.returncode == 0 and re.search(r"^manifold\s+yes$", m.stdout, re.M)
                  and re.search(r"^orientable\s+yes$", m.stdout, re.M),
                  "%s: meshlab output not manifold and oriented: %s" % (name, m.stdout.strip()[-300:]))
            if components is not None:
                found = re.search(r"^components\s+(\d+)$", m.stdout, re.M)
                check(found and int(found.group(1)) == components, "%s: meshlab output components: %s"
                      % (name, found.group(1) if found else "?"))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("fcvt")
    ap.add_argument("work")
    ap.add_argument("--source", default="")
    ap.add_argument("--plugin", default="")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    cli_checks(a.fcvt, a.work)
    if a.plugin:
        meshlab_checks(a.source, a.plugin, a.work, a.fcvt)
    print("%d check(s) failed" % len(failures) if failures else "all checks passed")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
