"""grade: build and run the graded tests, print a score table, write results.json.

    exercises/grade [--labs 1,2] [--json results.json] [--build-dir DIR] [--no-build] [--timeout S]

The labs graded are those named, else those the kit was made for (exercises/KIT),
else, in the full tree, all of them. Every graded test (exercises/labNN/*.cpp, and the
instructor's labNN/hidden/*.cpp) is worth one point. Pass or fail comes from the test
program's signed report (gtest_run.py), each run held by sandbox.py. Each exercise's
tests run in one process; when it hangs, crashes, ends early or leaves something
running, the test in progress fails with the reason, the tests it finished keep their
results, and the rest run in a new process -- except after a timeout, when the rest of
that exercise is not run. Every lab's visible tests run before any hidden one, so
nothing a hidden test's run leaves behind can reach a visible result. The last line
is `score: X/Y`, Y counting every graded test of the chosen labs, built or not.
Exit status: 0 when every lab built and ran, 1 when one did not (the score is still
printed), 2 for a bad command line.
"""
import argparse
import json
import math
import os
import re
import signal
import stat
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import before_main  # noqa: E402
import build      # noqa: E402
import gtest_run  # noqa: E402
import regions    # noqa: E402
import sandbox    # noqa: E402
from scores import gradescope, report, titles  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
SUITE = re.compile(r"^Ex(\d+)_(\d+)_")
TEST_MACRO = re.compile(r"^\s*TEST\(\s*(\w+)\s*,\s*(\w+)\s*\)", re.M)

# Seconds a test (or one exercise's tests together) may take. The reference's
# slowest graded test takes 0.1 s in release and 1.9 s under the sanitizers (measured
# on a loaded 2-core machine), so the limits are about 100 and 80 times the
# reference's; a sanitizer or debug build (read from the build tree's CMakeCache.txt)
# gets the longer one. Below MIN_TIMEOUT a program cannot even start on a busy machine.
LIMIT_RELEASE, LIMIT_SLOW_BUILD, MIN_TIMEOUT, MAX_TIMEOUT = 10.0, 150.0, 1.0, 3600.0


class UsageError(Exception):
    """A bad command line: one line, exit status 2."""


@dataclass
class Result:
    lab: int
    exercise: str    # "1.2"
    name: str        # "Ex1_2_RayPlane.ParallelRayMisses"
    passed: bool
    hint: str        # one line for the table: the test's own message
    detail: str      # the whole story, for results.json
    hidden: bool     # an instructor's test the student never saw


def exercise_of(name, lab):
    m = SUITE.match(name)
    return f"{int(m.group(1))}.{int(m.group(2))}" if m else f"{lab}.?"


def labs_in(root):
    """Lab numbers with graded tests: exercises/labNN/ holding .cpp files."""
    return sorted(int(d.name[3:]) for d in (Path(root) / "exercises").glob("lab[0-9][0-9]")
                  if any(d.glob("*.cpp")))


def source_tests(root, lab):
    """[(test name, hidden)] as written in the lab's sources: the tests the programs
    should hold, known even when they do not build. Hidden tests live in hidden/."""
    folder = Path(root) / "exercises" / f"lab{lab:02d}"
    found = []
    for hidden, pattern in ((False, "*.cpp"), (True, "hidden/*.cpp")):
        for file in sorted(folder.glob(pattern)):
            found += [(f"{s}.{t}", hidden) for s, t in TEST_MACRO.findall(file.read_text(errors="replace"))]
    return found


def kit_labs(root):
    """The labs a kit was made for (exercises/KIT lists its stubbed exercises), or None."""
    kit = Path(root) / "exercises" / "KIT"
    if not kit.is_file():
        return None
    return {int(line.split(".")[0]) for line in kit.read_text().splitlines() if re.match(r"^\d+\.\d+ ", line)}


def choose_labs(spec, root):
    """(labs, why) from --labs, else the kit's record, else every lab."""
    available = labs_in(root)
    if spec is not None:
        try:
            return sorted(regions.parse_labs(spec, available)), "named by --labs"
        except regions.RegionError as e:
            raise UsageError(str(e))
    recorded = kit_labs(root)
    if recorded is not None:
        return sorted(recorded & set(available)), "the labs this kit was made for (exercises/KIT); --labs chooses others"
    return available, "every lab (the full tree)"


def slow_build(build_dir):
    cache = Path(build_dir) / "CMakeCache.txt"
    text = cache.read_text(errors="replace") if cache.is_file() else ""
    return bool(re.search(r"^GI_SANITIZE:BOOL=ON$", text, re.M) or
                re.search(r"^CMAKE_BUILD_TYPE:STRING=Debug$", text, re.M))


def time_limit(build_dir, timeout):
    if timeout is not None:
        return timeout
    return LIMIT_SLOW_BUILD if slow_build(build_dir) else LIMIT_RELEASE


def failed_all(lab, tests, hint):
    return [Result(lab, exercise_of(n, lab), n, False, hint, hint, hidden) for n, hidden in tests]


def grade_program(runner, binary, lab, tests, limit, restubbed, hidden, together=False):
    """(results, problem) of one of a lab's programs. `tests`: [(name, hidden)] from the
    sources, those of this program; `problem` is "" unless the program could not run.
    Each exercise's tests run in one process -- or, `together`, the whole program's
    (the mutant suite: the course's own code, where a fault needs no more isolation)."""
    names = [n for n, _ in tests]
    if binary is None or not Path(binary).is_file():
        problem = "its test program was not built"
        return failed_all(lab, tests, problem), problem
    refused = before_main.refusal(binary)  # code placed to run before the harness takes its key
    if refused:
        problem = f"the lab's test program {refused}: none of its tests was run"
        return failed_all(lab, tests, problem), problem
    results, first = [], True
    exercises = list(dict.fromkeys(exercise_of(n, lab) for n in names))
    stubbed = [e for e in exercises if e in restubbed]
    for exercise in stubbed:
        why = restubbed[exercise]
        hint = why if why.startswith("not taken") else f"your code does not compile: {why}"
        results += [Result(lab, exercise, n, False, hint, hint, hidden) for n in names if exercise_of(n, lab) == exercise]
    groups = [[n for n in names if exercise_of(n, lab) not in stubbed]] if together else \
        [[n for n in names if exercise_of(n, lab) == e] for e in exercises if e not in stubbed]
    for group in groups:
        if not group:
            continue
        outcomes, problem = run_exercise(runner, binary, group, limit, first, lambda n: exercise_of(n, lab))
        first = False
        if problem:
            problem = f"the lab's test program {problem}"
            done = {r.name for r in results}
            return results + failed_all(lab, [(n, hidden) for n in names if n not in done], problem), problem
        results += [Result(lab, exercise_of(n, lab), n, o.passed, o.hint, o.detail, hidden) for n, o in outcomes.items()]
    order = {n: k for k, n in enumerate(names)}
    return sorted(results, key=lambda r: order[r.name]), ""


def grade_lab(runner, build_dir, root, lab, limit, restubbed=None, together=False):
    """(results, problems) of one lab's programs in a built tree, visible then hidden."""
    results, problems = [], []
    for kind, name in build.lab_targets(root, lab):
        tests = [(n, h) for n, h in source_tests(root, lab) if h == (kind == "hidden")]
        found, problem = grade_program(runner, build.program(build_dir, name), lab, tests, limit, restubbed or {},
                                       kind == "hidden", together)
        results += found
        problems += [problem] if problem else []
    return results, problems


def run_exercise(runner, binary, names, limit, first, exercise=lambda name: ""):
    """({test: Outcome}, problem). The tests run in one process; a fault costs the test
    in progress, and the rest run on in a new process -- after a timeout, except the
    rest of the culprit's exercise, which is not run (they would likely hang too)."""
    outcomes, remaining = {}, list(names)
    while remaining:
        run = runner.run_tests(binary, remaining, limit)
        outcomes.update({n: o for n, o in run.outcomes.items() if n in remaining})
        if first and not run.started and run.problem:
            why = "hangs before its first test" if run.returncode is None else \
                f"stops before its first test ({gtest_run.describe_exit(run.returncode)})"
            return {}, why
        first = False
        progress = any(n in outcomes for n in remaining)
        remaining = [n for n in remaining if n not in outcomes]
        if not run.problem or not remaining:
            break
        if run.culprit not in remaining and progress:
            continue  # it stopped between tests (the harness does, after a test left something): go on
        culprit = run.culprit if run.culprit in remaining else remaining[0]
        output = "\n".join(run.output.strip().splitlines()[-20:])
        outcomes[culprit] = gtest_run.Outcome(False, run.problem, f"{run.problem}\n{output}".strip())
        remaining.remove(culprit)
        if run.returncode is None:
            for n in [n for n in remaining if exercise(n) == exercise(culprit)]:
                outcomes[n] = gtest_run.Outcome(False, f"not run: {culprit.split('.')[-1]} of this exercise timed out")
                remaining.remove(n)
    return {n: outcomes[n] for n in names}, ""


class OneLineParser(argparse.ArgumentParser):
    # No abbreviations: '--build' must not quietly mean '--build-dir' and start a build there.
    def __init__(self, *args, **kwargs):
        super().__init__(*args, allow_abbrev=False, **kwargs)

    def error(self, message):
        raise UsageError(message)


def positive_seconds(text):
    try:
        value = float(text) if re.fullmatch(r"[0-9]+(\.[0-9]*)?|\.[0-9]+", text.strip()) else math.nan
    except ValueError:
        value = math.nan
    if not (MIN_TIMEOUT <= value <= MAX_TIMEOUT):
        raise argparse.ArgumentTypeError(f"--timeout takes seconds from {MIN_TIMEOUT:g} to {MAX_TIMEOUT:g} "
                                         f"(decimal digits), got '{text}'")
    return value


def folder(text):
    if not text.strip():
        raise argparse.ArgumentTypeError("--build-dir takes a folder, got ''")
    return Path(os.path.abspath(text))


def parse(argv):
    parser = OneLineParser(prog="grade", description="Grade the exercises of the tree this script stands in.")
    parser.add_argument("--labs", action="append", help="labs to grade, like 1,2 or 'all' (default: the kit's, else all)")
    parser.add_argument("--json", help="write Gradescope's results.json here (a new file, or a regular file it replaces)")
    parser.add_argument("--build-dir", type=folder, default=ROOT / "build" / "release")
    parser.add_argument("--no-build", action="store_true", help="use the graded tests already built")
    parser.add_argument("--timeout", type=positive_seconds, help="seconds per test program run (default: fits the build type)")
    parser.add_argument("--hidden-visibility", default="after_published",
                        choices=["hidden", "after_due_date", "after_published", "visible"],
                        help="Gradescope visibility of the hidden tests' results")
    parser.add_argument("--expect", choices=["full", "zero"], help="exit 1 unless the score is full (or zero)")
    args = parser.parse_args(argv)
    if args.labs is not None and len(args.labs) > 1:
        raise UsageError("--labs is given more than once; name every lab in one list, like --labs 1,2")
    args.labs = args.labs[0] if args.labs else None
    return args


def open_json(path):
    """A temporary file beside --json, made now so that a bad path fails before grading.
    The path must be new or name a regular file: never a folder, a device, a link."""
    if not path.strip():
        raise UsageError("--json takes a file name, got ''")
    target = Path(os.path.abspath(path))
    try:
        info = target.lstat()
    except FileNotFoundError:
        info = None
    except OSError as e:
        raise UsageError(f"cannot write --json {path}: {e.strerror}")
    if info is not None and not stat.S_ISREG(info.st_mode):
        kind = "a folder" if stat.S_ISDIR(info.st_mode) else "a link" if stat.S_ISLNK(info.st_mode) else \
            "not a regular file"
        raise UsageError(f"--json {path} is {kind}: name a new file or a regular one")
    try:
        fd, temp = tempfile.mkstemp(prefix=f".{target.name}.", dir=target.parent)
    except OSError as e:
        raise UsageError(f"cannot write --json {path}: {e.strerror}")
    os.close(fd)
    return Path(temp)


def write_json(temp, target, data):
    """Writes, then renames: a results.json is complete or absent."""
    target = Path(os.path.abspath(target))
    try:
        temp.write_text(json.dumps(data, indent=2))
        info = None
        try:
            info = target.lstat()
        except FileNotFoundError:
            pass
        if info is not None and not stat.S_ISREG(info.st_mode):
            raise OSError(0, f"{target} is no longer a regular file")
        os.replace(temp, target)
    except OSError as e:
        temp.unlink(missing_ok=True)
        raise build.BuildError(f"cannot write {target}: {e.strerror}")


def grade(root, labs, build_dir, limit, do_build, say=print, quick=False, scratch=False, hide=None, runner=None):
    """(results, problems, notes): every chosen lab's results, built or not; notes say
    what the sandbox could not do here."""
    build_dir = Path(build_dir)
    built = build.Built(build_dir)
    if do_build:
        try:
            built = build.build(root, build_dir, labs, say, quick, scratch)
        except build.ConfigureError as e:
            built.lab_errors = {lab: str(e) for lab in labs}
    elif not (build_dir / "bin").is_dir():
        raise build.BuildError(f"no built tree in {build_dir}: build the graded tests first, or drop --no-build")
    else:
        built.binaries = {(lab, kind): build.program(build_dir, name) for lab in labs
                          for kind, name in build.lab_targets(root, lab)}
    own_runner = runner is None
    runner = runner or gtest_run.Runner(hide=[root, build_dir] if hide is None else hide,
                                        memory=None if slow_build(build_dir) else gtest_run.MEMORY)
    by_lab, problems = {}, []
    try:
        for kind in ("graded", "hidden"):  # every visible test before any hidden one
            for lab in labs:
                tests = [(n, h) for n, h in source_tests(root, lab) if h == (kind == "hidden")]
                if not tests:
                    continue
                if lab in built.lab_errors:
                    problem = f"lab {lab} does not build: {built.lab_errors[lab]}"
                    lab_results = failed_all(lab, tests, problem)
                else:
                    lab_results, problem = grade_program(runner, built.binaries.get((lab, kind)), lab, tests, limit,
                                                         built.restubbed, kind == "hidden")
                    problem = f"lab {lab}: {problem}" if problem else ""
                by_lab.setdefault(lab, []).extend(lab_results)
                # A hidden program's problem stays with its tests, hidden as they are: a
                # line of its own would show a student, before publication, that the hidden
                # program failed and how (an exit status the submission could choose).
                if problem and kind == "graded" and problem not in problems:
                    problems.append(problem)
    finally:
        if own_runner:
            runner.close()
    results = [r for lab in labs for r in by_lab.get(lab, [])]
    notes = list(built.notes)
    if missing_note(runner.missing):
        notes.append(missing_note(runner.missing))
    return results, problems, notes


def missing_note(missing):
    """What this system could not give the code under test, in one line (or "")."""
    parts = ["verdicts read from gtest's own report, which the code under test could forge "
             "(this system has no signed report)"] if "channel" in missing else []
    note = sandbox.isolation_note(missing)
    return "; ".join(parts + ([f"the tests ran with {note}"] if note else []))


def stop(signum, frame):
    raise KeyboardInterrupt


_closing = []


def closing_line(text):
    """The run's one closing line on standard error: a signal that comes after it adds none."""
    if not _closing:
        _closing.append(text)
        print(text, file=sys.stderr)


def ignore_signals():
    """From here on a signal cannot interrupt: the cleaning up, or the exit itself."""
    for name in ("SIGINT", "SIGTERM", "SIGHUP"):
        if hasattr(signal, name):
            signal.signal(getattr(signal, name), signal.SIG_IGN)


def main(argv):
    temp = None
    for name in ("SIGTERM", "SIGHUP"):  # exercises/grade turns Ctrl-C into SIGTERM
        if hasattr(signal, name):
            signal.signal(getattr(signal, name), stop)
    try:
        args = parse(argv)
        labs, why = choose_labs(args.labs, ROOT)
        if not labs:
            raise UsageError("no lab to grade (the kit records none; name some with --labs)")
        temp = open_json(args.json) if args.json is not None else None
        limit = time_limit(args.build_dir, args.timeout)
        print(f"grading lab{'s' if len(labs) > 1 else ''} {', '.join(map(str, labs))}: {why}", flush=True)
        results, problems, notes = grade(ROOT, labs, args.build_dir, limit, not args.no_build)
        names = titles(ROOT)
        score, total = sum(r.passed for r in results), len(results)
        print(build.relative(report(results, names), ROOT))
        for p in problems:
            print(build.relative(f"grade: {p}", ROOT))
        for n in notes:
            print(f"grade: note: {n}")
        print(f"score: {score}/{total}")
        if temp:
            write_json(temp, Path(args.json), gradescope(results, names, args.hidden_visibility, ROOT))
            temp = None
    except UsageError as e:
        closing_line(f"grade: error: {e} (try --help)")
        return 2
    except (build.BuildError, regions.RegionError) as e:
        closing_line(f"grade: error: {e}")
        return 1
    except KeyboardInterrupt:
        ignore_signals()  # a second one must not interrupt the cleaning up
        closing_line("grade: interrupted")
        return 130
    finally:
        if temp:
            temp.unlink(missing_ok=True)
    if problems:
        return 1
    if args.expect == "full" and not (total > 0 and score == total):
        return 1
    if args.expect == "zero" and not (total > 0 and score == 0):
        return 1
    return 0


if __name__ == "__main__":
    # A signal that comes as main returns (after an error line, say) ends the run as
    # one does during it: one line, status 130, never a traceback from the exit.
    try:
        status = main(sys.argv[1:])
        ignore_signals()
    except KeyboardInterrupt:
        ignore_signals()
        closing_line("grade: interrupted")
        status = 130
    sys.exit(status)
