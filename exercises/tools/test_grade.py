"""The grader against test programs that misbehave on purpose (ctest: exercise_tools).

Each fake test program is a small Python script that answers gtest's command line
the way a real one does -- --gtest_list_tests and --gtest_output=json, the
premature-exit file -- and then does what a student's code can make a test program
do: fail, crash, hang, exit in the middle, print a fake pass line, print bytes that
are not UTF-8, leave a child process behind.
"""
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest
from pathlib import Path
from unittest import mock

sys.path.insert(0, str(Path(__file__).resolve().parent))
import grade      # noqa: E402
import gtest_run  # noqa: E402
import processes  # noqa: E402
import sandbox    # noqa: E402

ROOT = Path(__file__).resolve().parents[2]

FAKE = r"""#!/usr/bin/env python3
import hashlib, hmac, json, os, signal, subprocess, sys, time
TESTS = %(tests)r
STARTUP = %(startup)r
args = sys.argv[1:]
def flag(name):
    return next((a.split("=", 1)[1] for a in args if a.startswith(name + "=")), None)
key_fd, report_fd = flag("--gi_key"), flag("--gi_report")
key = b""
if key_fd is not None:
    fd = int(key_fd)
    while len(key) < 32:
        key += os.read(fd, 32 - len(key))
    os.close(fd)
report = os.fdopen(int(report_fd), "w") if report_fd is not None else None
seq = 0
def record(**fields):
    global seq
    payload = json.dumps(dict(n=seq, **fields), separators=(",", ":"))
    seq += 1
    report.write(hmac.new(key, payload.encode(), hashlib.sha256).hexdigest() + " " + payload + "\n")
    report.flush()
if STARTUP == "hang":
    time.sleep(600)
if STARTUP == "crash":
    os.kill(os.getpid(), signal.SIGSEGV)
wanted = flag("--gtest_filter").split(":")
for name in wanted:
    if name not in TESTS:
        continue
    what = TESTS[name]
    record(e="start", t=name)
    print("[ RUN      ] " + name, flush=True)
    fails = []
    if what == "hang":
        time.sleep(600)
    elif what == "crash":
        os.kill(os.getpid(), signal.SIGSEGV)
    elif what == "exit":
        sys.exit(0)
    elif what == "fake-pass":
        print("[  PASSED  ] 1 test.", flush=True)
        sys.exit(0)
    elif what == "forge":  # unsigned verdicts into every descriptor, then quit
        for fd in range(3, 64):
            try:
                os.write(fd, ('0' * 64 + ' {"n":%%d,"e":"end","t":"%%s","ok":true}\n' %% (seq, name)).encode())
            except OSError:
                pass
        sys.exit(0)
    elif what == "flood":
        signal.signal(signal.SIGXFSZ, signal.SIG_DFL)  # as in a C++ program (Python ignores it)
        while True:
            sys.stdout.write("x" * 65536)
    elif what == "memory":
        try:
            block = bytearray(8 << 30)
        except MemoryError:
            fails = ["t.cpp:1\nstd::bad_alloc: out of memory"]
    elif what == "detach":  # fork, setsid, fork: a grandchild that waits, then writes
        if os.fork() == 0:
            os.setsid()
            if os.fork() == 0:
                time.sleep(1.5)
                open(%(witness)r, "w").write("alive after grading")
            os._exit(0)
        os.wait()
    elif what == "bytes":
        sys.stdout.flush()
        os.write(1, b"\xff\xfe\x80 not utf-8\n")
        fails = ["t.cpp:1\nFailed\nbad bytes \xe2\x82\xac above"]
    elif what.startswith("fail:"):
        fails = [what[5:]]
    record(e="end", t=name, ok=not fails, skip=False, fail=fails)
record(e="done")
os._exit(0)
"""

NEAR = ("lab.cpp:12\nThe difference between hit->t and 4.0 is 2, which exceeds 1e-9, where\nhit->t evaluates to 6,\n"
        "4.0 evaluates to 4, and\n1e-9 evaluates to 1.0000000000000001e-09.\n"
        "t = 6 is the far side of the sphere: return the smaller root first")


def fake_program(folder, tests, startup="ok", witness="/dev/null"):
    path = Path(folder) / "lab99_graded"
    path.write_text(FAKE % {"tests": tests, "startup": startup, "witness": witness})
    path.chmod(0o755)
    return path


def results_of(binary, tests, limit=1.5):
    with gtest_run.Runner() as runner:
        results, problem = grade.grade_program(runner, binary, 99, [(n, False) for n in tests], limit, {}, False)
        missing = set(runner.missing)
    return {r.name: r for r in results}, problem, missing


class FakePrograms(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.folder = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def test_passes_and_failures_come_from_the_signed_report_with_the_tests_own_hint(self):
        tests = {"Ex99_1_A.Good": "pass", "Ex99_1_A.Bad": "fail:" + NEAR}
        found, problem, _ = results_of(fake_program(self.folder, tests), tests)
        self.assertEqual(problem, "")
        self.assertTrue(found["Ex99_1_A.Good"].passed)
        self.assertFalse(found["Ex99_1_A.Bad"].passed)
        self.assertEqual(found["Ex99_1_A.Bad"].hint, "t = 6 is the far side of the sphere: return the smaller root first")
        self.assertIn("evaluates to 6", found["Ex99_1_A.Bad"].detail)

    def test_a_printed_pass_line_and_exit_status_zero_earn_nothing(self):
        tests = {"Ex99_1_A.Liar": "fake-pass", "Ex99_1_A.Good": "pass"}
        found, _, _ = results_of(fake_program(self.folder, tests), tests)
        self.assertFalse(found["Ex99_1_A.Liar"].passed)
        self.assertIn("ended in the middle of this test", found["Ex99_1_A.Liar"].hint)
        self.assertTrue(found["Ex99_1_A.Good"].passed, "the other test, run in a new process, still counts")

    def test_unsigned_verdicts_written_into_every_descriptor_earn_nothing(self):
        tests = {"Ex99_1_A.One": "pass", "Ex99_1_A.Forger": "forge", "Ex99_1_A.Two": "pass"}
        found, _, _ = results_of(fake_program(self.folder, tests), tests)
        self.assertTrue(found["Ex99_1_A.One"].passed, "a test finished before the forgery keeps its signed pass")
        self.assertFalse(found["Ex99_1_A.Forger"].passed)
        self.assertIn("wrote into the grader's report", found["Ex99_1_A.Forger"].hint)
        self.assertTrue(found["Ex99_1_A.Two"].passed)

    def test_exit_in_the_middle_of_a_test_fails_that_test_only(self):
        tests = {"Ex99_1_A.Quits": "exit", "Ex99_1_A.Good": "pass"}
        found, _, _ = results_of(fake_program(self.folder, tests), tests)
        self.assertFalse(found["Ex99_1_A.Quits"].passed)
        self.assertTrue(found["Ex99_1_A.Good"].passed)

    def test_a_crash_costs_the_crashing_test_only(self):
        tests = {"Ex99_1_A.One": "pass", "Ex99_1_A.Crash": "crash", "Ex99_1_A.Two": "pass", "Ex99_2_B.Three": "pass"}
        found, _, _ = results_of(fake_program(self.folder, tests), tests)
        self.assertEqual([n for n, r in found.items() if not r.passed], ["Ex99_1_A.Crash"])
        self.assertIn("SIGSEGV", found["Ex99_1_A.Crash"].hint)

    def test_a_hang_is_cut_off_with_the_rest_of_its_exercise(self):
        tests = {"Ex99_1_A.One": "pass", "Ex99_1_A.Hang": "hang", "Ex99_1_A.After": "pass", "Ex99_2_B.Other": "pass"}
        start = time.monotonic()
        found, _, _ = results_of(fake_program(self.folder, tests), tests, limit=1.0)
        elapsed = time.monotonic() - start
        self.assertTrue(found["Ex99_1_A.One"].passed)
        self.assertIn("timed out after 1 s", found["Ex99_1_A.Hang"].hint)
        self.assertIn("not run", found["Ex99_1_A.After"].hint)
        self.assertTrue(found["Ex99_2_B.Other"].passed, "another exercise is graded as usual")
        self.assertLess(elapsed, 20, "a hang must cost one time limit, not one per test")

    def test_a_hang_before_the_first_test_costs_the_program_and_is_bounded(self):
        tests = {"Ex99_1_A.One": "pass", "Ex99_2_B.Two": "pass"}
        start = time.monotonic()
        found, problem, _ = results_of(fake_program(self.folder, tests, startup="hang"), tests, limit=1.0)
        self.assertLess(time.monotonic() - start, 15)
        self.assertIn("hangs before its first test", problem)
        self.assertEqual(len(found), 2, "every test of the lab is still counted, as failed")
        self.assertFalse(any(r.passed for r in found.values()))

    def test_a_crash_before_the_first_test_costs_the_program(self):
        tests = {"Ex99_1_A.One": "pass"}
        found, problem, _ = results_of(fake_program(self.folder, tests, startup="crash"), tests)
        self.assertIn("SIGSEGV", problem)
        self.assertFalse(found["Ex99_1_A.One"].passed)

    def test_a_hidden_programs_problem_stays_with_the_hidden_tests(self):
        root, build_dir = Path(self.folder) / "root", Path(self.folder) / "build"
        (root / "exercises" / "lab99" / "hidden").mkdir(parents=True)
        (root / "exercises" / "lab99" / "a_test.cpp").write_text("TEST(Ex99_1_A, One) {}\n")
        (root / "exercises" / "lab99" / "hidden" / "b_test.cpp").write_text("TEST(Ex99_1_A, Hidden) {}\n")
        (build_dir / "bin").mkdir(parents=True)
        fake_program(build_dir / "bin", {"Ex99_1_A.Hidden": "pass"}, startup="crash").rename(build_dir / "bin" /
                                                                                          "lab99_hidden")
        fake_program(build_dir / "bin", {"Ex99_1_A.One": "pass"})  # lab99_graded
        with gtest_run.Runner() as runner:
            results, problems, _ = grade.grade(root, [99], build_dir, 1.5, False, say=lambda line: None, runner=runner)
        found = {r.name: r for r in results}
        self.assertTrue(found["Ex99_1_A.One"].passed)
        self.assertFalse(found["Ex99_1_A.Hidden"].passed)
        self.assertIn("SIGSEGV", found["Ex99_1_A.Hidden"].hint, "the instructor reads why, with the hidden test")
        self.assertEqual(problems, [], "no line a student sees says that, or how, the hidden program failed")

    def test_output_that_is_not_utf8_is_no_trouble(self):
        tests = {"Ex99_1_A.Bytes": "bytes", "Ex99_1_A.Good": "pass"}
        found, _, _ = results_of(fake_program(self.folder, tests), tests)
        self.assertEqual(found["Ex99_1_A.Bytes"].hint, "bad bytes \u20ac above")
        self.assertTrue(found["Ex99_1_A.Good"].passed)

    def test_endless_output_is_cut_off(self):
        tests = {"Ex99_1_A.Flood": "flood", "Ex99_1_A.Good": "pass"}
        found, _, missing = results_of(fake_program(self.folder, tests), tests, limit=60)
        self.assertIn("SIGXFSZ", found["Ex99_1_A.Flood"].hint)
        self.assertTrue(found["Ex99_1_A.Good"].passed)

    def test_memory_is_limited(self):
        tests = {"Ex99_1_A.Bomb": "memory"}
        found, _, missing = results_of(fake_program(self.folder, tests), tests, limit=30)
        if "limits" in missing:
            self.skipTest("this system allows no resource limits")
        self.assertFalse(found["Ex99_1_A.Bomb"].passed)
        self.assertIn("bad_alloc", found["Ex99_1_A.Bomb"].hint)

    def test_a_detached_grandchild_does_not_outlive_grading(self):
        witness = Path(self.folder) / "witness"
        Path(self.folder).chmod(0o777)  # whoever the test runs as could write the witness, were it alive
        tests = {"Ex99_1_A.Detach": "detach"}
        start = time.monotonic()
        found, _, missing = results_of(fake_program(self.folder, tests, witness=str(witness)), tests, limit=10)
        self.assertTrue(found["Ex99_1_A.Detach"].passed)
        self.assertLess(time.monotonic() - start, 8, "grading does not wait for the grandchild")
        time.sleep(2.5)
        self.assertFalse(witness.exists(), "the grandchild was still alive after grading")

    def test_every_fallback_still_grades_and_says_what_is_missing(self):
        tests = {"Ex99_1_A.Good": "pass", "Ex99_1_A.Bad": "fail:" + NEAR, "Ex99_1_A.Detach": "detach"}
        witness = Path(self.folder) / "witness"
        Path(self.folder).chmod(0o777)
        with mock.patch.dict(os.environ, {"GI_SANDBOX_OFF": "all"}):
            found, problem, missing = results_of(fake_program(self.folder, tests, witness=str(witness)), tests)
        self.assertEqual(problem, "")
        self.assertTrue(found["Ex99_1_A.Good"].passed)
        self.assertFalse(found["Ex99_1_A.Bad"].passed)
        self.assertTrue({"user", "pidns", "subreaper", "limits"} <= missing, missing)
        note = sandbox.isolation_note(missing)
        self.assertEqual(len(note.splitlines()), 1)
        self.assertIn("no PID namespace", note)
        self.assertIn("may outlive grading", note, "without any layer, a detached process is not contained: say so")

    def test_each_fallback_alone_still_contains_a_detached_grandchild(self):
        for off in ("pidns", "pidns,user", "pidns,subreaper", "user,subreaper"):
            witness = Path(self.folder) / f"witness-{off}"
            tests = {"Ex99_1_A.Detach": "detach"}
            Path(self.folder).chmod(0o777)
            with mock.patch.dict(os.environ, {"GI_SANDBOX_OFF": off}):
                found, _, missing = results_of(fake_program(self.folder, tests, witness=str(witness)), tests, limit=10)
            self.assertTrue(found["Ex99_1_A.Detach"].passed, off)
            time.sleep(2.5)
            if not {"pidns", "user", "subreaper"} <= missing:
                self.assertFalse(witness.exists(), f"with {off} off, the grandchild outlived grading")

    def test_the_unsigned_path_still_grades(self):
        """GI_SANDBOX_OFF=channel: gtest's JSON report, as on a system without descriptors to pass."""
        report_writer = Path(self.folder) / "lab99_graded"
        report_writer.write_text("#!/usr/bin/env python3\nimport json, sys\n"
                                 "out = next(a for a in sys.argv if a.startswith('--gtest_output=json:'))[20:]\n"
                                 "json.dump({'testsuites': [{'name': 'Ex99_1_A', 'testsuite': [{'name': 'Good', "
                                 "'status': 'RUN', 'result': 'COMPLETED'}]}]}, open(out, 'w'))\n")
        report_writer.chmod(0o755)
        with mock.patch.dict(os.environ, {"GI_SANDBOX_OFF": "channel"}):
            found, problem, missing = results_of(report_writer, {"Ex99_1_A.Good": "pass"})
        self.assertTrue(found["Ex99_1_A.Good"].passed)
        self.assertIn("channel", missing)

    def test_without_posix_it_still_grades_and_says_so_in_one_line(self):
        """As on Windows (forced here): no sandbox, no descriptors to pass, no process
        groups; gtest's JSON report is read, the program is killed on its own."""
        writer = Path(self.folder) / "lab99_graded"
        writer.write_text("#!/usr/bin/env python3\nimport json, sys, time\n"
                          "out = next(a for a in sys.argv if a.startswith('--gtest_output=json:'))[20:]\n"
                          "json.dump({'testsuites': [{'name': 'Ex99_1_A', 'testsuite': [{'name': 'Good', "
                          "'status': 'RUN', 'result': 'COMPLETED'}, {'name': 'Bad', 'status': 'RUN', "
                          "'failures': [{'failure': 'a.cpp:1\\nFailed\\nthe far root'}]}]}]}, open(out, 'w'))\n"
                          "if 'Hang' in ' '.join(sys.argv): time.sleep(600)\n")
        writer.chmod(0o755)
        start = time.monotonic()
        with mock.patch.object(processes, "POSIX", False):
            found, problem, missing = results_of(writer, {"Ex99_1_A.Good": "", "Ex99_1_A.Bad": "", "Ex99_1_A.Hang": ""},
                                                 limit=8.0)
        self.assertLess(time.monotonic() - start, 40, "the deadline holds without process groups")
        self.assertTrue(found["Ex99_1_A.Good"].passed)
        self.assertEqual(found["Ex99_1_A.Bad"].hint, "the far root")
        self.assertIn("timed out", found["Ex99_1_A.Hang"].hint)
        self.assertTrue({"channel", "user", "pidns", "subreaper", "limits"} <= missing, missing)
        note = grade.missing_note(missing)
        self.assertEqual(len(note.splitlines()), 1, note)
        self.assertIn("could forge", note)
        self.assertIn("no resource limits", note)

    def test_a_missing_program_costs_its_lab(self):
        found, problem, _ = results_of(Path(self.folder) / "nothing", {"Ex99_1_A.One": "pass"})
        self.assertIn("not built", problem)
        self.assertFalse(found["Ex99_1_A.One"].passed)


class Users(unittest.TestCase):
    @unittest.skipUnless(processes.POSIX and os.geteuid() == 0 and "user" not in sandbox.switched_off(),
                         "a user of its own for the tests needs root")
    def test_two_graders_at_once_never_share_the_tests_user(self):
        # (the one that cleans up after its tests would kill the other's and remove its files)
        with gtest_run.Runner() as first, gtest_run.Runner() as second:
            self.assertIsNotNone(first.uid)
            self.assertNotEqual(first.uid, second.uid)
            taken = first.uid
        with gtest_run.Runner() as third:
            self.assertEqual(third.uid, taken, "a grader that has ended frees its user")

    @unittest.skipUnless(processes.POSIX and os.geteuid() == 0, "taking another user id needs root")
    def test_a_users_processes_are_killed_and_the_killing_ends_when_none_is_left(self):
        # Without a PID namespace, what a test leaves is killed by user id. kill(-1)
        # succeeds while the system has any other process, so its success cannot say
        # when the user has none left: /proc does.
        uid, lock = sandbox.free_uid()
        try:
            self.assertFalse(sandbox.others_of(uid))
            child = os.fork()
            if child == 0:
                os.setgroups([])
                os.setgid(uid)
                os.setuid(uid)
                if os.fork() == 0:  # a grandchild, detached, that would outlive its parent
                    os.setsid()
                    time.sleep(600)
                time.sleep(600)
                os._exit(0)
            deadline = time.monotonic() + 5
            while not sandbox.others_of(uid) and time.monotonic() < deadline:
                time.sleep(0.01)
            self.assertTrue(sandbox.others_of(uid), "the user's processes are seen")
            start = time.monotonic()
            sandbox.kill_user(uid, start + 30)
            self.assertLess(time.monotonic() - start, 20, "the killing ends when no process is left, not at the deadline")
            try:
                os.waitpid(child, 0)
            except ChildProcessError:
                pass  # kill_user reaps its caller's children as they die
            deadline = time.monotonic() + 5  # the grandchild's parent is now init, which reaps it
            while sandbox.others_of(uid) and time.monotonic() < deadline:
                time.sleep(0.01)
            self.assertFalse(sandbox.others_of(uid), "every process of the user is gone")
        finally:
            os.close(lock)


# A test program that reports what it sees of the machine: whether /proc is its own (the
# shell's pid by /proc's count is the one it knows itself by), how much of 256 MB (eight
# files under the file limit) it could write into /dev/shm, and it leaves a file in every
# folder anyone may write.
PROBE = """#!/bin/sh
read -r pid rest < /proc/self/stat
[ "$pid" = "$$" ] && echo "proc: own" || echo "proc: the machine's"
k=0
while [ $k -lt 8 ] && dd if=/dev/zero of=/dev/shm/%(mark)s-$k bs=1M count=32 2>/dev/null; do k=$((k + 1)); done
echo "shm: $((k * 32)) MB"
for d in /tmp /var/tmp /dev/shm /run/lock; do echo left > $d/%(mark)s 2>/dev/null; done
echo "user: $(id -u)"
"""


def probe(folder, runner):
    """(what the probe printed, the files it left behind outside the sandbox)."""
    mark = f"gi-probe-{os.getpid()}-{time.monotonic_ns()}"
    path = Path(folder) / "probe.sh"
    path.write_text(PROBE % {"mark": mark})
    path.chmod(0o755)
    code, output = runner.launch([str(runner.copy(path))], 20, (), runner.scratch())
    left = [f for d in ("/tmp", "/var/tmp", "/dev/shm", "/run/lock") for f in Path(d).glob(mark + "*")]
    for f in left:
        f.unlink()
    return code, output, left


@unittest.skipUnless(sys.platform.startswith("linux"), "the sandbox's namespaces are Linux's")
class PrivateFolders(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        Path(self.tmp.name).chmod(0o755)

    def tearDown(self):
        self.tmp.cleanup()

    def test_shared_folders_and_proc_are_the_runs_own_and_gone_after_it(self):
        with gtest_run.Runner() as runner:
            code, output, left = probe(self.tmp.name, runner)
            missing = set(runner.missing)
        self.assertEqual(code, 0, output)
        if "mount" in missing:
            self.skipTest("no mount namespace here")
        self.assertEqual(left, [], "files the program wrote outlived it")
        self.assertLessEqual(int(output.split("shm: ")[1].split()[0]), 64, "shared memory is capped at 64 MB")
        if "proc" not in missing:
            self.assertIn("proc: own", output)

    @unittest.skipUnless(os.geteuid() == 0, "becoming a user without root needs root first")
    def test_a_student_without_root_is_graded_in_a_user_namespace(self):
        """exercises/grade as a student runs it: not root, so the namespaces come from a
        user namespace of its own (the ids mapped into the program's second namespace
        must be read before it is entered)."""
        script = ("import json, sys; sys.path.insert(0, sys.argv[1]); import test_grade, gtest_run\n"
                  "with gtest_run.Runner() as r:\n"
                  "    code, output, left = test_grade.probe(sys.argv[2], r)\n"
                  "print(json.dumps([code, output, [str(f) for f in left], sorted(r.missing)]))\n")
        python = shutil.which("python3", path="/usr/bin:/bin")
        if python is None:
            self.skipTest("no python3 in /usr/bin or /bin for another user to run")
        tools = Path(self.tmp.name) / "tools"  # a copy the user may read wherever this tree is
        shutil.copytree(Path(__file__).parent, tools, ignore=shutil.ignore_patterns("__pycache__"))
        subprocess.run(["chmod", "-R", "a+rX", str(tools)], check=True)
        home = Path(self.tmp.name) / "student"
        home.mkdir()
        home.chmod(0o777)
        done = subprocess.run([python, "-c", script, str(tools), str(home)],
                              capture_output=True, text=True, timeout=60, env={"PATH": "/usr/bin:/bin", "HOME": "/"},
                              preexec_fn=lambda: (os.setgroups([]), os.setgid(65534), os.setuid(65534)))
        self.assertEqual(done.returncode, 0, done.stderr[-2000:])
        code, output, left, missing = json.loads(done.stdout.splitlines()[-1])
        self.assertEqual(code, 0, f"the program did not start: {output}")
        if "pidns" in missing:  # no user namespace for this user here: it runs as the student, and says so
            self.assertIn("user: 65534\n", output)
            return
        self.assertIn("user: 1000\n", output, "it is no one in a namespace of its own, not the namespace's root")
        self.assertEqual(left, [], "files the program wrote outlived it")
        if "proc" not in missing:
            self.assertIn("proc: own", output)


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
        done = subprocess.run([str(ROOT / "exercises" / "grade"), *args], capture_output=True,
                              text=True, env=env, timeout=120)
        self.assertNotIn("Traceback", done.stderr + done.stdout)
        return done

    def assert_one_line_error(self, done, status):
        self.assertEqual(done.returncode, status, done.stderr + done.stdout)
        self.assertEqual(len(done.stderr.strip().splitlines()), 1, done.stderr)

    def test_refuses_bad_options(self):
        for args in (["--labs", ","], ["--labs", ""], ["--labs", "1,99"], ["--labs", "x"], ["--timeout", "nan"],
                     ["--timeout", "-1"], ["--timeout", "inf"], ["--timeout", "0"], ["--timeout", "1e-9"],
                     ["--timeout", "0.01"], ["--timeout", "0x10"], ["--bogus"],
                     ["--labs", "\u0661"], ["--labs", "\uff11"], ["--labs", "1", "--labs", "2"], ["--build-dir", ""],
                     ["--build", "/nonexistent"], ["--time", "5"]):  # no abbreviations: --build is not --build-dir
            self.assert_one_line_error(self.grade(*args), 2)

    def test_refuses_a_json_path_it_cannot_write_before_grading(self):
        with tempfile.TemporaryDirectory() as tmp:
            self.assert_one_line_error(self.grade("--json", f"{tmp}/missing/results.json"), 2)
            self.assert_one_line_error(self.grade("--json", tmp), 2)
            self.assert_one_line_error(self.grade("--json", ""), 2)
            os.symlink(f"{tmp}/elsewhere", f"{tmp}/link.json")
            self.assert_one_line_error(self.grade("--json", f"{tmp}/link.json"), 2)
            self.assertFalse(os.path.lexists(f"{tmp}/elsewhere"))
        for device in ("/dev/null", "/dev/full"):
            if os.path.exists(device):
                self.assert_one_line_error(self.grade("--json", device), 2)
                self.assertTrue(Path(device).is_char_device(), f"{device} must stay a device")

    def test_a_relative_build_dir_is_taken_from_where_the_grader_runs(self):
        with tempfile.TemporaryDirectory() as tmp:
            done = subprocess.run([str(ROOT / "exercises" / "grade"), "--no-build", "--build-dir",
                                   "relative/build"], capture_output=True, text=True, cwd=tmp, timeout=120)
            self.assertEqual(done.returncode, 1)
            self.assertIn(f"{os.path.realpath(tmp)}/relative/build", done.stderr.replace(tmp, os.path.realpath(tmp)))

    def test_ctrl_c_at_any_moment_is_one_line(self):
        """As a terminal does: SIGINT to the whole foreground process group, at moments from
        Python's start to the middle of the work."""
        for delay in (0.0, 0.02, 0.05, 0.2, 0.5, 1.0):
            run = subprocess.Popen([str(ROOT / "exercises" / "grade"), "--labs", "1", "--no-build",
                                    "--build-dir", "/nonexistent"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                   text=True, start_new_session=True)
            time.sleep(delay)
            os.killpg(run.pid, signal.SIGINT)
            out, err = run.communicate(timeout=60)
            self.assertNotIn("Traceback", out + err, f"Ctrl-C after {delay} s")
            self.assertLessEqual(len(err.strip().splitlines()), 1, err)

    def test_missing_build_tree(self):
        with tempfile.TemporaryDirectory() as tmp:
            self.assert_one_line_error(self.grade("--no-build", "--build-dir", f"{tmp}/none"), 1)

    def test_no_cmake(self):
        with tempfile.TemporaryDirectory() as tmp:
            env = dict(os.environ, PATH=tmp)  # an empty folder: no cmake on the path
            done = subprocess.run([sys.executable, str(ROOT / "exercises" / "tools" / "grade.py"), "--labs", "1", "--build-dir",
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
        self.assertNotIn("/3", data["output"], "no count in the summary may include the hidden tests")
        self.assertRegex(data["output"], r"1\.1 +ray-sphere +1/2\n")
        self.assertIn("visible tests: 1/2", data["output"])
        self.assertIn("1 hidden", data["output"])

    def test_messages_carry_no_absolute_path_into_the_tree(self):
        results = [grade.Result(1, "1.1", "Ex1_1_A.C", False, f"{ROOT}/exercises/lab01/x_test.cpp:3: far root",
                                f"{ROOT}/lib/gi/geometry/sphere.cpp:9: note", False)]
        data = grade.gradescope(results, {}, "after_published", ROOT)
        self.assertNotIn(str(ROOT), json.dumps(data))
        self.assertIn("exercises/lab01/x_test.cpp:3", data["tests"][0]["output"])

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
