"""Unit tests of outputs.py (the docs' printed output) on a made-up lesson."""
import stat
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import outputs  # noqa: E402

# What the made-up lesson prints: a line with a time, a table with a time column,
# a line with a ratio of times.
PRINTED = """Cornell box, 571 elements; form factors 131 ms
Results
solver        ms  error
-----------------------
Jacobi     0.203  5.5e-01
Gauss-Seidel  12.5  3.4e-01

one step: 1.85 us; ratio 110 for n = 571
"""


def make_tree(block, marker="<!-- output: 99_fake --flag | skip: ratio -->"):
    root = Path(tempfile.mkdtemp())
    (root / "docs").mkdir()
    (root / "bin").mkdir()
    fake = root / "bin" / "99_fake"
    fake.write_text("#!/bin/sh\n[ \"$1\" = --flag ] || exit 2\ncat <<'END'\n" + PRINTED + "END\n")
    fake.chmod(fake.stat().st_mode | stat.S_IEXEC)
    (root / "docs" / "page.md").write_text("Text\n" + marker + "\n```\n" + block + "```\nMore\n")
    return root


class Outputs(unittest.TestCase):
    def check(self, root):
        return outputs.process(root, root / "bin", fix=False)

    def test_times_may_differ_and_nothing_else(self):
        same_but_times = PRINTED.replace("131 ms", "99 ms").replace("0.203", "7.000").replace(
            "1.85 us", "2.5 us").replace("ratio 110", "ratio 80")
        self.assertEqual(self.check(make_tree(same_but_times)), [])
        # A part of the output: consecutive lines, wider time column and all.
        part = "Results\nsolver           ms  error\n--------------------------\nJacobi     1000.25  5.5e-01\n"
        self.assertEqual(self.check(make_tree(part)), [])
        problems = self.check(make_tree(PRINTED.replace("5.5e-01", "5.6e-01")))
        self.assertEqual(len(problems), 1)
        self.assertIn("page.md:2: output of 99_fake --flag is stale", problems[0])
        self.assertIn("+Jacobi | * | 5.5e-01", problems[0])
        self.assertEqual(len(self.check(make_tree(PRINTED.replace("571 elements", "570 elements")))), 1)

    def test_a_near_column_compares_by_value_within_its_tolerance(self):
        near = "<!-- output: 99_fake --flag | skip: ratio | near: error 25% -->"
        # 5.5e-01 printed: 4.4e-01 is 20% below it, 4.0e-01 27%.
        self.assertEqual(self.check(make_tree(PRINTED.replace("5.5e-01", "4.4e-01"), near)), [])
        problems = self.check(make_tree(PRINTED.replace("5.5e-01", "4.0e-01"), near))
        self.assertEqual(len(problems), 1)
        self.assertIn("+Jacobi | * | ~5.5e-01", problems[0])
        # Only that column: other numbers are compared as text, as without it.
        self.assertEqual(len(self.check(make_tree(PRINTED.replace("571 elements", "570 elements"), near))), 1)
        # Without the marker's tolerance, the same 20% is a stale block.
        self.assertEqual(len(self.check(make_tree(PRINTED.replace("5.5e-01", "4.4e-01")))), 1)

    def test_fix_keeps_the_docs_times_and_adds_new_lines(self):
        old = PRINTED.replace("131 ms", "99 ms").replace("Gauss-Seidel  12.5  3.4e-01\n", "")
        root = make_tree(old.replace("5.5e-01", "5.0e-01"))
        self.assertEqual(outputs.process(root, root / "bin", fix=True), [])
        text = (root / "docs" / "page.md").read_text()
        self.assertIn("form factors 99 ms", text)  # the doc's own time is kept
        self.assertIn("Jacobi     0.203  5.5e-01", text)
        self.assertIn("Gauss-Seidel  12.5  3.4e-01", text)
        self.assertEqual(self.check(root), [])

    def test_bad_markers_and_failing_lessons_are_reported(self):
        root = make_tree(PRINTED, "<!-- output: 99_fake -->")  # without --flag the fake exits 2
        self.assertIn("exited 2", self.check(root)[0])
        root = make_tree(PRINTED, "<!-- output: 98_missing -->")
        self.assertIn("no lesson", self.check(root)[0])
        root = make_tree(PRINTED)
        (root / "docs" / "page.md").write_text("<!-- output: 99_fake -->\nnot a block\n")
        self.assertIn("must be followed by a plain ``` block", self.check(root)[0])



def quotes_tree(marker, paragraph):
    root = make_tree(PRINTED)
    (root / "docs" / "page.md").write_text("Text\n\n" + marker + "\n" + paragraph + "\n\nMore 99.\n")
    return root


class Quotes(unittest.TestCase):
    """Numbers in prose that quote a lesson: printed ones, derived ones, and the rest refused."""

    def problems(self, marker, paragraph):
        root = quotes_tree(marker, paragraph)
        return outputs.process(root, root / "bin", fix=False)

    def test_printed_numbers_pass_by_value(self):
        text = "The mesh has 571 elements; Jacobi's error is 5.5e-01, 0.55 as a number, in 131 ms of `--flag 7`."
        self.assertEqual(self.problems("<!-- quotes: 99_fake --flag -->", text), [])

    def test_a_drifted_number_is_refused(self):
        problems = self.problems("<!-- quotes: 99_fake --flag -->", "It has 570 elements\nand 5.5e-01 error.")
        self.assertEqual(len(problems), 1)
        self.assertIn("page.md:3: prose quoting 99_fake --flag: 570 is not a number the lesson prints", problems[0])

    def test_derived_numbers_must_round_to_the_prose(self):
        marker = "<!-- quotes: 99_fake --flag | derived: 62% = 100 * 3.4e-01 / 5.5e-01; 1.04× = 3.4e-01 + 0.7 -->"
        problems = self.problems(marker, "Gauss-Seidel's error is 62% of Jacobi's, and 1.04×.")
        self.assertEqual(len(problems), 1)  # 0.7 is not printed; 62 is right
        self.assertIn("derived 1.04 = 3.4e-01 + 0.7: 0.7 not among the printed numbers", problems[0])
        wrong = self.problems("<!-- quotes: 99_fake --flag | derived: 60% = 100 * 3.4e-01 / 5.5e-01 -->", "It is 60%.")
        self.assertIn("gives 61.8", wrong[0])

    def test_not_quotes_and_references_are_left_alone(self):
        text = "Lesson 12 and lab 3 (exercise 2.5) cite Whitted 1980; 571 elements."
        self.assertEqual(self.problems("<!-- quotes: 99_fake --flag | not: 1980 -->", text), [])
        self.assertEqual(len(self.problems("<!-- quotes: 99_fake --flag -->", text)), 1)

    def test_a_marker_needs_its_paragraph(self):
        problems = self.problems("<!-- quotes: 99_fake --flag -->", "")
        self.assertIn("must be followed by its paragraph", problems[0])


if __name__ == "__main__":
    unittest.main()
