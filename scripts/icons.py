#!/usr/bin/env python3
"""Draws Schwenkbar's app icon (web app manifest, issue 12) without any image library:
static/icons/icon.svg and the PNGs icon-192.png, icon-512.png from the same shapes.

The picture: the control's header blue as a rounded square, the untilted working plane as a
flat grey parallelogram, the tilted plane in white above it and the tool axis (the plane's Z)
as a yellow arrow (purpose "any"; the rounded corners are transparent, so not "maskable").
Run: python3 scripts/icons.py (writes into static/icons/).
Deterministic: the same bytes on every run."""
import math
import os
import struct
import sys
import zlib

GRID = 512
# Colours from static/app.css: --header, --bg, --panel, --cursor, --key-edge.
HEADER = (0x1F, 0x3D, 0x5C)
BG = (0xD9, 0xDD, 0xE3)
PANEL = (0xF4, 0xF6, 0xF8)
CURSOR = (0xFF, 0xE5, 0x8A)
EDGE = (0x8A, 0x96, 0xA3)


def rounded_rect(x0, y0, x1, y1, r, steps=16):
    pts = []
    for cx, cy, a0 in ((x1 - r, y0 + r, -90), (x1 - r, y1 - r, 0), (x0 + r, y1 - r, 90), (x0 + r, y0 + r, 180)):
        for i in range(steps + 1):
            a = math.radians(a0 + 90 * i / steps)
            pts.append((cx + r * math.cos(a), cy + r * math.sin(a)))
    return pts


def thick_line(p, q, w):
    dx, dy = q[0] - p[0], q[1] - p[1]
    n = math.hypot(dx, dy)
    ox, oy = -dy / n * w / 2, dx / n * w / 2
    return [(p[0] + ox, p[1] + oy), (q[0] + ox, q[1] + oy), (q[0] - ox, q[1] - oy), (p[0] - ox, p[1] - oy)]


def arrow_head(tip, base, w):
    dx, dy = tip[0] - base[0], tip[1] - base[1]
    n = math.hypot(dx, dy)
    ox, oy = -dy / n * w / 2, dx / n * w / 2
    return [tip, (base[0] + ox, base[1] + oy), (base[0] - ox, base[1] - oy)]


# The tilted plane's centre and its normal (drawn as the tool axis).
CENTRE = (262, 300)
TIP = (214, 96)
HEAD_BASE = (228, 156)
SHAPES = [
    (rounded_rect(0, 0, GRID, GRID, 96), HEADER),
    ([(92, 388), (316, 388), (420, 316), (196, 316)], EDGE),  # the untilted plane
    ([(118, 336), (318, 408), (406, 262), (206, 190)], PANEL),  # the tilted plane
    (thick_line(CENTRE, HEAD_BASE, 26), CURSOR),  # the tool axis
    (arrow_head(TIP, (HEAD_BASE[0] + 6, HEAD_BASE[1] + 24), 76), CURSOR),
]


def svg():
    def path(pts):
        return "M" + " L".join(f"{x:.1f} {y:.1f}" for x, y in pts) + " Z"

    body = "\n".join(
        f'  <path fill="#{c[0]:02x}{c[1]:02x}{c[2]:02x}" d="{path(p)}"/>' for p, c in SHAPES)
    return (f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {GRID} {GRID}" '
            f'width="{GRID}" height="{GRID}">\n'
            "  <title>Schwenkbar</title>\n" + body + "\n</svg>\n")


def spans(pts, y):
    """x-intervals of the polygon on the horizontal line y (even-odd rule)."""
    xs = []
    n = len(pts)
    for i in range(n):
        (x0, y0), (x1, y1) = pts[i], pts[(i + 1) % n]
        if (y0 <= y < y1) or (y1 <= y < y0):
            xs.append(x0 + (y - y0) * (x1 - x0) / (y1 - y0))
    xs.sort()
    return list(zip(xs[0::2], xs[1::2]))


def raster(size, ss=4):
    """RGBA rows, ss×ss samples per pixel."""
    s = size * ss
    scale = GRID / s
    colours = [None] + [c for _, c in SHAPES]
    rows = []
    for py in range(size):
        samples = []
        for sy in range(ss):
            y = (py * ss + sy + 0.5) * scale
            line = bytearray(s)
            for k, (pts, _) in enumerate(SHAPES, start=1):
                for a, b in spans(pts, y):
                    i0 = max(0, math.ceil(a / scale - 0.5))
                    i1 = min(s, math.ceil(b / scale - 0.5))
                    if i1 > i0:
                        line[i0:i1] = bytes([k]) * (i1 - i0)
            samples.append(line)
        row = bytearray()
        for px in range(size):
            r = g = b = n = 0
            for line in samples:
                for k in line[px * ss:(px + 1) * ss]:
                    if k:
                        c = colours[k]
                        r += c[0]; g += c[1]; b += c[2]; n += 1
            if n:
                row += bytes((round(r / n), round(g / n), round(b / n), round(255 * n / (ss * ss))))
            else:
                row += b"\0\0\0\0"
        rows.append(bytes(row))
    return rows


def png(size):
    rows = raster(size)
    raw = b"".join(b"\0" + r for r in rows)

    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", size, size, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "static", "icons")
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "icon.svg"), "w", encoding="utf-8") as f:
        f.write(svg())
    for size in (192, 512):
        with open(os.path.join(out, f"icon-{size}.png"), "wb") as f:
            f.write(png(size))
    print("icons written to static/icons/", file=sys.stderr)


if __name__ == "__main__":
    main()
