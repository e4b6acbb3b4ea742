#!/usr/bin/env python3
"""Small PNG helpers, standard library only (no PIL on the build machines): read any
non-interlaced 8-bit-or-less PNG (grey, RGB, palette, with or without alpha; the forms f3d
and optipng write) into RGB rows, write RGB rows, crop, count colours.

Command line:
  render_png.py info PNG                      -> "W H N_COLOURS" (colours of every pixel)
  render_png.py count PNG RRGGBB TOL          -> pixels within TOL (max per channel) of RRGGBB
  render_png.py crop IN OUT X Y W H           -> the W x H rectangle at (X, Y)
  render_png.py trim IN OUT [MARGIN]          -> crops the background (the corner pixel's colour)
                                                 down to the content plus MARGIN pixels
"""

import struct
import sys
import zlib


def read_png(path):
    """(width, height, rows): rows[y] is a bytes object of 3 * width RGB values (alpha
    composited over white)."""
    data = open(path, 'rb').read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise ValueError(path + ': not a PNG')
    pos, idat, palette, trns = 8, b'', None, None
    width = height = depth = ctype = interlace = None
    while pos < len(data):
        n, tag = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if tag == b'IHDR':
            width, height, depth, ctype, _, _, interlace = struct.unpack('>IIBBBBB', body)
        elif tag == b'PLTE':
            palette = [tuple(body[i:i + 3]) for i in range(0, len(body), 3)]
        elif tag == b'tRNS':
            trns = body
        elif tag == b'IDAT':
            idat += body
        elif tag == b'IEND':
            break
        pos += 12 + n
    if interlace:
        raise ValueError(path + ': interlaced PNG not supported')
    if depth == 16:
        raise ValueError(path + ': 16-bit PNG not supported')
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[ctype]
    bits = depth * channels
    stride = (width * bits + 7) // 8
    bpp = max(1, bits // 8)
    raw = zlib.decompress(idat)
    prev = bytearray(stride)
    rows = []
    for y in range(height):
        ftype = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        if ftype == 1:
            for i in range(bpp, stride):
                line[i] = (line[i] + line[i - bpp]) & 255
        elif ftype == 2:
            for i in range(stride):
                line[i] = (line[i] + prev[i]) & 255
        elif ftype == 3:
            for i in range(stride):
                left = line[i - bpp] if i >= bpp else 0
                line[i] = (line[i] + ((left + prev[i]) >> 1)) & 255
        elif ftype == 4:
            for i in range(stride):
                a = line[i - bpp] if i >= bpp else 0
                b = prev[i]
                c = prev[i - bpp] if i >= bpp else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else b if pb <= pc else c
                line[i] = (line[i] + pred) & 255
        prev = line
        rows.append(_to_rgb(line, width, depth, ctype, palette, trns))
    return width, height, rows


def _samples(line, width, depth, channels):
    if depth == 8:
        return line
    per = 8 // depth
    mask = (1 << depth) - 1
    out = bytearray()
    for x in range(width * channels):
        byte = line[x // per]
        out.append((byte >> (8 - depth * (x % per + 1))) & mask)
    return out


def _to_rgb(line, width, depth, ctype, palette, trns):
    if ctype == 2 and depth == 8:
        return bytes(line)
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[ctype]
    s = _samples(line, width, depth, channels)
    out = bytearray()

    def over_white(v, a):
        return (v * a + 255 * (255 - a)) // 255

    for x in range(width):
        if ctype == 3:
            r, g, b = palette[s[x]]
            a = trns[s[x]] if trns and s[x] < len(trns) else 255
            out += bytes((over_white(r, a), over_white(g, a), over_white(b, a)))
        elif ctype == 0:
            v = s[x] * 255 // ((1 << depth) - 1)
            out += bytes((v, v, v))
        elif ctype == 4:
            v = over_white(s[2 * x], s[2 * x + 1])
            out += bytes((v, v, v))
        elif ctype == 6:
            a = s[4 * x + 3]
            out += bytes(over_white(c, a) for c in s[4 * x:4 * x + 3])
        else:
            out += bytes(s[3 * x:3 * x + 3])
    return bytes(out)


def write_png(path, width, height, rows):
    def chunk(kind, payload):
        return (struct.pack('>I', len(payload)) + kind + payload +
                struct.pack('>I', zlib.crc32(kind + payload) & 0xFFFFFFFF))

    raw = b''.join(b'\0' + r for r in rows)
    with open(path, 'wb') as f:
        f.write(b'\x89PNG\r\n\x1a\n' +
                chunk(b'IHDR', struct.pack('>IIBBBBB', width, height, 8, 2, 0, 0, 0)) +
                chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b''))


def crop(rows, x, y, w, h):
    return [r[3 * x:3 * (x + w)] for r in rows[y:y + h]]


def content_box(width, height, rows, margin=0):
    """The smallest rectangle holding every pixel that differs from the top-left one."""
    bg = rows[0][:3]
    xs, ys = [], []
    for y, r in enumerate(rows):
        hit = [x for x in range(width) if r[3 * x:3 * x + 3] != bg]
        if hit:
            ys.append(y)
            xs += (hit[0], hit[-1])
    if not ys:
        return 0, 0, width, height
    x0, x1 = max(0, min(xs) - margin), min(width - 1, max(xs) + margin)
    y0, y1 = max(0, ys[0] - margin), min(height - 1, ys[-1] + margin)
    return x0, y0, x1 - x0 + 1, y1 - y0 + 1


def count_near(rows, rgb, tol):
    n = 0
    for r in rows:
        for x in range(0, len(r), 3):
            if abs(r[x] - rgb[0]) <= tol and abs(r[x + 1] - rgb[1]) <= tol and abs(r[x + 2] - rgb[2]) <= tol:
                n += 1
    return n


def main(argv):
    cmd = argv[1] if len(argv) > 1 else ''
    if cmd == 'info' and len(argv) == 3:
        w, h, rows = read_png(argv[2])
        colours = {r[x:x + 3] for r in rows for x in range(0, len(r), 3)}
        print(w, h, len(colours))
    elif cmd == 'count' and len(argv) == 5:
        _, _, rows = read_png(argv[2])
        t = argv[3].lstrip('#')
        print(count_near(rows, tuple(int(t[k:k + 2], 16) for k in (0, 2, 4)), int(argv[4])))
    elif cmd == 'crop' and len(argv) == 8:
        w, h, rows = read_png(argv[2])
        x, y, cw, ch = (int(v) for v in argv[4:8])
        cw, ch = min(cw, w - x), min(ch, h - y)
        write_png(argv[3], cw, ch, crop(rows, x, y, cw, ch))
    elif cmd == 'trim' and len(argv) in (4, 5):
        w, h, rows = read_png(argv[2])
        x, y, cw, ch = content_box(w, h, rows, int(argv[4]) if len(argv) == 5 else 0)
        write_png(argv[3], cw, ch, crop(rows, x, y, cw, ch))
        print(x, y, cw, ch)
    else:
        print(__doc__, file=sys.stderr)
        return 2
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
