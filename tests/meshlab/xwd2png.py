"""Converts a 24/32-bit TrueColor XWD screen dump (`xwd -root`) to PNG, standard library only,
and prints the image size and the number of distinct colours (a blank screen has 1).
Usage: xwd2png.py IN.xwd OUT.png [--scale K] (K >= 1: keep every K-th pixel, for small PNGs)"""
import struct
import sys
import zlib


def read_xwd(path):
    data = open(path, "rb").read()
    header_size = struct.unpack(">I", data[:4])[0]
    fields = struct.unpack(">25I", data[:100])
    (_, version, pixmap_format, depth, width, height, _, byte_order, _, _, _, bits_per_pixel,
     bytes_per_line, visual_class, red_mask, green_mask, blue_mask, _, _, ncolors) = fields[:20]
    if version != 7 or pixmap_format != 2 or bits_per_pixel not in (24, 32) or visual_class not in (4, 5):
        raise SystemExit(f"{path}: unsupported XWD (version {version}, format {pixmap_format}, "
                         f"{bits_per_pixel} bpp, visual {visual_class})")
    offset = header_size + 12 * ncolors
    step = bits_per_pixel // 8
    order = "little" if byte_order == 0 else "big"

    def shift(mask):
        return (mask & -mask).bit_length() - 1

    shifts = [shift(m) for m in (red_mask, green_mask, blue_mask)]
    rows = []
    for y in range(height):
        line = data[offset + y * bytes_per_line: offset + y * bytes_per_line + width * step]
        row = bytearray()
        for x in range(0, len(line), step):
            p = int.from_bytes(line[x:x + step], order)
            row += bytes(((p >> shifts[0]) & 255, (p >> shifts[1]) & 255, (p >> shifts[2]) & 255))
        rows.append(bytes(row))
    return width, height, rows


def write_png(path, width, height, rows):
    def chunk(kind, payload):
        return struct.pack(">I", len(payload)) + kind + payload + struct.pack(">I", zlib.crc32(kind + payload) & 0xFFFFFFFF)

    raw = b"".join(b"\0" + r for r in rows)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    src, dst = sys.argv[1], sys.argv[2]
    scale = int(sys.argv[sys.argv.index("--scale") + 1]) if "--scale" in sys.argv else 1
    width, height, rows = read_xwd(src)
    colours = set()
    for r in rows[::4]:
        colours.update(r[i:i + 3] for i in range(0, len(r), 12))
    if scale > 1:
        rows = [b"".join(r[i:i + 3] for i in range(0, len(r), 3 * scale)) for r in rows[::scale]]
        width, height = (width + scale - 1) // scale, len(rows)
    write_png(dst, width, height, rows)
    print(f"{width}x{height} {len(colours)} colours")


if __name__ == "__main__":
    main()
