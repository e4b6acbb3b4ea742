#!/usr/bin/env bash
# scripts/render_mesh.py: renders a small generated OFF (a right triangle and a quad) and an
# ASCII PLY copy of it, checks the PNG signature, the IHDR size, and the orientation (the
# right angle of the triangle, at the origin, is at the bottom left: not mirrored, not
# upside down).
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

cat > "$tmp/tri.off" <<'EOM'
OFF
# a right triangle in the z = 0 plane, right angle at the origin
3 1 0
0 0 0
1 0 0
0 1 0
3 0 1 2
EOM
cat > "$tmp/tri.ply" <<'PLY'
ply
format ascii 1.0
element vertex 3
property float x
property float y
property float z
property float nx
property float ny
property float nz
property float rosy_x
property float rosy_y
property float rosy_z
element face 1
property list uchar int vertex_indices
end_header
0 0 0 0 0 1 1 0 0
1 0 0 0 0 1 1 0 0
0 1 0 0 0 1 1 0 0
3 0 1 2
PLY

python3 "$here/scripts/render_mesh.py" "$tmp/tri.off" --out "$tmp/a.png" --size 64 48 --view 0 0 --valence --quiet
python3 "$here/scripts/render_mesh.py" "$tmp/tri.ply" --out "$tmp/b.png" --size 64 48 --view 0 0 --field --quiet

python3 - "$tmp/a.png" "$tmp/b.png" <<'PY'
import struct, sys, zlib
for path in sys.argv[1:]:
    data = open(path, 'rb').read()
    assert data[:8] == b'\x89PNG\r\n\x1a\n', path + ': bad PNG signature'
    assert data[12:16] == b'IHDR', path + ': no IHDR'
    w, h, depth, ctype = struct.unpack('>IIBB', data[16:26])
    assert (w, h, depth, ctype) == (64, 48, 8, 2), (path, w, h, depth, ctype)
    idat = b''
    pos = 8
    while pos < len(data):
        n, tag = struct.unpack('>I4s', data[pos:pos + 8])
        if tag == b'IDAT':
            idat += data[pos + 8:pos + 8 + n]
        pos += 12 + n
    raw = zlib.decompress(idat)
    assert len(raw) == h * (1 + 3 * w), path + ': bad pixel data size'
    def px(x, y):
        i = y * (1 + 3 * w) + 1 + 3 * x
        return tuple(raw[i:i + 3])
    white = (255, 255, 255)
    # the triangle fills 90 % of the height (43 px), centred: bottom-left corner ~ (10, 45)
    assert px(14, 40) != white, path + ': bottom left should be covered (mirrored/flipped?)'
    assert px(48, 14) == white, path + ': top right should be background'
    assert px(48, 40) != white, path + ': bottom right should be covered'
    assert px(14, 14) != white, path + ': top left should be covered'
print('render_mesh.py test passed')
PY
