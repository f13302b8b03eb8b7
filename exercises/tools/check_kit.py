"""check_kit: a student kit builds, scores 0 on every graded test, and holds no
solution text. Run by ctest as kit_check:

    check_kit.py ROOT WORKDIR

WORKDIR (wiped first) receives the kit and its build. The tree's own graded tests
must already be built in WORKDIR's parent (the tree's build folder).
"""
import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import grade    # noqa: E402
import kit      # noqa: E402
import regions  # noqa: E402


def distinctive_lines(root, all_regions):
    """Per region, the lines of its body that appear in no other source code:
    finding one of them anywhere in the kit means the solution leaked."""
    outside = set()
    in_region = {(r.path, i) for r in all_regions for i in range(r.begin + 1, r.end)}
    for rel in kit.project_files(root):
        if rel.suffix not in regions.SOURCE_SUFFIXES:
            continue  # docs quote the solution in excerpts; the kit must not, so they cannot vouch
        try:
            lines = (root / rel).read_text().splitlines()
        except UnicodeDecodeError:
            continue
        outside |= {l.strip() for i, l in enumerate(lines) if (rel, i) not in in_region}
    return {r.id: [l.strip() for l in regions.body(root, r) if len(l.strip()) >= 12 and l.strip() not in outside]
            for r in all_regions}


def leaks(kit_dir, secrets):
    """(file:line, exercise) wherever a distinctive solution line occurs in the kit."""
    wanted = {line: ident for ident, lines in secrets.items() for line in lines}
    found = []
    for path in sorted(p for p in kit_dir.rglob("*") if p.is_file() and "build" not in p.relative_to(kit_dir).parts):
        try:
            lines = path.read_text().splitlines()
        except UnicodeDecodeError:
            continue
        found += [(f"{path.relative_to(kit_dir)}:{i + 1}", wanted[l.strip()])
                  for i, l in enumerate(lines) if l.strip() in wanted]
    return found


def main(argv):
    root, work = Path(argv[1]).resolve(), Path(argv[2]).resolve()
    shutil.rmtree(work, ignore_errors=True)
    kit_dir, kit_build = work / "kit", work / "kit" / "build" / "release"
    all_regions = regions.find_regions(root)
    kit.make_kit(root, kit_dir, "all")
    problems = []

    for r in regions.find_regions(kit_dir):
        if regions.body(kit_dir, r) != [r.stub()]:
            problems.append(f"exercise {r.id}: the kit's region is not exactly the stub")
    if len(regions.find_regions(kit_dir)) != len(all_regions):
        problems.append("the kit lost or gained exercise regions")
    problems += [f"{where}: solution text of exercise {ident}" for where, ident in
                 leaks(kit_dir, distinctive_lines(root, all_regions))]

    # The kit must build as a student receives it.
    for step in (["cmake", "-S", str(kit_dir), "-B", str(kit_build), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release"],
                 ["cmake", "--build", str(kit_build), "-j", "2"]):
        done = subprocess.run(step, capture_output=True, text=True)
        if done.returncode != 0:
            print((done.stdout + done.stderr)[-4000:])
            problems.append(f"the kit does not build: {' '.join(step)}")
            break
    else:
        labs = grade.labs_in(kit_dir)
        kit_results, _ = grade.grade(labs, kit_build, 20, False)
        tree_results = sum(len(grade.list_tests(subprocess.run(
            [str(work.parent / "bin" / f"lab{lab:02d}_graded"), "--gtest_list_tests"],
            capture_output=True, text=True, check=True).stdout)) for lab in labs)
        passed = [r.name for r in kit_results if r.passed]
        print(f"kit: {len(kit_results)} graded tests, {len(passed)} passed on the stubs; tree has {tree_results}")
        if passed:
            problems.append("graded tests that pass on the stubs (they cannot fail): " + ", ".join(passed))
        if len(kit_results) != tree_results:
            problems.append(f"the kit has {len(kit_results)} graded tests, the tree {tree_results}")
        crashed = [r.name for r in kit_results if not r.passed and "NotImplemented" not in r.output
                   and "not implemented" not in r.output]
        if crashed:
            problems.append("graded tests that fail on the stubs for another reason than NotImplemented: " + ", ".join(crashed))

    for p in problems:
        print(f"kit_check: {p}")
    print("kit_check: " + ("FAILED" if problems else "the kit builds, scores 0 and holds no solution"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
