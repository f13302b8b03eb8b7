"""grade: build and run the graded tests, print a score table, write results.json.

    exercises/grade [--labs 1,2] [--json results.json] [--build-dir DIR] [--no-build]

Every graded test (exercises/labNN/*.cpp) is worth one point and runs in a process
of its own, so a crash or an endless loop costs that test alone. The last line is
`score: X/Y`. --json writes Gradescope's results.json.
"""
import argparse
import json
import re
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import regions  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
SUITE = re.compile(r"^Ex(\d+)_(\d+)_")


@dataclass
class Result:
    lab: int
    exercise: str   # "1.2"
    name: str       # "Ex1_2_RayPlane.ParallelRayMisses"
    passed: bool
    output: str


def labs_in(root):
    """Lab numbers with graded tests: exercises/labNN/ holding .cpp files."""
    return sorted(int(d.name[3:]) for d in (Path(root) / "exercises").glob("lab[0-9][0-9]")
                  if any(d.glob("*.cpp")))


def list_tests(listing):
    """Test names from the text of --gtest_list_tests."""
    names, suite = [], None
    for line in listing.splitlines():
        if not line.strip():
            continue
        if not line.startswith(" "):
            suite = line.split("#")[0].strip().rstrip(".")
        elif suite:
            names.append(f"{suite}.{line.split('#')[0].strip()}")
    return names


def failure_text(output, name):
    """What a failing test printed between its RUN and FAILED lines."""
    run = output.find(f"[ RUN      ] {name}")
    failed = output.find(f"[  FAILED  ] {name}", run)
    text = output[run:failed] if run >= 0 and failed > run else output
    return "\n".join(line for line in text.splitlines()[1:] if line.strip()).strip() or output.strip()


def run_test(binary, name, timeout):
    """(passed, output) of one test run alone."""
    try:
        done = subprocess.run([str(binary), f"--gtest_filter={name}", "--gtest_color=no"],
                              capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return False, f"timed out after {timeout} s (an endless loop?)"
    output = done.stdout + done.stderr
    if done.returncode == 0 and "[  PASSED  ] 1 test" in output:
        return True, "passed"
    if done.returncode < 0 or "[  FAILED  ]" not in output:
        return False, f"crashed (exit status {done.returncode})\n{output[-2000:]}"
    return False, failure_text(output, name)


def build(build_dir, labs):
    """Configures (if needed) and builds the labs' graded tests; returns the failure log or None."""
    steps = []
    if not (build_dir / "CMakeCache.txt").exists():
        steps.append(["cmake", "-S", str(ROOT), "-B", str(build_dir), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release"])
    steps.append(["cmake", "--build", str(build_dir), "--target"] + [f"lab{lab:02d}_graded" for lab in labs])
    for step in steps:
        done = subprocess.run(step, capture_output=True, text=True)
        if done.returncode != 0:
            return (done.stdout + done.stderr)[-6000:]
    return None


def grade(labs, build_dir, timeout, do_build):
    """All results, or (None, build log) when the build failed."""
    if do_build:
        log = build(build_dir, labs)
        if log:
            return None, log
    results = []
    for lab in labs:
        binary = build_dir / "bin" / f"lab{lab:02d}_graded"
        listing = subprocess.run([str(binary), "--gtest_list_tests"], capture_output=True, text=True, check=True).stdout
        for name in list_tests(listing):
            m = SUITE.match(name)
            exercise = f"{int(m.group(1))}.{int(m.group(2))}" if m else f"{lab}.?"
            passed, output = run_test(binary, name, timeout)
            results.append(Result(lab, exercise, name, passed, output))
    return results, None


def titles():
    try:
        return {r.id: r.title for r in regions.find_regions(ROOT)}
    except regions.RegionError:
        return {}


def report(results):
    """The score table, per lab and exercise."""
    names = titles()
    lines = []
    for lab in sorted({r.lab for r in results}):
        lines.append(f"Lab {lab}")
        for exercise in sorted({r.exercise for r in results if r.lab == lab}, key=lambda e: [int(x) for x in e.split(".") if x.isdigit()]):
            mine = [r for r in results if r.exercise == exercise]
            score = sum(r.passed for r in mine)
            lines.append(f"  {exercise:<5} {names.get(exercise, ''):<55} {score:>3}/{len(mine)}")
            lines += [f"        failed: {r.name}: {r.output.splitlines()[0] if r.output else ''}"
                      for r in mine if not r.passed]
        lab_results = [r for r in results if r.lab == lab]
        lines.append(f"  {'lab total':<61} {sum(r.passed for r in lab_results):>3}/{len(lab_results)}")
    return "\n".join(lines)


def gradescope(results, summary, build_log=None):
    names = titles()
    if build_log is not None:
        return {"score": 0, "output": "The build failed:\n" + build_log, "stdout_visibility": "visible", "tests": []}
    return {
        "score": sum(r.passed for r in results),
        "output": summary,
        "stdout_visibility": "visible",
        "tests": [{"name": f"{r.exercise} {names.get(r.exercise, '')}: {r.name}".strip(), "score": int(r.passed),
                   "max_score": 1, "output": r.output, "visibility": "visible"} for r in results],
    }


def main(argv):
    parser = argparse.ArgumentParser(prog="grade", description="Grade the exercises of the tree this script stands in.")
    parser.add_argument("--labs", default="all", help="'all' or a list like 1,2")
    parser.add_argument("--json", help="write Gradescope's results.json here")
    parser.add_argument("--build-dir", default=str(ROOT / "build" / "release"))
    parser.add_argument("--no-build", action="store_true", help="use the graded tests already built")
    parser.add_argument("--timeout", type=float, default=20, help="seconds per test")
    parser.add_argument("--expect", choices=["full", "zero"], help="exit 1 unless the score is full (or zero)")
    args = parser.parse_args(argv)
    try:
        labs = sorted(regions.parse_labs(args.labs, labs_in(ROOT)))
    except regions.RegionError as e:
        print(f"grade: error: {e}", file=sys.stderr)
        return 2
    results, build_log = grade(labs, Path(args.build_dir), args.timeout, not args.no_build)
    if build_log is not None:
        print(build_log)
        print("grade: the build failed; every test scores 0\nscore: 0/0")
        if args.json:
            Path(args.json).write_text(json.dumps(gradescope([], "", build_log), indent=2))
        return 1
    summary = report(results)
    score, total = sum(r.passed for r in results), len(results)
    print(summary)
    print(f"score: {score}/{total}")
    if args.json:
        Path(args.json).write_text(json.dumps(gradescope(results, summary), indent=2))
    if args.expect == "full" and not (total > 0 and score == total):
        return 1
    if args.expect == "zero" and not (total > 0 and score == 0):
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
