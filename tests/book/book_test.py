#!/usr/bin/env python3
"""The book's tool (docs/book/make_book.py) on small chapters written here: equations
pass the Markdown parser untouched and come out typeset, code keeps its dollars,
links and pictures lead to files that exist, and bad input stops with one line.
The browser test opens the real chapters' pages."""
import shutil
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

BOOK = Path(__file__).resolve().parents[2] / "docs" / "book"
sys.path.insert(0, str(BOOK))
from book_math import Equations  # noqa: E402
from chapter_html import markdown_to_html  # noqa: E402
from make_book import KATEX, missing_tool  # noqa: E402

TOOLS = missing_tool(KATEX)


def make_book(*args):
    return subprocess.run([sys.executable, str(BOOK / "make_book.py"), *map(str, args)], capture_output=True, text=True)


@unittest.skipIf(TOOLS, f"{TOOLS} is missing")
class Equations_(unittest.TestCase):
    def through_markdown(self, markdown):
        equations = Equations()
        page = equations.keep_in_code(markdown_to_html(shutil.which("cmark-gfm"), equations.protect(markdown)))
        return equations, page

    def test_underscores_and_asterisks_are_not_emphasis(self):
        equations, page = self.through_markdown("Then $a_i * b_j$ and $c_i * d_j$.\n")
        self.assertEqual([e.tex for e in equations.items], ["a_i * b_j", "c_i * d_j"])
        self.assertNotIn("<em>", page)
        typeset = Equations.put_back(page, equations.typeset(shutil.which("node"), KATEX))
        self.assertEqual(typeset.count('<span class="katex">'), 2)
        self.assertIn("<msub><mi>a</mi><mi>i</mi></msub>", typeset)

    def test_displayed_equations_and_backslashes(self):
        equations, _ = self.through_markdown("$$\\sum_i \\{x_i\\}$$\n\n```math\nB = E + \\rho F B\n```\n")
        self.assertEqual([(e.tex, e.display) for e in equations.items],
                         [("\\sum_i \\{x_i\\}", True), ("B = E + \\rho F B", True)])
        typeset = equations.typeset(shutil.which("node"), KATEX)
        self.assertTrue(all('class="katex-display"' in html for html in typeset))

    def test_dollars_that_are_not_equations(self):
        equations, page = self.through_markdown(
            "Costs \\$5 or $ 6, `$x$` is code.\n\n```sh\necho $HOME $PATH\n```\n\n    indented $y_1$ code\n")
        self.assertEqual(len(equations.items), 1)  # only the indented block's, put back as written
        self.assertIn("<code>$x$</code>", page)
        self.assertIn("echo $HOME $PATH", page)
        self.assertIn("indented $y_1$ code", page)
        self.assertIn("Costs $5 or $ 6", page)

    def test_an_equation_katex_refuses_names_its_chapter(self):
        equations = Equations()
        equations.protect("$\\frac{1$\n", "docs/99_bad.md")
        with self.assertRaisesRegex(ValueError, "docs/99_bad.md: KaTeX cannot typeset"):
            equations.typeset(shutil.which("node"), KATEX)


@unittest.skipIf(TOOLS, f"{TOOLS} is missing")
class Pages(unittest.TestCase):
    def setUp(self):
        self.folder = Path(tempfile.mkdtemp())
        self.docs, self.out = self.folder / "docs", self.folder / "out"
        (self.docs / "images").mkdir(parents=True)
        (self.docs / "viewer").mkdir()
        (self.docs / "viewer" / "report.css").write_text("body {}\n")
        (self.docs / "images" / "a.png").write_bytes(b"png")
        (self.docs / "README.md").write_text("# The course\n\n[one](01_one.md)\n")
        (self.docs / "01_one.md").write_text(
            "# 01 — One\n\n## The idea\n\nSee ![a](images/a.png), [two](02_two.md#the-idea), "
            "[lab](../exercises/lab01/README.md) and $x^2$.\n\n## The idea\n")
        (self.docs / "02_two.md").write_text("# 02 — Two\n\n## The idea\n\nHow it is built: [the architecture](architecture.md).\n")
        (self.docs / "architecture.md").write_text("# Architecture\n\nBack to [one](01_one.md#the-idea).\n")

    def tearDown(self):
        shutil.rmtree(self.folder)

    def test_a_small_picture_is_enlarged_pixel_for_pixel(self):
        def png_header(width, height):  # enough of a PNG for its size to be read
            return (b"\x89PNG\r\n\x1a\n" + (13).to_bytes(4, "big") + b"IHDR" + width.to_bytes(4, "big")
                    + height.to_bytes(4, "big"))
        (self.docs / "images" / "small.png").write_bytes(png_header(64, 64))
        (self.docs / "images" / "strip.png").write_bytes(png_header(200, 64))
        (self.docs / "images" / "large.png").write_bytes(png_header(480, 360))
        (self.docs / "03_three.md").write_text("# 03 — Three\n\n![s](images/small.png) ![t](images/strip.png) "
                                               "![l](images/large.png)\n")
        run = make_book("--docs", self.docs, "--out", self.out)
        self.assertEqual(run.returncode, 0, run.stderr)
        page = (self.out / "03_three" / "chapter.html").read_text()
        self.assertRegex(page, r'<img class="enlarged" width="320" src="[^"]*small.png"')  # 5 x 64
        self.assertRegex(page, r'<img class="enlarged" width="400" src="[^"]*strip.png"')  # 2 x 200
        self.assertRegex(page, r'<img src="[^"]*large.png"')  # already large enough

    def test_every_chapter_becomes_a_page_with_working_links(self):
        run = make_book("--docs", self.docs, "--out", self.out)
        self.assertEqual(run.returncode, 0, run.stderr)
        page = (self.out / "01_one" / "chapter.html").read_text()
        self.assertIn('src="../../docs/images/a.png"', page)
        self.assertIn('href="../02_two/chapter.html#the-idea"', page)
        self.assertIn('href="../../exercises/lab01/README.md"', page)
        self.assertIn('<h2 id="the-idea">', page)
        self.assertIn('<h2 id="the-idea-1">', page)  # GitHub's anchor for a repeated heading
        self.assertIn('class="katex"', page)
        self.assertIn('href="../01_one/chapter.html"', (self.out / "book" / "index.html").read_text())
        self.assertTrue((self.out / "book" / "katex" / "katex.min.css").is_file())
        # The guides the chapters link are pages of the book too, linked both ways.
        self.assertIn('href="../book/architecture.html"', (self.out / "02_two" / "chapter.html").read_text())
        guide = (self.out / "book" / "architecture.html").read_text()
        self.assertIn('href="../01_one/chapter.html#the-idea"', guide)
        self.assertIn('href="index.html"', guide, "a guide links the course's front page")
        self.assertEqual(list(self.out.rglob("*.tmp")), [], "no temporary file is left behind")

    def test_a_chapter_that_cannot_be_read_fails_with_one_line(self):
        run = make_book("--docs", self.docs, "--out", self.out, self.docs / "03_missing.md")
        self.assertEqual(run.returncode, 1)
        self.assertEqual(len(run.stderr.strip().splitlines()), 1, run.stderr)
        self.assertIn("cannot read the chapter", run.stderr)
        self.assertIn("03_missing.md", run.stderr)
        self.assertFalse(self.out.exists(), "nothing is written when a chapter fails")

    def test_without_katex_it_says_so_and_writes_nothing(self):
        run = make_book("--docs", self.docs, "--out", self.out, "--katex", self.folder / "no_katex")
        self.assertEqual(run.returncode, 0)
        self.assertEqual(len(run.stdout.strip().splitlines()), 1)
        self.assertIn("libjs-katex", run.stdout)
        self.assertFalse(self.out.exists())


if __name__ == "__main__":
    unittest.main()
