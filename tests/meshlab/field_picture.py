#!/usr/bin/env python3
"""Pixel checks of the "6-RoSy field" layer as the MeshLab GUI draws it by default (issue 15
item 3), on a screenshot of the 3D view: field pixels (amber, the drawing's colour, under MeshLab's
lighting) make many small separate marks, cover a bounded part of the model, and no red point
squares of the old drawing are left.

Usage: field_picture.py SCREEN.png X Y W H   (the 3D view's rectangle in the screenshot)
Prints the figures; exits 1 with the failed check."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from render_png import read_png  # noqa: E402


def amber(r, g, b):   # kFieldColour (255, 170, 0) lit: red high, green about 2/3 of it, no blue
    return r >= 120 and b <= 0.35 * r and 0.45 * r <= g <= 0.85 * r


def red(r, g, b):     # the old drawing's (220, 40, 40)
    return r >= 120 and g <= 0.35 * r and b <= 0.35 * r


def grey(r, g, b):    # MeshLab's default surface colour, lit
    return max(r, g, b) - min(r, g, b) <= 20 and max(r, g, b) >= 60


def main():
    path, x0, y0, w, h = sys.argv[1], *map(int, sys.argv[2:6])
    width, height, rows = read_png(path)
    mask = [[False] * w for _ in range(h)]
    n_amber = n_red = n_grey = 0
    for y in range(h):
        row = rows[y0 + y]
        for x in range(w):
            r, g, b = row[3 * (x0 + x): 3 * (x0 + x) + 3]
            if amber(r, g, b):
                mask[y][x] = True
                n_amber += 1
            elif red(r, g, b):
                n_red += 1
            elif grey(r, g, b):
                n_grey += 1
    # connected marks (8-neighbours)
    seen = [[False] * w for _ in range(h)]
    sizes = []
    for y in range(h):
        for x in range(w):
            if mask[y][x] and not seen[y][x]:
                stack, size = [(x, y)], 0
                seen[y][x] = True
                while stack:
                    cx, cy = stack.pop()
                    size += 1
                    for dx in (-1, 0, 1):
                        for dy in (-1, 0, 1):
                            nx, ny = cx + dx, cy + dy
                            if 0 <= nx < w and 0 <= ny < h and mask[ny][nx] and not seen[ny][nx]:
                                seen[ny][nx] = True
                                stack.append((nx, ny))
                sizes.append(size)
    sizes.sort()
    marks = [s for s in sizes if s >= 4]
    median = marks[len(marks) // 2] if marks else 0
    model = n_amber + n_grey
    coverage = n_amber / model if model else 0.0
    print(f"view {w}x{h}: field {n_amber} px in {len(marks)} marks (median {median} px, largest "
          f"{sizes[-1] if sizes else 0}), surface {n_grey} px, coverage {100 * coverage:.1f} %, red {n_red} px")
    checks = [
        (n_grey > 0.05 * w * h, "the model is not in the view"),
        (len(marks) >= 200, "fewer than 200 separate field marks"),
        (0.02 <= coverage <= 0.30, "the field covers %.1f %% of the model (want 2..30 %%)" % (100 * coverage)),
        (median <= 80, "the marks are blobs, not lines (median %d px)" % median),
        (n_red <= 0.002 * w * h, "%d red pixels: point squares or the old colour" % n_red),
    ]
    bad = [why for ok, why in checks if not ok]
    if bad:
        print("FAIL: " + "; ".join(bad))
        sys.exit(1)
    print("field picture checks passed")


if __name__ == "__main__":
    main()
