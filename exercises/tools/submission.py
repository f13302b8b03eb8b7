"""submission: grade students' work with the instructor's tests (Gradescope and local).

    submission.py prepare                                  # what setup.sh calls
    submission.py gradescope [--root /autograder]          # what run_autograder calls
    submission.py folder SUBMISSIONS --labs 1,2 --csv scores.csv [--work DIR]
    submission.py zip OUT.zip --labs 1,2 [--hidden-visibility after_published]

A submission is a student's kit, or any folder holding its files (lib/gi/... or just
the .cpp files). Only the exercise regions of the graded labs are taken from it --
the code between its BEGIN/END EXERCISE markers -- and copied into a copy of the
instructor's tree, where every graded region was stubbed first. So the student's
tests, CMake files and other edits count for nothing, the graded tests are the
instructor's (hidden ones included), and an exercise not found counts as not done.
"""
import argparse
import csv
import io
import json
import os
import shutil
import stat
import sys
import tempfile
import zipfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import build    # noqa: E402
import cpp_text  # noqa: E402
import grade    # noqa: E402
import kit      # noqa: E402
import regions  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
CONFIG = "autograder.json"  # written into the zip: {"labs": [...], "hidden_visibility": ..., "timeout": S or null}


class SubmissionError(Exception):
    pass


MAX_FILE = 1 << 20  # bytes of one submitted file read
MAX_ZIP_ENTRIES, MAX_ZIP_BYTES = 50000, 256 << 20  # a zip that unpacks to more is refused


def regular_files(submission):
    """{file name: [paths]} of the submission's regular files: never a link (to a file
    or a folder, followed or not), a file with a second hard link, a device, or anything
    under a build/ folder; the walk never leaves the submission."""
    found = {}
    for folder, subfolders, files in os.walk(submission, followlinks=False):
        subfolders[:] = [d for d in subfolders if d != "build" and not os.path.islink(os.path.join(folder, d))]
        for name in files:
            path = Path(folder, name)
            try:
                info = path.lstat()
            except OSError:
                continue
            if stat.S_ISREG(info.st_mode) and info.st_nlink == 1 and info.st_size <= MAX_FILE:
                found.setdefault(name, []).append(path)
    return found


def find_file(submission, rel, files=None):
    """The submission's copy of a library file: the same path, or a path ending like
    it (a kit inside a folder), or the only file of that name. Only regular files count."""
    files = regular_files(submission) if files is None else files
    candidates = files.get(rel.name, [])
    exact = [p for p in candidates if p.relative_to(submission).as_posix().endswith(rel.as_posix())]
    if exact:
        return min(exact, key=lambda p: len(p.parts))
    return candidates[0] if len(candidates) == 1 else None


def why_not_found(submission, rel):
    """Why a file of that name was not taken: a link, a hard link, too large, or absent."""
    for folder, _, names in os.walk(submission, followlinks=False):
        if rel.name in names:
            path = Path(folder, rel.name)
            info = path.lstat()
            if stat.S_ISLNK(info.st_mode):
                return f"{path.relative_to(submission)} is a link: only regular files are taken"
            if info.st_nlink > 1:
                return f"{path.relative_to(submission)} has a second hard link: only plain files are taken"
            if info.st_size > MAX_FILE:
                return f"{path.relative_to(submission)} is larger than {MAX_FILE >> 20} MB"
    return f"no {rel} in the submission"


def take_regions(submission, tree, labs):
    """Stubs every region of `labs` in `tree`, then fills in the submission's code: the
    text between its markers, taken only if it reads as a function body (cpp_text.py).
    Returns {exercise: why it was not taken} for the exercises left stubbed."""
    submission = Path(submission)
    chosen = [r for r in regions.find_regions(tree) if r.lab in labs]
    files = regular_files(submission)
    missing = {}
    for rel in sorted({r.path for r in chosen}):
        mine = [r for r in chosen if r.path == rel]
        text = regions.stub_text((tree / rel).read_text(), mine)
        theirs, found = find_file(submission, rel, files), {}
        if theirs is None:
            missing.update({r.id: why_not_found(submission, rel) for r in mine})
        else:
            try:
                their_text = theirs.read_bytes().decode("utf-8", errors="replace")
                found = {r.id: r for r in regions.regions_in(their_text, rel)}
            except (OSError, regions.RegionError) as e:
                missing.update({r.id: f"its exercise markers are broken ({e})" for r in mine})
        for r in sorted(mine, key=lambda r: r.begin, reverse=True):
            if r.id not in found:
                missing.setdefault(r.id, f"no region 'BEGIN EXERCISE {r.id}' in {theirs.name if theirs else rel}")
                continue
            body = their_text.splitlines(keepends=True)[found[r.id].begin + 1:found[r.id].end]
            try:
                cpp_text.check_body("".join(body))
            except cpp_text.TextError as e:
                missing[r.id] = f"not taken as written: {e}"
                continue
            lines = text.splitlines(keepends=True)
            here = next(x for x in regions.regions_in(text, rel) if x.id == r.id)
            lines[here.begin + 1:here.end] = body
            text = "".join(lines)
        (tree / rel).write_text(text)
    return missing


def grade_one(submission, labs, work, say=print, hide=(), timeout=None):
    """(results, notes) for one submission, built in work/src and work/build. The
    sandbox covers `hide` (with the tree and its build) from the code it runs; each
    test program run gets `timeout` seconds (None: what fits the build type)."""
    tree = work / "src"
    build.sync_tree(ROOT, tree)
    missing = take_regions(Path(submission), tree, labs)
    notes = [f"exercise {ident} not graded as written: {why}" for ident, why in sorted(missing.items())]
    for note in notes:
        say(f"grade: {note}")
    results, problems, sandbox_notes = grade.grade(
        tree, labs, work / "build", grade.time_limit(work / "build", timeout), True, say, quick=True, scratch=True,
        hide=[ROOT, work, *hide])
    broken = {r.exercise: r.hint for r in results if r.hint.startswith("your code does not compile")}
    notes += [f"exercise {ident}: {hint}" for ident, hint in sorted(broken.items())]
    clean = [build.relative(build.relative(n, tree), ROOT) for n in notes + problems]
    for r in results:
        r.hint, r.detail = (build.relative(build.relative(x, tree), ROOT) for x in (r.hint, r.detail))
    return results, clean, sandbox_notes


def lock_away(*folders):
    """As root, makes the folders reachable by root only: the user the tests run as may
    not read the instructor's tree (hidden tests, the reference, the build) nor touch
    the results."""
    if os.name == "posix" and os.geteuid() == 0:
        for folder in folders:
            if Path(folder).is_dir():
                os.chmod(folder, 0o700)


def write_atomically(path, text):
    path = Path(path)
    fd, temp = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
    try:
        with os.fdopen(fd, "w", newline="") as out:
            out.write(text)
        os.replace(temp, path)
    except OSError:
        Path(temp).unlink(missing_ok=True)
        raise


def work_folder(source):
    return Path(os.environ.get("GI_AUTOGRADER_WORK", source / "build" / "autograder"))


def prepare(source):
    """setup.sh: builds the graded labs once, exercises stubbed, so that a submission
    only recompiles what it changes."""
    config = json.loads((source / CONFIG).read_text())
    work = work_folder(source)
    with tempfile.TemporaryDirectory() as empty:
        build.sync_tree(ROOT, work / "src")
        take_regions(Path(empty), work / "src", config["labs"])
    built = build.build(work / "src", work / "build", config["labs"], quick=True)
    if built.lab_errors:
        raise SubmissionError(f"the instructor's tree does not build: {next(iter(built.lab_errors.values()))}")
    print(f"autograder ready: labs {', '.join(map(str, config['labs']))} built in {work / 'build'}")
    return 0


def gradescope(root):
    """Gradescope's run_autograder: /autograder/submission in, results/results.json out.
    The results are written after every process the submission started is gone."""
    source = root / "source"
    config = json.loads((source / CONFIG).read_text())
    work = work_folder(source)
    results_dir = root / "results"
    results_dir.mkdir(parents=True, exist_ok=True)
    lock_away(source, work, results_dir)
    results, notes, sandbox_notes = grade_one(root / "submission", config["labs"], work, hide=[results_dir],
                                              timeout=config.get("timeout"))
    data = grade.gradescope(results, grade.titles(ROOT), config.get("hidden_visibility", "after_published"), source)
    if notes:
        data["output"] = "\n".join(notes) + "\n\n" + data["output"]
    for note in sandbox_notes:
        print(f"autograder: note: {note}")  # for the instructor's log: stdout is hidden from students
    if results_dir.is_symlink() or not results_dir.is_dir():
        raise SubmissionError(f"{results_dir} is not a folder of the autograder's")
    write_atomically(results_dir / "results.json", json.dumps(data, indent=2))
    print(data["output"])
    return 0


def folder(submissions, labs, csv_path, work, timeout=None):
    """Grades every submission (a subfolder or .zip) and writes one CSV row each:
    the points per exercise, the score, the maximum, and notes."""
    entries = sorted(p for p in Path(submissions).iterdir() if p.is_dir() or p.suffix == ".zip")
    if not entries:
        raise SubmissionError(f"no submissions (folders or .zip files) in {submissions}")
    exercises = [r.id for r in regions.find_regions(ROOT) if r.lab in labs]
    tests = [n for lab in labs for n, _ in grade.source_tests(ROOT, lab)]
    maxima = [sum(1 for n in tests if grade.exercise_of(n, int(e.split(".")[0])) == e) for e in exercises]
    rows = [["student"] + exercises + ["score", "out of", "notes"]]
    for entry in entries:
        print(f"== {entry.name}", flush=True)
        with tempfile.TemporaryDirectory() as unpacked:
            path, notes, results = entry, [], []
            if entry.suffix == ".zip":
                try:
                    with zipfile.ZipFile(entry) as z:
                        sizes = [info.file_size for info in z.infolist()]
                        if len(sizes) > MAX_ZIP_ENTRIES or sum(sizes) > MAX_ZIP_BYTES:
                            raise zipfile.BadZipFile(f"more than {MAX_ZIP_ENTRIES} files or "
                                                     f"{MAX_ZIP_BYTES >> 20} MB unpacked")
                        z.extractall(unpacked)  # names with .. or a leading / stay inside; links come out as files
                    path = Path(unpacked)
                except (zipfile.BadZipFile, OSError) as e:
                    path, notes = None, [f"unreadable zip: {e}"]
            if path is not None:
                results, notes, sandbox_notes = grade_one(path, labs, work, say=lambda line: print(f"   {line}"),
                                                             timeout=timeout)
                for note in sandbox_notes:
                    print(f"   note: {note}")
        points = [sum(r.passed for r in results if r.exercise == e) for e in exercises]
        print(f"   score: {sum(points)}/{len(tests)}")
        rows.append([entry.stem] + points + [sum(points), len(tests), "; ".join(notes)])
    buffer = io.StringIO()
    csv.writer(buffer).writerows(rows)
    write_atomically(csv_path, buffer.getvalue())
    print(f"scores of {len(entries)} submission(s), out of {sum(maxima)}, written to {csv_path}")
    return 0


def unpack(archive, folder):
    """The zip unpacked as Gradescope's unzip does it, with each file's mode (scripts
    stay executable; Python's extractall drops the modes)."""
    folder = Path(folder)
    with zipfile.ZipFile(archive) as z:
        z.extractall(folder)
        for info in z.infolist():
            mode = (info.external_attr >> 16) & 0o777
            if mode and not info.is_dir():
                os.chmod(folder / info.filename, mode)


def make_zip(out, labs, hidden_visibility, timeout=None):
    """The zip Gradescope expects: the project (hidden tests included) at its root,
    with setup.sh, run_autograder and the labs to grade (and the seconds each test
    program may run, where the instructor sets them)."""
    here = ROOT / "exercises" / "autograder"
    config = json.dumps({"labs": sorted(labs), "hidden_visibility": hidden_visibility, "timeout": timeout})
    fd, temp = tempfile.mkstemp(prefix=f".{Path(out).name}.", dir=Path(out).resolve().parent)
    os.close(fd)
    try:
        with zipfile.ZipFile(temp, "w", zipfile.ZIP_DEFLATED) as z:
            for rel in build.project_files(ROOT):
                if not rel.as_posix().startswith(("exercises/mutants/", "docs/images/")):
                    z.write(ROOT / rel, rel.as_posix())
            for script in ("setup.sh", "run_autograder"):
                info = zipfile.ZipInfo(script)
                info.external_attr = 0o755 << 16
                z.writestr(info, (here / script).read_text())
            z.writestr(CONFIG, config)
        os.replace(temp, out)
    except OSError:
        Path(temp).unlink(missing_ok=True)
        raise
    print(f"Gradescope autograder for lab(s) {', '.join(map(str, sorted(labs)))} written to {out}")
    return 0


def main(argv):
    parser = kit.OneLineParser(prog="submission", description="Grade submissions with the instructor's tests.")
    commands = parser.add_subparsers(dest="command", required=True)
    commands.add_parser("prepare", help="what setup.sh calls")
    g = commands.add_parser("gradescope", help="what run_autograder calls")
    g.add_argument("--root", default=os.environ.get("GI_AUTOGRADER_ROOT", "/autograder"))
    f = commands.add_parser("folder", help="grade a folder of submissions into a CSV")
    f.add_argument("submissions")
    f.add_argument("--labs", required=True)
    f.add_argument("--csv", required=True)
    f.add_argument("--work", default=str(ROOT / "build" / "autograder"))
    f.add_argument("--timeout", type=grade.positive_seconds, help="seconds per test program run")
    z = commands.add_parser("zip", help="make Gradescope's autograder zip")
    z.add_argument("out")
    z.add_argument("--labs", required=True)
    z.add_argument("--hidden-visibility", default="after_published",
                   choices=["hidden", "after_due_date", "after_published", "visible"])
    z.add_argument("--timeout", type=grade.positive_seconds, help="seconds per test program run")
    try:
        args = parser.parse_args(argv)
        if args.command == "prepare":
            return prepare(ROOT)
        if args.command == "gradescope":
            return gradescope(Path(args.root))
        labs = sorted(regions.parse_labs(args.labs, grade.labs_in(ROOT)))
        if args.command == "zip":
            return make_zip(args.out, labs, args.hidden_visibility, args.timeout)
        return folder(args.submissions, labs, args.csv, Path(args.work).resolve(), args.timeout)
    except (kit.KitError, regions.RegionError) as e:
        print(f"submission: error: {e}", file=sys.stderr)
        return 2
    except (SubmissionError, build.BuildError, OSError, ValueError, KeyError) as e:
        print(f"submission: error: {e}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
