#!/usr/bin/env python3
"""The lessons' live pages: each lesson, built as WebAssembly, runs in a page.

    docs/live/make_live.py --bin build/wasm/bin --source-dir . [--out out]

For each lesson program BIN/NN_name.js (the wasm preset), writes beside the lesson's
report page and chapter:
  OUT/NN_name/live.html        the page: a form from the lesson's options, Run and
                               Stop, a progress bar, the outputs as they are written
  OUT/NN_name/live_lesson.js   the program, as the text a Web Worker is made from
and, shared by them all:
  OUT/live/live.js, live_worker.js   the page's script and the worker's (docs/live/)
  OUT/live/references.js       the stored reference pictures (lessons/references/)
                               for the lessons that read them, written into the
                               worker's file system where the program looks
  OUT/live/index.html          the list of live lessons, with their chapters
Every page works from file:// and from any static web server: nothing is fetched, each
script is loaded by a <script> tag. A page loads its program (about 1.5 MB), and the
lessons that read the references 2.6 MB more; make_live.py fails if a page would load
more than BUDGET_MB. Python 3.9 and its standard library only.
"""
import argparse
import base64
import html
import json
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "book"))
from make_book import write_whole  # noqa: E402  a page is written whole or not at all
# The lessons that read lessons/references/ (GI_SOURCE_DIR/lessons/references/...).
READS_REFERENCES = {"12_solver_showdown", "13_hierarchical", "14_path_tracing", "15_radiosity_vs_path_tracing",
                    "16_two_pass"}
# The most a page may load, all scripts together: a lecture hall's network, or a
# student's phone, opens it in a few seconds.
BUDGET_MB = 6.0


def title_of(lesson, source_dir=HERE.parent.parent):
    """'09_jacobi_gauss_seidel' -> 'Lesson 9: Jacobi and Gauss-Seidel', from the heading of
    its chapter (docs/09_jacobi_gauss_seidel.md: "# 09 — Jacobi and Gauss-Seidel"), or
    from the name where there is no chapter."""
    number, _, words = lesson.partition("_")
    chapter = source_dir / "docs" / (lesson + ".md")
    if chapter.is_file():
        heading = chapter.read_text(encoding="utf-8").partition("\n")[0]
        if heading.startswith("# ") and "—" in heading:
            words = heading.partition("—")[2].strip()
    return f"Lesson {int(number)}: {words.replace('_', ' ')}"


def page(lesson, references):
    css = (HERE.parent / "viewer" / "report.css").read_text() + (HERE / "live.css").read_text()
    data = '<script src="../live/references.js"></script>\n' if references else ""
    config = json.dumps({"lesson": lesson})
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{html.escape(title_of(lesson))}, live</title>
<style>
{css}</style>
</head>
<body>
<nav><a href="../live/index.html">every live lesson</a> · <a href="index.html">this lesson's last report</a>
 · <a href="chapter.html">the chapter</a></nav>
<h1>{html.escape(title_of(lesson))}</h1>
<p class="summary" id="summary"></p>
<p>The lesson's own program, compiled to WebAssembly, runs here in your browser, on one
thread, with nothing installed. Change a setting and press Run: the program checks the
settings as it checks a terminal's, then prints and writes what the native program
would, in the same bytes.</p>
<form id="form" novalidate>
<div class="fields" id="fields"></div>
<div class="controls">
<button type="submit" id="run" disabled>Run</button>
<button type="button" id="stop" disabled>Stop</button>
<button type="button" id="defaults" disabled>Defaults</button>
<progress id="progress" max="100" value="0"></progress>
<span id="progress-label"></span>
</div>
<p>The same run on a terminal: <code id="command"></code></p>
<p id="status"></p>
<p class="links" id="pages"></p>
</form>
<h2>What it printed</h2>
<pre id="log"></pre>
<h2>What it wrote</h2>
<div id="outputs"></div>
<div id="tables"></div>
<details><summary>Every other file it wrote (linear radiance as PFM, outputs.json, its report page)</summary>
<ul id="files"></ul>
</details>
<script>const GI_LIVE = {config};</script>
{data}<script src="live_lesson.js"></script>
<script src="../live/live_worker.js"></script>
<script src="../live/live.js"></script>
</body>
</html>
"""


def contents(lessons):
    css = (HERE.parent / "viewer" / "report.css").read_text()
    rows = "\n".join(
        f'<tr><td><a href="../{l}/live.html">{html.escape(title_of(l))}</a></td>'
        f'<td><a href="../{l}/chapter.html">chapter</a></td><td><a href="../{l}/index.html">last report</a></td></tr>'
        for l in lessons)
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>The lessons, live</title>
<style>
{css}</style>
</head>
<body>
<nav><a href="../index.html">the lessons' reports</a> · <a href="../book/index.html">the course book</a></nav>
<h1>The lessons, live</h1>
<p>Each lesson's program runs in its page, compiled to WebAssembly: set its options,
press Run, and watch its pictures and tables arrive.</p>
<table class="contents"><tbody>
{rows}
</tbody></table>
</body>
</html>
"""


def references_script(source_dir):
    folder = (source_dir / "lessons" / "references").resolve()
    files = [{"path": str(folder / f.name), "base64": base64.b64encode(f.read_bytes()).decode()}
             for f in sorted(folder.iterdir()) if f.is_file()]
    return "// The stored reference pictures, for the worker's file system (make_live.py).\n" \
           "self.giLiveFiles = " + json.dumps(files) + ";\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin", type=Path, required=True, help="the wasm build's programs (build/wasm/bin)")
    parser.add_argument("--source-dir", type=Path, default=HERE.parent.parent,
                        help="the source tree the programs were built from (its lessons/references)")
    parser.add_argument("--out", type=Path, default=HERE.parent.parent / "out", help="where the lessons' pages are")
    parser.add_argument("lessons", nargs="*", help="lessons to make (default: every BIN/NN_name.js)")
    args = parser.parse_args()

    # A lesson is a folder lessons/NN_name/ with its main.cpp; other programs (the
    # benchmarks, 14_make_reference) have no page.
    programs = sorted(p for p in args.bin.glob("[0-9][0-9]_*.js")
                      if (args.source_dir / "lessons" / p.stem / "main.cpp").is_file())
    lessons = [p.stem for p in programs if not args.lessons or p.stem in args.lessons]
    if not lessons:
        print(f"make_live.py: no lesson programs (NN_name.js) in {args.bin}: build them with "
              "'cmake --preset wasm && cmake --build --preset wasm'", file=sys.stderr)
        return 1
    shared = args.out / "live"
    references = references_script(args.source_dir)
    write_whole(shared / "references.js", references)
    for name in ("live.js", "live_worker.js"):
        write_whole(shared / name, (HERE / name).read_bytes())
    scripts = sum(len((HERE / n).read_bytes()) for n in ("live.js", "live_worker.js"))
    over = []
    for lesson in lessons:
        source = (args.bin / (lesson + ".js")).read_text()
        program = "// " + lesson + ", compiled to WebAssembly (make_live.py): the text of a Web Worker.\n" \
                  "self.giLessonSource = " + json.dumps(source) + ";\n"
        write_whole(args.out / lesson / "live_lesson.js", program)
        reads = lesson in READS_REFERENCES
        write_whole(args.out / lesson / "live.html", page(lesson, reads))
        loads = (len(program) + scripts + (len(references) if reads else 0)) / 1e6
        if loads > BUDGET_MB:
            over.append(f"{lesson} {loads:.1f} MB")
    write_whole(shared / "index.html", contents(lessons))
    if over:
        print(f"make_live.py: pages over the budget of {BUDGET_MB} MB: " + ", ".join(over), file=sys.stderr)
        return 1
    pages = "1 live page" if len(lessons) == 1 else f"{len(lessons)} live pages"
    print(f"make_live.py: {pages} in {args.out} (open {shared / 'index.html'})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
