"""Reading the PNGs Chromium writes (8-bit RGB or RGBA, not interlaced) and comparing
two of them, Python standard library only."""
import struct
import zlib


def read_png(data):
    """(width, height, rows): rows a list of bytes, 3 per pixel (alpha dropped)."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    at, idat, header = 8, b"", None
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        raise ValueError(f"unsupported PNG: depth {depth}, colour type {colour}, interlace {interlace}")
    channels = 3 if colour == 2 else 4
    stride = width * channels
    raw = zlib.decompress(idat)
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        row = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):  # the five filters of the PNG specification, undone
            left = row[i - channels] if i >= channels else 0
            up = previous[i]
            corner = previous[i - channels] if i >= channels else 0
            if kind == 1:
                row[i] = (row[i] + left) & 255
            elif kind == 2:
                row[i] = (row[i] + up) & 255
            elif kind == 3:
                row[i] = (row[i] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                row[i] = (row[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else corner)) & 255
        previous = row
        rows.append(bytes(row) if channels == 3 else bytes(b for k, b in enumerate(row) if k % 4 != 3))
    return width, height, rows


def difference(a, b):
    """Of two PNGs of the same size: the mean absolute difference per channel (0-255)
    and the share of pixels where some channel differs by more than 32."""
    wa, ha, ra = read_png(a)
    wb, hb, rb = read_png(b)
    if (wa, ha) != (wb, hb):
        raise ValueError(f"sizes differ: {wa}x{ha} against {wb}x{hb}")
    total, far = 0, 0
    for row_a, row_b in zip(ra, rb):
        d = [abs(x - y) for x, y in zip(row_a, row_b)]
        total += sum(d)
        far += sum(1 for k in range(0, len(d), 3) if max(d[k:k + 3]) > 32)
    return total / (3 * wa * ha), far / (wa * ha)
