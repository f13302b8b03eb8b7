"""gtest_run: run a GoogleTest program the way a grader must.

Pass or fail comes from gtest's own JSON report (--gtest_output=json) and from its
premature-exit file (TEST_PREMATURE_EXIT_FILE, which gtest deletes only when
RUN_ALL_TESTS returns), never from the text a test prints: code under test can
print "[  PASSED  ]" and exit 0, but it cannot make gtest record a pass. Every run
has a time limit that kills the program's whole process group, and its output goes
to a file, not a pipe, so a child left behind cannot stall the grader; the file may
grow to 64 MB (RLIMIT_FSIZE), so a test that prints without end cannot fill the disk.
"""
import json
import os
import re
import resource
import signal
import subprocess
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

KEEP_OUTPUT = 16384  # characters of a program's output kept for messages
MAX_FILE = 64 << 20  # bytes any file the program writes may reach


@dataclass
class Outcome:
    """What one test did: passed, and if not, the hint and the whole story."""
    passed: bool
    hint: str            # one line for the score table: the test's own message
    detail: str = ""     # everything gtest said, for results.json


@dataclass
class Run:
    """One run of a test program."""
    problem: str                      # "" when gtest wrote a complete report
    returncode: int | None = None     # None: killed at the time limit
    output: str = ""                  # the tail of stdout and stderr
    outcomes: dict = field(default_factory=dict)  # test name -> Outcome, from the report


def clean_env(extra):
    """The environment without GTEST_* variables (a grade must not depend on them)."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("GTEST_")}
    env.update(extra)
    return env


def limit_file_size():
    resource.setrlimit(resource.RLIMIT_FSIZE, (MAX_FILE, MAX_FILE))


def run_program(argv, timeout, env=None, cwd=None):
    """(return code or None on timeout, output tail). The program gets no stdin."""
    with tempfile.TemporaryFile() as out:
        try:
            process = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=out, stderr=subprocess.STDOUT,
                                       env=env, cwd=cwd, start_new_session=True, preexec_fn=limit_file_size)
        except OSError as e:
            return 127, f"cannot start {argv[0]}: {e.strerror}"
        try:
            code = process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            code = None
        finally:
            try:
                os.killpg(process.pid, signal.SIGKILL)  # the program and anything it started
            except ProcessLookupError:
                pass
            process.wait()
        size = out.seek(0, os.SEEK_END)
        out.seek(max(0, size - 4 * KEEP_OUTPUT))
        return code, out.read().decode("utf-8", errors="replace")[-KEEP_OUTPUT:]


def describe_exit(code):
    """'killed by SIGSEGV (segmentation fault)' or 'exit status 3'."""
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
                   "SIGXFSZ": "output past 64 MB: printing without end?"}.get(name)
        return f"killed by {name}" + (f" ({meaning})" if meaning else "")
    return f"exit status {code}"


def list_tests(binary, timeout):
    """(test names in gtest's order, problem). Listing runs the program's static
    initialisers, so it too may hang or crash; the list comes from gtest's JSON."""
    with tempfile.TemporaryDirectory() as tmp:
        report = Path(tmp) / "list.json"
        code, output = run_program([str(binary), "--gtest_list_tests", f"--gtest_output=json:{report}"], timeout,
                                   env=clean_env({}))
        if code is None:
            return [], f"hangs while listing its tests (killed after {timeout:g} s): code that runs before any test?"
        if code != 0:
            return [], f"fails while listing its tests ({describe_exit(code)})"
        try:
            data = json.loads(report.read_bytes().decode("utf-8", errors="replace"))
            return [f"{suite['name']}.{test['name']}" for suite in data["testsuites"] for test in suite["testsuite"]], ""
        except (OSError, ValueError, KeyError, TypeError):
            return [], "wrote no readable list of its tests"


def run_tests(binary, names, timeout):
    """Runs the named tests in one process; the report says which passed."""
    with tempfile.TemporaryDirectory() as tmp:
        report, premature = Path(tmp) / "report.json", Path(tmp) / "premature-exit"
        argv = [str(binary), "--gtest_filter=" + ":".join(names), f"--gtest_output=json:{report}", "--gtest_color=no"]
        code, output = run_program(argv, timeout, env=clean_env({"TEST_PREMATURE_EXIT_FILE": str(premature)}),
                                   cwd=tmp)
        run = Run("", code, output)
        if code is None:
            run.problem = f"timed out after {timeout:g} s (an endless loop?)"
        elif code < 0:
            run.problem = f"crashed, {describe_exit(code)}"
        elif premature.exists():
            run.problem = f"the program ended in the middle of a test ({describe_exit(code)}): exit() or abort() called?"
        else:
            try:
                run.outcomes = outcomes(json.loads(report.read_bytes().decode("utf-8", errors="replace")))
            except (OSError, ValueError, KeyError, TypeError):
                run.problem = f"ended without writing gtest's report ({describe_exit(code)})"
            else:
                missing = [n for n in names if n not in run.outcomes]
                if missing:
                    run.problem = f"gtest's report lacks {len(missing)} of the tests ({describe_exit(code)})"
        return run


def outcomes(report):
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
