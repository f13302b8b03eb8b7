"""check_autograder: the Gradescope autograder and the folder grader, end to end, on
lab 1 kits with a planted bug. Run by ctest as autograder_end_to_end:

    check_autograder.py WORK

WORK is a copy of the tree with a build (the mutant suite's, build/<preset>/mutants):
grading reuses it, so each submission costs a recompile of the files it changes.
The submissions, each a lab 1 kit:
  good     the reference solution copied into the kit's regions;
  planted  the same with a bug in exercise 1.1 (the mutant 1.1 far-root-first);
  broken   the same with a syntax error in exercise 1.2;
  empty    nothing at all.
Checked: the autograder zip holds setup.sh, run_autograder and the hidden tests;
run_autograder, run on the planted submission exactly as Gradescope runs it, writes
a results.json whose score is every test but those the bug fails, with the hidden
tests marked hidden and the failures' hints in their output; the folder grader's CSV
gives each submission the score it deserves (a syntax error costs its exercise only).
"""
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile
import zipfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import grade       # noqa: E402
import kit         # noqa: E402
import mutants     # noqa: E402
import regions     # noqa: E402
import submission  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]


def solved_kit(folder, mutate=None, break_region=None):
    """A lab 1 kit with the reference's regions put back, then a mutant or a syntax error."""
    kit.make_kit(ROOT, folder, "1")
    for r in [r for r in regions.find_regions(ROOT) if r.lab == 1]:
        text = (ROOT / r.path).read_text()
        if mutate and mutate.exercise == r.id:
            text = mutants.apply(text, mutate)
        if break_region == r.id:
            text = text.replace("  // END EXERCISE " + r.id, "  return Hit{  // a brace left open\n  // END EXERCISE " + r.id)
        (folder / r.path).write_text(text)


def expect(condition, message, problems):
    if not condition:
        problems.append(message)


def main(argv):
    work = Path(argv[1]).resolve()
    problems = []
    planted = next(m for m in mutants.load(sorted((ROOT / "exercises" / "mutants").glob("lab01.mut")))
                   if m.name == "far-root-first")
    tests = grade.source_tests(ROOT, 1)
    hidden = {n for n, h in tests if h}
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        folder = tmp / "submissions"
        solved_kit(folder / "good")
        solved_kit(folder / "planted", mutate=planted)
        solved_kit(folder / "broken", break_region="1.2")
        (folder / "empty").mkdir()

        # Gradescope: the zip, unpacked as Gradescope does, and run_autograder on the planted kit.
        submission.make_zip(tmp / "autograder.zip", [1], "after_published")
        with zipfile.ZipFile(tmp / "autograder.zip") as z:
            names = set(z.namelist())
        submission.unpack(tmp / "autograder.zip", tmp / "ag" / "source")
        for required in ("setup.sh", "run_autograder", submission.CONFIG):
            expect(required in names, f"the zip lacks {required}", problems)
        expect(any("/hidden/" in n for n in names), "the zip lacks the hidden tests", problems)
        expect(not any(n.startswith("exercises/mutants/") for n in names), "the zip carries the mutants", problems)
        shutil.copytree(folder / "planted", tmp / "ag" / "submission")
        script = tmp / "ag" / "source" / "run_autograder"
        done = subprocess.run([str(script)], capture_output=True, text=True, errors="replace",
                              env=dict(os.environ, GI_AUTOGRADER_ROOT=str(tmp / "ag"), GI_AUTOGRADER_WORK=str(work)))
        print(done.stdout[-3000:], done.stderr[-3000:])
        results = tmp / "ag" / "results" / "results.json"
        expect(done.returncode == 0, f"run_autograder exited with {done.returncode}", problems)
        if results.is_file():
            data = json.loads(results.read_text())
            failed = [t for t in data["tests"] if t["score"] == 0]
            expect(len(data["tests"]) == len(tests), f"results.json has {len(data['tests'])} tests, not {len(tests)}",
                   problems)
            expect(failed and all(" 1.1 " in f" {t['number']} " for t in failed),
                   "the planted bug in 1.1 must fail tests of 1.1 only", problems)
            expect(data["score"] == len(tests) - len(failed), "the score is not the number of tests passed", problems)
            expect(any("far side" in t["output"] for t in failed), "no failure carries the far-root hint", problems)
            marked = {t["name"].split(": ")[-1] for t in data["tests"] if t["visibility"] == "after_published"}
            expect(marked == hidden and hidden, f"hidden tests marked {sorted(marked)}, want {sorted(hidden)}", problems)
            print(f"autograder: score {data['score']} of {len(tests)}; failed {[t['name'] for t in failed]}")
        else:
            problems.append("run_autograder wrote no results.json")

        # The folder grader and its CSV.
        (folder / "garbage.zip").write_text("not a zip")
        scores = tmp / "scores.csv"
        done = subprocess.run([sys.executable, str(ROOT / "exercises" / "autograder" / "grade-folder"), str(folder),
                               "--labs", "1", "--csv", str(scores), "--work", str(work)],
                              capture_output=True, text=True, errors="replace")
        print(done.stdout[-4000:], done.stderr[-2000:])
        expect(done.returncode == 0, f"grade-folder exited with {done.returncode}", problems)
        rows = {row["student"]: row for row in csv.DictReader(scores.open())} if scores.is_file() else {}
        count = {e: sum(1 for n, _ in tests if grade.exercise_of(n, 1) == e) for e in ("1.1", "1.2")}
        want = {"good": (count["1.1"], count["1.2"]), "empty": (0, 0), "garbage": (0, 0), "broken": (count["1.1"], 0)}
        for student, (e11, e12) in want.items():
            row = rows.get(student)
            expect(row is not None and (int(row["1.1"]), int(row["1.2"])) == (e11, e12),
                   f"{student}: CSV row {row}, want 1.1 = {e11}, 1.2 = {e12}", problems)
        row = rows.get("planted")
        expect(row is not None and 0 < int(row["1.1"]) < count["1.1"] and int(row["1.2"]) == count["1.2"],
               f"planted: CSV row {row}", problems)
        expect(rows.get("broken") is not None and "1.2" in rows["broken"]["notes"] + done.stdout,
               "the syntax error is not reported", problems)

    for p in problems:
        print(f"autograder_end_to_end: {p}")
    print("autograder_end_to_end: " + ("FAILED" if problems else "the autograder grades kits with a planted bug right"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
