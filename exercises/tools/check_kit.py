"""check_kit: a student kit of every lab is what a student should receive. Run by
ctest as kit_check:

    check_kit.py ROOT WORKDIR

WORKDIR (wiped first) receives the kit and its build. Checked: no instructor-only
file and no solution text in the kit; it builds whole (lessons, unit tests, graded
tests); every graded test fails, and fails because of the stub it reaches (each
kit test must be able to fail: a test that passes on the stubs cannot tell a right
answer from none); the kit has the tree's visible graded tests; the kit's own ctest
passes (a test reaching a stub is reported as skipped, never as failed); and the
`lessons` target runs every lesson, not stopping at the first that reaches a stub.
"""
import re
import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import build    # noqa: E402
import grade    # noqa: E402
import kit      # noqa: E402
import regions  # noqa: E402


def run(argv, problems, what):
    done = subprocess.run(argv, capture_output=True, text=True, errors="replace", stdin=subprocess.DEVNULL)
    if done.returncode != 0:
        print((done.stdout + done.stderr)[-4000:])
        problems.append(f"{what} fails: {' '.join(map(str, argv))}")
    return done


def main(argv):
    root, work = Path(argv[1]).resolve(), Path(argv[2]).resolve()
    shutil.rmtree(work, ignore_errors=True)
    kit_dir, kit_build = work / "kit", work / "kit" / "build" / "release"
    problems = []
    try:
        punched = kit.make_kit(root, kit_dir, "all")
    except (kit.KitError, regions.RegionError) as e:
        print(f"kit_check: FAILED: make-kit: {e}")
        return 1
    if len(punched) != len(regions.find_regions(root)):
        problems.append("the kit does not stub every exercise")
    problems += [f"instructor-only file in the kit: {rel}" for rel in build.project_files(kit_dir)
                 if kit.instructor_only(rel)]

    configure = ["cmake", "-S", str(kit_dir), "-B", str(kit_build), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release"]
    if run(configure, problems, "configuring the kit").returncode == 0 and \
            run(["cmake", "--build", str(kit_build), "-j", "2"], problems, "building the kit").returncode == 0:
        labs = grade.labs_in(kit_dir)
        results, lab_problems, _ = grade.grade(kit_dir, labs, kit_build, grade.time_limit(kit_build, None), False)
        problems += lab_problems
        visible = sum(1 for lab in labs for _, hidden in grade.source_tests(root, lab) if not hidden)
        passed = [r.name for r in results if r.passed]
        print(f"kit: {len(results)} graded tests, {len(passed)} passed on the stubs; the tree has {visible} visible")
        if passed:
            problems.append("graded tests that pass on the stubs (they cannot fail): " + ", ".join(passed))
        if len(results) != visible:
            problems.append(f"the kit has {len(results)} graded tests, the tree {visible} visible ones")
        other = [f"{r.name} ({r.hint})" for r in results if not r.passed and "not implemented" not in r.hint]
        if other:
            problems.append("graded tests failing on the stubs for another reason than NotImplemented: "
                            + "; ".join(other[:5]))
        run(["ctest", "--test-dir", str(kit_build), "-j", "2", "--timeout", "300"], problems, "the kit's ctest")
        lessons = run(["cmake", "--build", str(kit_build), "--target", "lessons"], problems, "the kit's lessons target")
        ran = len(re.findall(r"^== \d\d_\w+ ==$", lessons.stdout + lessons.stderr, re.M))  # one line per lesson
        expected = len(list((kit_dir / "lessons").glob("[0-9][0-9]_*/main.cpp")))
        if ran < expected:
            problems.append(f"the lessons target ran {ran} of {expected} lessons")

    for p in problems:
        print(f"kit_check: {p}")
    print("kit_check: " + ("FAILED" if problems else "the kit builds, scores 0, passes its ctest and holds no solution"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
