"""build: compile the graded tests of some labs for the grader.

Each lab's test program is built on its own, so a lab whose tests do not compile
costs that lab only. A compile error inside an exercise region of lib/ would stop
every lab (they all link the library), so the grader then builds a copy of the tree
in which that region is stubbed again, as in a fresh kit: the exercise scores 0 with
the compiler's first error as its hint, and every other exercise is graded as usual.
"""
import filecmp
import os
import re
import shutil
import subprocess
from dataclasses import dataclass, field
from pathlib import Path

import regions

SKIP = {"build", "out", ".git", "__pycache__"}

# GCC and Clang: "path:line:col: error: message" (also "fatal error").
ERROR = re.compile(r"^(?P<path>[^\s:][^:\n]*):(?P<line>\d+):(?:\d+:)? (?:fatal )?error: (?P<message>.*)$", re.M)
LINKER = re.compile(r"^.*(undefined reference to .*|multiple definition of .*|ld returned \d+ exit status)$", re.M)


class BuildError(Exception):
    """No build is possible (no cmake, no built tree): one line."""


class ConfigureError(BuildError):
    """cmake cannot configure the tree: every lab scores 0, with this line as the hint."""


@dataclass
class Built:
    binary_dir: Path                                   # where bin/labNN_graded are
    lab_errors: dict = field(default_factory=dict)     # lab -> first compiler error
    restubbed: dict = field(default_factory=dict)      # exercise id -> first compiler error


def first_error(log):
    """The first compiler or linker error of a build log, as one line."""
    found = ERROR.search(log) or LINKER.search(log)
    if found:
        return found.group(0).strip()
    lines = [line.strip() for line in log.splitlines() if line.strip() and not line.startswith("[")]
    return lines[-1] if lines else "the build failed"


def run(argv, cwd=None):
    try:
        done = subprocess.run(argv, cwd=cwd, stdin=subprocess.DEVNULL, capture_output=True)
    except OSError as e:
        raise BuildError(f"cannot run {argv[0]}: {e.strerror}")
    return done.returncode, (done.stdout + done.stderr).decode("utf-8", errors="replace")


# A tree built only to be graded, many times over (mutants, the autograder): -O1 and
# no link-time optimisation, so that changing one file costs a quick compile and a
# plain link rather than the whole program's optimisation at every link.
QUICK = ["-DCMAKE_BUILD_TYPE=RelWithDebInfo", "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -DNDEBUG"]


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
        raise ConfigureError(f"cmake cannot configure {root}: {first_error(log)}")


def build_labs(build_dir, labs):
    """Builds the labs' graded tests together: None, or the build log of a failure."""
    if shutil.which("cmake") is None:
        raise BuildError("cmake not found: install it (Debian: apt-get install cmake ninja-build)")
    code, log = run(["cmake", "--build", str(build_dir), "--target"] + [f"lab{lab:02d}_graded" for lab in labs])
    return None if code == 0 else log


def build_lab(build_dir, lab):
    """None, or the build log of a failure."""
    return build_labs(build_dir, [lab])


def broken_regions(root, log):
    """The exercise regions of lib/ the log's compile errors fall in: the region
    holding the error's line, or every region of the file when the error lies
    outside them (a brace left open inside a region is reported further down)."""
    all_regions = regions.find_regions(root)
    found = {}
    for m in ERROR.finditer(log):
        try:
            rel = Path(m.group("path")).resolve().relative_to(root.resolve())
        except ValueError:
            continue
        in_file = [r for r in all_regions if r.path == rel]
        line = int(m.group("line")) - 1
        inside = [r for r in in_file if r.begin < line < r.end]
        for r in inside or in_file:
            found.setdefault(r.id, f"{rel}:{m.group('line')}: error: {m.group('message').strip()}")
    return found


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


def sync_tree(root, copy):
    """Makes `copy` hold the project's source files, copying only what changed (so
    that the copy's build stays incremental)."""
    for rel in project_files(root):
        path, target = root / rel, copy / rel
        if not target.exists() or not filecmp.cmp(path, target, shallow=False):
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(path, target)  # a new mtime: a stale object is never kept
            shutil.copymode(path, target)


def restub(copy, ids):
    """Puts the stub back into the given exercises' regions of the copy."""
    chosen = [r for r in regions.find_regions(copy) if r.id in ids]
    for rel in {r.path for r in chosen}:
        path = copy / rel
        path.write_text(regions.stub_text(path.read_text(), [r for r in chosen if r.path == rel]))


def build(root, build_dir, labs, say=print, quick=False, scratch=False):
    """Builds the labs' graded tests; stubs regions that do not compile again. A
    `scratch` tree is a copy made for grading (the autograder's), whose regions may be
    stubbed in place; a student's own tree is never edited: a copy is built instead."""
    root, build_dir = Path(root), Path(build_dir)
    configure(root, build_dir, quick)
    built = Built(build_dir)
    for lab in labs:
        log = build_lab(build_dir, lab)
        if log is None:
            continue
        broken = broken_regions(root, log)
        if broken:
            for ident, error in broken.items():
                say(f"grade: exercise {ident} does not compile ({error})")
            if scratch:
                return build_restubbed(root, build_dir, labs, broken)
            work = build_dir / "grade-restubbed"
            say(f"grade: grading the other exercises with it stubbed out, as in a fresh kit (a second build in {work})")
            sync_tree(root, work / "src")
            configure(work / "src", work / "build", quick)
            return build_restubbed(work / "src", work / "build", labs, broken)
        built.lab_errors[lab] = first_error(log)
    return built


def build_restubbed(tree, build_dir, labs, broken):
    """Builds the labs with the broken regions of `tree` stubbed, and any others that
    turn out not to compile."""
    built = Built(build_dir, restubbed=dict(broken))
    restub(tree, set(built.restubbed))
    for lab in labs:
        while True:
            log = build_lab(build_dir, lab)
            if log is None:
                break
            more = {k: v for k, v in broken_regions(tree, log).items() if k not in built.restubbed}
            if not more:
                built.lab_errors[lab] = first_error(log)
                break
            built.restubbed.update(more)
            restub(tree, set(more))
    return built
