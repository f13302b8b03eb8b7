"""check_kit: a student kit of every lab is what a student should receive. Run by
ctest as kit_check:

    check_kit.py ROOT WORK

WORK is the copy of the tree with a build that the mutant suite keeps (build/<preset>/
mutants: WORK/src, WORK/build). The kit is written to WORK/kit and checked as text: no
instructor-only file and no solution text. Then the copy becomes the kit -- only the
files that differ are copied (the exercises' files, the docs, exercises/KIT) and the
instructor's removed -- and is built whole, incrementally: the files with exercises and
what includes them are compiled again, every program relinked, instead of a second
tree built from nothing. Checked on that build: it builds without warnings from the
stubs; every graded test fails, and fails because of the stub it reaches (a test that
passes on the stubs cannot tell a right answer from none); the kit has the tree's
visible graded tests; its own ctest passes (a test reaching a stub is skipped, never
failed); and the `lessons` target runs every lesson, not stopping at the first that
reaches a stub. At the end the copy is the reference again (built on demand by the
next user).
"""
import re
import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import build      # noqa: E402
import grade      # noqa: E402
import gtest_run  # noqa: E402
import kit        # noqa: E402
import regions    # noqa: E402


def run(argv, problems, what, cwd=None):
    done = subprocess.run(argv, capture_output=True, text=True, errors="replace", stdin=subprocess.DEVNULL, cwd=cwd)
    if done.returncode != 0:
        print((done.stdout + done.stderr)[-4000:])
        problems.append(f"{what} fails: {' '.join(map(str, argv))}")
    return done


def become(tree, source, build_dir):
    """Makes the copy `tree` hold exactly `source`'s files, and configures its build again
    (a kit's CMake differs: exercises/KIT ends exercises/CMakeLists.txt early)."""
    changed = build.sync_tree(source, tree)
    build.configure(tree, build_dir, quick=True)
    code, log = build.run(["cmake", str(build_dir)])
    if code != 0:
        raise build.BuildError(f"cmake cannot configure {tree} again: {build.first_error(log)}")
    return changed


def main(argv):
    root, work = Path(argv[1]).resolve(), Path(argv[2]).resolve()
    tree, kit_build, kit_dir = work / "src", work / "build", work / "kit"
    shutil.rmtree(kit_dir, ignore_errors=True)
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
    try:
        changed = become(tree, kit_dir, kit_build)
        print(f"kit: {len(changed)} files differ from the reference's copy; building it incrementally", flush=True)
        done = run(["cmake", "--build", str(kit_build), "--", "-j", "2"], problems, "building the kit")
        warnings = sorted({line for line in (done.stdout + done.stderr).splitlines() if "warning:" in line})
        if warnings:
            problems.append(f"the kit builds with {len(warnings)} warning(s), the first: {warnings[0]}")
        if done.returncode == 0:
            labs = grade.labs_in(tree)
            with gtest_run.Runner(isolate=False) as runner:
                results, lab_problems, _ = grade.grade(tree, labs, kit_build, grade.time_limit(kit_build, None), False,
                                                       runner=runner)
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
            lessons = run(["cmake", "--build", str(kit_build), "--target", "lessons"], problems,
                          "the kit's lessons target")
            ran = len(re.findall(r"^== \d\d_\w+ ==$", lessons.stdout + lessons.stderr, re.M))  # one line per lesson
            expected = len(list((tree / "lessons").glob("[0-9][0-9]_*/main.cpp")))
            if ran < expected:
                problems.append(f"the lessons target ran {ran} of {expected} lessons")
    except build.BuildError as e:
        problems.append(str(e))
    finally:
        try:
            become(tree, root, kit_build)
        except build.BuildError as e:
            problems.append(f"the copy cannot be made the reference again: {e}")

    for p in problems:
        print(f"kit_check: {p}")
    print("kit_check: " + ("FAILED" if problems else "the kit builds, scores 0, passes its ctest and holds no solution"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
