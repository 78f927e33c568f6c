#!/usr/bin/env python3
"""matte.py ON_BLACK.png ON_WHITE.png OUT.png: the same picture rendered on a black and on a
white background gives each pixel's coverage, alpha = 1 - (white - black), and its colour,
black / alpha; OUT is that picture as RGBA with a transparent background. Reads and writes
8-bit non-interlaced RGB or RGBA PNGs (what zeroset writes) with the standard library only."""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, color, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and color in (2, 6) and interlace == 0, path
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    channels = 4 if color == 6 else 3
    raw, stride = zlib.decompress(idat), width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        prev = line
    return width, height, rows


def write_png(path, width, height, rgba_rows):
    raw = b"".join(b"\x00" + bytes(row) for row in rgba_rows)
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 9)))
        f.write(chunk(b"IEND", b""))


def main():
    w, h, black = read_png(sys.argv[1])
    w2, h2, white = read_png(sys.argv[2])
    assert (w, h) == (w2, h2)
    out = []
    for y in range(h):
        row = []
        for (kb, wb) in zip(black[y], white[y]):
            alpha = 255 - max(0, min(255, round(sum(wc - bc for bc, wc in zip(kb, wb)) / 3)))
            color = [min(255, round(c * 255 / alpha)) if alpha else 0 for c in kb]
            row += color + [alpha]
        out.append(row)
    write_png(sys.argv[3], w, h, out)


if __name__ == "__main__":
    main()
