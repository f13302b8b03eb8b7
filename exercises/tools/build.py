"""build: compile the graded tests of some labs for the grader.

Every chosen lab's programs (labNN_graded, and labNN_hidden for the instructor's
hidden tests) are built in one go that keeps going past errors, so a lab whose tests
do not compile costs that lab only, and the compiler's first error in an exercise
region is printed the moment it appears. Such a region -- or one refused as text
(cpp_text.py: a preprocessor line, a brace that closes its function, asm) -- is stubbed
again, as in a fresh kit: the exercise scores 0 with the error as its hint, and the
other exercises are graded as usual. In a copy of the tree made for grading (the
autograder's, the mutant suite's) the region is stubbed in place and the build goes
on incrementally; a student's own tree is never edited: the stubbed files go to an
overlay (overlay.py) from which only the objects they feed and the program's link are
built again.
"""
import filecmp
import os
import re
import shutil
import subprocess
import threading
from dataclasses import dataclass, field
from pathlib import Path

import cpp_text
import overlay
import processes
import regions

SKIP = {"build", "out", ".git", "__pycache__"}

# GCC and Clang: "path:line:col: error: message" (also "fatal error").
ERROR = re.compile(r"^(?P<path>[^\s:][^:\n]*):(?P<line>\d+):(?:\d+:)? (?:fatal )?error: (?P<message>.*)$", re.M)
LINKER = re.compile(r"^.*(undefined reference to .*|multiple definition of .*|ld returned \d+ exit status)$", re.M)
FAILED = re.compile(r"^FAILED: (.+?)\s*$", re.M)


class BuildError(Exception):
    """No build is possible (no cmake, no built tree): one line."""


class ConfigureError(BuildError):
    """cmake cannot configure the tree: every lab scores 0, with this line as the hint."""


@dataclass
class Built:
    binary_dir: Path                                   # the build tree
    binaries: dict = field(default_factory=dict)       # (lab, "graded" | "hidden") -> program to run
    lab_errors: dict = field(default_factory=dict)     # lab -> first compiler error
    restubbed: dict = field(default_factory=dict)      # exercise id -> why it was stubbed again
    notes: list = field(default_factory=list)


def relative(text, root):
    """Text with the tree's absolute path taken out of file names."""
    return text.replace(str(Path(root).resolve()) + "/", "")


def first_error(log, root=None):
    """The first compiler or linker error of a build log, as one line."""
    found = ERROR.search(log) or LINKER.search(log)
    line = found.group(0).strip() if found else next(
        (l.strip() for l in reversed(log.splitlines()) if l.strip() and not l.startswith("[")), "the build failed")
    return relative(line, root) if root else line


def run(argv, cwd=None):
    try:
        done = subprocess.run(argv, cwd=cwd, stdin=subprocess.DEVNULL, capture_output=True)
    except OSError as e:
        raise BuildError(f"cannot run {argv[0]}: {e.strerror}")
    return done.returncode, (done.stdout + done.stderr).decode("utf-8", errors="replace")


# Minutes a build may take before it is stopped: a template or constexpr bomb in a
# region must not hold the grader (the whole project builds in about 8 minutes).
BUILD_DEADLINE = 30 * 60


def stream(argv, on_line, deadline=BUILD_DEADLINE):
    """(status, log) of a command whose output lines are handed to on_line as they come;
    stopped (status None) at the deadline."""
    try:  # a session of its own: an interrupted grader stops the whole build, compilers included
        process = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                   **processes.own_group())
    except OSError as e:
        raise BuildError(f"cannot run {argv[0]}: {e.strerror}")
    lines, expired = [], []

    def stop():
        expired.append(True)
        processes.kill_group(process)

    timer = threading.Timer(deadline, stop)
    timer.start()
    try:
        for raw in process.stdout:
            line = raw.decode("utf-8", errors="replace")
            lines.append(line)
            on_line(line.rstrip("\n"))
    except BaseException:
        processes.kill_group(process)
        raise
    finally:
        timer.cancel()
        process.stdout.close()
        process.wait()
    if expired:
        lines.append(f"\nthe build did not end within {deadline // 60} minutes: stopped\n")
    return process.returncode, "".join(lines)


# A tree built only to be graded, many times over (mutants, the autograder): -O1 and
# no link-time optimisation, so that changing one file costs a quick compile and a
# plain link rather than the whole program's optimisation at every link; precompiled
# headers, as in Release (cmake/PrecompiledHeaders.cmake): the tree is built whole
# once per suite, and its compiles are mostly the reading of headers.
QUICK = ["-DCMAKE_BUILD_TYPE=RelWithDebInfo", "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -DNDEBUG", "-DGI_LTO=OFF", "-DGI_PCH=ON"]


def configure(root, build_dir, quick=False):
    if (build_dir / "CMakeCache.txt").exists():
        return
    if shutil.which("cmake") is None:
        raise BuildError("cmake not found: install it (Debian: apt-get install cmake ninja-build)")
    if build_dir.resolve() == (root / "build" / "release").resolve() and not quick:
        code, log = run(["cmake", "--preset", "release"], cwd=root)
    else:
        flags = QUICK if quick else ["-DCMAKE_BUILD_TYPE=Release"]
        code, log = run(["cmake", "-S", str(root), "-B", str(build_dir), "-G", "Ninja"] + flags)
    if code != 0:
        raise ConfigureError(f"cmake cannot configure {root}: {first_error(log, root)}")


def ninja(build_dir):
    cache = Path(build_dir) / "CMakeCache.txt"
    text = cache.read_text(errors="replace") if cache.is_file() else ""
    return bool(re.search(r"^CMAKE_GENERATOR:INTERNAL=Ninja", text, re.M)) and shutil.which("ninja") is not None


def program(build_dir, name):
    """A program of the build: bin/NAME, or bin/NAME.exe where programs are Windows'
    (built on Windows, or by MinGW for it)."""
    plain = Path(build_dir) / "bin" / name
    exe = plain.with_name(name + ".exe")
    return exe if os.name == "nt" or (exe.is_file() and not plain.is_file()) else plain


def lab_targets(root, lab):
    """The programs of a lab: its visible tests, and its hidden ones where the tree has them."""
    folder = Path(root) / "exercises" / f"lab{lab:02d}"
    return [("graded", f"lab{lab:02d}_graded")] + ([("hidden", f"lab{lab:02d}_hidden")]
                                                   if any(folder.glob("hidden/*.cpp")) else [])


def build_targets(build_dir, targets, on_line=lambda line: None):
    """(status, log) of building the targets together, going on past errors."""
    if shutil.which("cmake") is None:
        raise BuildError("cmake not found: install it (Debian: apt-get install cmake ninja-build)")
    keep_going = ["--", "-k", "0"] if ninja(build_dir) else ["--", "-k"]
    return stream(["cmake", "--build", str(build_dir), "--target", *targets, *keep_going], on_line)


def build_labs(build_dir, labs, root=None):
    """Builds the labs' programs together: None, or the build log of a failure."""
    targets = [t for lab in labs for _, t in (lab_targets(root, lab) if root else [("graded", f"lab{lab:02d}_graded")])]
    code, log = build_targets(build_dir, targets)
    return None if code == 0 else log


def outputs_of(build_dir, target):
    """Every file Ninja makes on the way to the target (objects, archives, the program)."""
    found = set()
    for command in overlay.ninja_commands(build_dir, target):
        parts = overlay.compile_parts(command)
        if parts:
            found.add(parts[1])
        found |= set(overlay.ARCHIVE.findall(command))
        found |= set(re.findall(r"(?<![^\s])-o\s+(\S+)", command))
    return found


def built_whole(build_dir, target, log):
    """Did the last build (that went on past errors) make the target? With Ninja: the
    program is there and nothing on its way failed; otherwise: build it alone."""
    if ninja(build_dir):
        failed = {o for line in FAILED.findall(log) for o in line.split()}
        return program(build_dir, target).is_file() and not failed & outputs_of(build_dir, target)
    code, _ = run(["cmake", "--build", str(build_dir), "--target", target])
    return code == 0


def broken_regions(root, log):
    """The exercise regions of lib/ the log's compile errors fall in: the region
    holding the error's line, or every region of the file when the error lies
    outside them (a brace left open inside a region is reported further down).
    Errors in an overlay's copy count for the file it copies."""
    root = Path(root).resolve()
    all_regions = regions.find_regions(root)
    found = {}
    for m in ERROR.finditer(log):
        path = Path(m.group("path"))
        try:
            rel = path.resolve().relative_to(root)
        except (ValueError, OSError):
            continue
        parts = rel.parts
        if overlay.FOLDER in parts:  # build/.../grade-overlay/lib/gi/x.cpp -> lib/gi/x.cpp
            rel = Path(*parts[parts.index(overlay.FOLDER) + 1:])
        in_file = [r for r in all_regions if r.path == rel]
        line = int(m.group("line")) - 1
        inside = [r for r in in_file if r.begin < line < r.end]
        for r in inside or in_file:
            found.setdefault(r.id, f"{rel}:{m.group('line')}: error: {m.group('message').strip()}")
    return found


def refused_regions(root, labs):
    """{exercise id: why} for the regions of the labs that do not read as a function body."""
    refused = {}
    for r in regions.find_regions(root):
        if r.lab in labs:
            try:
                cpp_text.check_body("".join(regions.body(root, r)))
            except cpp_text.TextError as e:
                refused[r.id] = f"{r.path}: {e}"
    return refused


def project_files(root):
    """The project's files, relative to root: git's tracked and untracked-but-not-ignored
    files in a checkout, otherwise everything outside build products."""
    root = Path(root)
    try:
        top = subprocess.run(["git", "rev-parse", "--show-toplevel"], cwd=root, check=True, capture_output=True)
        if Path(top.stdout.decode().strip()).resolve() != root.resolve():
            raise ValueError("inside another checkout (a kit under build/, say)")
        listed = subprocess.run(["git", "ls-files", "--cached", "--others", "--exclude-standard", "-z"],
                                cwd=root, check=True, capture_output=True).stdout.decode()
        return sorted({Path(p) for p in listed.split("\0") if p and (root / p).is_file()})
    except (OSError, ValueError, subprocess.CalledProcessError):
        found = []
        for folder, subfolders, files in os.walk(root):
            subfolders[:] = sorted(d for d in subfolders if d not in SKIP)
            found += [Path(folder, f).relative_to(root) for f in files]
        return sorted(found)


def sync_tree(root, copy, files=None):
    """Makes `copy` hold the project's source files (or the given ones), copying only
    what changed, so that the copy's build stays incremental; files the project no
    longer has are removed from the copy. Returns the paths copied."""
    wanted = project_files(root) if files is None else files
    changed = []
    for rel in wanted:
        path, target = root / rel, copy / rel
        if not target.exists() or not filecmp.cmp(path, target, shallow=False):
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(path, target)  # a new mtime: a stale object is never kept
            shutil.copymode(path, target)
            changed.append(rel)
        elif path.stat().st_mode != target.stat().st_mode:
            shutil.copymode(path, target)  # the same text, made executable (or not) since
    if files is None and (copy / "exercises").is_dir():
        keep = {rel.as_posix() for rel in wanted}
        for old in project_files(copy):
            if old.as_posix() not in keep and old.parts[0] in ("lib", "exercises", "lessons", "tests", "docs"):
                (copy / old).unlink()
                changed.append(old)
    return changed


def restub(copy, ids):
    """Puts the stub back into the given exercises' regions of the copy."""
    chosen = [r for r in regions.find_regions(copy) if r.id in ids]
    for rel in {r.path for r in chosen}:
        path = copy / rel
        path.write_text(regions.stub_text(path.read_text(), [r for r in chosen if r.path == rel]))


def stubbed_texts(root, ids):
    """{file: its text with the given exercises' regions stubbed} for the files holding them."""
    chosen = [r for r in regions.find_regions(root) if r.id in ids]
    return {r.path.as_posix(): regions.stub_text((root / r.path).read_text(), [x for x in chosen if x.path == r.path])
            for r in chosen}


class Reporter:
    """Says each region's first compile error the moment the compiler prints it."""

    def __init__(self, root, say, known):
        self.root, self.say, self.known = root, say, dict(known)

    def __call__(self, line):
        if " error: " not in line:
            return
        for ident, error in broken_regions(self.root, line).items():
            if ident not in self.known:
                self.known[ident] = error
                self.say(f"grade: exercise {ident} does not compile ({error})")


def build(root, build_dir, labs, say=print, quick=False, scratch=False):
    """Builds the labs' programs; stubs regions that do not compile, or are refused as
    text, again. A `scratch` tree is a copy made for grading, whose regions may be
    stubbed in place; a student's own tree is never edited (see overlay.py)."""
    root, build_dir = Path(root).resolve(), Path(build_dir).resolve()
    configure(root, build_dir, quick)
    built = Built(build_dir)
    refused = refused_regions(root, labs)
    for ident, why in refused.items():
        say(f"grade: exercise {ident} is not taken as written ({why}); it is graded as not done")
    built.restubbed.update({k: f"not taken: {v}" for k, v in refused.items()})
    targets = [(lab, kind, name) for lab in labs for kind, name in lab_targets(root, lab)]
    if scratch and refused:
        restub(root, set(refused))
    reporter = Reporter(root, say, built.restubbed)
    overlay.clear(build_dir)
    code, log = build_targets(build_dir, [name for _, _, name in targets], reporter)
    broken = {k: v for k, v in broken_regions(root, log).items() if k not in built.restubbed} if code else {}
    built.restubbed.update(broken)
    if scratch:
        while code != 0 and broken:  # stub in place, build again (incrementally)
            restub(root, set(broken))
            code, log = build_targets(build_dir, [name for _, _, name in targets], reporter)
            broken = {k: v for k, v in broken_regions(root, log).items() if k not in built.restubbed} if code else {}
            built.restubbed.update(broken)
    elif built.restubbed and (code != 0 or refused):
        try:
            return rebuilt_with_overlay(root, build_dir, built, targets, log, reporter)
        except overlay.OverlayError as e:
            built.notes.append(f"the quick rebuild is not possible here ({e}): a second build of the tree instead")
            say(f"grade: {built.notes[-1]}")
            return rebuilt_in_a_copy(root, build_dir, built, labs, quick)
    for lab, kind, name in targets:
        if code == 0 or built_whole(build_dir, name, log):
            built.binaries[(lab, kind)] = program(build_dir, name)
        else:
            built.lab_errors.setdefault(lab, first_error(log, root))
    return built


def rebuilt_with_overlay(root, build_dir, built, targets, log, reporter):
    """Each program that holds a stubbed-again region (or failed to build), relinked
    from the overlay; new errors in the overlay's copies stub more regions, until none."""
    failed = {o for line in FAILED.findall(log) for o in line.split()}
    for lab, kind, name in targets:
        for _ in range(20):
            files = {str((root / r.path).resolve()) for r in regions.find_regions(root) if r.id in built.restubbed}
            objects = objects_to_rebuild(build_dir, name, files, failed)
            if not objects:
                if built_whole(build_dir, name, log):
                    built.binaries[(lab, kind)] = program(build_dir, name)
                else:
                    built.lab_errors.setdefault(lab, first_error(log, root))
                break
            program, error_log = overlay.rebuild(root, build_dir, name, objects, stubbed_texts(root, set(built.restubbed)))
            if program:
                built.binaries[(lab, kind)] = program
                break
            reporter(error_log)
            more = {k: v for k, v in broken_regions(root, error_log).items() if k not in built.restubbed}
            if not more:
                built.lab_errors.setdefault(lab, first_error(error_log, root))
                break
            built.restubbed.update(more)
    return built


def objects_to_rebuild(build_dir, target, files, failed):
    """The target's objects compiled from the given files, or from files including one
    of them (Ninja's recorded dependencies), or whose compile failed."""
    found = dependencies(build_dir, overlay.ninja_commands(build_dir, target))
    return {obj for obj, paths in found.items() if paths & set(files)} | (set(failed) & set(found))


def dependencies(build_dir, commands):
    """{object: the resolved paths of its source and of every header it includes} for
    the compiles among a target's commands (`ninja -t commands`), from the dependencies
    Ninja recorded when it last built them."""
    compiles = [p for p in map(overlay.compile_parts, commands) if p]
    found = {obj: {str((Path(build_dir) / source).resolve())} for source, obj in compiles}
    if found:
        _, text = run(["ninja", "-C", str(build_dir), "-t", "deps", *sorted(found)])
        current = None
        for line in text.splitlines():
            if line and not line[0].isspace():
                current = line.split(":")[0]
            elif line.strip() and current in found:
                found[current].add(str((Path(build_dir) / line.strip()).resolve()))
    return found


def rebuilt_in_a_copy(root, build_dir, built, labs, quick):
    """The fallback where the build cannot be replayed: a copy of the tree with the
    regions stubbed, built beside the first."""
    work = build_dir / "grade-restubbed"
    sync_tree(root, work / "src")
    restub(work / "src", set(built.restubbed))
    copy = build(work / "src", work / "build", labs, say=lambda line: None, quick=quick, scratch=True)
    copy.restubbed = {**built.restubbed, **copy.restubbed}
    copy.notes = built.notes
    return copy
