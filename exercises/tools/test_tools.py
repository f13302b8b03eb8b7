"""Unit tests of the exercise tools on small made-up trees (ctest: exercise_tools)."""
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import excerpts  # noqa: E402
import grade     # noqa: E402
import regions   # noqa: E402

SOURCE = """#include "gi/core/not_implemented.hpp"
double twice(double x) {
  // BEGIN EXERCISE 3.1 doubling
  const double y = x + x;
  return y;
  // END EXERCISE 3.1
}
"""


class Regions(unittest.TestCase):
    def test_finds_region_and_stubs_it(self):
        found = regions.regions_in(SOURCE, "a.cpp")
        self.assertEqual([(r.id, r.title, r.begin, r.end) for r in found], [("3.1", "doubling", 2, 5)])
        stubbed = regions.stub_text(SOURCE, found)
        self.assertIn('  throw gi::NotImplemented("exercise 3.1 doubling");\n', stubbed)
        self.assertNotIn("x + x", stubbed)
        self.assertIn("// END EXERCISE 3.1", stubbed)

    def test_malformed_markers_name_the_line(self):
        with self.assertRaisesRegex(regions.RegionError, r"a.cpp:3: exercise 3.1 has no END"):
            regions.regions_in(SOURCE.replace("  // END EXERCISE 3.1\n", ""), "a.cpp")
        with self.assertRaisesRegex(regions.RegionError, r"a.cpp:6: END EXERCISE 3.2 closes exercise 3.1"):
            regions.regions_in(SOURCE.replace("END EXERCISE 3.1", "END EXERCISE 3.2"), "a.cpp")
        with self.assertRaisesRegex(regions.RegionError, "not_implemented.hpp"):
            regions.regions_in(SOURCE.replace('#include "gi/core/not_implemented.hpp"', ""), "a.cpp")

    def test_lab_lists(self):
        self.assertEqual(regions.parse_labs("all", {1, 2}), {1, 2})
        self.assertEqual(regions.parse_labs("2", {1, 2}), {2})
        with self.assertRaisesRegex(regions.RegionError, "no lab 7"):
            regions.parse_labs("1,7", {1, 2})
        with self.assertRaises(regions.RegionError):
            regions.parse_labs("one", {1, 2})


class Excerpts(unittest.TestCase):
    def make_tree(self, code_in_doc):
        root = Path(tempfile.mkdtemp())
        (root / "lib").mkdir()
        (root / "docs").mkdir()
        (root / "lib" / "a.cpp").write_text(SOURCE)
        (root / "docs" / "page.md").write_text(
            "Text\n<!-- excerpt: lib/a.cpp | double twice( -->\n```cpp\n" + code_in_doc + "```\nMore\n")
        return root

    def test_matching_excerpt_passes_and_stale_one_is_reported_and_fixed(self):
        fresh = "".join(SOURCE.splitlines(keepends=True)[1:])
        self.assertEqual(excerpts.process(self.make_tree(fresh), fix=False), [])
        root = self.make_tree("double twice(double x) { return 2 * x; }\n")
        problems = excerpts.process(root, fix=False)
        self.assertEqual(len(problems), 1)
        self.assertIn("page.md:2: excerpt of lib/a.cpp is stale", problems[0])
        excerpts.process(root, fix=True)
        self.assertEqual(excerpts.process(root, fix=False), [])

    def test_missing_prefix_is_reported(self):
        root = self.make_tree("x\n")
        (root / "docs" / "page.md").write_text("<!-- excerpt: lib/a.cpp | int nothing( -->\n```cpp\n```\n")
        self.assertIn("no line starts with", excerpts.process(root, fix=False)[0])


class Grader(unittest.TestCase):
    def test_lists_tests_from_gtest_output(self):
        listing = "Ex1_1_RaySphere.\n  NearRoot\n  FarRoot\nEx1_2_Plane.\n  Parallel  # GetParam() = 1\n"
        self.assertEqual(grade.list_tests(listing),
                         ["Ex1_1_RaySphere.NearRoot", "Ex1_1_RaySphere.FarRoot", "Ex1_2_Plane.Parallel"])

    def test_failure_text_is_what_the_test_printed(self):
        output = ("[ RUN      ] S.T\nfile.cpp:10: Failure\nexpected 4, got 6\nreturn the nearer root\n"
                  "[  FAILED  ] S.T (0 ms)\n[  FAILED  ] 1 test, listed below:\n")
        self.assertEqual(grade.failure_text(output, "S.T"),
                         "file.cpp:10: Failure\nexpected 4, got 6\nreturn the nearer root")

    def test_gradescope_json_shape(self):
        results = [grade.Result(1, "1.1", "Ex1_1_A.B", True, "passed"), grade.Result(1, "1.1", "Ex1_1_A.C", False, "no")]
        data = grade.gradescope(results, "summary")
        self.assertEqual(data["score"], 1)
        self.assertEqual([t["max_score"] for t in data["tests"]], [1, 1])
        self.assertEqual({t["visibility"] for t in data["tests"]}, {"visible"})


if __name__ == "__main__":
    unittest.main()
