"""mutants: tests of the graded tests. Each mutant is a realistic student bug planted
in one exercise region of the reference; the graded tests of that exercise must fail.

    exercises/tools/mutants.py [--work DIR] [--only ID,...] [--jobs N] [--min-caught 0.95]
                               [--name-first] [FILE.mut ...]

The mutants (exercises/mutants/*.mut, or the files named) are built against a copy of
the tree in WORK/src, whose build in WORK/build holds the reference's graded programs.
That build is never changed: each mutant is built in an overlay folder of its own
(overlay.py) -- the compile of the mutated file (of every object including it, for a
header), its library's archive and one program's link -- so mutants build and are
graded side by side, --jobs at a time (default: one per core), none seeing another's
bug, and nothing needs rebuilding back afterwards. A mutant is graded on its lab's
visible program first; its hidden program is built and run only when no visible test
of the mutant's exercise fails. A mutant that no longer applies (its lines are not
found, exactly once, inside its region) or no longer compiles is an error, never
"caught". The report lists per mutant the tests that caught it, the first hint a
student would read, and visible tests of *other* exercises that failed too (one bug
charged twice). Exit status: 0 when at least --min-caught of the mutants are caught,
all apply, and each one's first failing test is the one its '>' line names; 1
otherwise, 2 for a bad command line.

Format of a .mut file (lines starting with '#' are comments):

    == 1.1 far-root-first
    Returns the far root of the quadratic first.
    > Ex1_1_RaySphere.ReturnsTheNearerRootFromOutside
    @ lib/gi/geometry/sphere.cpp
    -   double t = (-h - root) / a;
    +   double t = (-h + root) / a;

'== EXERCISE NAME' opens a mutant of that exercise's region, free text says what the
student did, '> TEST' names the test that must fail first (its hint is the first a
student reads, so it must name this bug's cause: the graded tests are ordered so that
it does), '@ FILE' names the file holding the region. --name-first writes the '>' line
of every caught mutant that has none, from the run. Then hunks: '-' lines are
found in the region as consecutive lines (compared without their indentation) and
replaced by the '+' lines that follow (indented like the first line found). A
mutant may have several hunks.
"""
import argparse
import concurrent.futures
import os
import shlex
import shutil
import subprocess
import sys
import threading
from dataclasses import dataclass, field
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import build    # noqa: E402
import grade    # noqa: E402
import gtest_run  # noqa: E402
import overlay  # noqa: E402
import regions  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
OVERLAYS = "mutant-overlays"  # in WORK/build: one folder per mutant while it is built and graded


class MutantError(Exception):
    pass


@dataclass
class Mutant:
    exercise: str
    name: str
    where: str                  # file:line of the '==' line
    why: str = ""
    first: str = ""             # the test that must fail first
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
        elif line.startswith("> "):
            if found[-1].first or found[-1].hunks:
                raise MutantError(f"{where}: one '> TEST' line per mutant, before its hunks")
            found[-1].first = line[2:].strip()
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

    @property
    def wrong_first(self):
        """The test that failed first, when it is not the one the mutant names."""
        first = self.caught_by[0] if self.caught_by else ""
        return first if self.mutant.first and first and first != self.mutant.first else ""


def verdict(mutant, results, problem):
    if problem:
        return Verdict(mutant, [], [], "", problem)
    failed = [r for r in results if not r.passed]
    mine = [r for r in failed if r.exercise == mutant.exercise]
    return Verdict(mutant, [r.name for r in mine], [r.name for r in failed if r.exercise != mutant.exercise],
                   mine[0].hint if mine else "")


class Reference:
    """The reference's build of the lab programs, read once: each program's commands
    and its objects' dependencies (Ninja's), and each lab's graded tests."""

    def __init__(self, work):
        self.work, self.lock = work, threading.Lock()
        self.programs, self.tests = {}, {}

    def program(self, target):
        with self.lock:
            if target not in self.programs:
                commands = overlay.ninja_commands(self.work / "build", target)
                self.programs[target] = commands, build.dependencies(self.work / "build", commands)
            return self.programs[target]

    def tests_of(self, lab, hidden):
        with self.lock:
            if lab not in self.tests:
                self.tests[lab] = grade.source_tests(self.work / "src", lab)
            return [(n, h) for n, h in self.tests[lab] if h == hidden]


def leading_includes(text):
    """The #include lines a source file opens with (blank and // lines among them kept), or ""."""
    lines = []
    for line in text.splitlines(keepends=True):
        if not (line.startswith("#include") or not line.strip() or line.lstrip().startswith("//")):
            break
        lines.append(line)
    return "".join(lines) if any(line.startswith("#include") for line in lines) else ""


class Preambles:
    """Each mutated source file's opening #include lines, compiled once into a
    precompiled header with the flags of the file's own compile (less CMake's own
    precompiled header, which this one replaces), for all the mutants of that file: a
    mutant's compile then reads the headers from it and parses only the file's own
    code, about a third of the time (the file's #include lines find their
    headers already read: #pragma once). Removed when the file's last mutant is done.
    Where one cannot be made (a header, a compiler that refuses), mutants compile as usual."""

    def __init__(self, work, mutants):
        self.work, self.lock = work, threading.Lock()
        self.made, self.users = {}, {}
        for m in mutants:
            self.users[m.file] = self.users.get(m.file, 0) + 1

    def of(self, rel, command):
        """The preamble to -include for the file (compile `command` is the reference's), or None."""
        with self.lock:
            if rel not in self.made:
                self.made[rel] = self.make(rel, command)
            return self.made[rel]

    def make(self, rel, command):
        text = leading_includes((self.work / "src" / rel).read_text()) if rel.endswith(".cpp") else ""
        if not text or not command:
            return None
        header = self.work / "build" / OVERLAYS / "preambles" / (rel.replace("/", "_") + ".hpp")
        header.parent.mkdir(parents=True, exist_ok=True)
        header.write_text(text)
        words, argv, skip = shlex.split(overlay.without_cmake_pch(command)), [], 0
        for word in words:
            if skip:
                skip -= 1
            elif word in ("-MT", "-MF", "-o", "-c"):
                skip = 1
            elif word != "-MD":
                argv.append(word)
        done = subprocess.run(argv + ["-x", "c++-header", str(header), "-o", f"{header}.gch"],
                              cwd=self.work / "build", capture_output=True, stdin=subprocess.DEVNULL)
        return header if done.returncode == 0 else None

    def done_with(self, rel):
        with self.lock:
            self.users[rel] -= 1
            header = self.made.get(rel) if not self.users[rel] else None
        if header:
            Path(f"{header}.gch").unlink(missing_ok=True)


def build_program(mutant, target, reference, folder, preambles):
    """(the program with the mutant in it, "") or (None, why it does not build)."""
    commands, found = reference.program(target)
    mutated = str((reference.work / "src" / mutant.file).resolve())
    objects = {obj for obj, paths in found.items() if mutated in paths}
    if not objects:  # the program does not hold the mutated file: the reference's is the mutant's
        return reference.work / "build" / "bin" / target, ""
    own = [c for c in commands if (overlay.compile_parts(c) or ("", ""))[0]
           and str((reference.work / "build" / overlay.compile_parts(c)[0]).resolve()) == mutated]
    preamble = preambles.of(mutant.file, own[0] if own else None)
    text = apply((reference.work / "src" / mutant.file).read_text(), mutant)
    try:
        for prefix in ([{mutant.file: preamble}] if preamble else []) + [None]:
            program, log = overlay.rebuild(reference.work / "src", reference.work / "build", target, objects,
                                           {mutant.file: text}, folder=folder, commands=commands, prefix=prefix)
            if program:
                return program, ""
    except overlay.OverlayError as e:
        return None, f"cannot be built in an overlay: {e}"
    return None, f"does not compile: {build.first_error(log)}"


def judge_mutant(number, mutant, reference, preambles, limit, runner):
    """The mutant's verdict: built in its own overlay, graded on its lab's visible
    program, then, when none of its exercise's visible tests fails, on the hidden one."""
    folder = f"{OVERLAYS}/{number}"
    results = []
    try:
        for kind, target in build.lab_targets(reference.work / "src", mutant.lab):
            program, problem = build_program(mutant, target, reference, folder, preambles)
            if problem:
                return verdict(mutant, [], problem)
            found, problem = grade.grade_program(runner, program, mutant.lab, reference.tests_of(mutant.lab, kind == "hidden"),
                                                 limit, {}, kind == "hidden", together=True)
            if problem:
                return verdict(mutant, [], problem)
            results += found
            if any(not r.passed and r.exercise == mutant.exercise for r in found):
                break  # caught: its hidden tests would tell no more
        return verdict(mutant, results, "")
    finally:
        shutil.rmtree(reference.work / "build" / folder, ignore_errors=True)
        preambles.done_with(mutant.file)


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
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2, help="mutants built and graded at once")
    parser.add_argument("--name-first", action="store_true",
                        help="write each caught mutant's first failing test as its '>' line where it has none")
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
        if v.wrong_first:
            print(f"        FIRST FAILS {v.wrong_first}, not {v.mutant.first}", flush=True)

    # The course's own code, run without the sandbox; each mutant in an overlay of its own.
    runner = gtest_run.Runner(isolate=False)
    reference, preambles = Reference(work), Preambles(work, mutants)
    shutil.rmtree(work / "build" / OVERLAYS, ignore_errors=True)
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            pending = [pool.submit(judge_mutant, k, m, reference, preambles, limit, runner)
                       for k, m in enumerate(mutants)]
            for done in concurrent.futures.as_completed(pending):
                say(done.result())
    finally:
        runner.close()
        shutil.rmtree(work / "build" / OVERLAYS, ignore_errors=True)
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
    misled = [v for v in verdicts if v.wrong_first]
    for v in misled:
        print(f"  first hint from the wrong test: {v.mutant.id} ({v.mutant.where}): {v.wrong_first} fails "
              f"before {v.mutant.first}")
    unnamed = [v for v in verdicts if v.caught_by and not v.mutant.first]
    if args.name_first and unnamed:
        name_first(unnamed)
    elif unnamed:
        print(f"  {len(unnamed)} caught mutants name no first test ('> TEST'; --name-first writes them)")
    print(f"first hint from the test each mutant names: {len(caught) - len(misled) - len(unnamed)} of {len(caught)}")
    return 0 if fraction >= args.min_caught and not broken and not misled else 1


def name_first(verdicts):
    """Writes '> TEST' (the test that failed first) under each mutant's '==' line."""
    by_file = {}
    for v in verdicts:
        file, line = v.mutant.where.rsplit(":", 1)
        by_file.setdefault(file, []).append((int(line), v.caught_by[0]))
    for name, insertions in by_file.items():
        path = ROOT / "exercises" / "mutants" / name
        lines = path.read_text().splitlines(keepends=True)
        for line, test in sorted(insertions, reverse=True):
            at = line  # after the '==' line and the free text that follows it
            while at < len(lines) and lines[at].strip() and lines[at][:2] not in ("@ ", "- ", "+ ", "> "):
                at += 1
            lines.insert(at, f"> {test}\n")
        path.write_text("".join(lines))
        print(f"  named the first failing test of {len(insertions)} mutants in {path.relative_to(ROOT)}")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
