#!/usr/bin/env python3
"""Compares the pictures two runs of the lessons wrote, such as every lesson's defaults
built for x86-64 and for ARM64 (run by qemu-user) or Windows (run by Wine):

    tests/platform/compare_pictures.py out-x86-64 out-arm64 [--tolerance 1e-5]

For each PFM (the unclamped linear picture) in both folders, recursively: the same
bytes, or the largest difference of a value relative to the picture's brightest value
(0 to 1), and how many values differ; for each PNG: the same bytes, or the largest
difference of a channel (0 to 255). A PFM differs "within the tolerance" when its
largest relative difference is at most --tolerance. Prints one line per picture that
differs and a summary; exits 1 if a PFM differs beyond the tolerance or a picture is
missing from the second folder. Python standard library only.
"""
import argparse
import struct
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "browser"))
from png import read_png  # noqa: E402  (the browser test's PNG reader)


def read_pfm(data):
    """(width, height, values) of a little-endian RGB PFM, as written by image_io.cpp."""
    fields, at = [], 0
    while len(fields) < 4:
        while data[at:at + 1].isspace():
            at += 1
        end = at
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[at:end].decode("ascii"))
        at = end
    at += 1  # the one whitespace byte after the scale
    magic, width, height, scale = fields[0], int(fields[1]), int(fields[2]), float(fields[3])
    if magic != "PF" or scale >= 0:
        raise ValueError("not a little-endian RGB PFM")
    count = 3 * width * height
    return width, height, struct.unpack(f"<{count}f", data[at:at + 4 * count])


def compare_pfm(a, b):
    """(largest difference relative to the brightest value, values that differ)."""
    wa, ha, va = read_pfm(a)
    wb, hb, vb = read_pfm(b)
    if (wa, ha) != (wb, hb):
        return float("inf"), wa * ha * 3
    brightest = max(max(abs(x) for x in va), 1e-30)
    differ = sum(1 for x, y in zip(va, vb) if x != y)
    largest = max(abs(x - y) for x, y in zip(va, vb))
    return largest / brightest, differ


def compare_png(a, b):
    """The largest difference of one channel, 0 to 255."""
    wa, ha, ra = read_png(a)
    wb, hb, rb = read_png(b)
    if (wa, ha) != (wb, hb):
        return 255
    return max(max(abs(x - y) for x, y in zip(row_a, row_b)) for row_a, row_b in zip(ra, rb))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("first", type=Path)
    parser.add_argument("second", type=Path)
    parser.add_argument("--tolerance", type=float, default=1e-5,
                        help="largest difference of a PFM value relative to its picture's brightest (default 1e-5)")
    args = parser.parse_args()
    same = {".pfm": 0, ".png": 0}
    within, beyond, missing, png_worst, pfm_worst = 0, 0, 0, 0, 0.0
    for file in sorted(args.first.rglob("*")):
        if file.suffix not in same:
            continue
        name = file.relative_to(args.first)
        other = args.second / name
        if not other.exists():
            print(f"{name}: missing from {args.second}")
            missing += 1
            continue
        a, b = file.read_bytes(), other.read_bytes()
        if a == b:
            same[file.suffix] += 1
        elif file.suffix == ".pfm":
            relative, differ = compare_pfm(a, b)
            pfm_worst = max(pfm_worst, relative)
            ok = relative <= args.tolerance
            within, beyond = within + ok, beyond + (not ok)
            print(f"{name}: {differ} values differ, the largest by {relative:.3g} of the brightest"
                  f"{'' if ok else ' (beyond the tolerance)'}")
        else:
            worst = compare_png(a, b)
            png_worst = max(png_worst, worst)
            print(f"{name}: differs, by at most {worst} of 255 in a channel")
    print(f"PFM: {same['.pfm']} the same bytes, {within} within {args.tolerance:g} (largest {pfm_worst:.3g}), "
          f"{beyond} beyond; PNG: {same['.png']} the same bytes, the others by at most {png_worst} of 255; "
          f"{missing} missing")
    return 1 if beyond or missing else 0


if __name__ == "__main__":
    sys.exit(main())
