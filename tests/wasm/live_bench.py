#!/usr/bin/env python3
"""Each lesson's time in its live page against the native program's, both on one thread.

    tests/wasm/live_bench.py NATIVE_BIN WASM_BIN [--repeats N] [LESSON ...]

For each lesson (default: every one with a live page), runs it at its defaults N times
in headless Chromium (its page, docs/live/) and N times natively with --threads 1,
alternating the two, and prints the medians and their ratio. The page's time is the
worker's own clock, from the run's start to its exit status: it includes compiling the
program, not loading the page. A benchmark, not a test: it checks nothing. Python 3.9
and its standard library only.
"""
import argparse
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent / "browser"))
from cdp import Browser, Page  # noqa: E402
from live_test import MAKE_LIVE, address, run_in_page  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("native_bin", type=Path)
    parser.add_argument("wasm_bin", type=Path)
    parser.add_argument("--repeats", type=int, default=3, help="runs of each, alternated (default 3)")
    parser.add_argument("lessons", nargs="*")
    args = parser.parse_intermixed_args()
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if not chromium or not args.wasm_bin.is_dir():
        sys.exit("live_bench.py: needs Chromium and a WebAssembly build (cmake --build --preset wasm)")
    with tempfile.TemporaryDirectory() as work_name, tempfile.TemporaryDirectory() as profile:
        work = Path(work_name)
        pages = work / "pages"
        subprocess.run([sys.executable, str(MAKE_LIVE), "--bin", str(args.wasm_bin.resolve()), "--out", str(pages),
                        *args.lessons], check=True, capture_output=True)
        lessons = sorted(p.name for p in pages.iterdir() if (p / "live.html").is_file())
        version = subprocess.run([chromium, "--version"], capture_output=True, text=True).stdout.strip()
        print(f"{version}; native: {args.native_bin}; medians of {args.repeats} runs each, alternated, one thread")
        print(f"{'lesson':32} {'page (s)':>9} {'native (s)':>11} {'ratio':>6}")
        browser = Browser(chromium, profile, timeout=60)
        try:
            page = Page(browser, 1200, 900)
            for lesson in lessons:
                page_times, native_times = [], []
                for _ in range(args.repeats):
                    status, seconds, _, _ = run_in_page(page, address(pages, lesson, ""))
                    if status != 0:
                        sys.exit(f"live_bench.py: {lesson} ended with status {status} in the page")
                    page_times.append(seconds)
                    started = time.monotonic()
                    native = subprocess.run([str(args.native_bin / lesson), "--threads", "1", "--out",
                                             str(work / "native" / lesson)], capture_output=True, text=True)
                    if native.returncode == 2:  # a lesson without --threads runs on one thread anyway
                        started = time.monotonic()
                        native = subprocess.run([str(args.native_bin / lesson), "--out", str(work / "native" / lesson)],
                                                capture_output=True, text=True)
                    native_times.append(time.monotonic() - started)
                p, n = statistics.median(page_times), statistics.median(native_times)
                print(f"{lesson:32} {p:9.2f} {n:11.2f} {p / n:6.2f}", flush=True)
        finally:
            browser.close()


if __name__ == "__main__":
    main()
