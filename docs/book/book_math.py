"""Equations through the Markdown parser untouched.

A Markdown parser reads `a_i * b_j` as emphasis and `\\{` as an escaped brace, so an
equation is swapped for a plain token (letters and digits, which no Markdown rule
changes) before parsing, and the typeset equation takes the token's place after.
The delimiters are GitHub's, so a chapter reads the same there: $inline$, $$display$$
and a fenced ```math block. A dollar sign is literal when escaped (\\$), inside code,
when followed by a space (an amount: "$ 5") or when no closing one follows.
"""
import html
import json
import re
import subprocess
from dataclasses import dataclass
from pathlib import Path

TOKEN = re.compile(r"GIMATH(\d{5})X")


@dataclass
class Equation:
    tex: str
    display: bool
    source: str  # as written in the chapter, delimiters included
    chapter: str


class Equations:
    """The equations taken out of one or more chapters, numbered by their tokens."""

    def __init__(self):
        self.items: list[Equation] = []
        self.chapter = ""

    def token(self, tex, display, source):
        self.items.append(Equation(tex, display, source, self.chapter))
        return f"GIMATH{len(self.items) - 1:05d}X"

    def protect(self, markdown, chapter=""):
        """The chapter with every equation replaced by its token; `chapter` names it
        in an error."""
        self.chapter = chapter
        out, fence = [], None
        prose = []
        for line in markdown.splitlines(keepends=True):
            opening = re.match(r" {0,3}(`{3,}|~{3,})\s*(\w*)", line)
            if fence is None and opening:
                out.append(self._inline("".join(prose)))
                prose = []
                fence = (opening.group(1), opening.group(2) == "math", [line])
            elif fence is not None:
                marker, is_math, lines = fence
                if line.strip().startswith(marker[0] * len(marker)) and line.strip().strip(marker[0]) == "":
                    if is_math:  # GitHub's ```math block: one displayed equation
                        body = "".join(lines[1:])
                        source = "".join(lines) + line
                        out.append("\n" + self.token(body.strip(), True, source) + "\n\n")
                    else:
                        out.append("".join(lines) + line)
                    fence = None
                else:
                    lines.append(line)
            else:
                prose.append(line)
        if fence is not None:  # a fence never closed runs to the end, as in CommonMark
            out.append("".join(fence[2]))
        out.append(self._inline("".join(prose)))
        return "".join(out)

    def _inline(self, text):
        out, i, n = [], 0, len(text)
        while i < n:
            c = text[i]
            if c == "\\" and i + 1 < n:  # an escaped character, \$ included, stays as written
                out.append(text[i:i + 2])
                i += 2
            elif c == "`":  # a code span: copied to its closing run of as many backticks
                run = len(text[i:]) - len(text[i:].lstrip("`"))
                end = text.find("`" * run, i + run)
                while end != -1 and text[end + run:end + run + 1] == "`":
                    end = text.find("`" * run, end + run + 1)
                stop = i + run if end == -1 else end + run
                out.append(text[i:stop])
                i = stop
            elif text.startswith("$$", i):
                end = text.find("$$", i + 2)
                if end == -1 or "\n\n" in text[i:end]:
                    out.append("$$")
                    i += 2
                    continue
                out.append(self.token(text[i + 2:end].strip(), True, text[i:end + 2]))
                i = end + 2
            elif c == "$":
                end = self._inline_end(text, i)
                if end is None:
                    out.append(c)
                    i += 1
                    continue
                out.append(self.token(text[i + 1:end], False, text[i:end + 1]))
                i = end + 1
            else:
                out.append(c)
                i += 1
        return "".join(out)

    @staticmethod
    def _inline_end(text, start):
        """Where $...$ opened at `start` closes: not after a space or a backslash, not
        before a digit, and within its paragraph; None when it does not."""
        if start + 1 >= len(text) or text[start + 1].isspace():
            return None
        j = start + 1
        while True:
            j = text.find("$", j)
            if j == -1 or "\n\n" in text[start:j]:
                return None
            if not text[j - 1].isspace() and text[j - 1] != "\\" and not text[j + 1:j + 2].isdigit():
                return j
            j += 1

    def keep_in_code(self, page):
        """Tokens that landed inside code (an indented block) go back to their source."""
        def restore(match):
            return TOKEN.sub(lambda t: html.escape(self.items[int(t.group(1))].source, quote=False), match.group(0))
        return re.sub(r"<code[^>]*>.*?</code>", restore, page, flags=re.S)

    def plain(self, text):
        """Tokens replaced by their TeX source: for a heading's anchor and contents line."""
        return TOKEN.sub(lambda t: self.items[int(t.group(1))].tex, text)

    def typeset(self, node, katex_dir):
        """Every equation's HTML, KaTeX's, from one run of node; raises ValueError
        naming the first equation KaTeX refuses."""
        if not self.items:
            return []
        script = Path(__file__).with_name("render_katex.js")
        request = json.dumps([{"tex": e.tex, "display": e.display} for e in self.items])
        run = subprocess.run([node, str(script), str(katex_dir)], input=request, capture_output=True, text=True)
        if run.returncode != 0:
            last = (run.stderr.strip().splitlines() or ["no message"])[-1]
            raise ValueError(f"KaTeX did not run under {node}: {last}")
        results = json.loads(run.stdout)
        for equation, result in zip(self.items, results):
            if "error" in result:
                raise ValueError(f"{equation.chapter}: KaTeX cannot typeset {equation.source.strip()!r}: "
                                 f"{result['error']}")
        return [r["html"] for r in results]

    @staticmethod
    def put_back(page, typeset):
        return TOKEN.sub(lambda t: typeset[int(t.group(1))], page)
