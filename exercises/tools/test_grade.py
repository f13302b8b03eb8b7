"""The grader against test programs that misbehave on purpose (ctest: exercise_tools).

Each fake test program is a small Python script that answers gtest's command line
the way a real one does -- --gtest_list_tests and --gtest_output=json, the
premature-exit file -- and then does what a student's code can make a test program
do: fail, crash, hang, exit in the middle, print a fake pass line, print bytes that
are not UTF-8, leave a child process behind.
"""
import json
import os
import subprocess
import sys
import tempfile
import time
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import grade      # noqa: E402
import gtest_run  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]

FAKE = r'''#!/usr/bin/env python3
import json, os, signal, subprocess, sys, time
TESTS = %(tests)r
LISTING = %(listing)r
args = sys.argv[1:]
report = next((a[len("--gtest_output=json:"):] for a in args if a.startswith("--gtest_output=json:")), None)
def suites(names):
    by = {}
    for n in names:
        s, t = n.split(".")
        by.setdefault(s, []).append(t)
    return by
if "--gtest_list_tests" in args:
    if LISTING == "hang":
        time.sleep(600)
    if LISTING == "crash":
        os.kill(os.getpid(), signal.SIGSEGV)
    json.dump({"testsuites": [{"name": s, "testsuite": [{"name": t} for t in ts]}
                              for s, ts in suites(TESTS).items()]}, open(report, "w"))
    sys.exit(0)
wanted = next(a[len("--gtest_filter="):] for a in args if a.startswith("--gtest_filter=")).split(":")
premature = os.environ.get("TEST_PREMATURE_EXIT_FILE")
if premature:
    open(premature, "w").close()
results = {}
for name in wanted:
    what = TESTS[name]
    print("[ RUN      ] " + name, flush=True)
    if what == "hang":
        time.sleep(600)
    elif what == "crash":
        os.kill(os.getpid(), signal.SIGSEGV)
    elif what == "exit":
        sys.exit(0)
    elif what == "fake-pass":
        print("[  PASSED  ] 1 test.", flush=True)
        sys.exit(0)
    elif what == "flood":
        signal.signal(signal.SIGXFSZ, signal.SIG_DFL)  # as in a C++ program (Python ignores it)
        while True:
            sys.stdout.write("x" * 65536)
    elif what == "child":
        subprocess.Popen(["sleep", "600"])
        results[name] = []
    elif what == "bytes":
        sys.stdout.flush()
        os.write(1, b"\xff\xfe\x80 not utf-8\n")
        results[name] = ["t.cpp:1\nFailed\nbad bytes above"]
    elif what.startswith("fail:"):
        results[name] = [what[5:]]
    else:
        results[name] = []
doc = {"testsuites": [{"name": s, "testsuite": [
    {"name": t, "status": "RUN", "result": "COMPLETED",
     **({"failures": [{"failure": f, "type": ""} for f in results[s + "." + t]]} if results[s + "." + t] else {})}
    for t in ts]} for s, ts in suites([n for n in wanted if n in results]).items()]}
json.dump(doc, open(report, "w"))
if premature:
    os.remove(premature)
sys.exit(1 if any(results.values()) else 0)
'''

NEAR = ("lab.cpp:12\nThe difference between hit->t and 4.0 is 2, which exceeds 1e-9, where\nhit->t evaluates to 6,\n"
        "4.0 evaluates to 4, and\n1e-9 evaluates to 1.0000000000000001e-09.\n"
        "t = 6 is the far side of the sphere: return the smaller root first")


def fake_program(folder, tests, listing="ok"):
    path = Path(folder) / "lab99_graded"
    path.write_text(FAKE % {"tests": tests, "listing": listing})
    path.chmod(0o755)
    return path


def results_of(binary, tests, limit=1.5):
    results, problem = grade.grade_lab(binary, 99, [(n, False) for n in tests], limit, {})
    return {r.name: r for r in results}, problem


class FakePrograms(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.folder = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def test_passes_and_failures_come_from_the_report_with_the_tests_own_hint(self):
        tests = {"Ex99_1_A.Good": "pass", "Ex99_1_A.Bad": "fail:" + NEAR}
        found, problem = results_of(fake_program(self.folder, tests), tests)
        self.assertEqual(problem, "")
        self.assertTrue(found["Ex99_1_A.Good"].passed)
        self.assertFalse(found["Ex99_1_A.Bad"].passed)
        self.assertEqual(found["Ex99_1_A.Bad"].hint, "t = 6 is the far side of the sphere: return the smaller root first")
        self.assertIn("evaluates to 6", found["Ex99_1_A.Bad"].detail)

    def test_a_printed_pass_line_and_exit_status_zero_earn_nothing(self):
        tests = {"Ex99_1_A.Liar": "fake-pass", "Ex99_1_A.Good": "pass"}
        found, _ = results_of(fake_program(self.folder, tests), tests)
        self.assertFalse(found["Ex99_1_A.Liar"].passed)
        self.assertIn("ended in the middle of a test", found["Ex99_1_A.Liar"].hint)
        self.assertTrue(found["Ex99_1_A.Good"].passed, "the other test, run on its own, still counts")

    def test_exit_in_the_middle_of_a_test_fails_that_test_only(self):
        tests = {"Ex99_1_A.Quits": "exit", "Ex99_1_A.Good": "pass"}
        found, _ = results_of(fake_program(self.folder, tests), tests)
        self.assertFalse(found["Ex99_1_A.Quits"].passed)
        self.assertTrue(found["Ex99_1_A.Good"].passed)

    def test_a_crash_costs_the_crashing_test_only(self):
        tests = {"Ex99_1_A.One": "pass", "Ex99_1_A.Crash": "crash", "Ex99_1_A.Two": "pass", "Ex99_2_B.Three": "pass"}
        found, _ = results_of(fake_program(self.folder, tests), tests)
        self.assertEqual([n for n, r in found.items() if not r.passed], ["Ex99_1_A.Crash"])
        self.assertIn("SIGSEGV", found["Ex99_1_A.Crash"].hint)

    def test_a_hang_is_cut_off_with_the_rest_of_its_exercise(self):
        tests = {"Ex99_1_A.One": "pass", "Ex99_1_A.Hang": "hang", "Ex99_1_A.After": "pass", "Ex99_2_B.Other": "pass"}
        start = time.monotonic()
        found, _ = results_of(fake_program(self.folder, tests), tests, limit=1.0)
        elapsed = time.monotonic() - start
        self.assertTrue(found["Ex99_1_A.One"].passed)
        self.assertIn("timed out after 1 s", found["Ex99_1_A.Hang"].hint)
        self.assertIn("not run", found["Ex99_1_A.After"].hint)
        self.assertTrue(found["Ex99_2_B.Other"].passed, "another exercise is graded as usual")
        # The exercise's run (1 s), then the hanging test alone (1 s), plus start-ups.
        self.assertLess(elapsed, 10, "a hang must cost about two time limits, not one per test")

    def test_a_hang_while_listing_costs_the_lab_and_is_bounded(self):
        tests = {"Ex99_1_A.One": "pass", "Ex99_1_A.Two": "pass"}
        start = time.monotonic()
        found, problem = results_of(fake_program(self.folder, tests, listing="hang"), tests, limit=1.0)
        self.assertLess(time.monotonic() - start, 5)
        self.assertIn("hangs while listing", problem)
        self.assertEqual(len(found), 2, "every test of the lab is still counted, as failed")
        self.assertFalse(any(r.passed for r in found.values()))

    def test_a_crash_while_listing_costs_the_lab(self):
        tests = {"Ex99_1_A.One": "pass"}
        found, problem = results_of(fake_program(self.folder, tests, listing="crash"), tests)
        self.assertIn("SIGSEGV", problem)
        self.assertFalse(found["Ex99_1_A.One"].passed)

    def test_output_that_is_not_utf8_is_no_trouble(self):
        tests = {"Ex99_1_A.Bytes": "bytes", "Ex99_1_A.Good": "pass"}
        found, _ = results_of(fake_program(self.folder, tests), tests)
        self.assertEqual(found["Ex99_1_A.Bytes"].hint, "bad bytes above")
        self.assertTrue(found["Ex99_1_A.Good"].passed)

    def test_endless_output_is_cut_off(self):
        tests = {"Ex99_1_A.Flood": "flood", "Ex99_1_A.Good": "pass"}
        found, _ = results_of(fake_program(self.folder, tests), tests, limit=60)
        self.assertIn("SIGXFSZ", found["Ex99_1_A.Flood"].hint)
        self.assertTrue(found["Ex99_1_A.Good"].passed)

    def test_a_child_left_running_does_not_stall_the_grader(self):
        tests = {"Ex99_1_A.Child": "child"}
        start = time.monotonic()
        found, _ = results_of(fake_program(self.folder, tests), tests, limit=5)
        self.assertTrue(found["Ex99_1_A.Child"].passed)
        self.assertLess(time.monotonic() - start, 4)

    def test_a_missing_program_costs_its_lab(self):
        found, problem = results_of(Path(self.folder) / "nothing", {"Ex99_1_A.One": "pass"})
        self.assertIn("not built", problem)
        self.assertFalse(found["Ex99_1_A.One"].passed)


class Hints(unittest.TestCase):
    def test_the_tests_message_without_gtests_lines(self):
        self.assertEqual(gtest_run.hint("a.cpp:5\nExpected equality of these values:\n  v[0]\n    Which is: (1, 2, 3)\n"
                                        "  Color(1)\n    Which is: (1, 1, 1)\nvertex 0 takes its element's value"),
                         "vertex 0 takes its element's value")
        self.assertEqual(gtest_run.hint("a.cpp:7\nValue of: hit\n  Actual: false\nExpected: true\nmust hit"), "must hit")
        self.assertEqual(gtest_run.hint("a.cpp:7\nExpected: (a) < (b), actual: 3 vs 2\nfewer sweeps"), "fewer sweeps")
        self.assertEqual(gtest_run.hint("a.cpp:9\nFailed\nwhy"), "why")

    def test_an_exception_names_itself(self):
        text = ('unknown file\nC++ exception with description "exercise 1.1 ray-sphere intersection is not '
                'implemented yet (see exercises/)" thrown in the test body.')
        self.assertEqual(gtest_run.hint(text),
                         "threw: exercise 1.1 ray-sphere intersection is not implemented yet (see exercises/)")

    def test_gtests_text_when_the_test_gave_none(self):
        self.assertEqual(gtest_run.hint("a.cpp:5\nExpected equality of these values:\n  1\n  2"),
                         "Expected equality of these values: 1 2")


class CommandLine(unittest.TestCase):
    """exercises/grade itself: every bad input is one line and a non-zero exit, never a traceback."""

    def grade(self, *args, env=None):
        done = subprocess.run([sys.executable, str(ROOT / "exercises" / "grade"), *args], capture_output=True,
                              text=True, env=env, timeout=120)
        self.assertNotIn("Traceback", done.stderr + done.stdout)
        return done

    def assert_one_line_error(self, done, status):
        self.assertEqual(done.returncode, status, done.stderr + done.stdout)
        self.assertEqual(len(done.stderr.strip().splitlines()), 1, done.stderr)

    def test_refuses_bad_options(self):
        for args in (["--labs", ","], ["--labs", ""], ["--labs", "1,99"], ["--labs", "x"], ["--timeout", "nan"],
                     ["--timeout", "-1"], ["--timeout", "inf"], ["--timeout", "0"], ["--bogus"],
                     ["--build", "/nonexistent"], ["--time", "5"]):  # no abbreviations: --build is not --build-dir
            self.assert_one_line_error(self.grade(*args), 2)

    def test_refuses_a_json_path_it_cannot_write_before_grading(self):
        with tempfile.TemporaryDirectory() as tmp:
            self.assert_one_line_error(self.grade("--json", f"{tmp}/missing/results.json"), 2)
            self.assert_one_line_error(self.grade("--json", tmp), 2)

    def test_missing_build_tree(self):
        with tempfile.TemporaryDirectory() as tmp:
            self.assert_one_line_error(self.grade("--no-build", "--build-dir", f"{tmp}/none"), 1)

    def test_no_cmake(self):
        with tempfile.TemporaryDirectory() as tmp:
            env = dict(os.environ, PATH=tmp)  # an empty folder: no cmake on the path
            done = subprocess.run([sys.executable, str(ROOT / "exercises" / "grade"), "--labs", "1", "--build-dir",
                                   f"{tmp}/build"], capture_output=True, text=True, env=env, timeout=60)
            self.assertNotIn("Traceback", done.stderr)
            self.assertEqual(done.returncode, 1)
            self.assertIn("cmake not found", done.stderr)


class Report(unittest.TestCase):
    def test_gradescope_json_marks_hidden_tests_and_keeps_them_out_of_the_summary(self):
        results = [grade.Result(1, "1.1", "Ex1_1_A.B", True, "", "passed", False),
                   grade.Result(1, "1.1", "Ex1_1_A.C", False, "the far root", "…", False),
                   grade.Result(1, "1.1", "Ex1_1_H.D", False, "secret hint", "…", True)]
        data = grade.gradescope(results, {"1.1": "ray-sphere"}, "after_published")
        self.assertEqual(data["score"], 1)
        self.assertEqual([t["visibility"] for t in data["tests"]], ["visible", "visible", "after_published"])
        self.assertEqual([t["max_score"] for t in data["tests"]], [1, 1, 1])
        self.assertIn("the far root", data["output"])
        self.assertNotIn("secret hint", data["output"])
        self.assertIn("score: 1/3", data["output"])

    def test_the_table_prints_each_failures_hint(self):
        results = [grade.Result(1, "1.1", "Ex1_1_A.C", False, "t = 6 is the far side", "", False)]
        self.assertIn("failed: C: t = 6 is the far side", grade.report(results, {}))

    def test_source_tests_and_kit_labs(self):
        with tempfile.TemporaryDirectory() as tmp:
            lab = Path(tmp) / "exercises" / "lab03"
            (lab / "hidden").mkdir(parents=True)
            (lab / "a_test.cpp").write_text("TEST(Ex3_1_A, One) {}\n  TEST(Ex3_2_B, Two) {\n}\n")
            (lab / "hidden" / "h_test.cpp").write_text("TEST(Ex3_1_H, Secret) {}\n")
            self.assertEqual(grade.source_tests(tmp, 3),
                             [("Ex3_1_A.One", False), ("Ex3_2_B.Two", False), ("Ex3_1_H.Secret", True)])
            self.assertIsNone(grade.kit_labs(tmp))
            (Path(tmp) / "exercises" / "KIT").write_text("3.1 jittered\n3.2 adaptive\n")
            self.assertEqual(grade.kit_labs(tmp), {3})
            self.assertEqual(grade.choose_labs(None, tmp), ([3], grade.choose_labs(None, tmp)[1]))


if __name__ == "__main__":
    unittest.main()
