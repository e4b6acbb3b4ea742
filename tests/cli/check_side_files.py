"""The files a mesh names and the files a run writes beside OUT, class by class (issue 50 items
1-3): a material library, an image or a PLY TextureFile that is a FIFO, a device, a directory,
oversized, or not a material library is a warning and the run goes on (texture coordinates kept,
the bad file neither read whole nor named by the output); OUT.mtl and OUT_texture.png are never
written through a link, over the input's own files or over an existing file this run did not
create (numbered instead, with a warning; --overwrite replaces what is not the input's); --texture
keep never edits the input's library; OUT itself replaces a link rather than writing through it.
Every run has a time-out: a hang is a failure, not a stuck test.
Usage: check_side_files.py FCVT TEXTURED_DIR WORK_DIR"""
import os
import shutil
import struct
import sys
import zlib

from fcvt_check import check, finish, read_obj, run

fcvt, textured, work = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
MESH = os.path.join(textured, "bunny10k_textured.obj")
IMAGE = os.path.join(textured, "TextureDouble_A.png")
LIBRARY = "newmtl 01_-_Default\nKd 0.6 0.6 0.6\nmap_Kd TextureDouble_A.png\n"
with open(MESH) as f:
    MESH_TEXT = f.read()


def case(name, library_name="mats.mtl", library=LIBRARY, image=True):
    """A folder work/NAME/in with mesh.obj naming `library_name` (written with `library` unless
    None), the image beside it; and an empty work/NAME/out. Returns (in folder, out folder)."""
    folder = os.path.join(work, name, "in")
    out = os.path.join(work, name, "out")
    os.makedirs(folder)
    os.makedirs(out)
    with open(os.path.join(folder, "mesh.obj"), "w") as f:
        f.write(MESH_TEXT.replace("mtllib ./bunny10k_textured.mtl", "mtllib " + library_name))
    if library is not None:
        with open(os.path.join(folder, library_name), "w") as f:
            f.write(library)
    if image:
        shutil.copy(IMAGE, folder)
    return folder, out


def remesh(inp, out, *extra, timeout=120):
    """fcvt remesh at 300 vertices; a run that does not end within `timeout` s is a failure."""
    try:
        return run([fcvt, "remesh", inp, out, "--vertices", "300", "--threads", "2", "--quiet"] + list(extra),
                   timeout=timeout)
    except Exception as e:  # subprocess.TimeoutExpired: the hang the issue saw
        return -1, "", f"did not finish: {e}"


def libraries_of(obj):
    return read_obj(obj)[3]


def has_texture(obj):
    v, vt, faces, _, _ = read_obj(obj)
    return len(vt) > 0


def read_bytes(path):
    with open(path, "rb") as f:
        return f.read()


def huge_png(path, width, height):
    """A PNG whose header says width x height (the pixels themselves are not there)."""
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    chunk = b"IHDR" + header
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + struct.pack(">I", len(header)) + chunk + struct.pack(">I", zlib.crc32(chunk)))


# --- Side files read: special files, oversized, not a material library -----------------------
for kind in ["fifo", "device", "directory", "oversized", "notes"]:
    name = {"directory": "mats.d", "notes": "../private/notes.txt"}.get(kind, "mats.mtl")
    folder, out = case("read_" + kind, name, library=None)
    path = os.path.normpath(os.path.join(folder, name))
    if kind == "fifo":
        os.mkfifo(path)
    elif kind == "device":
        os.symlink("/dev/zero", path)
    elif kind == "directory":
        os.makedirs(path)
    elif kind == "oversized":
        with open(path, "w") as f:  # a valid library, too big: 17 MiB over the 16 MiB limit
            f.write(LIBRARY + "# padding\n" * (17 * 1024 * 1024 // 10))
    else:
        os.makedirs(os.path.dirname(path))
        with open(path, "w") as f:
            f.write("Private notes.\nThe password is swordfish.\nDo not share this file.\n")
    out_obj = os.path.join(out, "mesh.obj")
    code, _, err = remesh(os.path.join(folder, "mesh.obj"), out_obj, "--texture", "keep")
    check(code == 0, f"{kind} library: exit {code} ({err.strip()[-300:]})")
    if code != 0:
        continue
    reason = {"fifo": "FIFO", "device": "character device", "directory": "directory", "oversized": "limit",
              "notes": "not a material library"}[kind]
    check("warning" in err and reason in err, f"{kind} library: a warning that says '{reason}' ({err.strip()[-300:]})")
    check(has_texture(out_obj), f"{kind} library: the texture coordinates are kept")
    check(libraries_of(out_obj) == [], f"{kind} library: OUT names no library ({libraries_of(out_obj)})")
    check(sorted(os.listdir(out)) == ["mesh.obj"], f"{kind} library: nothing written beside OUT ({os.listdir(out)})")

# An image that is a FIFO, with --texture bake: a warning, the atlas kept, the FIFO not named.
folder, out = case("image_fifo", image=False)
os.mkfifo(os.path.join(folder, "TextureDouble_A.png"))
out_obj = os.path.join(out, "mesh.obj")
code, _, err = remesh(os.path.join(folder, "mesh.obj"), out_obj, "--texture", "bake")
check(code == 0 and "FIFO" in err, f"FIFO image: exit 0 and a warning ({code}, {err.strip()[-300:]})")
if code == 0:
    check(has_texture(out_obj), "FIFO image: the atlas is kept")
    mtl = [os.path.join(out, lib) for lib in libraries_of(out_obj)]
    check(all("TextureDouble_A.png" not in open(m).read() for m in mtl), "FIFO image: OUT's library does not name it")

# An image too large in pixels (its header says 10000 x 10000): not decoded, the atlas kept.
folder, out = case("image_pixels", image=False)
huge_png(os.path.join(folder, "TextureDouble_A.png"), 10000, 10000)
code, _, err = remesh(os.path.join(folder, "mesh.obj"), os.path.join(out, "mesh.obj"), "--texture", "bake")
check(code == 0 and "Mpixel" in err, f"huge image: exit 0, a warning naming the limit ({code}, {err.strip()[-300:]})")

# A PLY whose TextureFile is a FIFO (the default texture mode reads the image to decide).
folder, out = case("ply_fifo")
ply = os.path.join(folder, "mesh.ply")
code, _, err = run([fcvt, "convert", os.path.join(folder, "mesh.obj"), ply, "--quiet"], timeout=120)
check(code == 0 and b"TextureFile TextureDouble_A.png" in read_bytes(ply), f"PLY with TextureFile made ({err})")
os.remove(os.path.join(folder, "TextureDouble_A.png"))
os.mkfifo(os.path.join(folder, "TextureDouble_A.png"))
code, _, err = remesh(ply, os.path.join(out, "mesh.ply"))
check(code == 0 and "FIFO" in err, f"PLY TextureFile FIFO: exit 0 and a warning ({code}, {err.strip()[-300:]})")

# texture-compare with a FIFO image: one clear error, no hang.
try:
    code, stdout, err = run([fcvt, "texture-compare", os.path.join(folder, "mesh.obj"), ply], timeout=60)
except Exception as e:
    code, stdout, err = -1, "", f"did not finish: {e}"
check(code not in (0, -1) and "FIFO" in err and len(err.strip().splitlines()) == 1,
      f"texture-compare with a FIFO image: one error line ({code}, {err.strip()[-300:]})")

# --- Files written beside OUT --------------------------------------------------------------
# OUT_texture.png a link to another file: that file untouched, the link kept, a numbered image.
folder, out = case("write_link")
victim = os.path.join(work, "write_link", "victim.png")
shutil.copy(IMAGE, victim)
before = read_bytes(victim)
os.symlink(victim, os.path.join(out, "mesh_texture.png"))
out_obj = os.path.join(out, "mesh.obj")
code, _, err = remesh(os.path.join(folder, "mesh.obj"), out_obj, "--texture", "bake")
check(code == 0, f"link: exit {code} ({err.strip()[-300:]})")
check(read_bytes(victim) == before, "link: the file the link points to is not written")
check(os.path.islink(os.path.join(out, "mesh_texture.png")), "link: the link is not replaced without --overwrite")
check("mesh_texture_2.png" in err and os.path.isfile(os.path.join(out, "mesh_texture_2.png")),
      f"link: the image written as mesh_texture_2.png, with a warning ({err.strip()[-300:]})")
mtl = os.path.join(out, "mesh.mtl")
check(os.path.isfile(mtl) and "map_Kd mesh_texture_2.png" in open(mtl).read(), "link: OUT.mtl names the numbered image")
# Again with --overwrite: the link itself replaced by the image, its target still untouched.
os.remove(os.path.join(out, "mesh_texture_2.png"))
code, _, err = remesh(os.path.join(folder, "mesh.obj"), out_obj, "--texture", "bake", "--overwrite")
check(code == 0 and read_bytes(victim) == before, f"--overwrite: exit 0, the link's target untouched ({code})")
check(not os.path.islink(os.path.join(out, "mesh_texture.png")) and os.path.isfile(os.path.join(out, "mesh_texture.png")),
      "--overwrite: the link is replaced by the image")

# OUT.mtl and OUT_texture.png are the input's own files: never written, even with --overwrite.
folder, _ = case("write_input", "out.mtl", LIBRARY.replace("TextureDouble_A.png", "out_texture.png"), image=False)
shutil.copy(IMAGE, os.path.join(folder, "out_texture.png"))
library_before, image_before = read_bytes(os.path.join(folder, "out.mtl")), read_bytes(os.path.join(folder, "out_texture.png"))
for extra in ([], ["--overwrite"]):
    code, _, err = remesh(os.path.join(folder, "mesh.obj"), os.path.join(folder, "out.obj"), "--texture", "bake", *extra)
    check(code == 0, f"input's files {extra}: exit {code} ({err.strip()[-300:]})")
    check(read_bytes(os.path.join(folder, "out.mtl")) == library_before, f"input's files {extra}: its library untouched")
    check(read_bytes(os.path.join(folder, "out_texture.png")) == image_before, f"input's files {extra}: its image untouched")
    check("input's own files" in err, f"input's files {extra}: a warning says why the names changed")

# An existing, unrelated OUT_texture.png: kept (numbered image) unless --overwrite.
folder, out = case("write_existing")
existing = os.path.join(out, "mesh_texture.png")
with open(existing, "wb") as f:
    f.write(b"someone else's file")
code, _, err = remesh(os.path.join(folder, "mesh.obj"), os.path.join(out, "mesh.obj"), "--texture", "bake")
check(code == 0 and read_bytes(existing) == b"someone else's file", "existing image: kept")
check("--overwrite" in err and os.path.isfile(os.path.join(out, "mesh_texture_2.png")), "existing image: numbered, warned")
code, _, err = remesh(os.path.join(folder, "mesh.obj"), os.path.join(out, "mesh.obj"), "--texture", "bake", "--overwrite")
check(code == 0 and read_bytes(existing)[:8] == b"\x89PNG\r\n\x1a\n", "existing image: replaced with --overwrite")

# --texture keep with the input's library shared in OUT's folder: never edited; OUT has its own.
folder, out = case("keep_shared", "../out/shared.mtl", library=None)
with open(os.path.join(out, "shared.mtl"), "w") as f:
    f.write(LIBRARY)
shared_before = read_bytes(os.path.join(out, "shared.mtl"))
out_obj = os.path.join(out, "remeshed.obj")
code, _, err = remesh(os.path.join(folder, "mesh.obj"), out_obj, "--texture", "keep")
check(code == 0 and read_bytes(os.path.join(out, "shared.mtl")) == shared_before, f"keep: the shared library untouched ({code})")
check(libraries_of(out_obj) == ["remeshed.mtl"], f"keep: OUT has its own library ({libraries_of(out_obj)})")
if os.path.isfile(os.path.join(out, "remeshed.mtl")):
    text = open(os.path.join(out, "remeshed.mtl")).read()
    check("map_Kd ../in/TextureDouble_A.png" in text, f"keep: OUT's library names the image from OUT's folder ({text!r})")

# OUT itself a link to another file: the link replaced, the file it pointed to untouched.
folder, out = case("out_link")
victim = os.path.join(work, "out_link", "victim.ply")
with open(victim, "wb") as f:
    f.write(b"not to be overwritten")
os.symlink(victim, os.path.join(out, "mesh.ply"))
code, _, err = remesh(os.path.join(folder, "mesh.obj"), os.path.join(out, "mesh.ply"), "--no-texture")
check(code == 0 and read_bytes(victim) == b"not to be overwritten", f"OUT a link: its target untouched ({code})")
check(not os.path.islink(os.path.join(out, "mesh.ply")), "OUT a link: replaced by the output file")
check(not any(n.startswith(".") for n in os.listdir(out)), f"no temporary file left ({os.listdir(out)})")

finish()
