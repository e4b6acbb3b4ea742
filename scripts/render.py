#!/usr/bin/env python3
"""Render a triangle mesh to a PNG with f3d (Debian package `f3d`, 1.3), off screen under
`xvfb-run -a`: flat-shaded faces, the mesh edges, vertex colours, a fixed camera computed
from the mesh, white background. For the README's pictures (scripts/render_readme.sh).

The mesh is not handed to f3d as it is. The script reads it (PLY binary/ASCII, OBJ, OFF) and
writes a VTK XML PolyData copy (.vtp) that f3d 1.3 renders the way we want:
  * no normals, so VTK shades every face flat (fcvt's PLY output has per-vertex normals,
    which would give smooth shading);
  * one unsigned-char RGB point array, shown with f3d's direct scalars (`--scalars=RGB
    --comp=-2`; f3d's default component -1 would map the colour's magnitude through a
    colour map): the input's own vertex colours (PLY red green blue, e.g. the output of
    MeshLab's "Remeshing Quality Report (FCVT)"), or with --valence the colours by valence
    computed here (as that filter does: interior vertices target 6, vertices on an open
    boundary target 4; blue below, pink above, white at it; grey on no face), else a uniform
    light grey;
  * the mesh edges as line cells of the same data set, with their own points coloured
    --edge-color (f3d 1.3's `--edges` draws them black and has no option for their colour;
    `--edges f3d` uses it anyway), lifted by --edge-lift mean edge lengths along the vertex
    normals (at the faces' own depth about half of them lose the depth test); lines are not
    lit, so the edges keep their exact colour;
  * with --field, the 6-RoSy field of a PLY written by `fcvt remesh`/`fcvt field`
    (rosy_x rosy_y rosy_z) as three short red segments per vertex (a cross with six
    branches), lifted a little off the surface along the vertex normal.
The light (--light sky, the default): f3d 1.3 has no option for its lights, and its default
ones (a light kit, PBR material) render white faces mid-grey and wash the colours out; so the
scene is lit by an environment image (--hdri) made here, bright above the up axis and dark
below, with a matte material (--roughness 1). f3d then draws that image as the background
(--bg-color and --no-background are ignored), so a second pass with the default lights on a
magenta background gives the mask of the background, painted --background. --light f3d: one
pass, f3d's default lights.
The camera: looking at the mesh's bounding box from azimuth/elevation (--view) about the
up axis (--up), the box fitted to the picture (--zoom to come closer, --focus to centre on
another point of the box), view angle 15 degrees. f3d runs with --dry-run (no user
config file) and --quiet; --output renders in an X window of --resolution, so the Xvfb
screen is made a little larger than the picture. The PNG is then recompressed with optipng, and reduced to a
256-colour palette with pngquant if still above --max-bytes (both when installed).

Examples:
  python3 scripts/render.py out/bunny-fcvt.ply --out bunny.png --valence
  python3 scripts/render.py quality.ply --out q.png                # the PLY's own colours
  python3 scripts/render.py field.ply --out f.png --valence --field --zoom 3 --focus 0.5 0.8 0.5
"""

import argparse
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile

sys.dont_write_bytecode = True  # no __pycache__ in scripts/
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import render_png  # noqa: E402


class MeshError(Exception):
    pass


# ----------------------------------------------------------------------------------------
# Mesh readers: (vertices [(x, y, z)], polygons [(i, j, k, ...)], vertex properties
# {name: [float per vertex]}).
# ----------------------------------------------------------------------------------------

_PLY_TYPES = {
    'char': 'b', 'int8': 'b', 'uchar': 'B', 'uint8': 'B',
    'short': 'h', 'int16': 'h', 'ushort': 'H', 'uint16': 'H',
    'int': 'i', 'int32': 'i', 'uint': 'I', 'uint32': 'I',
    'float': 'f', 'float32': 'f', 'double': 'd', 'float64': 'd',
}


def read_ply(path):
    with open(path, 'rb') as f:
        data = f.read()
    if not data.startswith(b'ply'):
        raise MeshError(path + ': not a PLY file')
    end = data.find(b'end_header')
    if end < 0:
        raise MeshError(path + ': no end_header')
    nl = data.find(b'\n', end)
    body = nl + 1 if nl >= 0 else len(data)
    fmt = None
    elements = []  # [name, count, [(name, type, count type or None)]]
    for line in data[:end].decode('ascii', 'replace').splitlines():
        tok = line.split()
        if not tok:
            continue
        if tok[0] == 'format':
            fmt = tok[1]
        elif tok[0] == 'element':
            elements.append([tok[1], int(tok[2]), []])
        elif tok[0] == 'property':
            if not elements:
                raise MeshError(path + ': property before any element')
            if tok[1] == 'list':
                if tok[2] not in _PLY_TYPES or tok[3] not in _PLY_TYPES:
                    raise MeshError(path + ': unknown PLY type in ' + line)
                elements[-1][2].append((tok[4], tok[3], tok[2]))
            else:
                if tok[1] not in _PLY_TYPES:
                    raise MeshError(path + ': unknown PLY type in ' + line)
                elements[-1][2].append((tok[2], tok[1], None))
    if fmt not in ('ascii', 'binary_little_endian', 'binary_big_endian'):
        raise MeshError('%s: unsupported PLY format %r' % (path, fmt))

    verts, polys, vprops = [], [], {}
    if fmt == 'ascii':
        tokens = data[body:].split()
        pos = 0
        for name, count, props in elements:
            rows = []
            for _ in range(count):
                row = []
                for _, _, ctype in props:
                    if ctype is None:
                        row.append(float(tokens[pos]))
                        pos += 1
                    else:
                        n = int(float(tokens[pos]))
                        row.append([int(float(t)) for t in tokens[pos + 1:pos + 1 + n]])
                        pos += 1 + n
                rows.append(row)
            _ply_store(path, name, props, rows, verts, polys, vprops)
        return verts, polys, vprops

    endian = '<' if fmt == 'binary_little_endian' else '>'
    off = body
    try:
        for name, count, props in elements:
            if all(ctype is None for _, _, ctype in props):
                sfmt = endian + ''.join(_PLY_TYPES[t] for _, t, _ in props)
                size = struct.calcsize(sfmt)
                if off + size * count > len(data):
                    raise MeshError(path + ': file truncated in element ' + name)
                rows = list(struct.iter_unpack(sfmt, data[off:off + size * count]))
                off += size * count
            else:
                rows = []
                for _ in range(count):
                    row = []
                    for _, ptype, ctype in props:
                        if ctype is None:
                            sf = endian + _PLY_TYPES[ptype]
                            row.append(struct.unpack_from(sf, data, off)[0])
                            off += struct.calcsize(sf)
                        else:
                            cf = endian + _PLY_TYPES[ctype]
                            n = struct.unpack_from(cf, data, off)[0]
                            off += struct.calcsize(cf)
                            lf = endian + _PLY_TYPES[ptype] * n
                            row.append(list(struct.unpack_from(lf, data, off)))
                            off += struct.calcsize(lf)
                    rows.append(row)
            _ply_store(path, name, props, rows, verts, polys, vprops)
    except struct.error:
        raise MeshError(path + ': file truncated')
    return verts, polys, vprops


def _ply_store(path, name, props, rows, verts, polys, vprops):
    names = [p[0] for p in props]
    if name == 'vertex':
        try:
            ix, iy, iz = names.index('x'), names.index('y'), names.index('z')
        except ValueError:
            raise MeshError(path + ': PLY vertex element has no x y z')
        verts.extend((float(r[ix]), float(r[iy]), float(r[iz])) for r in rows)
        for k, (pname, _, ctype) in enumerate(props):
            if ctype is None:
                vprops[pname] = [float(r[k]) for r in rows]
    elif name == 'face':
        k = next((names.index(c) for c in ('vertex_indices', 'vertex_index') if c in names), None)
        if k is None:
            k = next((i for i, p in enumerate(props) if p[2] is not None), None)
        if k is None:
            raise MeshError(path + ': PLY face element has no list property')
        polys.extend(tuple(int(i) for i in r[k]) for r in rows)


def read_obj(path):
    verts, polys = [], []
    with open(path, 'r', errors='replace') as f:
        for line in f:
            if line.startswith('v '):
                t = line.split()
                verts.append((float(t[1]), float(t[2]), float(t[3])))
            elif line.startswith('f '):
                idx = []
                for t in line.split()[1:]:
                    i = int(t.split('/')[0])
                    idx.append(i - 1 if i > 0 else len(verts) + i)
                polys.append(tuple(idx))
    return verts, polys, {}


def read_off(path):
    with open(path, 'r', errors='replace') as f:
        tokens = []
        for line in f:
            tokens += line.split('#', 1)[0].split()
    if not tokens or not tokens[0].endswith('OFF'):
        raise MeshError(path + ': not an OFF file')
    nv, nf = int(tokens[1]), int(tokens[2])
    pos = 4
    verts = [tuple(float(x) for x in tokens[pos + 3 * k:pos + 3 * k + 3]) for k in range(nv)]
    pos += 3 * nv
    polys = []
    for _ in range(nf):
        n = int(tokens[pos])
        polys.append(tuple(int(x) for x in tokens[pos + 1:pos + 1 + n]))
        pos += 1 + n
    return verts, polys, {}


def read_mesh(path):
    with open(path, 'rb') as f:
        head = f.read(4)
    if head.startswith(b'ply'):
        return read_ply(path)
    if b'OFF' in head:
        return read_off(path)
    return read_obj(path)


# ----------------------------------------------------------------------------------------
# Geometry helpers
# ----------------------------------------------------------------------------------------

def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def unit(v):
    n = math.sqrt(dot(v, v))
    return (v[0] / n, v[1] / n, v[2] / n) if n > 0 else (0.0, 0.0, 0.0)


def mesh_edges(polys):
    """{(a, b) with a < b: number of faces}"""
    edges = {}
    for p in polys:
        for k in range(len(p)):
            a, b = p[k], p[(k + 1) % len(p)]
            key = (a, b) if a < b else (b, a)
            edges[key] = edges.get(key, 0) + 1
    return edges


LOW, HIGH, REGULAR, UNUSED = (30, 90, 235), (235, 40, 175), (255, 255, 255), (160, 160, 160)


def valence_colours(nv, edges):
    """The quality report's colours: blue below the target valence (6 inside, 4 on an open
    boundary), pink above, white at it, grey for vertices on no face. Returns (colours, counts)."""
    valence = [0] * nv
    boundary = [False] * nv
    for (a, b), nf in edges.items():
        valence[a] += 1
        valence[b] += 1
        if nf == 1:
            boundary[a] = boundary[b] = True
    colours, counts = [], {'low': 0, 'regular': 0, 'high': 0, 'unused': 0}
    for i in range(nv):
        if valence[i] == 0:
            colours.append(UNUSED)
            counts['unused'] += 1
            continue
        target = 4 if boundary[i] else 6
        kind = 'low' if valence[i] < target else 'high' if valence[i] > target else 'regular'
        counts[kind] += 1
        colours.append({'low': LOW, 'high': HIGH, 'regular': REGULAR}[kind])
    return colours, counts


def vertex_normals(verts, polys):
    vn = [[0.0, 0.0, 0.0] for _ in verts]
    for p in polys:
        o = verts[p[0]]
        for k in range(1, len(p) - 1):
            n = cross(sub(verts[p[k]], o), sub(verts[p[k + 1]], o))
            for i in (p[0], p[k], p[k + 1]):
                vn[i][0] += n[0]
                vn[i][1] += n[1]
                vn[i][2] += n[2]
    return [unit(v) for v in vn]


# ----------------------------------------------------------------------------------------
# Camera
# ----------------------------------------------------------------------------------------

AXES = {'x': (1.0, 0.0, 0.0), 'y': (0.0, 1.0, 0.0), 'z': (0.0, 0.0, 1.0)}
# The side seen at azimuth 0, elevation 0 for each up axis: +z for y up, -y for z up, +z for x up.
FRONT = {'x': (0.0, 0.0, 1.0), 'y': (0.0, 0.0, 1.0), 'z': (0.0, -1.0, 0.0)}


def camera(verts, used, args):
    """f3d's --camera-position, --camera-focal-point, --camera-view-up, --camera-view-angle."""
    sign = -1.0 if args.up.startswith('-') else 1.0
    axis = args.up[-1]
    up = tuple(sign * c for c in AXES[axis])
    front = tuple(sign * c for c in FRONT[axis]) if axis != 'y' else FRONT[axis]
    side = cross(up, front)  # what azimuth +90 degrees looks at
    az, el = math.radians(args.view[0]), math.radians(max(-89.0, min(89.0, args.view[1])))
    towards = unit(tuple(math.cos(el) * (math.cos(az) * f + math.sin(az) * s) + math.sin(el) * u
                         for f, s, u in zip(front, side, up)))
    right = unit(cross(up, towards))
    vup = cross(towards, right)
    pts = [verts[i] for i in used]
    lo = [min(p[k] for p in pts) for k in range(3)]
    hi = [max(p[k] for p in pts) for k in range(3)]
    xs = [dot(p, right) for p in pts]
    ys = [dot(p, vup) for p in pts]
    zs = [dot(p, towards) for p in pts]
    half_w, half_h = 0.5 * (max(xs) - min(xs)), 0.5 * (max(ys) - min(ys))
    half_d = 0.5 * (max(zs) - min(zs))
    if args.focus is None:
        cx, cy, cz = 0.5 * (max(xs) + min(xs)), 0.5 * (max(ys) + min(ys)), 0.5 * (max(zs) + min(zs))
        focal = tuple(cx * r + cy * u + cz * t for r, u, t in zip(right, vup, towards))
    else:
        focal = tuple(l + f * (h - l) for l, h, f in zip(lo, hi, args.focus))
    width, height = args.size
    fill = 0.92
    half_view = max(half_h, half_w * height / width, 1e-30) / fill / args.zoom
    angle = 15.0
    # the nearest point of the box sits half_d in front of the focal plane
    dist = half_view / math.tan(math.radians(angle / 2)) + half_d / args.zoom
    position = tuple(f + dist * t for f, t in zip(focal, towards))
    return position, focal, vup, angle


# ----------------------------------------------------------------------------------------
# VTK XML PolyData writer
# ----------------------------------------------------------------------------------------

def write_vtp(path, points, colours, polys, lines, verts=()):
    def array(kind, name, comps, values, fmt):
        head = '<DataArray type="%s"%s%s format="ascii">\n' % (
            kind, ' Name="%s"' % name if name else '',
            ' NumberOfComponents="%d"' % comps if comps else '')
        return head + ' '.join(fmt % v for v in values) + '\n</DataArray>\n'

    def cells(tag, cell_list):
        conn = [i for c in cell_list for i in c]
        offs, o = [], 0
        for c in cell_list:
            o += len(c)
            offs.append(o)
        return ('<%s>\n' % tag + array('Int32', 'connectivity', 0, conn, '%d') +
                array('Int32', 'offsets', 0, offs, '%d') + '</%s>\n' % tag)

    with open(path, 'w') as out:
        out.write('<?xml version="1.0"?>\n'
                  '<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">\n<PolyData>\n')
        out.write('<Piece NumberOfPoints="%d" NumberOfVerts="%d" NumberOfLines="%d" '
                  'NumberOfStrips="0" NumberOfPolys="%d">\n' % (len(points), len(verts), len(lines), len(polys)))
        out.write('<PointData Scalars="RGB">\n' +
                  array('UInt8', 'RGB', 3, [c for rgb in colours for c in rgb], '%d') + '</PointData>\n')
        out.write('<Points>\n' + array('Float64', None, 3, [c for p in points for c in p], '%.9g') +
                  '</Points>\n')
        if verts:
            out.write(cells('Verts', [(i,) for i in verts]))
        if lines:
            out.write(cells('Lines', lines))
        out.write(cells('Polys', polys))
        out.write('</Piece>\n</PolyData>\n</VTKFile>\n')


# ----------------------------------------------------------------------------------------

def colour_arg(text):
    t = text.lstrip('#')
    if len(t) != 6:
        raise argparse.ArgumentTypeError('colour RRGGBB expected, got ' + text)
    return tuple(int(t[k:k + 2], 16) for k in (0, 2, 4))


def build_scene(args):
    verts, polys, vprops = read_mesh(args.mesh)
    nv = len(verts)
    polys = [p for p in polys if len(p) >= 3 and all(0 <= i < nv for i in p)]
    if nv == 0 or not polys:
        raise MeshError(args.mesh + ': no vertices or no faces')
    used = sorted({i for p in polys for i in p})
    edges = mesh_edges(polys)
    info = {'vertices': nv, 'faces': len(polys)}

    if args.valence:
        colours, counts = valence_colours(nv, edges)
        info['valence'] = counts
    elif not args.no_colours and all(k in vprops for k in ('red', 'green', 'blue')):
        rgb = [vprops['red'], vprops['green'], vprops['blue']]
        scale = 255.0 if max(max(c) for c in rgb) <= 1.0 else 1.0  # float colours in [0, 1]
        colours = [tuple(max(0, min(255, int(round(rgb[k][i] * scale)))) for k in range(3))
                   for i in range(nv)]
        info['colours'] = 'from the file'
    else:
        colours = [args.face_color] * nv

    points, cols, lines, dots = list(verts), list(colours), [], []
    mean_edge = sum(math.sqrt(dot(sub(verts[a], verts[b]), sub(verts[a], verts[b])))
                    for a, b in edges) / len(edges)
    if args.edges == 'lines':
        # the edges on their own copies of the vertices, so that they have their own colour
        # lifted a little along the vertex normals: at the faces' own depth, VTK hides about
        # half of them (its coincident-topology offset does not separate cells of one actor)
        normals = vertex_normals(verts, polys)
        lift = args.edge_lift * mean_edge
        base = len(points)
        remap = {}
        for i in used:
            remap[i] = base + len(remap)
            points.append(tuple(verts[i][k] + lift * normals[i][k] for k in range(3)))
            cols.append(args.edge_color)
        lines += [(remap[a], remap[b]) for a, b in edges]
    if args.field:
        need = ('rosy_x', 'rosy_y', 'rosy_z')
        missing = [k for k in need if k not in vprops]
        if missing:
            raise MeshError(args.mesh + ': --field needs the PLY vertex properties rosy_x rosy_y '
                            'rosy_z (written by fcvt remesh / fcvt field); missing ' + ' '.join(missing))
        normals = vertex_normals(verts, polys)
        half, lift = 0.3 * mean_edge, 0.03 * mean_edge
        for i in used:
            n = normals[i]
            d = (vprops['rosy_x'][i], vprops['rosy_y'][i], vprops['rosy_z'][i])
            d = unit(sub(d, tuple(dot(d, n) * c for c in n)))
            if d == (0.0, 0.0, 0.0):
                continue
            e = cross(n, d)
            c = tuple(verts[i][k] + lift * n[k] for k in range(3))
            for ang in (0.0, math.pi / 3, 2 * math.pi / 3):
                r = tuple(math.cos(ang) * d[k] + math.sin(ang) * e[k] for k in range(3))
                points.append(tuple(c[k] - half * r[k] for k in range(3)))
                points.append(tuple(c[k] + half * r[k] for k in range(3)))
                cols += [args.field_color, args.field_color]
                lines.append((len(points) - 2, len(points) - 1))
    if args.dots > 0:
        # a dot on every vertex whose colour is not white (valence off target, or a file's
        # colour): vertex cells drawn --dots pixels wide, lifted like the edges
        normals = vertex_normals(verts, polys)
        lift = 2 * args.edge_lift * mean_edge
        for i in used:
            if colours[i] != REGULAR and colours[i] != args.face_color:
                points.append(tuple(verts[i][k] + lift * normals[i][k] for k in range(3)))
                cols.append(colours[i])
                dots.append(len(points) - 1)
    return verts, used, points, cols, polys, lines, dots, info


def write_sky(path, width=64, height=32):
    """An equirectangular environment image for f3d's --hdri: grey level by elevation, 255 at
    the zenith down to 40 at the nadir (a sky light: faces turned up are brighter)."""
    rows = []
    for y in range(height):
        t = (y + 0.5) / height  # 0 at the zenith, 1 at the nadir
        v = int(round(40 + 215 * (1 - t) ** 1.5))
        rows.append(bytes([v]) * (3 * width))
    render_png.write_png(path, width, height, rows)


def optimise(png, args):
    """Lossless recompression with optipng; if the PNG is still above --max-bytes, a palette of
    at most 256 colours with pngquant (dense meshes: the vertex colours blended over the faces
    and the light give tens of thousands of colours), then optipng again."""
    opt, quant = shutil.which('optipng'), shutil.which('pngquant')
    if opt:
        subprocess.run([opt, '-quiet', '-o2', png], check=True, timeout=args.timeout)
    if quant and args.max_bytes > 0 and os.path.getsize(png) > args.max_bytes:
        small = png + '.q.png'
        res = subprocess.run([quant, '--quality', '70-95', '--speed', '3', '--force', '--output', small,
                              '--', png], timeout=args.timeout)
        if res.returncode == 0 and os.path.exists(small):
            os.replace(small, png)
            if opt:
                subprocess.run([opt, '-quiet', '-o2', png], check=True, timeout=args.timeout)


def run_f3d(f3d, vtp, png, options, args):
    cmd = [f3d, vtp, '--output', png] + options
    if shutil.which('xvfb-run') and not args.no_xvfb:
        # the screen must hold the window: f3d renders into it, then reads it back
        cmd = ['xvfb-run', '-a', '-s', '-screen 0 %dx%dx24' % (max(args.size[0], 640) + 64,
                                                              max(args.size[1], 480) + 64)] + cmd
    res = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=args.timeout)
    if res.returncode != 0 or not os.path.exists(png):
        raise MeshError('f3d failed (exit %d): %s\n%s' % (res.returncode, ' '.join(cmd),
                                                          res.stdout.decode(errors='replace')))


def render(args):
    f3d = args.f3d or shutil.which('f3d')
    if not f3d:
        raise MeshError('f3d not found (Debian package f3d)')
    verts, used, points, cols, polys, lines, dots, info = build_scene(args)
    position, focal, vup, angle = camera(verts, used, args)
    tmp = tempfile.mkdtemp(prefix='fcvt-render-')
    try:
        vtp = args.keep_vtp or os.path.join(tmp, 'scene.vtp')
        write_vtp(vtp, points, cols, polys, lines, dots)
        out = os.path.abspath(args.out)
        fmt = lambda v: ','.join('%.9g' % c for c in v)
        common = ['--dry-run', '--quiet', '--resolution', '%d,%d' % tuple(args.size),
                  '--scalars=RGB', '--comp=-2', '--line-width', '%g' % args.line_width,
                  '--point-size', '%g' % max(args.dots, 1),
                  '--camera-position', fmt(position), '--camera-focal-point', fmt(focal),
                  '--camera-view-up', fmt(vup), '--camera-view-angle', '%g' % angle,
                  '--up', ('-' if args.up.startswith('-') else '+') + args.up[-1].upper()]
        if args.edges == 'f3d':
            common.append('--edges')
        if args.fxaa:
            common.append('--fxaa')
        common += args.f3d_arg
        shot = os.path.join(tmp, 'shot.png')
        if args.light == 'f3d':
            run_f3d(f3d, vtp, shot, common + ['--bg-color', fmt(c / 255.0 for c in args.background)], args)
        else:
            # Pass 1, lit by a sky: an environment image (--hdri) bright above, dark below the
            # model's up axis, matte (roughness 1). f3d 1.3 then shows the image as the
            # background (--bg-color and --no-background have no effect), hence pass 2: the
            # same scene with f3d's default lights on a magenta background, a colour no shaded
            # face takes, gives the mask of the background, which is painted --background.
            sky = os.path.join(tmp, 'sky.png')
            write_sky(sky)
            lit = os.path.join(tmp, 'lit.png')
            mask = os.path.join(tmp, 'mask.png')
            run_f3d(f3d, vtp, lit, common + ['--hdri', sky, '--roughness', '1'], args)
            run_f3d(f3d, vtp, mask, common + ['--bg-color', '1,0,1'], args)
            w, h, lit_rows = render_png.read_png(lit)
            w2, h2, mask_rows = render_png.read_png(mask)
            if (w, h) != (w2, h2) or (w, h) != tuple(args.size):
                raise MeshError('f3d wrote %dx%d and %dx%d pictures, not %dx%d' % (w, h, w2, h2, *args.size))
            bg = bytes(args.background)
            rows = []
            for lr, mr in zip(lit_rows, mask_rows):
                row = bytearray(lr)
                for x in range(0, len(mr), 3):
                    if mr[x:x + 3] == b'\xff\x00\xff':
                        row[x:x + 3] = bg
                rows.append(bytes(row))
            render_png.write_png(shot, w, h, rows)
        if not args.no_optimise:
            optimise(shot, args)
        shutil.copyfile(shot, out)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    info['png_bytes'] = os.path.getsize(out)
    return info


def main(argv=None):
    ap = argparse.ArgumentParser(
        description='Render a mesh to PNG with f3d under xvfb-run: flat shading, edges, vertex '
                    'colours (the file\'s, or by valence), optional 6-RoSy field crosses.')
    ap.add_argument('mesh', help='input mesh (.ply binary/ASCII, .obj, .off)')
    ap.add_argument('--out', '-o', required=True, help='output PNG')
    ap.add_argument('--size', nargs=2, type=int, default=[600, 600], metavar=('W', 'H'),
                    help='picture size in pixels (default 600 600)')
    ap.add_argument('--view', nargs=2, type=float, default=[0.0, 0.0], metavar=('AZ', 'EL'),
                    help='camera azimuth and elevation in degrees (default 0 0: looking at the '
                         '+z side for --up y, the -y side for --up z)')
    ap.add_argument('--up', choices=['x', 'y', 'z', '-x', '-y', '-z', '+x', '+y', '+z'], default='y',
                    help="the model's up axis (default y)")
    ap.add_argument('--zoom', type=float, default=1.0, help='> 1 comes closer (default 1: whole mesh)')
    ap.add_argument('--focus', nargs=3, type=float, metavar=('FX', 'FY', 'FZ'),
                    help='look at this point of the bounding box (fractions: 0 0 0 = min corner, '
                         '0.5 0.5 0.5 = centre; default: the centre of the mesh as seen)')
    ap.add_argument('--valence', action='store_true',
                    help='colour vertices by valence (blue < target, pink > target, white = '
                         'target; target 6 inside, 4 on an open boundary)')
    ap.add_argument('--dots', type=float, default=0, metavar='PX',
                    help='also draw a PX-pixel dot on every coloured (non-white) vertex, e.g. the '
                         'irregular ones with --valence (default 0: none)')
    ap.add_argument('--no-colours', action='store_true', help="ignore the file's vertex colours")
    ap.add_argument('--field', action='store_true',
                    help='draw the 6-RoSy field (PLY rosy_x rosy_y rosy_z) as red crosses')
    ap.add_argument('--edges', choices=['lines', 'f3d', 'none'], default='lines',
                    help="lines: the edges as line cells in --edge-color (default); f3d: f3d's "
                         "own --edges (black); none")
    ap.add_argument('--edge-lift', type=float, default=0.02,
                    help='with --edges lines: lift along the normals, in mean edge lengths (default 0.02)')
    ap.add_argument('--line-width', type=float, default=1.0, help='edge and field line width in px')
    ap.add_argument('--edge-color', type=colour_arg, default=(40, 40, 48), help='RRGGBB')
    ap.add_argument('--face-color', type=colour_arg, default=(235, 235, 235),
                    help='RRGGBB, when no vertex colours')
    ap.add_argument('--field-color', type=colour_arg, default=(220, 20, 20), help='RRGGBB')
    ap.add_argument('--background', type=colour_arg, default=(255, 255, 255), help='RRGGBB')
    ap.add_argument('--light', choices=['sky', 'f3d'], default='sky',
                    help="sky: bright matte light from above the up axis (default); f3d: f3d's "
                         "default lights (darker, with highlights)")
    ap.add_argument('--fxaa', action='store_true', help="f3d's anti-aliasing (bigger PNGs)")
    ap.add_argument('--no-optimise', action='store_true', help='keep the PNG as f3d wrote it')
    ap.add_argument('--max-bytes', type=int, default=200000,
                    help='above this size (after optipng) reduce the PNG to 256 colours with '
                         'pngquant when installed; 0: never (default 200000)')
    ap.add_argument('--no-xvfb', action='store_true', help='run f3d on $DISPLAY, not under xvfb-run')
    ap.add_argument('--keep-vtp', metavar='FILE', help='also keep the scene handed to f3d')
    ap.add_argument('--f3d', help='the f3d binary (default: f3d on PATH)')
    ap.add_argument('--f3d-arg', action='append', default=[], metavar='ARG',
                    help='extra argument for f3d (repeatable), e.g. --f3d-arg=--ssao')
    ap.add_argument('--timeout', type=float, default=300, help='seconds (default 300)')
    ap.add_argument('--quiet', '-q', action='store_true')
    args = ap.parse_args(argv)
    if args.size[0] < 16 or args.size[1] < 16:
        ap.error('--size: at least 16 x 16')
    if args.zoom <= 0:
        ap.error('--zoom must be > 0')
    try:
        info = render(args)
    except (MeshError, OSError, subprocess.SubprocessError) as e:
        print('render.py: error: %s' % e, file=sys.stderr)
        return 1
    if not args.quiet:
        extra = ''
        if 'valence' in info:
            c = info['valence']
            extra = ', valence: %d below target (blue), %d above (pink), %d regular' % (
                c['low'], c['high'], c['regular'])
        print('%s: %d x %d, %d bytes (%d vertices, %d faces%s)' % (
            args.out, args.size[0], args.size[1], info['png_bytes'], info['vertices'], info['faces'], extra))
    return 0


if __name__ == '__main__':
    sys.exit(main())
