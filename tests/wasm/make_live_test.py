#!/usr/bin/env python3
"""The live pages' maker (docs/live/make_live.py) on programs of its own: stand-in
lesson files, no WebAssembly build needed. A second; Python 3.9's standard library.

Checks what a course copies to its web space: each page and every script it names
is there and readable by a web server, the reference pictures go only to the
lessons that read them, the size budget is enforced, and a folder with no lesson
program gives one line and status 1.
"""
import json
import re
import stat
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

MAKE_LIVE = Path(__file__).resolve().parents[2] / "docs" / "live" / "make_live.py"


def make_live(bin_dir, out, *extra):
    return subprocess.run([sys.executable, str(MAKE_LIVE), "--bin", str(bin_dir), "--out", str(out), *extra],
                          capture_output=True, text=True)


class MakeLive(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.root = Path(self.folder.name)
        self.bin = self.root / "bin"
        self.bin.mkdir()
        # A lesson program as Emscripten writes it, in miniature: it defines gi_lesson.
        for name in ("01_rays", "14_path_tracing"):
            (self.bin / (name + ".js")).write_text("var gi_lesson = function () { return '</script>\\n'; };\n")
        (self.bin / "14_make_reference.js").write_text("// not a lesson: no NN_name page\n")

    def tearDown(self):
        self.folder.cleanup()

    def test_each_page_and_every_script_it_names(self):
        out = self.root / "out"
        done = make_live(self.bin, out)
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertEqual(sorted(p.name for p in out.iterdir()), ["01_rays", "14_path_tracing", "live"])
        for lesson in ("01_rays", "14_path_tracing"):
            page = (out / lesson / "live.html").read_text()
            for script in re.findall(r'<script src="([^"]+)"', page):
                self.assertTrue((out / lesson / script).is_file(), f"{lesson}/live.html names {script}")
            # The program is kept as the text of a string, whatever it holds.
            program = (out / lesson / "live_lesson.js").read_text()
            literal = program.split("self.giLessonSource = ", 1)[1].rstrip().rstrip(";")
            self.assertEqual(json.loads(literal), (self.bin / (lesson + ".js")).read_text())
        # Only the lessons that read the stored references load them.
        self.assertNotIn("references.js", (out / "01_rays" / "live.html").read_text())
        self.assertIn("references.js", (out / "14_path_tracing" / "live.html").read_text())
        self.assertIn("cornell_256x256.pfm", (out / "live" / "references.js").read_text())
        # The list of pages links each one.
        contents = (out / "live" / "index.html").read_text()
        self.assertIn('href="../01_rays/live.html"', contents)
        self.assertNotIn("14_make_reference", contents)
        # Readable by a web server: not the 0600 of a temporary file.
        for f in out.rglob("*"):
            if f.is_file():
                self.assertTrue(f.stat().st_mode & stat.S_IROTH, f"{f} is not readable by others")

    def test_a_page_over_the_budget_is_refused(self):
        (self.bin / "01_rays.js").write_text("var gi_lesson = 0; // " + "x" * 7_000_000 + "\n")
        done = make_live(self.bin, self.root / "out")
        self.assertEqual(done.returncode, 1)
        self.assertEqual(len(done.stderr.strip().splitlines()), 1, done.stderr)
        self.assertIn("01_rays 7.0 MB", done.stderr)

    def test_no_program_is_one_line(self):
        empty = self.root / "empty"
        empty.mkdir()
        done = make_live(empty, self.root / "out")
        self.assertEqual(done.returncode, 1)
        self.assertEqual(len(done.stderr.strip().splitlines()), 1, done.stderr)
        self.assertIn("cmake --preset wasm", done.stderr)


if __name__ == "__main__":
    unittest.main(verbosity=2)
