#!/usr/bin/env python3
"""The lessons' pages in a real browser (headless Chromium, SwiftShader's WebGL2).

Runs every lesson small into a scratch folder, then checks that
  - every report page (index.html) and out/index.html load with no console error,
    show all their images, fit a window 1280 px wide (nothing overflows sideways),
    link the lesson's chapter (its page chapter.html where the book made one, else
    docs/NN_topic.md, a file that exists) and its lab, and that out/index.html links
    each lesson's page, chapter and lab;
  - every chapter page the book made (docs/book/make_book.py, run here before the
    lessons, as the `lessons` target does) and its front page load with no console
    error and fit the window; outside code no raw Markdown survives (no `$`, `![` or
    `](`), every image loads, every equation is typeset (KaTeX's, none in error),
    every link of the contents lands on a heading and every link to a file names one
    that exists; the chapter link of a lesson's page opens its chapter page;
  - every false-colour picture has its colour bar: each figure the page marks as
    false colour shows a bar with its values and quantity, and every PNG whose
    pixels lie on the false-colour ramp (black, blue, green, yellow, red; read here
    from the file, not from the page) is such a figure;
  - each viewer loads with no console error and draws, on its last frame (the
    solution; play replays from the first); moving the step slider (a
    real click on it), a light's slider and dragging the camera change the canvas;
    the pointer over the chart writes the curves' values under it;
  - lesson 13's viewer (hierarchical radiosity): a click on the mesh picks a leaf
    and a scripted pick of a known one lists its links; the readout's count equals
    the count of links this script finds in viewer_data.js for that leaf and its
    ancestors (decoded here, not with the page's code), the sum it prints agrees
    with what the solver handed the leaf, and the outlines change the canvas;
  - the mesh of lesson 11 after a chosen shot matches tests/data/viewer_11_shot.png:
    mean absolute difference at most 2 of 255 per channel, and at most 1% of the
    pixels off by more than 32 in some channel (rasterisation may differ at edges
    between CPUs; a wrong colour, camera or shot moves far more than that).
Writes screenshots of the whole viewer pages of lessons 11 and 13 for docs/viewer.md,
and of every report page, into the scratch folder. Exits 77 (ctest: skipped) with one line when Chromium is missing.

    browser_test.py BIN_DIR WORK_DIR [--update]   (--update rewrites the reference)
"""
import base64
import json
import re
import shutil
import struct
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from cdp import Browser, Page, ProtocolError  # noqa: E402
from png import difference, read_png  # noqa: E402

REFERENCE = Path(__file__).parent.parent / "data" / "viewer_11_shot.png"
MEAN_LIMIT, FAR_LIMIT = 2.0, 0.01
LESSONS = {
    "01_rays": ["--width", "64", "--height", "48"],
    "02_recursive": ["--width", "48", "--height", "36", "--max-depth", "3", "--reference-depth", "6", "--repeat", "1"],
    "03_antialiasing": ["--width", "48", "--height", "36", "--depth", "1", "--reference-n", "6"],
    "04_soft_shadows": ["--width", "40", "--height", "30", "--reference-n", "6"],
    "05_acceleration": ["--width", "16", "--height", "16", "--max-spheres", "10", "--room-quads", "100",
                        "--change-rays", "16", "--picture-scale", "0.05", "--threads", "2"],
    "06_form_factors": ["--rays", "200", "--resolution", "20", "--order", "2", "--sweep-rays", "1000",
                        "--reference-rays", "10000"],
    "07_hemicube": ["--elements", "40", "--resolution", "30", "--max-resolution", "20", "--speed-elements", "100",
                    "--speed-rays", "3000"],
    "08_radiosity_system": ["--elements", "60", "--resolution", "20", "--bounces", "3", "--width", "32", "--height", "32"],
    "09_jacobi_gauss_seidel": ["--elements", "60", "--resolution", "20", "--iterations", "20"],
    "11_progressive": ["--patches", "60", "--resolution", "20", "--width", "16", "--height", "16",
                       "--speed-elements", "100"],
    "10_southwell": ["--elements", "60", "--resolution", "20", "--sweeps", "10"],
    "12_solver_showdown": ["--elements", "20", "--bandwidth-n", "100", "--skip-mesh-study"],
    "13_hierarchical": ["--skip-studies", "--threshold", "1e-2", "--min-area", "3e-3"],
    "14_path_tracing": ["--width", "32", "--height", "32", "--max-spp", "8"],
    "15_radiosity_vs_path_tracing": ["--size", "64", "--max-spp", "4", "--caustic-spp", "32"],
    "16_two_pass": ["--width", "32", "--height", "32", "--elements", "100", "--samples", "1", "--gather", "2"],
}
VIEWERS = ["08_radiosity_system", "09_jacobi_gauss_seidel", "10_southwell", "11_progressive", "12_solver_showdown",
           "13_hierarchical"]
PAGE_WIDTH = 1280
SHOT_FRAME = 12  # the frame of lesson 11's replay the reference shows

problems = []


def check(ok, message):
    if not ok:
        problems.append(message)
    return ok


def no_errors(page, what):
    for error in page.errors():
        problems.append(f"{what}: console: {error}")


def canvas_shot(page, selector="#mesh"):
    return page.screenshot(page.box(selector))


def changed(before, after):
    mean, _ = difference(before, after)
    return mean > 0.5


def srgb_to_linear(c):
    c /= 255
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def on_ramp(r, g, b):
    """Whether an sRGB pixel lies on the false-colour ramp (image/diff.hpp): black to
    blue (r = g = 0), blue to green (r = 0, g + b = 1 in linear terms), green to
    yellow (g full, b = 0), yellow to red (r full, b = 0)."""
    lo, hi = 3, 252
    if r <= lo and g <= lo:
        return True
    if r <= lo:
        return abs(srgb_to_linear(g) + srgb_to_linear(b) - 1) < 0.03
    if b <= lo and (g >= hi or r >= hi):
        return True
    return False


def is_false_colour(png_bytes):
    """A PNG nearly all of whose pixels lie on the ramp, with some colour in it."""
    width, height, rows = read_png(png_bytes)
    step = max(1, (width * height) // 20000)  # a sample of the pixels is enough
    total = on = coloured = 0
    for k in range(0, width * height, step):
        row = rows[k // width]
        r, g, b = row[3 * (k % width):3 * (k % width) + 3]
        total += 1
        if on_ramp(r, g, b):
            on += 1
            coloured += max(r, g, b) > 40
    return on >= 0.97 * total and coloured >= 0.02 * total


def page_links(page):
    return page.evaluate("Array.from(document.links).map((a) => [a.className, a.getAttribute('href'), a.href])")


def linked_file(href):
    """The file a file:// link names."""
    from urllib.parse import unquote, urlparse
    return Path(unquote(urlparse(href).path))


def chapter_of(out, lesson):
    """What a lesson's chapter link should open: the book's page, or the Markdown."""
    page = out / lesson / "chapter.html"
    return page if page.is_file() else Path(__file__).resolve().parents[2] / "docs" / f"{lesson}.md"


# What a chapter page shows a reader outside its code and equations, and what of it
# still reads as Markdown: a dollar, a picture's or a link's brackets.
PAGE_TEXT = """(() => {
    const main = document.querySelector('main').cloneNode(true);
    main.querySelectorAll('pre, code, .katex').forEach((e) => e.remove());
    return main.textContent;
})()"""
RAW_MARKDOWN = re.compile(r"\$|!\[|\]\(")


def chapter_pages(browser, out):
    pages = sorted(out.glob("*/chapter.html"))
    if not pages:
        print("chapter pages not checked: the book made none (it says why above)")
        return
    page = Page(browser, PAGE_WIDTH, 900)
    for path in [*pages, out / "book" / "index.html"]:
        what = str(path.relative_to(out))
        page.open(path.as_uri())
        raw = RAW_MARKDOWN.findall(page.evaluate(PAGE_TEXT))
        check(not raw, f"{what}: Markdown left as text: {raw[:5]}")
        images = page.evaluate("Array.from(document.images).map((i) => [i.getAttribute('src'), i.naturalWidth > 0])")
        for src, shown in images:
            check(shown, f"{what}: the image {src} does not load")
        maths = page.evaluate("""[document.querySelectorAll('.katex').length,
            document.querySelectorAll('.katex-error').length,
            Array.from(document.querySelectorAll('.katex-html'))
                .filter((e) => e.getBoundingClientRect().width == 0).length]""")
        check(maths[1] == 0 and maths[2] == 0,
              f"{what}: of {maths[0]} equations {maths[1]} in error, {maths[2]} not drawn")
        check(page.evaluate("getComputedStyle(document.querySelector('nav.sidebar')).position") == "sticky",
              f"{what}: the book's style sheet did not load")
        missing = page.evaluate("""Array.from(document.querySelectorAll('ol.toc a'))
            .map((a) => a.getAttribute('href')).filter((h) => !document.getElementById(h.slice(1)))""")
        check(not missing, f"{what}: contents links to no heading: {missing}")
        for _, _, href in page_links(page):
            if href.startswith("file:"):
                check(linked_file(href).exists(), f"{what}: links {href}, which does not exist")
        overflow = page.evaluate("document.documentElement.scrollWidth - window.innerWidth")
        check(overflow <= 0, f"{what}: {overflow} px wider than a {PAGE_WIDTH} px window")
        (out / f"chapter_{path.parent.name}.png").write_bytes(page.full_page_screenshot(PAGE_WIDTH))
    no_errors(page, "the chapter pages")
    # A student reaches a chapter from the lesson's page.
    lesson = pages[0].parent.name
    page.open((out / lesson / "index.html").as_uri())
    page.open(page.evaluate("document.querySelector('a.doc').href"))
    check(page.evaluate("location.pathname").endswith(f"/{lesson}/chapter.html")
          and page.evaluate("document.querySelector('main h1') !== null"),
          f"{lesson}/index.html: its chapter link does not open the chapter page")


def report_pages(browser, out):
    page = Page(browser, PAGE_WIDTH, 900)
    for lesson in LESSONS:
        what = f"{lesson}/index.html"
        page.open((out / lesson / "index.html").as_uri())
        images = page.evaluate("Array.from(document.images).map((i) => i.complete && i.naturalWidth > 0)")
        check(images and all(images), f"{what}: {images.count(False)} of {len(images)} images not shown")
        check(page.evaluate("document.querySelector('p.status').textContent") == "complete",
              f"{what}: the status is not 'complete'")
        overflow = page.evaluate("document.documentElement.scrollWidth - window.innerWidth")
        check(overflow <= 0, f"{what}: {overflow} px wider than a {PAGE_WIDTH} px window")
        check(page.evaluate("document.querySelector('section.shows p').textContent.length") > 80,
              f"{what}: no 'what this shows' at the top")
        links = page_links(page)
        docs = [href for kind, _, href in links if kind == "doc"]
        check(len(docs) == 1 and linked_file(docs[0]) == chapter_of(out, lesson) and linked_file(docs[0]).is_file(),
              f"{what}: no link to its chapter {chapter_of(out, lesson)} that opens: {docs}")
        for kind, _, href in links:
            if kind == "lab":
                check(linked_file(href).is_file(), f"{what}: its lab link {href} names no file")
        # The colour bars: every figure marked false colour has one that shows its
        # values, and every false-colour PNG on the page is so marked.
        figures = page.evaluate("""Array.from(document.querySelectorAll('figure')).map((f) => {
            const bar = f.querySelector('.colour-bar');
            return [f.querySelector('img').getAttribute('src'), f.classList.contains('false-colour'),
                    bar ? bar.getBoundingClientRect().width : 0, bar ? bar.querySelectorAll('.ticks span').length : 0,
                    bar ? bar.querySelector('.quantity').textContent : ''];
        })""")
        for src, marked, bar_width, ticks, quantity in figures:
            if src.endswith(".png") and is_false_colour((out / lesson / src).read_bytes()):
                check(marked, f"{what}: {src} is in false colour but has no colour bar")
            if marked:
                check(bar_width >= 200 and ticks >= 2 and quantity.strip(),
                      f"{what}: {src}'s colour bar is {bar_width} px wide with {ticks} values, quantity '{quantity}'")
        no_errors(page, what)
        (out / f"page_{lesson}.png").write_bytes(page.full_page_screenshot(PAGE_WIDTH))
    page.open((out / "index.html").as_uri())
    links = page_links(page)
    hrefs = [href for _, href, _ in links]
    for lesson in LESSONS:
        check(f"{lesson}/index.html" in hrefs, f"out/index.html does not link {lesson}'s page")
        check(any(kind == "doc" and linked_file(url) == chapter_of(out, lesson) and linked_file(url).is_file()
                  for kind, _, url in links), f"out/index.html does not link {lesson}'s chapter")
    for lesson in VIEWERS:
        check(f"{lesson}/viewer.html" in hrefs, f"out/index.html does not link {lesson}'s viewer")
    check(sum(kind == "lab" for kind, _, _ in links) >= 15, "out/index.html does not link every lab")
    overflow = page.evaluate("document.documentElement.scrollWidth - window.innerWidth")
    check(overflow <= 0, f"out/index.html: {overflow} px wider than a {PAGE_WIDTH} px window")
    no_errors(page, "out/index.html")
    (out / "page_index.png").write_bytes(page.full_page_screenshot(PAGE_WIDTH))


def open_viewer(browser, out, lesson):
    page = Page(browser, 1200, 1000)
    page.open((out / lesson / "viewer.html").as_uri())
    page.wait_until("document.body.dataset.ready === 'yes' || !document.getElementById('problem').hidden",
                    f"{lesson}'s viewer drawing")
    check(page.evaluate("document.getElementById('problem').hidden"),
          f"{lesson}'s viewer: " + str(page.evaluate("document.getElementById('problem').textContent")))
    return page


def move_slider(page, selector, fraction):
    x, y, w, h = page.box(selector)
    page.click(x + 8 + (w - 16) * fraction, y + h / 2)


def progressive_viewer(browser, out, update):
    page = open_viewer(browser, out, "11_progressive")
    check(page.evaluate("(() => { const s = document.getElementById('step'); return s.value === s.max; })()"),
          "11's viewer does not open on its last frame, the solution")
    check(page.evaluate("document.getElementById('play').textContent") == "replay from the start",
          "11's viewer: at the last frame, play does not offer to replay from the start")
    check("unshot energy " in page.evaluate("document.getElementById('statuses').textContent"),
          "11's viewer: the run's status does not say how much energy is left unshot")
    first = canvas_shot(page)
    move_slider(page, "#step", 0.5)
    check(int(page.evaluate("document.getElementById('step').value")) > 0, "11's viewer: the click did not move the slider")
    check(changed(first, canvas_shot(page)), "11's viewer: moving the step slider did not change the canvas")
    check("shot)" in page.evaluate("document.getElementById('view-labels').textContent"),
          "11's viewer: the label does not name the patch that shot")
    # The reference: a chosen frame, set exactly (a click lands where the slider's width says).
    page.evaluate(f"(() => {{ const s = document.getElementById('step'); s.value = {SHOT_FRAME};"
                  " s.dispatchEvent(new Event('input')); })()")
    shot = canvas_shot(page)
    if update:
        REFERENCE.write_bytes(shot)
    elif check(REFERENCE.exists(), f"no reference {REFERENCE} (run with --update)"):
        mean, far = difference(shot, REFERENCE.read_bytes())
        check(mean <= MEAN_LIMIT and far <= FAR_LIMIT,
              f"11's viewer at frame {SHOT_FRAME}: mean difference {mean:.2f} (at most {MEAN_LIMIT}), "
              f"{100 * far:.2f}% of pixels far off (at most {100 * FAR_LIMIT}%) against {REFERENCE}")
        print(f"11's viewer at frame {SHOT_FRAME} against the reference: mean difference {mean:.3f} of 255, "
              f"{100 * far:.3f}% of pixels off by more than 32")
    # The page as docs/viewer.md shows it: the pointer on the chart, its values read out.
    x, y, w, h = page.box("#curves")
    page.hover(x + w * 0.3, y + h / 2)
    check("progressive" in page.evaluate("document.getElementById('readout').textContent"),
          "11's viewer: the pointer over the chart reads no value")
    (out / "viewer_11.png").write_bytes(page.screenshot())
    x, y, w, h = page.box("#mesh")
    page.drag((x + w / 2, y + h / 2), (x + w / 2 + 120, y + h / 2 + 40))
    check(changed(shot, canvas_shot(page)), "11's viewer: dragging did not turn the camera")
    no_errors(page, "11's viewer")


def relighting_viewer(browser, out):
    page = open_viewer(browser, out, "08_radiosity_system")
    page.evaluate("document.querySelector('input[name=mode][value=lights]').click()")
    before = canvas_shot(page)
    check(page.evaluate("document.querySelectorAll('#lights input').length") == 3,
          "08's viewer: not one slider per light (the ceiling light and two lamps)")
    move_slider(page, "#light-1", 0.9)
    check(float(page.evaluate("document.getElementById('light-1').value")) > 1,
          "08's viewer: the click did not move the lamp's slider")
    check(changed(before, canvas_shot(page)), "08's viewer: turning a lamp up did not change the canvas")
    no_errors(page, "08's viewer")


def curves_viewer(browser, out, lesson, drawn):
    """A viewer of solvers side by side: `drawn` meshes, and the chart reads every
    curve's value under the pointer."""
    page = open_viewer(browser, out, lesson)
    check(page.evaluate("document.getElementById('view-labels').children.length") == drawn,
          f"{lesson}'s viewer: not {drawn} meshes side by side")
    x, y, w, h = page.box("#curves")
    page.hover(x + w / 2, y + h / 2)
    readout = page.evaluate("document.getElementById('readout').textContent")
    names = page.evaluate("GI_VIEWER_DATA.runs.map((r) => r.name)")
    check(names and all(name in readout for name in names) and "(at " in readout,
          f"{lesson}'s viewer: the pointer over the chart reads '{readout}', not every one of {names}")
    no_errors(page, f"{lesson}'s viewer")


def hierarchy_links(out):
    """Per element, how many links its leaf and the leaf's ancestors receive, read
    from lesson 13's viewer_data.js with Python's own base64 and struct."""
    text = (out / "13_hierarchical" / "viewer_data.js").read_text()
    data = json.loads(text[text.index("= ") + 2:text.rindex(";")])
    h = data["hierarchy"]

    def int32s(a):
        return struct.unpack(f"<{a['count']}i", base64.b64decode(a["base64"]))

    parent, receiver = int32s(h["nodes"]["parent"]), int32s(h["links"]["receiver"])
    per_node = [0] * len(parent)
    for r in receiver:
        per_node[r] += 1
    counts = []
    for leaf in int32s(h["element_node"]):
        count, n = 0, leaf
        while n >= 0:
            count, n = count + per_node[n], parent[n]
        counts.append(count)
    return counts


def hierarchical_viewer(browser, out):
    counts = hierarchy_links(out)
    page = open_viewer(browser, out, "13_hierarchical")
    links = "document.getElementById('links')"
    check(not page.evaluate(f"{links}.hidden"), "13's viewer: no readout of links")
    before = canvas_shot(page)
    x, y, w, h = page.box("#mesh")
    page.click(x + 0.62 * w, y + 0.3 * h)  # the back wall, above the short block
    element = int(page.evaluate(f"{links}.dataset.element"))
    if check(0 <= element < len(counts), f"13's viewer: a click on the back wall picked element {element}"):
        shown = int(page.evaluate(f"{links}.dataset.links"))
        check(shown == counts[element] > 0,
              f"13's viewer: element {element} lists {shown} links, the data file has {counts[element]}")
        check("on 'back wall'" in page.evaluate(f"{links}.textContent"),
              f"13's viewer: a click on the back wall picked element {element}, not on the back wall")
    picked = canvas_shot(page)
    check(changed(before, picked), "13's viewer: picking a leaf drew no outlines")
    (out / "viewer_13.png").write_bytes(page.screenshot())
    known = max(range(len(counts)), key=lambda e: counts[e])  # the leaf with the most links
    page.evaluate(f"GI.pickLeaf({known})")
    shown = int(page.evaluate(f"{links}.dataset.links"))
    check(shown == counts[known], f"13's viewer: element {known} lists {shown} links, the data file has {counts[known]}")
    readout = page.evaluate(f"{links}.textContent")
    off = re.search(r"differ by ([0-9.e+-]+)%", readout)
    check(off and float(off.group(1)) < 0.01,
          f"13's viewer: the links' sum does not match what the solver handed the leaf: '{readout}'")
    with_links = canvas_shot(page)
    page.evaluate("document.getElementById('outline').click()")
    check(changed(with_links, canvas_shot(page)), "13's viewer: the leaf outlines did not change the canvas")
    page.evaluate("document.getElementById('outline').click()")
    no_errors(page, "13's viewer")


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    bin_dir, work = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve()  # file:// needs absolute paths
    update = "--update" in sys.argv[3:]
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if not chromium:
        print("browser test skipped: Chromium not found (Debian: apt-get install chromium)")
        sys.exit(77)
    out = work / "browser_out"
    shutil.rmtree(out, ignore_errors=True)
    book = Path(__file__).resolve().parents[2] / "docs" / "book" / "make_book.py"
    made = subprocess.run([sys.executable, str(book), "--out", str(out)], capture_output=True, text=True)
    if made.returncode != 0:
        sys.exit(f"the book: {made.stderr.strip()}")
    print(made.stdout.strip())
    for lesson, args in LESSONS.items():
        run = subprocess.run([str(bin_dir / lesson), *args, "--out", str(out / lesson)], capture_output=True, text=True)
        if run.returncode == 3:  # a student kit: the lesson stops at an exercise still to be written
            print(f"browser test skipped: {lesson} stops at an exercise not written yet")
            sys.exit(77)
        if run.returncode != 0:
            sys.exit(f"{lesson} failed ({run.returncode}): {run.stderr.strip()}")
    with tempfile.TemporaryDirectory() as profile:
        browser = Browser(chromium, profile)
        try:
            report_pages(browser, out)
            chapter_pages(browser, out)
            progressive_viewer(browser, out, update)
            relighting_viewer(browser, out)
            curves_viewer(browser, out, "09_jacobi_gauss_seidel", 3)  # Jacobi, Gauss-Seidel, SOR
            curves_viewer(browser, out, "10_southwell", 3)  # Southwell, Jacobi, Gauss-Seidel
            curves_viewer(browser, out, "12_solver_showdown", 1)  # no replay: one final solution
            hierarchical_viewer(browser, out)
        except ProtocolError as e:
            problems.append(f"the browser: {e}")
        finally:
            browser.close()
    for p in problems:
        print(p)
    if problems:
        sys.exit(1)
    print(f"browser test: every page loaded with no console error; screenshots {out / 'viewer_11.png'}, "
          f"{out / 'viewer_13.png'}")


if __name__ == "__main__":
    main()
