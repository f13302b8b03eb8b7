"""gtest_run: run a graded test program the way a grader must.

Pass or fail comes from the program's signed report (support/graded_main.cpp): the
grader hands the program a fresh random key through a pipe, which the harness reads
and closes before any test runs, and a descriptor of a file only the grader can open
by name, where the harness writes one line per test, signed with that key (HMAC-
SHA256). Only lines whose signature checks, in sequence, count. What the program
prints, the files it writes, its exit status, a line it writes into every descriptor
it can find: none of it is signed, so none of it earns a point.

Every run goes through sandbox.py (its own user, PID namespace, limits, a deadline;
what the system does not allow is said once, in one line). Where the report cannot
be had (a system without POSIX descriptors, or GI_SANDBOX_OFF=channel to test that
path), gtest's JSON report is read instead, which the code under test could forge:
good enough for grading your own work on your own machine, and said so.
"""
from __future__ import annotations  # `int | None` in the dataclass below, on Python 3.9

import hashlib
import hmac
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
from dataclasses import dataclass, field
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import processes  # noqa: E402
import sandbox  # noqa: E402

KEEP_OUTPUT = 16384         # characters of a program's output kept for messages
MAX_REPORT = 32 << 20       # bytes of a report read
MEMORY = 2 << 30            # bytes of data a test program may allocate (at most half the machine's)


@dataclass
class Outcome:
    """What one test did: passed, and if not, the hint and the whole story."""
    passed: bool
    hint: str            # one line for the score table: the test's own message
    detail: str = ""     # everything the test said, for results.json


@dataclass
class Run:
    """One run of a test program over some tests."""
    problem: str = ""                 # "" when it reported on every test it was given
    culprit: str | None = None        # the test in progress when it stopped
    started: bool = False             # it began at least one test
    returncode: int | None = None     # None: killed at the time limit
    output: str = ""                  # the tail of stdout and stderr
    outcomes: dict = field(default_factory=dict)  # test name -> Outcome, from the signed report


def describe_exit(code):
    """'killed by SIGSEGV (segmentation fault: ...)' or 'exit status 3'."""
    if code is None:
        return "no exit"
    if code < 0:
        try:
            name = signal.Signals(-code).name
        except ValueError:
            name = f"signal {-code}"
        meaning = {"SIGSEGV": "segmentation fault: an index out of range or a bad pointer?",
                   "SIGABRT": "abort: a failed assert, or an exception nothing caught",
                   "SIGFPE": "arithmetic fault: an integer divided by zero?",
                   "SIGKILL": "killed: out of memory?",
                   "SIGBUS": "bus error: a bad pointer?",
                   "SIGXFSZ": "output past 64 MB: printing without end?",
                   "SIGXCPU": "out of processor time"}.get(name)
        return f"killed by {name}" + (f" ({meaning})" if meaning else "")
    return f"exit status {code}"


def program_env(scratch):
    """The environment a test program gets: nothing of the grader's, no GTEST_* variable."""
    if not processes.POSIX:  # Windows needs its own variables (SystemRoot, the DLLs' PATH) to start a program
        return {k: v for k, v in os.environ.items() if not k.startswith("GTEST_")}
    env = {"PATH": "/usr/bin:/bin", "HOME": str(scratch), "TMPDIR": str(scratch), "LANG": "C.UTF-8", "TZ": "UTC"}
    env.update({k: v for k, v in os.environ.items() if k.startswith(("ASAN_", "UBSAN_", "LSAN_"))})
    return env


def tail(file):
    size = file.seek(0, os.SEEK_END)
    file.seek(max(0, size - 4 * KEEP_OUTPUT))
    return file.read().decode("utf-8", errors="replace")[-KEEP_OUTPUT:]


def from_bytes(text):
    """A string of the report, whose non-ASCII bytes came as \\u00XX: back to UTF-8."""
    return text.encode("latin-1", errors="replace").decode("utf-8", errors="replace")


class Runner:
    """Runs test programs for one grading session: copies of the programs in a folder
    of its own, one scratch folder per run, the sandbox's settings, and what the
    system could not give (`missing`, said once by the grader)."""

    def __init__(self, hide=(), memory=MEMORY, isolate=True):
        """`isolate`=False runs the programs directly, in a process group of their own
        with the deadline but no sandbox: for the course's own code only (the mutant
        suite, the kit check), never for a student's."""
        self.isolate = isolate and processes.POSIX  # the sandbox is POSIX (fork, rlimits, signals)
        self.base = Path(tempfile.mkdtemp(prefix="gi-grade-"))
        self.hide = [str(Path(h).resolve()) for h in hide]
        off = sandbox.switched_off()
        self.channel = processes.POSIX and "channel" not in off
        self.uid, self.uid_lock = (sandbox.free_uid() if self.isolate and os.geteuid() == 0 and "user" not in off
                                   else (None, None))
        physical = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") if hasattr(os, "sysconf") else 0
        self.memory = min(memory, physical // 2) if memory and physical else memory
        self.missing = set() if self.channel else {"channel"}
        if isolate and not self.isolate:
            self.missing |= {"user", "pidns", "subreaper", "limits"}
        self.copies, self.count, self.lock = {}, 0, threading.Lock()  # runs may come from several threads
        (self.base / "bin").mkdir()
        (self.base / "reports").mkdir(mode=0o700)
        if self.uid is not None:
            self.base.chmod(0o711)  # its user may pass through to bin/ and its scratch folder, nothing else

    def close(self):
        shutil.rmtree(self.base, ignore_errors=True)
        if self.uid_lock is not None:
            os.close(self.uid_lock)  # the uid is free for another grader
            self.uid_lock = None

    def __enter__(self):
        return self

    def __exit__(self, *_):
        self.close()

    def copy(self, binary):
        """The program, copied where the user running it may execute it (the build
        tree itself may be out of its reach)."""
        info = Path(binary).stat()
        key = (str(binary), info.st_mtime_ns, info.st_size)
        with self.lock:
            if key not in self.copies:
                target = self.base / "bin" / f"{len(self.copies)}-{Path(binary).name}"
                shutil.copyfile(binary, target)
                target.chmod(0o755)
                self.copies[key] = target
            return self.copies[key]

    def launch(self, argv, timeout, pass_fds, scratch):
        """(return code or None at the deadline, output tail) of one sandboxed run."""
        if not self.isolate:
            return self.launch_directly(argv, timeout, pass_fds, scratch)
        status_read, status_write = os.pipe()
        config = {"argv": argv, "timeout": timeout, "scratch": str(scratch), "env": program_env(scratch),
                  "uid": self.uid, "hide": self.hide, "keep": str(self.base), "memory": self.memory,
                  "status_fd": status_write}
        with tempfile.TemporaryFile() as out:
            try:
                process = subprocess.Popen(sandbox.command(config), stdin=subprocess.DEVNULL, stdout=out,
                                           stderr=subprocess.STDOUT, pass_fds=(*pass_fds, status_write),
                                           **processes.own_group())
            except OSError as e:
                os.close(status_read), os.close(status_write)
                return 127, f"cannot start the sandbox: {e.strerror}"
            os.close(status_write)
            try:
                process.wait(timeout=timeout + 30)  # the sandbox keeps the time; this is its own backstop
            except subprocess.TimeoutExpired:
                pass
            finally:
                processes.kill_group(process)
                process.wait()
            with os.fdopen(status_read, "rb") as r:
                text = r.read(65536)
            try:
                status = json.loads(text)
            except ValueError:
                status = {"returncode": None, "missing": [], "error": "the sandbox stopped without a word"}
            self.missing |= set(status.get("missing", []))
            output = tail(out)
            if status.get("error"):
                output += f"\nsandbox: {status['error']}"
            return status.get("returncode"), output

    def launch_directly(self, argv, timeout, pass_fds, scratch):
        with tempfile.TemporaryFile() as out:
            try:
                process = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=out, stderr=subprocess.STDOUT,
                                           pass_fds=pass_fds, cwd=scratch, env=program_env(scratch),
                                           **processes.own_group())
            except OSError as e:
                return 127, f"cannot start {argv[0]}: {e.strerror}"
            try:
                code = process.wait(timeout=timeout)
            except subprocess.TimeoutExpired:
                code = None
            finally:
                processes.kill_group(process)
                process.wait()
            return code, tail(out)

    def scratch(self):
        with self.lock:
            self.count += 1
            folder = self.base / f"run-{self.count}"
        folder.mkdir(mode=0o700)
        if self.uid is not None:
            os.chown(folder, self.uid, self.uid)
        return folder

    def run_tests(self, binary, names, timeout):
        """Runs the named tests in one process; the signed report says which passed."""
        if not self.channel:
            return self.run_tests_unsigned(binary, names, timeout)
        program, scratch = self.copy(binary), self.scratch()
        key = os.urandom(32)
        key_read, key_write = os.pipe()
        os.write(key_write, key)
        os.close(key_write)
        # The program may only append to its report: it cannot read a signed line back
        # (to try a guessed key against it) nor write over one.
        report_path = self.base / "reports" / scratch.name
        report = os.open(report_path, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_APPEND, 0o600)
        argv = [str(program), "--gtest_filter=" + ":".join(names), "--gtest_color=no",
                f"--gi_key={key_read}", f"--gi_report={report}"]
        try:
            code, output = self.launch(argv, timeout, (key_read, report), scratch)
        finally:
            os.close(key_read)
            os.close(report)
        with open(report_path, "rb") as signed:
            lines = signed.read(MAX_REPORT).decode("ascii", errors="replace").splitlines()
        report_path.unlink(missing_ok=True)
        shutil.rmtree(scratch, ignore_errors=True)
        return judge(lines, key, names, code, output, timeout)

    def run_tests_unsigned(self, binary, names, timeout):
        """gtest's JSON report, for systems without the signed one."""
        scratch = self.scratch()
        report = scratch / "report.json"
        argv = [str(self.copy(binary)), "--gtest_filter=" + ":".join(names), "--gtest_color=no",
                f"--gtest_output=json:{report}"]
        code, output = self.launch(argv, timeout, (), scratch)
        run = Run("", None, True, code, output)
        try:
            run.outcomes = outcomes_of_json(json.loads(report.read_bytes().decode("utf-8", errors="replace")))
        except (OSError, ValueError, KeyError, TypeError):
            pass
        shutil.rmtree(scratch, ignore_errors=True)
        missing = [n for n in names if n not in run.outcomes]
        if missing:
            run.culprit, run.started = missing[0], bool(run.outcomes) or code is not None
            run.problem = stop_reason(code, timeout)
        return run


def judge(lines, key, names, code, output, timeout):
    """The Run a signed report tells: the outcomes of the tests it finished, and why it stopped."""
    run, sequence, current, done = Run("", None, False, code, output), 0, None, False
    for line in lines:
        mark, _, payload = line.partition(" ")
        expected = hmac.new(key, payload.encode("ascii", errors="replace"), hashlib.sha256).hexdigest()
        try:
            record = json.loads(payload) if hmac.compare_digest(mark, expected) else None
        except ValueError:
            record = None
        if not isinstance(record, dict) or record.get("n") != sequence or done:
            run.problem = ("the code under test wrote into the grader's report (a line without a valid signature): "
                           "it counts as failed")
            run.culprit = current
            return run
        sequence += 1
        event, test = record.get("e"), record.get("t")
        if event == "start":
            run.started, current = True, test
        elif event == "end" and test == current:
            run.outcomes[test] = outcome(record)
            current = None
        elif event == "done" and current is None:
            done = True
    if done:
        for name in names:
            run.outcomes.setdefault(name, Outcome(False, "the test program does not hold this test: rebuild it"))
        return run
    run.culprit = current
    run.problem = stop_reason(code, timeout)
    return run


def stop_reason(code, timeout):
    if code is None:
        return f"timed out after {timeout:g} s (an endless loop?)"
    if code < 0:
        return f"crashed, {describe_exit(code)}"
    return f"the program ended in the middle of this test ({describe_exit(code)}): exit() or abort() called?"


def outcome(record):
    failures = [from_bytes(f) for f in record.get("fail", []) if isinstance(f, str)]
    if record.get("skip"):
        return Outcome(False, "skipped (a skipped test scores nothing)", "skipped")
    if record.get("ok") is True:
        return Outcome(True, "", "passed")
    return Outcome(False, hint(failures[0]) if failures else "failed", "\n\n".join(failures) or "failed")


def outcomes_of_json(report):
    """Test name -> Outcome, from a gtest JSON report."""
    found = {}
    for suite in report["testsuites"]:
        for test in suite["testsuite"]:
            name = f"{suite['name']}.{test['name']}"
            failures = [f["failure"] for f in test.get("failures", [])]
            if test.get("result") == "SKIPPED":
                found[name] = Outcome(False, "skipped (a skipped test scores nothing)", "skipped")
            elif test.get("status") != "RUN":
                found[name] = Outcome(False, "not run (disabled)", "not run")
            elif failures:
                found[name] = Outcome(False, hint(failures[0]), "\n\n".join(failures))
            else:
                found[name] = Outcome(True, "", "passed")
    return found


# Lines gtest writes around a test's own message: the location, then the assertion.
LOCATION = re.compile(r"^(unknown file|.+:\d+)$")
BOILERPLATE = [re.compile(p) for p in (
    r"^\s",                              # indented: the values of EXPECT_EQ, "  Actual: ..."
    r"^Expected[: ]",                    # "Expected: (a) < (b), actual: ...", "Expected equality ..."
    r"^Value of: ",
    r"^The difference between .* where$",
    r"^.* evaluates to .*(,|, and|\.)$",
    r"^Failed$",
    r"^With diff:$",
    r"^Which is: ",
)]
EXCEPTION = re.compile(r'^C\+\+ exception with description "(.*)" thrown in (the test body|SetUp\(\)|TearDown\(\))\.$',
                       re.DOTALL)


def hint(failure):
    """The test's own message from one gtest failure text, without gtest's lines
    about where and which assertion; gtest's text when the test gave none."""
    lines = failure.strip("\n").split("\n")
    if lines and LOCATION.match(lines[0]):
        lines = lines[1:]
    text = "\n".join(lines)
    thrown = EXCEPTION.match(text)
    if thrown:
        return f"threw: {thrown.group(1)}"
    k = 0
    while k < len(lines) and any(p.match(lines[k]) for p in BOILERPLATE):
        k += 1
    message = " ".join(line.strip() for line in lines[k:] if line.strip())
    return message or " ".join(line.strip() for line in lines if line.strip())
