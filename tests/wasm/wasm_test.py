#!/usr/bin/env python3
"""The WebAssembly build computes what the native build computes.

    tests/wasm/wasm_test.py NATIVE_BIN WASM_BIN WORK [--node NODE]

For each lesson built as WebAssembly (WASM_BIN/NN_name.js, the wasm preset) that is
listed in LESSONS below, runs it under Node.js (docs/live/node_run.js, the real file
system) and its native twin (NATIVE_BIN/NN_name)
with the same small options, each into a folder of its own below WORK, and checks:
  - both finish with status 0 and write the same PNG, PFM and CSV files;
  - each PNG and PFM holds the same bytes;
  - each CSV table has the same cells, but for the columns that measure time (their
    header names a unit of time, a rate or a ratio of times: ms, s, Mrays/s, speedup,
    ...): a wall-clock time differs between two runs of the same program, so there
    both cells need only be numbers (or "-", a time below the clock's tick). A lesson whose arithmetic differs between the
    two builds (LESSONS says where and why) is allowed a stated relative difference
    in the numbers of its tables;
  - a bad option value gives the same one-line error on stderr and status 2.
A lesson built as WebAssembly but not listed is reported as not compared yet (a
skipped test). Exits 77 (ctest's "skipped") with one line when WASM_BIN or Node.js
is missing. Python 3.9 and its standard library only.
"""
import argparse
import csv
import re
import shutil
import subprocess
import sys
import unittest
from pathlib import Path

class Tolerance:
    """How far a number of a table may be from the native one: `relative` of the larger
    in size, or `absolute` (for an error column whose values sit at rounding noise, a
    relative test of two noises would fail on nothing), or for a column named in
    `columns` that column's own relative tolerance."""

    def __init__(self, relative=0.0, absolute=0.0, columns=None):
        self.relative, self.absolute, self.columns = relative, absolute, columns or {}

    def __bool__(self):
        return bool(self.relative or self.absolute or self.columns)

    def __str__(self):
        parts = [f"{self.relative:g} of it"] if self.relative else []
        parts += [f"{self.absolute:g}"] if self.absolute else []
        return " or ".join(parts) or "0"


# Each lesson's small options (its outputs in about a second natively), a bad option
# value it must refuse before any work, and the largest difference allowed in a number
# of its tables: a number, relative, or a Tolerance (0: the same text). Where it is not
# 0 the reason is said.
# Pictures (PNG, PFM) are held to the same bytes in every lesson.
LESSONS = {
    "01_rays": ("--width 64 --height 48", "--width 5", 0),
    "02_recursive": ("--width 48 --height 36 --max-depth 3 --reference-depth 6 --repeat 1", "--max-depth 41", 0),
    # PSNR is 10 log10(1 / MSE): glibc's log10 natively, musl's in WebAssembly, each
    # within an ulp of the exact value but not always the same one (measured at the
    # defaults: 2.2e-16 of the value).
    "03_antialiasing": ("--width 48 --height 36 --depth 1 --reference-n 6", "--reference-n 3", 1e-14),
    "04_soft_shadows": ("--width 40 --height 30 --reference-n 6", "--light-size 5", 0),
    "05_acceleration": ("--width 16 --height 16 --max-spheres 10 --room-quads 100 --change-rays 16 "
                        "--picture-scale 0.05 --threads 2", "--room-quads 99", 0),
    # The failure cases' errors are relative errors of small form factors, measured
    # against closed forms that sum in gi::wide, long double: 64 bits of mantissa on
    # x86-64, 113 in WebAssembly (gi/core/wide_float.hpp). For a 5 cm square 4 m up
    # (F = 4.7e-5) the two exact values differ by 2.9e-11 of F, and every error
    # measured against them moves by that much: an error of 1e-14 in one build is
    # 3e-11 in the other. So an error may differ by 1e-10, far below any error a
    # method has; other numbers by 1e-8 of themselves.
    "06_form_factors": ("--rays 1000 --sweep-rays 1000 --reference-rays 10000 --resolution 50", "--resolution 3",
                        Tolerance(relative=1e-8, absolute=1e-10)),
    "07_hemicube": ("--elements 40 --resolution 30 --max-resolution 20 --speed-elements 100 --speed-rays 3000",
                    "--resolution 21", 0),
    "08_radiosity_system": ("--elements 60 --resolution 20 --width 32 --height 32", "--bounces 0", 0),
    "09_jacobi_gauss_seidel": ("--elements 40 --resolution 20", "--omega 2", 0),
    "10_southwell": ("--elements 40 --resolution 20", "--sweeps 0", 0),
    "11_progressive": ("--patches 40 --resolution 20 --width 32 --height 32 --speed-elements 200", "--patches 10", 0),
    # The leaf mesh sums in gi::wide, long double: 64 bits of mantissa on x86-64, 113
    # in WebAssembly (gi/core/wide_float.hpp). The change in B between rounds differs
    # in its last digits (measured: 1.5e-13 of itself).
    # The float matrix's error (column "float") is the rounding of float sums, whose
    # order the compiler's vector code chooses differently for x86-64 and WebAssembly:
    # where the sweeps reach that floor (4e-9 to 8e-9) the two builds' floors differ
    # by up to a third (measured: 5.3e-9 against 4.0e-9), so within half of the
    # larger; a solve that failed to converge would be orders of magnitude off. The
    # furnace's and reciprocity's deviations sit at double rounding (1e-16 to 1e-13)
    # and move by 2e-16.
    "12_solver_showdown": ("--elements 60 --bandwidth-n 200 --skip-mesh-study", "--elements 5",
                           Tolerance(relative=1e-8, absolute=1e-12, columns={"float": 0.5})),
    "13_hierarchical": ("--uniform-elements 100 --min-area 1e-3", "--threshold 2", 1e-11),
    # The Monte Carlo table calls std::sin, which the C library provides: glibc's
    # natively, musl's in WebAssembly, each within an ulp of the exact value but not
    # always the same one (measured: 2.2e-16 of the value).
    "14_path_tracing": ("--width 32 --height 32 --max-spp 8", "--max-spp 0", 1e-14),
    "15_radiosity_vs_path_tracing": ("--size 64 --max-spp 2", "--size 32", 0),
    "16_two_pass": ("--width 16 --height 16 --elements 40 --gather 1", "--samples 17", 0),
}
# The header of a column that measures time, or is worked out from times: a unit
# of time as a word (ms, s, us, "time (s)", "us/ray"), a rate per unit of time
# (Mrays/s, GB/s, "rows per second"), or a ratio of times (x, speedup, efficiency).
# Units in lower case only: "G-S r" is Gauss-Seidel's residual. Lesson 04's "light
# size s" is the side s of its light, in scene units.
TIME_COLUMN = re.compile(r"(^|[^A-Za-z-])(ms|s|us|µs|ns)([^A-Za-z]|$)|second|^x($|\s)|speed-?up|efficiency")
NOT_TIME = {"light size s"}

ARGS = None  # the command line, parsed in main()


def run(command, timeout=600):
    """(exit status, stdout, stderr) of a command."""
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=timeout)
    return done.returncode, done.stdout.decode("utf-8", "replace"), done.stderr.decode("utf-8", "replace")


def native_command(lesson):
    return [str(ARGS.native_bin / lesson)]


NODE_RUN = Path(__file__).resolve().parents[2] / "docs" / "live" / "node_run.js"


def wasm_command(lesson):
    return [ARGS.node, str(NODE_RUN), str(ARGS.wasm_bin / (lesson + ".js"))]


def outputs(folder):
    """The compared files a run wrote: their names below the folder."""
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*") if p.suffix in (".png", ".pfm", ".csv"))


def first_difference(a, b):
    """The offset of the first byte that differs (or where the shorter one ends)."""
    for i, (x, y) in enumerate(zip(a, b)):
        if x != y:
            return i
    return min(len(a), len(b))


def is_number(cell):
    try:
        float(cell)
        return True
    except ValueError:
        return False


def is_time(cell):
    """A measured time or a figure worked out from one: a number, or "-" where the
    time was below the clock's tick (a browser's clock ticks every 0.1 ms)."""
    return is_number(cell) or cell == "-"


def same_cell(x, y, tolerance, column=""):
    """Equal text, or numbers within the tolerance (a Tolerance, or a number: relative)."""
    if not isinstance(tolerance, Tolerance):
        tolerance = Tolerance(relative=tolerance)
    if x == y:
        return True
    if not tolerance or not (is_number(x) and is_number(y)):
        return False
    a, b = float(x), float(y)
    relative = tolerance.columns.get(column, tolerance.relative)
    return abs(a - b) <= max(relative * max(abs(a), abs(b)), tolerance.absolute)


def csv_difference(native_file, wasm_file, tolerance):
    """None if the tables agree cell by cell (time columns: numbers on both sides;
    other numbers within `tolerance`), else one line saying where they first differ."""
    with open(native_file, newline="", encoding="utf-8") as f:
        a = list(csv.reader(f))
    with open(wasm_file, newline="", encoding="utf-8") as f:
        b = list(csv.reader(f))
    if len(a) != len(b):
        return f"{len(b)} rows, the native table has {len(a)}"
    header = a[0] if a else []
    for row, (ra, rb) in enumerate(zip(a, b), start=1):
        if len(ra) != len(rb):
            return f"row {row} has {len(rb)} cells, the native table's {len(ra)}"
        for column, (x, y) in enumerate(zip(ra, rb)):
            name = header[column] if column < len(header) else str(column + 1)
            if row > 1 and TIME_COLUMN.search(name) and name not in NOT_TIME:
                if not (is_time(x) and is_time(y)):
                    return f"row {row}, column '{name}' (a time): {y!r}, native {x!r}"
            elif not same_cell(x, y, tolerance, name):
                return f"row {row}, column '{name}': {y!r}, native {x!r}" + (
                    f" (beyond {tolerance})" if tolerance else "")
    return None


class WebAssemblyMatchesNative(unittest.TestCase):
    longMessage = False  # a failure says one line, ours, not unittest's comparison too

    def compare_runs(self, lesson, options, tolerance):
        work = ARGS.work / lesson
        shutil.rmtree(work, ignore_errors=True)
        native_out, wasm_out = work / "native", work / "wasm"
        status, _, err = run(native_command(lesson) + options.split() + ["--out", str(native_out)])
        self.assertEqual(status, 0, f"{lesson} native: status {status}: {err.strip()[-300:]}")
        status, _, err = run(wasm_command(lesson) + options.split() + ["--out", str(wasm_out)])
        self.assertEqual(status, 0, f"{lesson} wasm: status {status}: {err.strip()[-300:]}")

        native_files, wasm_files = outputs(native_out), outputs(wasm_out)
        self.assertTrue(native_files, f"{lesson}: the native run wrote no PNG, PFM or CSV file")
        only_native = sorted(set(native_files) - set(wasm_files))
        only_wasm = sorted(set(wasm_files) - set(native_files))
        self.assertTrue(not only_native and not only_wasm, f"{lesson}: only the native run wrote {only_native}, "
                                                           f"only the wasm run wrote {only_wasm}")
        for name in native_files:
            a, b = (native_out / name).read_bytes(), (wasm_out / name).read_bytes()
            if name.endswith(".csv"):
                difference = csv_difference(native_out / name, wasm_out / name, tolerance)
                self.assertIsNone(difference, f"{lesson} {name}: {difference}")
            else:
                self.assertTrue(a == b, f"{lesson} {name}: differs from the native file from byte "
                                        f"{first_difference(a, b)} ({len(b)} bytes, native {len(a)})")

    def compare_refusals(self, lesson, bad):
        status_n, _, err_n = run(native_command(lesson) + bad.split() + ["--out", str(ARGS.work / "refused")])
        status_w, _, err_w = run(wasm_command(lesson) + bad.split() + ["--out", str(ARGS.work / "refused")])
        self.assertEqual(status_n, 2, f"{lesson} native {bad}: status {status_n}, not 2: {err_n.strip()}")
        self.assertEqual(status_w, 2, f"{lesson} wasm {bad}: status {status_w}, not 2: {err_w.strip()}")
        self.assertEqual(len(err_n.strip().splitlines()), 1, f"{lesson} native {bad}: not one line: {err_n!r}")
        self.assertEqual(err_w, err_n, f"{lesson} {bad}: wasm says {err_w.strip()!r}, native {err_n.strip()!r}")

    def test_each_lesson_computes_what_the_native_one_does(self):
        found = sorted(p.name[:-3] for p in ARGS.wasm_bin.glob("[0-9][0-9]_*.js"))
        self.assertTrue(found, f"no lesson in {ARGS.wasm_bin}")
        for lesson in found:
            if lesson not in LESSONS:
                continue
            options, bad, tolerance = LESSONS[lesson]
            with self.subTest(lesson=lesson):
                self.assertTrue((ARGS.native_bin / lesson).exists(), f"{lesson}: no native program in {ARGS.native_bin}")
                self.compare_runs(lesson, options, tolerance)
                self.compare_refusals(lesson, bad)

    def test_node_run_refuses_what_is_not_a_lesson(self):
        """docs/live/node_run.js given a missing file or a script that is not a lesson:
        one line and status 2, not Node.js's stack trace."""
        not_a_lesson = ARGS.work / "not_a_lesson.js"
        not_a_lesson.write_text("module.exports = 5;\n")
        for given in (ARGS.work / "missing.js", not_a_lesson):
            status, _, err = run([ARGS.node, str(NODE_RUN), str(given)])
            self.assertEqual(status, 2, f"{given.name}: status {status}")
            self.assertEqual(len(err.strip().splitlines()), 1, f"{given.name}: {err!r}")
            self.assertIn(given.name, err)

    def test_lessons_not_compared_yet(self):
        found = sorted(p.name[:-3] for p in ARGS.wasm_bin.glob("[0-9][0-9]_*.js"))
        missing = [lesson for lesson in found if lesson not in LESSONS]
        if missing:
            self.skipTest("built but not compared yet: " + ", ".join(missing))


def main():
    global ARGS
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("native_bin", type=Path, help="the native build's bin folder")
    parser.add_argument("wasm_bin", type=Path, help="the wasm build's bin folder (build/wasm/bin)")
    parser.add_argument("work", type=Path, help="a folder for the runs' outputs")
    parser.add_argument("--node", default=shutil.which("node"), help="Node.js (default: node on PATH)")
    ARGS, rest = parser.parse_known_args()
    if not ARGS.wasm_bin.is_dir():
        print(f"skipped: no WebAssembly build in {ARGS.wasm_bin} (cmake --preset wasm && cmake --build --preset wasm)")
        return 77
    if not ARGS.node:
        print("skipped: node not found (apt-get install nodejs)")
        return 77
    ARGS.work.mkdir(parents=True, exist_ok=True)
    result = unittest.main(argv=[sys.argv[0]] + rest, exit=False, verbosity=2).result
    return 0 if result.wasSuccessful() else 1


if __name__ == "__main__":
    sys.exit(main())
