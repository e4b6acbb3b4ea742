#!/usr/bin/env python3
"""Render a triangle mesh to a PNG, the way remeshing papers show results.

Flat-shaded light-grey faces (Lambert, fixed light, orthographic projection), dark edges on
top (1 px, anti-aliased), optionally vertices coloured by valence (< 6 blue, > 6 magenta,
boundary vertices not coloured) and the 6-RoSy field of a PLY written by `fcvt field` /
`fcvt remesh` (short red segments). A per-pixel z-buffer hides hidden faces, edges, dots and
field segments. Standard library only (the PNG is written with zlib + struct).

Inputs: PLY (binary little/big endian or ASCII; vertex x y z float/double plus any other
properties; faces as a list property vertex_indices / vertex_index), OBJ (v / f, with
`f a/b/c` forms and negative indices) and OFF. Polygons are drawn with their own edges and
fan-triangulated for shading.

Examples:
  python3 scripts/render_mesh.py resources/bunny.obj --out bunny.png
  python3 scripts/render_mesh.py out/bunny-fcvt.ply --out remeshed.png --valence
  python3 scripts/render_mesh.py field.ply --out field.png --field --view 0 90 --up z
"""

import argparse
import math
import struct
import sys
import time
import zlib


# ----------------------------------------------------------------------------------------
# Mesh readers. Each returns (vertices [(x, y, z)], polygons [(i, j, k, ...)], vprops dict
# name -> list of floats for every vertex property, or {} when there are none).
# ----------------------------------------------------------------------------------------

class MeshError(Exception):
    pass


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
    body_start = nl + 1 if nl >= 0 else len(data)
    header = data[:end].decode('ascii', 'replace').splitlines()
    fmt = None
    elements = []  # [name, count, [(name, type, counttype or None)]]
    for line in header:
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
        raise MeshError(path + ': unsupported PLY format %r' % fmt)

    vertices, polys, vprops = [], [], {}

    if fmt == 'ascii':
        tokens = data[body_start:].split()
        pos = 0
        for name, count, props in elements:
            rows = []
            for _ in range(count):
                row = []
                for pname, ptype, ctype in props:
                    if ctype is None:
                        row.append(float(tokens[pos]))
                        pos += 1
                    else:
                        n = int(float(tokens[pos]))
                        pos += 1
                        row.append([int(float(t)) for t in tokens[pos:pos + n]])
                        pos += n
                rows.append(row)
            _ply_store(name, props, rows, vertices, polys, vprops)
        return vertices, polys, vprops

    endian = '<' if fmt == 'binary_little_endian' else '>'
    off = body_start
    for name, count, props in elements:
        if all(ctype is None for _, _, ctype in props):
            sfmt = endian + ''.join(_PLY_TYPES[t] for _, t, _ in props)
            size = struct.calcsize(sfmt)
            block = data[off:off + size * count]
            if len(block) < size * count:
                raise MeshError(path + ': file truncated in element ' + name)
            rows = list(struct.iter_unpack(sfmt, block))
            off += size * count
        elif name == 'face' and len(props) == 1:
            # fast path: one list property
            _, itype, ctype = props[0]
            cfmt = endian + _PLY_TYPES[ctype]
            csize = struct.calcsize(cfmt)
            isize = struct.calcsize(_PLY_TYPES[itype])
            ich = _PLY_TYPES[itype]
            unpack = struct.unpack_from
            tri_fmt = endian + _PLY_TYPES[ctype] + ich * 3
            rows = []
            try:
                for _ in range(count):
                    n = unpack(cfmt, data, off)[0]
                    if n == 3:
                        rows.append([list(unpack(tri_fmt, data, off)[1:])])
                    else:
                        rows.append([list(unpack(endian + ich * n, data, off + csize))])
                    off += csize + n * isize
            except struct.error:
                raise MeshError(path + ': file truncated in element face')
        else:
            rows = []
            try:
                for _ in range(count):
                    row = []
                    for pname, ptype, ctype in props:
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
            except struct.error:
                raise MeshError(path + ': file truncated in element ' + name)
        _ply_store(name, props, rows, vertices, polys, vprops)
    return vertices, polys, vprops


def _ply_store(name, props, rows, vertices, polys, vprops):
    names = [p[0] for p in props]
    if name == 'vertex':
        try:
            ix, iy, iz = names.index('x'), names.index('y'), names.index('z')
        except ValueError:
            raise MeshError('PLY vertex element has no x y z')
        for r in rows:
            vertices.append((float(r[ix]), float(r[iy]), float(r[iz])))
        for k, (pname, _, ctype) in enumerate(props):
            if ctype is None:
                vprops[pname] = [float(r[k]) for r in rows]
    elif name == 'face':
        k = None
        for cand in ('vertex_indices', 'vertex_index'):
            if cand in names:
                k = names.index(cand)
                break
        if k is None:
            k = next((i for i, p in enumerate(props) if p[2] is not None), None)
        if k is None:
            raise MeshError('PLY face element has no list property')
        for r in rows:
            polys.append(tuple(int(i) for i in r[k]))


def read_obj(path):
    vertices, polys = [], []
    with open(path, 'r', errors='replace') as f:
        for line in f:
            if line.startswith('v '):
                t = line.split()
                vertices.append((float(t[1]), float(t[2]), float(t[3])))
            elif line.startswith('f '):
                idx = []
                nv = len(vertices)
                for t in line.split()[1:]:
                    i = int(t.split('/')[0])
                    idx.append(i - 1 if i > 0 else nv + i)
                polys.append(tuple(idx))
    return vertices, polys, {}


def read_off(path):
    with open(path, 'r', errors='replace') as f:
        lines = []
        for line in f:
            line = line.split('#', 1)[0].strip()
            if line:
                lines.append(line)
    if not lines or not lines[0].split()[0].endswith('OFF'):
        raise MeshError(path + ': not an OFF file')
    first = lines[0].split()
    li = 1
    if len(first) >= 3:
        counts = first[1:]
    else:
        counts = lines[1].split()
        li = 2
    nv, nf = int(counts[0]), int(counts[1])
    vertices, polys = [], []
    for k in range(nv):
        t = lines[li + k].split()
        vertices.append((float(t[0]), float(t[1]), float(t[2])))
    li += nv
    for k in range(nf):
        t = lines[li + k].split()
        n = int(t[0])
        polys.append(tuple(int(x) for x in t[1:1 + n]))
    return vertices, polys, {}


def read_mesh(path):
    low = path.lower()
    if low.endswith('.ply'):
        return read_ply(path)
    if low.endswith('.obj'):
        return read_obj(path)
    if low.endswith('.off'):
        return read_off(path)
    with open(path, 'rb') as f:
        head = f.read(4)
    if head.startswith(b'ply'):
        return read_ply(path)
    if b'OFF' in head:
        return read_off(path)
    return read_obj(path)


# ----------------------------------------------------------------------------------------
# PNG writer
# ----------------------------------------------------------------------------------------

def write_png(path, width, height, rgb):
    stride = width * 3
    raw = bytearray()
    for y in range(height):
        raw.append(0)
        raw += rgb[y * stride:(y + 1) * stride]

    def chunk(tag, payload):
        c = struct.pack('>I', len(payload)) + tag + payload
        return c + struct.pack('>I', zlib.crc32(tag + payload) & 0xffffffff)

    png = b'\x89PNG\r\n\x1a\n'
    png += chunk(b'IHDR', struct.pack('>IIBBBBB', width, height, 8, 2, 0, 0, 0))
    png += chunk(b'IDAT', zlib.compress(bytes(raw), 6))
    png += chunk(b'IEND', b'')
    with open(path, 'wb') as f:
        f.write(png)


# ----------------------------------------------------------------------------------------
# A tiny 5x7 bitmap font for --title (ASCII 32..126; lower case drawn as upper case).
# Each glyph: 7 rows of 5 bits, most significant bit on the left.
# ----------------------------------------------------------------------------------------

_FONT = {
    ' ': [0, 0, 0, 0, 0, 0, 0],
    'A': [14, 17, 17, 31, 17, 17, 17], 'B': [30, 17, 17, 30, 17, 17, 30],
    'C': [14, 17, 16, 16, 16, 17, 14], 'D': [30, 17, 17, 17, 17, 17, 30],
    'E': [31, 16, 16, 30, 16, 16, 31], 'F': [31, 16, 16, 30, 16, 16, 16],
    'G': [14, 17, 16, 23, 17, 17, 15], 'H': [17, 17, 17, 31, 17, 17, 17],
    'I': [14, 4, 4, 4, 4, 4, 14], 'J': [7, 2, 2, 2, 2, 18, 12],
    'K': [17, 18, 20, 24, 20, 18, 17], 'L': [16, 16, 16, 16, 16, 16, 31],
    'M': [17, 27, 21, 21, 17, 17, 17], 'N': [17, 17, 25, 21, 19, 17, 17],
    'O': [14, 17, 17, 17, 17, 17, 14], 'P': [30, 17, 17, 30, 16, 16, 16],
    'Q': [14, 17, 17, 17, 21, 18, 13], 'R': [30, 17, 17, 30, 20, 18, 17],
    'S': [15, 16, 16, 14, 1, 1, 30], 'T': [31, 4, 4, 4, 4, 4, 4],
    'U': [17, 17, 17, 17, 17, 17, 14], 'V': [17, 17, 17, 17, 17, 10, 4],
    'W': [17, 17, 17, 21, 21, 21, 10], 'X': [17, 17, 10, 4, 10, 17, 17],
    'Y': [17, 17, 17, 10, 4, 4, 4], 'Z': [31, 1, 2, 4, 8, 16, 31],
    '0': [14, 17, 19, 21, 25, 17, 14], '1': [4, 12, 4, 4, 4, 4, 14],
    '2': [14, 17, 1, 2, 4, 8, 31], '3': [31, 2, 4, 2, 1, 17, 14],
    '4': [2, 6, 10, 18, 31, 2, 2], '5': [31, 16, 30, 1, 1, 17, 14],
    '6': [6, 8, 16, 30, 17, 17, 14], '7': [31, 1, 2, 4, 8, 8, 8],
    '8': [14, 17, 17, 14, 17, 17, 14], '9': [14, 17, 17, 15, 1, 2, 12],
    '.': [0, 0, 0, 0, 0, 12, 12], ',': [0, 0, 0, 0, 12, 4, 8],
    ':': [0, 12, 12, 0, 12, 12, 0], ';': [0, 12, 12, 0, 12, 4, 8],
    '-': [0, 0, 0, 31, 0, 0, 0], '+': [0, 4, 4, 31, 4, 4, 0],
    '=': [0, 0, 31, 0, 31, 0, 0], '_': [0, 0, 0, 0, 0, 0, 31],
    '/': [1, 1, 2, 4, 8, 16, 16], '(': [2, 4, 8, 8, 8, 4, 2],
    ')': [8, 4, 2, 2, 2, 4, 8], '[': [14, 8, 8, 8, 8, 8, 14],
    ']': [14, 2, 2, 2, 2, 2, 14], '%': [24, 25, 2, 4, 8, 19, 3],
    '!': [4, 4, 4, 4, 4, 0, 4], '?': [14, 17, 1, 2, 4, 0, 4],
    "'": [4, 4, 8, 0, 0, 0, 0], '"': [10, 10, 0, 0, 0, 0, 0],
    '<': [2, 4, 8, 16, 8, 4, 2], '>': [8, 4, 2, 1, 2, 4, 8],
    '*': [0, 4, 21, 14, 21, 4, 0], '#': [10, 10, 31, 10, 31, 10, 10],
    '&': [12, 18, 20, 8, 21, 18, 13], '|': [4, 4, 4, 4, 4, 4, 4],
    '^': [4, 10, 17, 0, 0, 0, 0], '~': [0, 0, 8, 21, 2, 0, 0],
    '@': [14, 17, 1, 13, 21, 21, 14], '$': [4, 15, 20, 14, 5, 30, 4],
    '{': [2, 4, 4, 8, 4, 4, 2], '}': [8, 4, 4, 2, 4, 4, 8],
    '`': [8, 4, 0, 0, 0, 0, 0], '\\': [16, 16, 8, 4, 2, 1, 1],
}


def draw_text(fb, width, height, text, scale, color):
    """Draws `text` centred at the top of the picture with the 5x7 font, `scale` px a dot."""
    adv = 6 * scale
    tw = len(text) * adv - scale
    x0 = max(0, (width - tw) // 2)
    y0 = 2 * scale
    for ci, ch in enumerate(text):
        glyph = _FONT.get(ch.upper(), _FONT['?'])
        gx = x0 + ci * adv
        for row, bits in enumerate(glyph):
            for col in range(5):
                if bits & (16 >> col):
                    for dy in range(scale):
                        py = y0 + row * scale + dy
                        if py >= height:
                            continue
                        for dx in range(scale):
                            px = gx + col * scale + dx
                            if 0 <= px < width:
                                i = 3 * (py * width + px)
                                fb[i], fb[i + 1], fb[i + 2] = color


# ----------------------------------------------------------------------------------------
# Rendering
# ----------------------------------------------------------------------------------------

def _normalize(v):
    n = math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
    if n == 0:
        return (0.0, 0.0, 0.0)
    return (v[0] / n, v[1] / n, v[2] / n)


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def view_basis(azimuth, elevation):
    """Right, up and towards-the-viewer unit vectors of the camera, in y-up world space.
    Azimuth 0 looks at the +z side of the mesh; positive azimuth turns the camera towards +x;
    positive elevation looks from above."""
    el = max(-89.9, min(89.9, elevation))
    a, e = math.radians(azimuth), math.radians(el)
    c = (math.sin(a) * math.cos(e), math.sin(e), math.cos(a) * math.cos(e))
    right = _normalize(_cross((0.0, 1.0, 0.0), c))
    up = _cross(c, right)
    return right, up, c


def render(args):
    t0 = time.time()
    verts, polys, vprops = read_mesh(args.mesh)
    nv = len(verts)
    if nv == 0 or not polys:
        raise MeshError(args.mesh + ': no vertices or no faces')
    polys = [p for p in polys if len(p) >= 3 and all(0 <= i < nv for i in p)]
    if args.field:
        need = ('nx', 'ny', 'nz', 'rosy_x', 'rosy_y', 'rosy_z')
        missing = [k for k in need if k not in vprops]
        if missing:
            raise MeshError(args.mesh + ': --field needs PLY vertex properties '
                            'nx ny nz rosy_x rosy_y rosy_z (missing: %s)' % ' '.join(missing))
    t_read = time.time() - t0

    # up axis -> y up (a rotation, no mirroring)
    def to_yup(p):
        if args.up == 'z':
            return (p[0], p[2], -p[1])
        if args.up == 'x':
            return (-p[1], p[0], p[2])
        return p

    right, upv, towards = view_basis(args.view[0], args.view[1])
    vs = []
    for p in verts:
        q = to_yup(p)
        vs.append((_dot(q, right), _dot(q, upv), _dot(q, towards)))

    W, H = args.size
    xs = [v[0] for v in vs]
    ys = [v[1] for v in vs]
    zs = [v[2] for v in vs]
    cx, cy = 0.5 * (min(xs) + max(xs)), 0.5 * (min(ys) + max(ys))
    ext_x = max(max(xs) - min(xs), 1e-30)
    ext_y = max(max(ys) - min(ys), 1e-30)
    top_margin = 0
    if args.title:
        top_margin = 12 * args.title_scale
    s = min(W * 0.9 / ext_x, (H - top_margin) * 0.9 / ext_y) * args.zoom
    ox, oy = W * 0.5, top_margin + (H - top_margin) * 0.5
    # screen space: x right, y down, z towards the viewer (all in pixels)
    sx = [ox + (x - cx) * s for x in xs]
    sy = [oy - (y - cy) * s for y in ys]
    sz = [z * s for z in zs]

    # edges of the polygons and their faces
    edge_faces = {}
    for fi, p in enumerate(polys):
        n = len(p)
        for k in range(n):
            a, b = p[k], p[(k + 1) % n]
            key = (a, b) if a < b else (b, a)
            lst = edge_faces.get(key)
            if lst is None:
                edge_faces[key] = [fi]
            else:
                lst.append(fi)
    tot = 0.0
    for a, b in edge_faces:
        pa, pb = verts[a], verts[b]
        tot += math.sqrt((pa[0] - pb[0]) ** 2 + (pa[1] - pb[1]) ** 2 + (pa[2] - pb[2]) ** 2)
    mean_edge = tot / max(1, len(edge_faces))
    mean_edge_px = mean_edge * s

    # --- faces -------------------------------------------------------------------------
    light = _normalize((-0.35, 0.45, 1.0))
    lx, ly, lz = light
    base = args.face_color
    ambient, diffuse = 0.35, 0.65
    NEG = float('-inf')
    npx = W * H
    zb = [NEG] * npx
    sb = [0.0] * npx          # shade factor per pixel
    ib = [-1] * npx           # polygon id per pixel
    ceil = math.ceil
    t1 = time.time()
    for fi, p in enumerate(polys):
        # polygon normal in view space (Newell) for the flat shade
        nx = ny = nz = 0.0
        n = len(p)
        for k in range(n):
            a, b = vs[p[k]], vs[p[(k + 1) % n]]
            nx += (a[1] - b[1]) * (a[2] + b[2])
            ny += (a[2] - b[2]) * (a[0] + b[0])
            nz += (a[0] - b[0]) * (a[1] + b[1])
        ln = math.sqrt(nx * nx + ny * ny + nz * nz)
        if ln == 0:
            continue
        shade = ambient + diffuse * abs(nx * lx + ny * ly + nz * lz) / ln
        i0 = p[0]
        for k in range(1, n - 1):
            tri = ((sx[i0], sy[i0], sz[i0]),
                   (sx[p[k]], sy[p[k]], sz[p[k]]),
                   (sx[p[k + 1]], sy[p[k + 1]], sz[p[k + 1]]))
            (x0, y0, z0), (x1, y1, z1), (x2, y2, z2) = tri
            area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
            if area == 0.0 or abs(area) < 1e-12:
                continue
            dzdx = ((z1 - z0) * (y2 - y0) - (z2 - z0) * (y1 - y0)) / area
            dzdy = ((x1 - x0) * (z2 - z0) - (x2 - x0) * (z1 - z0)) / area
            # sort by y
            a, b, c = sorted(tri, key=lambda t: t[1])
            ya, yc = a[1], c[1]
            py0 = max(0, int(ceil(ya - 0.5)))
            py1 = min(H - 1, int(ceil(yc - 0.5)) - 1)
            if py0 > py1:
                continue
            xa, xb, xc = a[0], b[0], c[0]
            yb = b[1]
            sl_ac = (xc - xa) / (yc - ya)
            sl_ab = (xb - xa) / (yb - ya) if yb > ya else 0.0
            sl_bc = (xc - xb) / (yc - yb) if yc > yb else 0.0
            zc0 = z0 - dzdx * x0 - dzdy * y0
            for py in range(py0, py1 + 1):
                yy = py + 0.5
                xl = xa + (yy - ya) * sl_ac
                if yy < yb:
                    xr = xa + (yy - ya) * sl_ab
                else:
                    xr = xb + (yy - yb) * sl_bc
                if xl > xr:
                    xl, xr = xr, xl
                px0 = int(ceil(xl - 0.5))
                px1 = int(ceil(xr - 0.5)) - 1
                if px0 < 0:
                    px0 = 0
                if px1 >= W:
                    px1 = W - 1
                if px0 > px1:
                    continue
                z = zc0 + dzdy * yy + dzdx * (px0 + 0.5)
                row = py * W
                for q in range(row + px0, row + px1 + 1):
                    if z > zb[q]:
                        zb[q] = z
                        sb[q] = shade
                        ib[q] = fi
                    z += dzdx
    t_faces = time.time() - t1

    # --- frame buffer -------------------------------------------------------------------
    bg = args.background
    fb = bytearray(bytes(bg) * npx)
    br, bgc, bb = base
    for q in range(npx):
        if ib[q] >= 0:
            sh = sb[q]
            j = 3 * q
            fb[j] = int(br * sh)
            fb[j + 1] = int(bgc * sh)
            fb[j + 2] = int(bb * sh)

    # depth tolerance (pixels) for edges / field / dots against the z-buffer
    eps = 1.0 + 0.25 * mean_edge_px

    def draw_line(x0, y0, z0, x1, y1, z1, color, alpha, allowed=None, ztest=True):
        """Xiaolin Wu anti-aliased line; each pixel is drawn when it is on the background,
        on one of the polygons in `allowed` or within eps of the z-buffer."""
        er, eg, eb = color
        steep = abs(y1 - y0) > abs(x1 - x0)
        if steep:
            x0, y0, x1, y1 = y0, x0, y1, x1
        if x0 > x1:
            x0, x1, y0, y1, z0, z1 = x1, x0, y1, y0, z1, z0
        dx = x1 - x0
        grad = (y1 - y0) / dx if dx > 1e-12 else 0.0
        dz = (z1 - z0) / dx if dx > 1e-12 else 0.0
        xs0 = int(math.floor(x0 + 0.5))
        xs1 = int(math.floor(x1 + 0.5))
        for xi in range(xs0, xs1 + 1):
            xc = xi + 0.5
            t = xc - x0
            if t < 0:
                t = 0.0
            elif t > dx:
                t = dx
            yline = y0 + grad * t - 0.5
            zl = z0 + dz * t
            yi = int(math.floor(yline))
            fr = yline - yi
            for yy, w in ((yi, 1.0 - fr), (yi + 1, fr)):
                if w <= 0.0:
                    continue
                if steep:
                    px, py = yy, xi
                else:
                    px, py = xi, yy
                if px < 0 or py < 0 or px >= W or py >= H:
                    continue
                q = py * W + px
                if ztest:
                    f = ib[q]
                    if f >= 0 and not (allowed is not None and f in allowed) and zl < zb[q] - eps:
                        continue
                a = alpha * w
                j = 3 * q
                fb[j] = int(fb[j] + (er - fb[j]) * a + 0.5)
                fb[j + 1] = int(fb[j + 1] + (eg - fb[j + 1]) * a + 0.5)
                fb[j + 2] = int(fb[j + 2] + (eb - fb[j + 2]) * a + 0.5)

    # --- edges --------------------------------------------------------------------------
    t2 = time.time()
    if not args.no_edges:
        # faces around each vertex, so that an edge pixel on a face sharing one of its
        # vertices counts as visible
        vfaces = [[] for _ in range(nv)]
        for fi, p in enumerate(polys):
            for i in p:
                vfaces[i].append(fi)
        ec = args.edge_color
        ea = args.edge_alpha
        if ea is None:
            # dense meshes would turn black: lighten edges shorter than ~12 px
            ea = max(0.3, min(1.0, mean_edge_px / 12.0))
        for (a, b), fl in edge_faces.items():
            allowed = set(vfaces[a])
            allowed.update(vfaces[b])
            draw_line(sx[a], sy[a], sz[a], sx[b], sy[b], sz[b], ec, ea, allowed)
    t_edges = time.time() - t2

    # vertex visibility: its pixel shows one of its faces, or the vertex faces the viewer
    # (area-weighted normal) and its pixel is background or within eps of the z-buffer
    def vertex_visible(i):
        px, py = int(sx[i]), int(sy[i])
        if not (0 <= px < W and 0 <= py < H):
            return False
        q = py * W + px
        f = ib[q]
        if f >= 0 and f in vfs[i]:
            return True
        if vnz[i] < -0.05:
            return False
        return f < 0 or sz[i] >= zb[q] - eps

    need_vf = args.valence or args.field
    if need_vf:
        vfs = [set() for _ in range(nv)]
        vn = [[0.0, 0.0, 0.0] for _ in range(nv)]
        for fi, p in enumerate(polys):
            nx = ny = nz = 0.0
            n = len(p)
            for k in range(n):
                a, b = vs[p[k]], vs[p[(k + 1) % n]]
                nx += (a[1] - b[1]) * (a[2] + b[2])
                ny += (a[2] - b[2]) * (a[0] + b[0])
                nz += (a[0] - b[0]) * (a[1] + b[1])
            for i in p:
                vfs[i].add(fi)
                acc = vn[i]
                acc[0] += nx
                acc[1] += ny
                acc[2] += nz
        vnz = [_normalize(v)[2] for v in vn]

    # --- field --------------------------------------------------------------------------
    t3 = time.time()
    if args.field:
        L = 0.4 * mean_edge
        fc = args.field_color
        NX, NY, NZ = vprops['nx'], vprops['ny'], vprops['nz']
        RX, RY, RZ = vprops['rosy_x'], vprops['rosy_y'], vprops['rosy_z']
        for i in range(nv):
            if not vfs[i] or not vertex_visible(i):
                continue
            n = _normalize((NX[i], NY[i], NZ[i]))
            d = (RX[i], RY[i], RZ[i])
            dn = _dot(d, n)
            d = _normalize((d[0] - dn * n[0], d[1] - dn * n[1], d[2] - dn * n[2]))
            if d == (0.0, 0.0, 0.0):
                continue
            nd = _cross(n, d)
            p = verts[i]
            for ang in (0.0, math.pi / 3, 2 * math.pi / 3):
                ca, sa = math.cos(ang), math.sin(ang)
                r = (d[0] * ca + nd[0] * sa, d[1] * ca + nd[1] * sa, d[2] * ca + nd[2] * sa)
                ends = []
                for sgn in (-0.5, 0.5):
                    q = to_yup((p[0] + sgn * L * r[0], p[1] + sgn * L * r[1], p[2] + sgn * L * r[2]))
                    vx, vy, vz = _dot(q, right), _dot(q, upv), _dot(q, towards)
                    ends.append((ox + (vx - cx) * s, oy - (vy - cy) * s, vz * s))
                (ax, ay, az), (bx, by, bz) = ends
                draw_line(ax, ay, az, bx, by, bz, fc, 1.0, vfs[i])
    t_field = time.time() - t3

    # --- valence dots -------------------------------------------------------------------
    t4 = time.time()
    n_low = n_high = 0
    if args.valence:
        nbrs = [set() for _ in range(nv)]
        boundary = [False] * nv
        for (a, b), fl in edge_faces.items():
            nbrs[a].add(b)
            nbrs[b].add(a)
            if len(fl) == 1:
                boundary[a] = boundary[b] = True
        r = args.dot_radius
        if r is None:
            r = max(1.8, min(7.0, 0.28 * mean_edge_px))
        ri = int(math.ceil(r + 1))
        for i in range(nv):
            if boundary[i] or not vfs[i]:
                continue
            val = len(nbrs[i])
            if val == 6:
                continue
            if val < 6:
                color = args.low_color
                n_low += 1
            else:
                color = args.high_color
                n_high += 1
            if not vertex_visible(i):
                continue
            cxp, cyp = sx[i], sy[i]
            cr, cg, cb = color
            for py in range(int(cyp) - ri, int(cyp) + ri + 1):
                if py < 0 or py >= H:
                    continue
                for px in range(int(cxp) - ri, int(cxp) + ri + 1):
                    if px < 0 or px >= W:
                        continue
                    d = math.hypot(px + 0.5 - cxp, py + 0.5 - cyp)
                    a = r + 0.5 - d
                    if a <= 0:
                        continue
                    if a > 1:
                        a = 1.0
                    j = 3 * (py * W + px)
                    fb[j] = int(fb[j] + (cr - fb[j]) * a + 0.5)
                    fb[j + 1] = int(fb[j + 1] + (cg - fb[j + 1]) * a + 0.5)
                    fb[j + 2] = int(fb[j + 2] + (cb - fb[j + 2]) * a + 0.5)
    t_dots = time.time() - t4

    if args.title:
        draw_text(fb, W, H, args.title, args.title_scale, (0, 0, 0))

    write_png(args.out, W, H, fb)
    if not args.quiet:
        msg = ('%s: %d vertices, %d faces, mean edge %.2f px -> %s (%dx%d) in %.1f s '
               '(read %.1f, faces %.1f, edges %.1f' %
               (args.mesh, nv, len(polys), mean_edge_px, args.out, W, H, time.time() - t0,
                t_read, t_faces, t_edges))
        if args.field:
            msg += ', field %.1f' % t_field
        if args.valence:
            msg += ', dots %.1f; %d interior vertices of valence < 6, %d > 6' % (t_dots, n_low, n_high)
        print(msg + ')')


def _color(text):
    t = text.lstrip('#')
    if len(t) == 6:
        return tuple(int(t[k:k + 2], 16) for k in (0, 2, 4))
    parts = text.split(',')
    if len(parts) == 3:
        return tuple(max(0, min(255, int(p))) for p in parts)
    raise argparse.ArgumentTypeError('colour must be RRGGBB or r,g,b: %r' % text)


def main(argv=None):
    ap = argparse.ArgumentParser(
        description='Render a triangle mesh (PLY, OBJ, OFF) to a PNG: flat-shaded faces, '
                    'edges, optional valence dots and 6-RoSy field. Standard library only.')
    ap.add_argument('mesh', help='input mesh (.ply binary/ascii, .obj, .off)')
    ap.add_argument('--out', '-o', required=True, help='output PNG file')
    ap.add_argument('--size', nargs=2, type=int, default=[800, 800], metavar=('W', 'H'),
                    help='picture size in pixels (default 800 800)')
    ap.add_argument('--view', nargs=2, type=float, default=[30.0, 20.0], metavar=('AZ', 'EL'),
                    help='camera azimuth and elevation in degrees (default 30 20: 3/4 front '
                         'view from slightly above; 0 0 looks at the +z side, y up, from +z '
                         'in the up-converted frame)')
    ap.add_argument('--up', choices=['x', 'y', 'z'], default='y',
                    help="the mesh's up axis (default y)")
    ap.add_argument('--zoom', type=float, default=1.0,
                    help='zoom factor (1: the mesh fills 90%% of the picture)')
    ap.add_argument('--valence', action='store_true',
                    help='colour interior vertices of valence < 6 blue, > 6 magenta')
    ap.add_argument('--field', action='store_true',
                    help='draw the 6-RoSy field (PLY nx ny nz rosy_x rosy_y rosy_z) as red '
                         'segments, 0.4 x mean edge length')
    ap.add_argument('--title', help='text written at the top of the picture')
    ap.add_argument('--title-scale', type=int, default=3, help='title dot size in px (default 3)')
    ap.add_argument('--no-edges', action='store_true', help='do not draw the edges')
    ap.add_argument('--edge-alpha', type=float, default=None,
                    help='edge opacity 0..1 (default: 1, lighter when edges are < 12 px, down to 0.3)')
    ap.add_argument('--dot-radius', type=float, default=None,
                    help='valence dot radius in px (default 0.28 x mean edge, 1.8..7)')
    ap.add_argument('--face-color', type=_color, default=(222, 222, 226), help='RRGGBB')
    ap.add_argument('--edge-color', type=_color, default=(25, 25, 30), help='RRGGBB')
    ap.add_argument('--background', type=_color, default=(255, 255, 255), help='RRGGBB')
    ap.add_argument('--low-color', type=_color, default=(30, 90, 235), help='valence < 6, RRGGBB')
    ap.add_argument('--high-color', type=_color, default=(235, 40, 175), help='valence > 6, RRGGBB')
    ap.add_argument('--field-color', type=_color, default=(220, 20, 20), help='RRGGBB')
    ap.add_argument('--quiet', '-q', action='store_true', help='print nothing but errors')
    args = ap.parse_args(argv)
    if args.size[0] < 1 or args.size[1] < 1:
        ap.error('--size must be positive')
    if args.zoom <= 0:
        ap.error('--zoom must be positive')
    try:
        render(args)
    except (MeshError, OSError, ValueError, IndexError) as e:
        print('render_mesh.py: error: %s' % e, file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
