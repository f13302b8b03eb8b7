"""grade: build and run the graded tests, print a score table, write results.json.

    exercises/grade [--labs 1,2] [--json results.json] [--build-dir DIR] [--no-build] [--timeout S]

The labs graded are those named, else those the kit was made for (exercises/KIT),
else, in the full tree, all of them. Every graded test (exercises/labNN/*.cpp) is
worth one point. Pass or fail comes from gtest's own report (see gtest_run.py);
each exercise runs in one process, and only when that process hangs, crashes or
ends early are its tests run one per process, so that the fault costs the test
that caused it. After a test's first timeout the rest of its exercise is not run.
The last line is `score: X/Y`, where Y counts every graded test of the chosen labs,
built or not. Exit status: 0 when every lab built and ran, 1 when one did not (the
score is still printed), 2 for a bad command line.
"""
import argparse
import json
import math
import os
import re
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import build      # noqa: E402
import gtest_run  # noqa: E402
import regions    # noqa: E402
from scores import gradescope, report, titles  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
SUITE = re.compile(r"^Ex(\d+)_(\d+)_")
TEST_MACRO = re.compile(r"^\s*TEST\(\s*(\w+)\s*,\s*(\w+)\s*\)", re.M)

# Seconds a test (or one exercise's tests together) may take. The reference's
# slowest graded test takes 0.1 s in release and 1.9 s under the sanitizers (measured
# on a loaded 2-core machine), so the limits are about 100 and 80 times the
# reference's; a sanitizer or debug build (read from the build tree's CMakeCache.txt)
# gets the longer one.
LIMIT_RELEASE, LIMIT_SLOW_BUILD = 10.0, 150.0


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
    """[(test name, hidden)] as written in the lab's sources: the tests the program
    should hold, known even when it does not build. Hidden tests live in hidden/."""
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


def time_limit(build_dir, timeout):
    if timeout is not None:
        return timeout
    cache = Path(build_dir) / "CMakeCache.txt"
    text = cache.read_text(errors="replace") if cache.is_file() else ""
    slow = re.search(r"^GI_SANITIZE:BOOL=ON$", text, re.M) or re.search(r"^CMAKE_BUILD_TYPE:STRING=Debug$", text, re.M)
    return LIMIT_SLOW_BUILD if slow else LIMIT_RELEASE


def failed_all(lab, tests, hint):
    return [Result(lab, exercise_of(n, lab), n, False, hint, hint, hidden) for n, hidden in tests]


def grade_lab(binary, lab, tests, limit, restubbed):
    """(results, problem) of one lab. `tests`: [(name, hidden)] from the sources;
    `problem` is "" unless the lab's program could not be run at all."""
    hidden = {n for n, h in tests if h}
    if not Path(binary).is_file():
        problem = f"no test program {binary}: it was not built"
        return failed_all(lab, tests, problem), problem
    names, problem = gtest_run.list_tests(binary, limit)
    if problem:
        problem = f"the lab's test program {problem}"
        return failed_all(lab, tests, problem), problem
    names = sorted(names, key=lambda n: n in hidden)  # the student's own tests first
    results = []
    for exercise in dict.fromkeys(exercise_of(n, lab) for n in names):
        mine = [n for n in names if exercise_of(n, lab) == exercise]
        if exercise in restubbed:
            hint = f"your code does not compile: {restubbed[exercise]}"
            results += [Result(lab, exercise, n, False, hint, hint, n in hidden) for n in mine]
            continue
        run = gtest_run.run_tests(binary, mine, limit)
        outcomes = run.outcomes if not run.problem else one_by_one(binary, mine, limit)
        results += [Result(lab, exercise, n, o.passed, o.hint, o.detail, n in hidden) for n, o in outcomes.items()]
    return results, ""


def one_by_one(binary, names, limit):
    """Each test in its own process; after a timeout the others are not run."""
    outcomes, timed_out = {}, None
    for name in names:
        if timed_out:
            outcomes[name] = gtest_run.Outcome(False, f"not run: {timed_out} of this exercise timed out")
            continue
        run = gtest_run.run_tests(binary, [name], limit)
        if not run.problem:
            outcomes[name] = run.outcomes[name]
            continue
        tail = "\n".join(run.output.strip().splitlines()[-20:])
        outcomes[name] = gtest_run.Outcome(False, run.problem, f"{run.problem}\n{tail}".strip())
        if run.returncode is None:
            timed_out = name.split(".")[-1]
    return outcomes


class OneLineParser(argparse.ArgumentParser):
    # No abbreviations: '--build' must not quietly mean '--build-dir' and start a build there.
    def __init__(self, *args, **kwargs):
        super().__init__(*args, allow_abbrev=False, **kwargs)

    def error(self, message):
        raise UsageError(message)


def positive_seconds(text):
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"--timeout takes seconds, got '{text}'")
    if not (math.isfinite(value) and 0 < value <= 3600):
        raise argparse.ArgumentTypeError(f"--timeout takes seconds in (0, 3600], got '{text}'")
    return value


def parse(argv):
    parser = OneLineParser(prog="grade", description="Grade the exercises of the tree this script stands in.")
    parser.add_argument("--labs", help="labs to grade, like 1,2 or 'all' (default: the kit's, else all)")
    parser.add_argument("--json", help="write Gradescope's results.json here")
    parser.add_argument("--build-dir", default=str(ROOT / "build" / "release"))
    parser.add_argument("--no-build", action="store_true", help="use the graded tests already built")
    parser.add_argument("--timeout", type=positive_seconds, help="seconds per test (default: fits the build type)")
    parser.add_argument("--hidden-visibility", default="after_published",
                        choices=["hidden", "after_due_date", "after_published", "visible"],
                        help="Gradescope visibility of the hidden tests' results")
    parser.add_argument("--expect", choices=["full", "zero"], help="exit 1 unless the score is full (or zero)")
    return parser.parse_args(argv)


def open_json(path):
    """A temporary file beside --json, made now so that a bad path fails before grading."""
    target = Path(path)
    if target.is_dir():
        raise UsageError(f"--json {path} is a folder")
    try:
        fd, temp = tempfile.mkstemp(prefix=f".{target.name}.", dir=target.parent if str(target.parent) else ".")
    except OSError as e:
        raise UsageError(f"cannot write --json {path}: {e.strerror}")
    os.close(fd)
    return Path(temp)


def write_json(temp, target, data):
    """Writes, then renames: a results.json is complete or absent."""
    try:
        temp.write_text(json.dumps(data, indent=2))
        os.replace(temp, target)
    except OSError as e:
        temp.unlink(missing_ok=True)
        raise build.BuildError(f"cannot write {target}: {e.strerror}")


def grade(root, labs, build_dir, limit, do_build, say=print, quick=False, scratch=False):
    """(results, problems): every chosen lab's results, built or not."""
    build_dir = Path(build_dir)
    built = build.Built(build_dir)
    if do_build:
        try:
            built = build.build(root, build_dir, labs, say, quick, scratch)
        except build.ConfigureError as e:
            built.lab_errors = {lab: str(e) for lab in labs}
    elif not (build_dir / "bin").is_dir():
        raise build.BuildError(f"no built tree in {build_dir}: build the graded tests first, or drop --no-build")
    results, problems = [], []
    for lab in labs:
        tests = source_tests(root, lab)
        if lab in built.lab_errors:
            problem = f"lab {lab} does not build: {built.lab_errors[lab]}"
            results += failed_all(lab, tests, problem)
        else:
            lab_results, problem = grade_lab(built.binary_dir / "bin" / f"lab{lab:02d}_graded", lab, tests, limit,
                                             built.restubbed)
            results += lab_results
        if problem:
            problems.append(problem)
    return results, problems


def main(argv):
    temp = None
    try:
        args = parse(argv)
        labs, why = choose_labs(args.labs, ROOT)
        if not labs:
            raise UsageError("no lab to grade (the kit records none; name some with --labs)")
        temp = open_json(args.json) if args.json else None
        limit = time_limit(args.build_dir, args.timeout)
        print(f"grading lab{'s' if len(labs) > 1 else ''} {', '.join(map(str, labs))}: {why}")
        results, problems = grade(ROOT, labs, args.build_dir, limit, not args.no_build)
        names = titles(ROOT)
        score, total = sum(r.passed for r in results), len(results)
        print(report(results, names))
        for p in problems:
            print(f"grade: {p}")
        print(f"score: {score}/{total}")
        if temp:
            write_json(temp, Path(args.json), gradescope(results, names, args.hidden_visibility))
            temp = None
    except UsageError as e:
        print(f"grade: error: {e} (try --help)", file=sys.stderr)
        return 2
    except (build.BuildError, regions.RegionError) as e:
        print(f"grade: error: {e}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("grade: interrupted", file=sys.stderr)
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
    sys.exit(main(sys.argv[1:]))
