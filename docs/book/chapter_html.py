"""One chapter's Markdown as the body of its page: cmark-gfm's HTML, with anchors on
the headings (GitHub's, so links written for GitHub land), a contents list made from
them, links and pictures pointed at files that exist beside the pages, and code
excerpts coloured where Pygments is installed."""
import html
import os
import re
import subprocess
from pathlib import Path
from urllib.parse import quote, unquote, urlsplit

try:  # colours for the code excerpts; the pages read the same without them
    from pygments import highlight
    from pygments.formatters import HtmlFormatter
    from pygments.lexers import get_lexer_by_name
    from pygments.util import ClassNotFound
except ImportError:
    highlight = None


def markdown_to_html(cmark, markdown):
    """GitHub's dialect: tables, ~~strikethrough~~ and bare web addresses as links.
    Raw HTML is left out (cmark-gfm's safe default): the chapters hold none."""
    run = subprocess.run([cmark, "--to", "html", "-e", "table", "-e", "strikethrough", "-e", "autolink"],
                         input=markdown, capture_output=True, text=True)
    if run.returncode != 0:
        raise ValueError(f"cmark-gfm failed: {run.stderr.strip()}")
    return run.stdout


def text_of(fragment):
    return html.unescape(re.sub(r"<[^>]+>", "", fragment))


def slug(text):
    """GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens."""
    return re.sub(r"[^\w\- ]", "", text.strip().lower()).replace(" ", "-")


def anchor_headings(page, plain):
    """Gives every heading its id; returns the page, its title (the h1) and the
    contents: (level, id, text) for each h2 and h3. `plain` turns equation tokens back
    into their TeX for the anchor."""
    seen, contents, title = {}, [], []

    def anchor(match):
        level, inner = int(match.group(1)), match.group(2)
        text = text_of(plain(inner))
        base = slug(text)
        count = seen.get(base, 0)
        seen[base] = count + 1
        ident = base if count == 0 else f"{base}-{count}"
        if level == 1 and not title:
            title.append(text)
        elif level in (2, 3):
            contents.append((level, ident, inner))
        return f'<h{level} id="{html.escape(ident)}">{inner}</h{level}>'

    page = re.sub(r"<h([1-6])>(.*?)</h\1>", anchor, page, flags=re.S)
    return page, (title[0] if title else ""), contents


def point_links(page, source, page_dir, pages):
    """Relative links and pictures, written from the chapter's folder (docs/), made to
    work from the page's folder: a chapter or the front page becomes its page, any
    other file of the tree (a lab, a picture) is reached by a relative path to it."""
    def repoint(match):
        attribute, url = match.group(1), html.unescape(match.group(2))
        parts = urlsplit(url)
        if parts.scheme or parts.netloc or url.startswith(("#", "/")) or not parts.path:
            return match.group(0)
        target = os.path.normpath(source.parent / unquote(parts.path))
        new = pages.get(Path(target))
        path = os.path.relpath(new if new else target, page_dir)
        link = quote(Path(path).as_posix()) + (f"#{parts.fragment}" if parts.fragment else "")
        return f'{attribute}="{html.escape(link)}"'
    return re.sub(r'\b(href|src)="([^"]*)"', repoint, page)


def png_width(path):
    """A PNG's width from its header (IHDR, bytes 16-19), or None for anything else."""
    try:
        with open(path, "rb") as f:
            head = f.read(24)
    except OSError:
        return None
    if head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        return None
    return int.from_bytes(head[16:20], "big")


def shown_width(width):
    """The width a picture is shown at: a whole multiple of its own, at least 320 pixels
    where that fits in 1100, as the lessons' report pages show them (report_page.cpp)."""
    return width * max(1, min(1100 // width, -(-320 // width)))


def enlarge_small_pictures(page, source):
    """A small picture (a 64 x 64 error map) is enlarged pixel for pixel, not left a
    thumbnail: its <img> gets the width the report page would give it. `src` is still
    relative to the chapter's folder."""
    def enlarge(match):
        tag, url = match.group(0), html.unescape(match.group(1))
        if urlsplit(url).scheme or not url.lower().endswith(".png"):
            return tag
        width = png_width(source.parent / unquote(url))
        if not width or shown_width(width) == width:
            return tag
        return tag.replace("<img ", f'<img class="enlarged" width="{shown_width(width)}" ', 1)
    return re.sub(r'<img [^>]*?src="([^"]*)"[^>]*>', enlarge, page)


def colour_code(page):
    """Code excerpts fenced with a language (```cpp) coloured by Pygments."""
    if highlight is None:
        return page

    def colour(match):
        language, code = match.group(1), html.unescape(match.group(2))
        try:
            lexer = get_lexer_by_name(language)
        except ClassNotFound:
            return match.group(0)
        body = highlight(code, lexer, HtmlFormatter(nowrap=True))
        return f'<pre class="highlight"><code class="language-{language}">{body}</code></pre>'
    return re.sub(r'<pre><code class="language-([\w+-]+)">(.*?)</code></pre>', colour, page, flags=re.S)


def contents_html(contents):
    items = "".join(f'<li class="level{level}"><a href="#{html.escape(ident)}">{inner}</a></li>\n'
                    for level, ident, inner in contents)
    return f'<ol class="toc">\n{items}</ol>\n' if items else ""


def page_html(title, body, contents, nav, assets):
    """The whole page. `nav` is the links above the contents; `assets` the relative
    path to the shared folder (style sheets and KaTeX)."""
    return f"""<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{html.escape(title)}</title>
<link rel="stylesheet" href="{assets}/report.css">
<link rel="stylesheet" href="{assets}/katex/katex.min.css">
<link rel="stylesheet" href="{assets}/book.css">
</head>
<body class="book">
<nav class="sidebar">
{nav}
{contents_html(contents)}</nav>
<main>
{body}</main>
</body>
</html>
"""
