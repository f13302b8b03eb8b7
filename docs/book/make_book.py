#!/usr/bin/env python3
"""The course book: each chapter, docs/NN_topic.md, as a page a browser opens from
file:// with no network, OUT/NN_topic/chapter.html beside the lesson's own page;
docs/README.md as the book's front page, OUT/book/index.html; and the guides the
chapters link (docs/architecture.md, viewer.md, scene_files.md, engineering.md) as
OUT/book/GUIDE.html.

    make_book.py [--docs DIR] [--out DIR] [--katex DIR] [CHAPTER.md ...]

The Markdown stays the source, readable on GitHub. cmark-gfm reads it (GitHub's
dialect, so a page shows what GitHub shows) and KaTeX typesets its equations once,
here, under node: a page needs only KaTeX's style sheet and fonts, which are copied
into OUT/book/ with the pages' own style sheets. Pictures and labs are reached by
relative paths into the tree, as the lessons' pages reach the chapters.

Naming chapters makes only those (and the front page); the default is every chapter.
Exit status 0 when the pages are written, or when a tool is missing: then one line
says so, nothing is written, and the lessons' pages keep linking the Markdown.
Exit status 1, with one line, when a chapter cannot be read or made. Each file is
written whole or not at all (a temporary file, then a rename).
"""
import argparse
import os
import shutil
import sys
import tempfile
from pathlib import Path

from book_math import Equations
from chapter_html import anchor_headings, colour_code, enlarge_small_pictures, markdown_to_html, page_html, point_links

HERE = Path(__file__).resolve().parent
KATEX = Path("/usr/share/javascript/katex")  # Debian's libjs-katex
GUIDES = ("architecture", "viewer", "scene_files", "engineering")  # docs/GUIDE.md, where it exists


def missing_tool(katex):
    """What is missing to make the pages, as the line to print; None when nothing is."""
    if not shutil.which("cmark-gfm"):
        return "cmark-gfm (Debian: apt-get install cmark-gfm)"
    if not (shutil.which("node") or shutil.which("nodejs")):
        return "node, which runs KaTeX (Debian: apt-get install nodejs)"
    if not (katex / "katex.js").is_file() or not (katex / "fonts").is_dir():
        return f"KaTeX in {katex} (Debian: apt-get install libjs-katex)"
    return None


def write_whole(path, data):
    """Writes a file whole or not at all: a reader never finds half a page."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, temporary = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data.encode() if isinstance(data, str) else data)
        os.chmod(temporary, 0o644)  # mkstemp's 0600 would hide the page from a web server
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise


def copy_assets(docs, katex, shared):
    """The pages' style sheets, and KaTeX's with its fonts (WOFF2, which every browser
    of the last decade reads; the other formats would triple the size)."""
    write_whole(shared / "report.css", (docs / "viewer" / "report.css").read_bytes())
    write_whole(shared / "book.css", (HERE / "book.css").read_bytes())
    write_whole(shared / "katex" / "katex.min.css", (katex / "katex.min.css").read_bytes())
    for font in sorted((katex / "fonts").glob("*.woff2")):
        write_whole(shared / "katex" / "fonts" / font.name, font.read_bytes())


def navigation(source, chapters, out, page_dir, shared):
    """The links above a page's contents: for a chapter the front page, the lesson's
    own page, and the chapters before and after; for a guide the front page and the
    lessons; for the front page the lessons."""
    def link(target, text, kind):
        return f'<a class="{kind}" href="{Path(os.path.relpath(target, page_dir)).as_posix()}">{text}</a>'
    lessons = link(out / "index.html", "every lesson, as run here", "lessons")
    if source.name == "README.md":  # the front page
        return f"<p>{lessons}</p>"
    if source not in chapters:  # a guide
        return f'<p>{link(shared / "index.html", "the course", "front")} &middot; {lessons}</p>'
    k = chapters.index(source)
    home = [link(shared / "index.html", "the course", "front"),
            link(page_dir / "index.html", f"lesson {source.stem[:2]}'s page", "lesson")]
    turn = []
    if k > 0:
        turn.append(link(out / chapters[k - 1].stem / "chapter.html", f"&larr; {chapters[k - 1].stem[:2]}", "previous"))
    if k + 1 < len(chapters):
        turn.append(link(out / chapters[k + 1].stem / "chapter.html", f"{chapters[k + 1].stem[:2]} &rarr;", "next"))
    return "".join(f"<p>{' &middot; '.join(line)}</p>" for line in (home, turn) if line)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--docs", type=Path, default=HERE.parent, help="the chapters' folder (default: docs/)")
    parser.add_argument("--out", type=Path, default=HERE.parent.parent / "out", help="where the lessons write")
    parser.add_argument("--katex", type=Path, default=KATEX, help=f"KaTeX's folder (default: {KATEX})")
    parser.add_argument("chapters", nargs="*", type=Path, help="chapters to make (default: every docs/NN_*.md)")
    args = parser.parse_args()
    docs, out = args.docs.resolve(), args.out.resolve()
    shared = out / "book"

    lacking = missing_tool(args.katex)
    if lacking:
        print(f"book: chapter pages not made, {lacking} is missing; the lessons' pages link the Markdown")
        return 0

    chapters = sorted(docs.glob("[0-9][0-9]_*.md")) if not args.chapters else [c.resolve() for c in args.chapters]
    front = docs / "README.md"
    page_of = {c: out / c.stem / "chapter.html" for c in chapters}
    page_of[front] = shared / "index.html"
    page_of.update({docs / f"{g}.md": shared / f"{g}.html" for g in GUIDES if (docs / f"{g}.md").is_file()})
    cmark = shutil.which("cmark-gfm")
    node = shutil.which("node") or shutil.which("nodejs")

    equations, pages = Equations(), {}
    for source, page in page_of.items():
        try:
            markdown = source.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as e:
            sys.exit(f"book: cannot read the chapter {source}: {getattr(e, 'strerror', None) or e}")
        try:
            body = equations.keep_in_code(markdown_to_html(cmark, equations.protect(markdown, str(source))))
            body, title, contents = anchor_headings(colour_code(body), equations.plain)
            body = point_links(enlarge_small_pictures(body, source), source, page.parent, page_of)
        except ValueError as e:
            sys.exit(f"book: {source}: {e}")
        nav = navigation(source, chapters, out, page.parent, shared)
        assets = Path(os.path.relpath(shared, page.parent)).as_posix()
        pages[page] = page_html(title or source.stem, body, contents, nav, assets)
    try:
        typeset = equations.typeset(node, args.katex)
    except ValueError as e:
        sys.exit(f"book: {e}")

    copy_assets(docs, args.katex, shared)
    for page, text in pages.items():
        write_whole(page, Equations.put_back(text, typeset))
    guides = len(page_of) - len(chapters) - 1
    print(f"book: {len(chapters)} chapter pages (out/NN_topic/chapter.html), {guides} guides and the front page "
          f"{shared / 'index.html'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
