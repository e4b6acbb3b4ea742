"""Writes the seed corpora of the libFuzzer targets (fuzz_read_mesh: small good meshes in every
format and variant, prefixed by the extension byte; fuzz_remesh: small meshes in its byte
encoding). Usage: make_seeds.py OUT_DIR  -> OUT_DIR/read_mesh/, OUT_DIR/remesh/"""
import os
import struct
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "robustness"))
import meshgen as g  # noqa: E402

EXT_BYTE = {"ply": 0, "obj": 1, "off": 2, "stl": 3}


def remesh_seed(mesh, target=8, iterations=3 + 6 * 3, field=0, misc=6 * 1, frame=6):
    """The byte layout of fuzz_remesh.cpp: counts, parameters, frame, int16 coordinates, faces."""
    v, f = mesh
    out = bytes([len(v) - 3, len(f) - 1, target - 4, iterations, field, misc, frame])
    for p in v:
        out += b"".join(struct.pack("<h", max(-32000, min(32000, int(round(c * 4096))))) for c in p)
    for t in f:
        out += bytes(t)
    return out


def main():
    out = sys.argv[1]
    read_dir, remesh_dir = os.path.join(out, "read_mesh"), os.path.join(out, "remesh")
    os.makedirs(read_dir, exist_ok=True)
    os.makedirs(remesh_dir, exist_ok=True)
    small = {"tet": g.tetrahedron(), "ico0": g.icosphere(0), "grid2": g.grid(2), "quads": g.quad_cube(1),
             "cones": g.two_cones_at_apex(3)}
    n = 0
    for name, mesh in small.items():
        for ext in ("ply", "obj", "off", "stl"):
            for variant in range(3 if ext in ("ply", "stl") else 1):
                with open(os.path.join(read_dir, "%s-%d.%s" % (name, variant, ext)), "wb") as fh:
                    fh.write(bytes([EXT_BYTE[ext]]) + g.mesh_bytes(mesh, ext, variant))
                n += 1
    tiny = {"tet": g.tetrahedron(), "ico0": g.icosphere(0), "grid1": g.grid(1), "grid2": g.grid(2),
            "cones": g.two_cones_at_apex(3)}
    for name, mesh in tiny.items():
        v, f = mesh
        if len(v) > 15 or len(f) > 24:
            continue
        for k, (target, field) in enumerate([(8, 0), (12, 3 + 6), (4, 0)]):
            with open(os.path.join(remesh_dir, "%s-%d" % (name, k)), "wb") as fh:
                fh.write(remesh_seed(mesh, target=target, field=field))
            n += 1
    print("%d seeds in %s" % (n, out))


if __name__ == "__main__":
    main()
