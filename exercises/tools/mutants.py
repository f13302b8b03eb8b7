"""mutants: tests of the graded tests. Each mutant is a realistic student bug planted
in one exercise region of the reference; the graded tests of that exercise must fail.

    exercises/tools/mutants.py [--work DIR] [--only ID,...] [--min-caught 0.95] [FILE.mut ...]

The mutants (exercises/mutants/*.mut, or the files named) are planted in a copy of
the tree in WORK/src, whose build in WORK/build is incremental: a mutant costs one
file's compile and one lab's link. They go in rounds of one mutant per lab, built
together (no graded test calls another lab's exercises, so each lab's tests see their
own lab's bug only); --serial plants one at a time. A mutant that no longer applies
(its lines are not found, exactly once, inside its region) or no longer compiles is
an error, never "caught". The report lists per mutant the tests that caught it, the
first hint a student would read, and tests of *other* exercises that failed too
(one bug charged twice). Exit status: 0 when at least --min-caught of the mutants
are caught and all apply, 1 otherwise, 2 for a bad command line.

Format of a .mut file (lines starting with '#' are comments):

    == 1.1 far-root-first
    Returns the far root of the quadratic first.
    @ lib/gi/geometry/sphere.cpp
    -   double t = (-h - root) / a;
    +   double t = (-h + root) / a;

'== EXERCISE NAME' opens a mutant of that exercise's region, free text says what the
student did, '@ FILE' names the file holding the region. Then hunks: '-' lines are
found in the region as consecutive lines (compared without their indentation) and
replaced by the '+' lines that follow (indented like the first line found). A
mutant may have several hunks.
"""
import argparse
import concurrent.futures
import shutil
import sys
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import build    # noqa: E402
import grade    # noqa: E402
import gtest_run  # noqa: E402
import regions  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]


class MutantError(Exception):
    pass


@dataclass
class Mutant:
    exercise: str
    name: str
    where: str                  # file:line of the '==' line
    why: str = ""
    file: str = ""
    hunks: list = field(default_factory=list)  # [(search lines, replacement lines)]

    @property
    def id(self):
        return f"{self.exercise} {self.name}"

    @property
    def lab(self):
        return int(self.exercise.split(".")[0])


def parse(text, origin):
    """The mutants of one .mut file."""
    found = []
    for number, line in enumerate(text.splitlines(), 1):
        where = f"{origin}:{number}"
        if line.startswith("#") or (not line.strip() and not found):
            continue
        if line.startswith("== "):
            parts = line[3:].split()
            if len(parts) != 2 or not regions.BEGIN.match(f"// BEGIN EXERCISE {parts[0]} x"):
                raise MutantError(f"{where}: expected '== EXERCISE NAME', like '== 1.1 far-root-first'")
            found.append(Mutant(parts[0], parts[1], where))
        elif not found:
            raise MutantError(f"{where}: text before the first '== EXERCISE NAME' line")
        elif line.startswith("@ "):
            found[-1].file = line[2:].strip()
        elif line[:1] in "-+" and line[:2] in ("- ", "+ ", "-", "+"):
            if not found[-1].file:
                raise MutantError(f"{where}: a hunk before '@ FILE'")
            hunks = found[-1].hunks
            if line[0] == "-" and (not hunks or hunks[-1][1]):
                hunks.append(([], []))
            elif line[0] == "+" and not hunks:
                hunks.append(([], []))
            hunks[-1][0 if line[0] == "-" else 1].append(line[2:])
        elif line.strip() and not found[-1].hunks:
            found[-1].why += (" " if found[-1].why else "") + line.strip()
        elif line.strip():
            raise MutantError(f"{where}: a line inside hunks must start with '- ' or '+ '")
    for m in found:
        if not m.file or not m.hunks or any(not search for search, _ in m.hunks):
            raise MutantError(f"{m.where}: mutant {m.id} needs '@ FILE' and hunks with '-' lines")
    return found


def load(files):
    mutants = []
    for file in files:
        mutants += parse(Path(file).read_text(), Path(file).name)
    seen = set()
    for m in mutants:
        if m.id in seen:
            raise MutantError(f"{m.where}: a second mutant named {m.id}")
        seen.add(m.id)
    return mutants


def apply(text, mutant):
    """The file's text with the mutant applied inside its region, or MutantError."""
    region = next((r for r in regions.regions_in(text, mutant.file) if r.id == mutant.exercise), None)
    if region is None:
        raise MutantError(f"{mutant.where}: {mutant.file} has no region for exercise {mutant.exercise}")
    lines = text.splitlines(keepends=True)
    body = list(range(region.begin + 1, region.end))
    for search, replacement in mutant.hunks:
        want = [s.strip() for s in search]
        starts = [i for i in body if i + len(want) <= region.end
                  and [lines[i + k].strip() for k in range(len(want))] == want]
        if len(starts) != 1:
            raise MutantError(f"{mutant.where}: mutant {mutant.id} no longer applies: its line '{want[0]}' "
                              f"is found {len(starts)} times in region {mutant.exercise} (needs exactly once)")
        start = starts[0]
        indent = lines[start][:len(lines[start]) - len(lines[start].lstrip())]
        base = min((len(r) - len(r.lstrip()) for r in replacement if r.strip()), default=0)
        lines[start:start + len(want)] = [indent + r[base:] + "\n" for r in replacement]
        shift = len(replacement) - len(want)
        region.end += shift
        body = list(range(region.begin + 1, region.end))
    return "".join(lines)


@dataclass
class Verdict:
    mutant: Mutant
    caught_by: list     # failing tests of the mutant's exercise
    elsewhere: list     # failing tests of other exercises
    hint: str           # what the first failing test tells the student
    problem: str = ""   # does not apply / does not compile


def verdict(mutant, results, problem):
    if problem:
        return Verdict(mutant, [], [], "", problem)
    failed = [r for r in results if not r.passed]
    mine = [r for r in failed if r.exercise == mutant.exercise]
    return Verdict(mutant, [r.name for r in mine], [r.name for r in failed if r.exercise != mutant.exercise],
                   mine[0].hint if mine else "")


def plant(batch, work):
    """Writes the batch's mutants into the copy of the tree; returns the files written."""
    texts = {m.file: (ROOT / m.file).read_text() for m in batch}
    for m in batch:
        texts[m.file] = apply(texts[m.file], m)
    for file, text in texts.items():
        (work / "src" / file).write_text(text)
    return list(texts)


def restore(files, work):
    for file in files:
        shutil.copyfile(ROOT / file, work / "src" / file)  # a new mtime, so the build sees the change back


def build_round(batch, work, snapshots):
    """[(mutant, folder of its lab's programs, problem)] for mutants of different labs,
    planted and built together: each lab's tests see their own lab's bug only, since no
    graded test calls another lab's exercises. The programs are copied out, so that the
    next round can build while these are graded. A round that does not build is built
    one mutant at a time."""
    files = plant(batch, work)
    try:
        error = build.build_labs(work / "build", sorted({m.lab for m in batch}), work / "src")
        if not error:
            built = []
            for m in batch:
                folder = Path(tempfile.mkdtemp(prefix=f"lab{m.lab:02d}-", dir=snapshots))
                (folder / "bin").mkdir()
                for _, name in build.lab_targets(work / "src", m.lab):
                    shutil.copy2(work / "build" / "bin" / name, folder / "bin" / name)
                built.append((m, folder, ""))
            return built
        if len(batch) == 1:
            return [(batch[0], None, f"does not compile: {build.first_error(error)}")]
    finally:
        restore(files, work)
    return [b for m in batch for b in build_round([m], work, snapshots)]


def judge_mutant(mutant, folder, work, limit, runner):
    try:
        results, problems = grade.grade_lab(runner, folder, work / "src", mutant.lab, limit, together=True)
        return verdict(mutant, results, "; ".join(problems))
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def rounds(mutants, serial):
    """The mutants in rounds of at most one per lab (or one per round, `serial`)."""
    if serial:
        return [[m] for m in mutants]
    by_lab = {}
    for m in mutants:
        by_lab.setdefault(m.lab, []).append(m)
    return [[queue[k] for queue in by_lab.values() if k < len(queue)] for k in range(max(map(len, by_lab.values())))]


def prepare(work, labs):
    """The copy of the tree and its build, with the reference's graded tests passing."""
    build.sync_tree(ROOT, work / "src")
    build.configure(work / "src", work / "build", quick=True)
    error = build.build_labs(work / "build", labs, work / "src")
    if error:
        raise MutantError(f"the reference's graded tests do not build: {build.first_error(error)}")


def main(argv):
    parser = argparse.ArgumentParser(prog="mutants", allow_abbrev=False, description="Plant student bugs; check the graded tests fail.")
    parser.add_argument("files", nargs="*", help=".mut files (default: exercises/mutants/*.mut)")
    parser.add_argument("--work", default=str(ROOT / "build" / "mutants"), help="copy of the tree and its build")
    parser.add_argument("--only", help="mutant names or exercise ids, comma-separated")
    parser.add_argument("--min-caught", type=float, default=0.95)
    parser.add_argument("--timeout", type=grade.positive_seconds, default=None)
    parser.add_argument("--serial", action="store_true",
                        help="one mutant at a time (for mutants whose lab's tests call another lab's exercises)")
    args = parser.parse_args(argv)
    files = args.files or sorted((ROOT / "exercises" / "mutants").glob("*.mut"))
    try:
        mutants = load(files)
        if args.only:
            wanted = set(args.only.split(","))
            mutants = [m for m in mutants if m.name in wanted or m.exercise in wanted]
        if not mutants:
            raise MutantError("no mutants to run")
        for m in mutants:  # all of them must apply before anything is built
            apply((ROOT / m.file).read_text(), m)
        work = Path(args.work).resolve()
        prepare(work, sorted({m.lab for m in mutants}))
    except (MutantError, regions.RegionError, build.BuildError, OSError) as e:
        print(f"mutants: error: {e}", file=sys.stderr)
        return 1
    limit = grade.time_limit(work / "build", args.timeout)
    verdicts = []

    def say(v):
        verdicts.append(v)
        status = v.problem or (f"caught by {len(v.caught_by)}" if v.caught_by else "NOT CAUGHT")
        extra = f"; also fails {len(v.elsewhere)} of other exercises: {', '.join(v.elsewhere[:3])}" if v.elsewhere else ""
        print(f"[{len(verdicts)}/{len(mutants)}] {v.mutant.id:<45} {status}{extra}", flush=True)
        if v.hint:
            print(f"        hint: {v.hint[:160]}", flush=True)

    # Round k is graded (two at a time) while round k + 1 compiles: the course's own
    # code, run without the sandbox, from copies of the round's programs.
    runner = gtest_run.Runner(isolate=False)
    snapshots = Path(tempfile.mkdtemp(prefix="mutant-programs-"))
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
            pending = []
            for batch in rounds(mutants, args.serial):
                for m, folder, problem in build_round(batch, work, snapshots):
                    if problem:
                        say(Verdict(m, [], [], "", problem))
                    else:
                        pending.append(pool.submit(judge_mutant, m, folder, work, limit, runner))
                for done in [f for f in pending if f.done()]:
                    say(done.result())
                    pending.remove(done)
            for done in concurrent.futures.as_completed(pending):
                say(done.result())
    finally:
        runner.close()
        shutil.rmtree(snapshots, ignore_errors=True)
    order = {m.id: k for k, m in enumerate(mutants)}
    verdicts.sort(key=lambda v: order[v.mutant.id])
    broken = [v for v in verdicts if v.problem]
    caught = [v for v in verdicts if v.caught_by]
    fraction = len(caught) / len(verdicts)
    print(f"\nmutants caught: {len(caught)} of {len(verdicts)} ({100 * fraction:.1f}%)"
          f"{f'; {len(broken)} broken' if broken else ''}")
    for v in verdicts:
        if not v.caught_by:
            print(f"  not caught: {v.mutant.id} ({v.mutant.where}): {v.problem or v.mutant.why}")
    charged_twice = [v for v in verdicts if v.elsewhere]
    print(f"charged twice (tests of another exercise fail too): {len(charged_twice)}")
    return 0 if fraction >= args.min_caught and not broken else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
