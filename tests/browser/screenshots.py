#!/usr/bin/env python3
"""Screenshots of the lessons' pages as a student sees them, for a person to look at.

    screenshots.py OUT_DIR SHOTS_DIR [WIDTH]

Opens OUT_DIR/index.html and every OUT_DIR/NN_topic/index.html (a run of all the
lessons: `cmake --build --preset release --target lessons` writes out/) in headless
Chromium at WIDTH px (1280 unless given) and writes each whole page as a PNG into
SHOTS_DIR: index.png, 01_rays.png, ... Prints each page's height and whether anything
overflows the window sideways. Not a test: browser_test.py checks the pages.
"""
import shutil
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from cdp import Browser, Page  # noqa: E402


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, shots = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve()
    width = int(sys.argv[3]) if len(sys.argv) > 3 else 1280
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if not chromium:
        sys.exit("no chromium on PATH")
    shots.mkdir(parents=True, exist_ok=True)
    pages = [("index", out / "index.html")] + [(p.parent.name, p) for p in sorted(out.glob("*/index.html"))]
    with tempfile.TemporaryDirectory() as profile:
        browser = Browser(chromium, profile, timeout=120)
        try:
            page = Page(browser, width, 900)
            for name, path in pages:
                page.open(path.as_uri())
                height = page.evaluate("document.documentElement.scrollHeight")
                overflow = page.evaluate("document.documentElement.scrollWidth - window.innerWidth")
                (shots / f"{name}.png").write_bytes(page.full_page_screenshot(width))
                print(f"{name}: {height} px high{f', {overflow} px too wide' if overflow > 0 else ''}")
        finally:
            browser.close()


if __name__ == "__main__":
    main()
