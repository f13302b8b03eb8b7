#!/usr/bin/env python3
"""The lessons' live pages, in headless Chromium: the WebAssembly build, run in a page.

    tests/wasm/live_test.py NATIVE_BIN WASM_BIN WORK

Makes the live pages (docs/live/make_live.py) into WORK/pages, opens each from file://
and checks, for every lesson that wasm_test.py compares:
  - the form holds the lesson's options (its --options-json), but the host's own
    (--out, --threads, --mesh-folder), each at its default, and an untouched form
    is the lesson's command with no options;
  - run from the page at its defaults, it ends with status 0 and writes the same PNG,
    PFM and CSV files as the native program: pictures the same bytes, tables cell by
    cell within the tolerance wasm_test.py states;
  - a bad option value given in the page's address (?resolution=21&run) ends the run
    with status 2 and shows the native program's one error line;
and, once, that Stop ends a long run within a second and a run after it works, and
that the report page and the viewer a run writes (lesson 08's) open from the page.
Each lesson's time in the page is printed beside the native one's, both on one thread. Exits 77 (ctest's
"skipped") with one line when WASM_BIN, Node.js or Chromium is missing. Python 3.9
and its standard library only.
"""
import base64
import json
import shutil
import subprocess
import sys
import tempfile
import time
import urllib.parse
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent / "browser"))
from cdp import Browser, Page, ProtocolError  # noqa: E402
from wasm_test import LESSONS, csv_difference, first_difference  # noqa: E402

MAKE_LIVE = HERE.parents[1] / "docs" / "live" / "make_live.py"
# Each lesson: a bad option value it must refuse, and the tolerance of its tables'
# numbers (wasm_test.py says why any is not 0).
LIVE = {lesson: (bad, tolerance) for lesson, (_, bad, tolerance) in LESSONS.items()}
LIVE = dict(sorted(LIVE.items()))
HOST_OPTIONS = {"--out", "--threads", "--mesh-folder"}
RUN_SECONDS = 300  # the longest a lesson may take in the page (its defaults: 20 s at most)
problems = []


def check(condition, message):
    if not condition:
        problems.append(message)
    return condition


def address(pages, lesson, options, run=True):
    """The page's address with the options in its query: "--width 64" -> ?width=64."""
    words = options.split()
    query = []
    i = 0
    while i < len(words):
        name = words[i][2:]
        if i + 1 < len(words) and not words[i + 1].startswith("--"):
            query.append((name, words[i + 1]))
            i += 2
        else:
            query.append((name, "1"))
            i += 1
    if run:
        query.append(("run", ""))
    return (pages / lesson / "live.html").as_uri() + "?" + urllib.parse.urlencode(query)


def run_in_page(page, url):
    """Opens the page, which runs the lesson; returns (status, seconds, files, lines)."""
    page.open(url)
    deadline = time.monotonic() + RUN_SECONDS
    while page.evaluate("window.giLive && window.giLive.status") is None:
        if time.monotonic() > deadline:
            raise ProtocolError(f"{url}: no end within {RUN_SECONDS} s")
        time.sleep(0.1)
    status, seconds = page.evaluate("[giLive.status, giLive.seconds]")
    # One file at a time: a lesson's defaults write tens of megabytes of pictures.
    files = {}
    for path in page.evaluate("Object.keys(giLive.files)"):
        if path.endswith((".png", ".pfm", ".csv")):
            files[path] = base64.b64decode(page.evaluate(f"""(() => {{
                const bytes = giLive.files[{json.dumps(path)}].bytes;
                let text = '';
                for (let i = 0; i < bytes.length; i += 0x8000) text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
                return btoa(text); }})()"""))
    lines = page.evaluate("giLive.lines")
    return status, seconds, files, lines


def compare(lesson, native_out, files, tolerance, work):
    """The page's files against the native run's: same names, same bytes or cells."""
    prefix = "out/" + lesson + "/"
    page_files = {k[len(prefix):]: v for k, v in files.items() if k.startswith(prefix)}
    kept = (".png", ".pfm", ".csv")
    native = sorted(str(p.relative_to(native_out)) for p in native_out.rglob("*") if p.suffix in kept)
    mine = sorted(k for k in page_files if k.endswith(kept))
    if not check(native == mine, f"{lesson}: the page wrote {sorted(set(mine) - set(native))} that the native "
                                 f"run did not, and not {sorted(set(native) - set(mine))}"):
        return
    for name in native:
        a, b = (native_out / name).read_bytes(), page_files[name]
        if name.endswith(".csv"):
            copy = work / "page_tables" / lesson / name
            copy.parent.mkdir(parents=True, exist_ok=True)
            copy.write_bytes(b)
            difference = csv_difference(native_out / name, copy, tolerance)
            check(difference is None, f"{lesson} {name}: {difference}")
        else:
            check(a == b, f"{lesson} {name}: differs from the native file from byte {first_difference(a, b)}")


def form_holds_the_options(page, lesson, wasm_bin):
    listed = subprocess.run(["node", str(MAKE_LIVE.parent / "node_run.js"), str(wasm_bin / (lesson + ".js")),
                             "--options-json"], capture_output=True, text=True, timeout=60)
    table = json.loads(listed.stdout)
    expected = [o["name"] for o in table["options"] if o["name"] not in HOST_OPTIONS]
    page.open((page.pages / lesson / "live.html").as_uri())
    page.wait_until("document.querySelectorAll('#fields .field').length > 0", f"{lesson}: the form")
    shown = page.evaluate("[...document.querySelectorAll('#fields .field code')].map(e => e.textContent)")
    check(shown == expected, f"{lesson}: the form shows {shown}, the lesson has {expected}")
    command = page.evaluate("document.getElementById('command').textContent")
    check(command == lesson, f"{lesson}: the untouched form runs '{command}', not the lesson with no options")
    errors = page.errors()
    check(not errors, f"{lesson}: the page logged {errors[:3]}")
    return table


def pages_of_the_run_open(browser, page, lesson):
    """After a run, the page offers the run's own report page and viewer, each made
    whole (its scripts, styles and pictures inside it): each opens in a tab of its own
    with no error, the viewer with its canvas drawn."""
    offered = page.evaluate("[...document.querySelectorAll('#pages a')].map(a => [a.className, a.href])")
    kinds = sorted(kind or "report" for kind, _ in offered)
    if not check(kinds == ["report", "viewer-link"], f"{lesson}: the page offers {kinds}, not the report and viewer"):
        return
    for kind, url in offered:
        tab = Page(browser, 1200, 900)
        tab.open(url)
        if kind == "viewer-link":
            tab.wait_until("document.querySelector('canvas') && document.querySelector('canvas').width > 0",
                           f"{lesson}: the run's viewer")
        else:
            check(tab.evaluate("document.querySelectorAll('img').length") > 0, f"{lesson}: the run's report shows no picture")
        check(not tab.errors(), f"{lesson}: the run's {kind or 'report'} page logged {tab.errors()[:3]}")
        browser.send("Target.closeTarget", {"targetId": tab.target})


def stop_ends_a_long_run(page):
    lesson = "14_path_tracing"  # its defaults take tens of seconds in the page
    page.open(address(page.pages, lesson, ""))
    page.wait_until("giLive.running && giLive.lines.length > 0", "14: the long run starting")
    started = time.monotonic()
    page.evaluate("document.getElementById('stop').click()")
    page.wait_until("giLive.status === 'stopped' && !document.getElementById('run').disabled", "14: Stop")
    check(time.monotonic() - started < 1.0, f"Stop took {time.monotonic() - started:.1f} s")
    # The next run starts in a new worker and finishes.
    page.evaluate("""(() => { const set = (n, v) => { document.getElementById('option--' + n).value = v; };
        set('width', 32); set('height', 32); set('max-spp', 2);
        document.getElementById('run').click(); })()""")
    deadline = time.monotonic() + RUN_SECONDS
    while page.evaluate("giLive.status") in (None, "stopped"):
        check(time.monotonic() < deadline, "the run after Stop did not end")
        if time.monotonic() > deadline:
            return
        time.sleep(0.1)
    check(page.evaluate("giLive.status") == 0, f"the run after Stop: status {page.evaluate('giLive.status')}")


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    native_bin, wasm_bin, work = (Path(a).resolve() for a in sys.argv[1:])
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    for missing, what in ((not wasm_bin.is_dir(), f"no WebAssembly build in {wasm_bin}"),
                          (not shutil.which("node"), "node not found (apt-get install nodejs)"),
                          (not chromium, "Chromium not found (apt-get install chromium)")):
        if missing:
            print(f"skipped: {what}")
            return 77
    pages = work / "pages"
    shutil.rmtree(work, ignore_errors=True)
    made = subprocess.run([sys.executable, str(MAKE_LIVE), "--bin", str(wasm_bin), "--out", str(pages)],
                          capture_output=True, text=True)
    if made.returncode != 0:
        print(made.stderr.strip())
        return 1
    print(made.stdout.strip())
    lessons = [l for l in LIVE if (wasm_bin / (l + ".js")).exists()]
    with tempfile.TemporaryDirectory() as profile:
        browser = Browser(chromium, profile, timeout=60)
        try:
            page = Page(browser, 1200, 900)
            page.pages = pages
            print("Each lesson at its defaults, in the page and natively, both on one thread:")
            print(f"{'lesson':32} {'page (s)':>11} {'native (s)':>11} {'ratio':>7}")
            for lesson in lessons:
                bad, tolerance = LIVE[lesson]
                table = form_holds_the_options(page, lesson, wasm_bin)
                # The native run on one thread, as the page's: the same outputs for any
                # count, and a fair time to set the page's beside.
                # But lesson 05, whose study of threads has a row per thread up to
                # --threads: the page's is 2 (threads.cpp), wherever it runs.
                one_thread = ["--threads", "1"] if any(o["name"] == "--threads" for o in table["options"]) else []
                if lesson == "05_acceleration":
                    one_thread = ["--threads", "2"]
                native_out = work / "native" / lesson
                started = time.monotonic()
                native = subprocess.run([str(native_bin / lesson), *one_thread, "--out", str(native_out)],
                                        capture_output=True, text=True)
                native_seconds = time.monotonic() - started
                if not check(native.returncode == 0, f"{lesson} native: status {native.returncode}"):
                    continue
                status, seconds, files, _ = run_in_page(page, address(pages, lesson, ""))
                print(f"{lesson:32} {seconds:11.2f} {native_seconds:11.2f} {seconds / native_seconds:7.2f}", flush=True)
                if check(status == 0, f"{lesson}: the page's run ended with status {status}"):
                    compare(lesson, native_out, files, tolerance, work)
                    if lesson == "08_radiosity_system":  # the first lesson with a viewer
                        pages_of_the_run_open(browser, page, lesson)
                refused = subprocess.run([str(native_bin / lesson), *bad.split(), "--out", str(work / "refused")],
                                         capture_output=True, text=True)
                status, _, _, lines = run_in_page(page, address(pages, lesson, bad))
                shown = [l["text"] for l in lines if l["stream"] == "stderr"]
                check(status == 2, f"{lesson} {bad}: the page's run ended with status {status}, not 2")
                check(shown == refused.stderr.strip().splitlines(),
                      f"{lesson} {bad}: the page says {shown}, the native program {refused.stderr.strip()!r}")
            if "14_path_tracing" in lessons:
                stop_ends_a_long_run(page)
        except ProtocolError as e:
            problems.append(f"the browser: {e}")
        finally:
            browser.close()
    for p in problems:
        print(p)
    if problems:
        return 1
    print(f"live pages: {len(lessons)} lessons run in the page as their native twins do" +
          ("; Stop ends a long run" if "14_path_tracing" in lessons else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
