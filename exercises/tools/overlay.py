"""overlay: a lab's test program rebuilt with some regions stubbed, without touching
the student's tree and without a second build of it.

When a region of a student's own tree does not compile (or is refused as text), the
grader needs the lab's program with that region stubbed, as in a fresh kit, so that
the other exercises are graded. It writes the stubbed copies of the files concerned
under BUILD/grade-overlay/ and replays, from Ninja's own list of the target's commands
(`ninja -t commands`), only those that the failed objects feed: their compiles (with
the overlay's copies first on the include path, so a stubbed header wins), the
archives that hold them, and the program's link, each writing into the overlay
folder. Everything else is the student's build, as it is: a syntax error costs the
compile of the files that include it and one link, seconds, not a second tree.

The mutant suite builds each planted bug the same way, each in an overlay folder of its
own (`folder`), so that the reference's build is never touched and several mutants can
be built at once: the mutated file's objects, its archive and one lab's link.
"""
import concurrent.futures
import os
import re
import shlex
import shutil
import subprocess
from pathlib import Path

FOLDER = "grade-overlay"
# "ar qc lib/x.a objects..." (also gcc-ar-12, llvm-ar, and quoted as CMake writes an
# LTO build's archiver: "/usr/bin/gcc-ar-12" cr lib/x.a ...): the archive it writes.
ARCHIVE = re.compile(r"(?<![^\s/])(?:[\w.+-]*-)?ar(?:-[\d.]+)?\"?\s+[a-zA-Z]+\s+(\S+\.a)(?![^\s])")


# CMake's precompiled header on a compile line. GCC: -include DIR/cmake_pch.hxx (and
# -Winvalid-pch); Clang: -Xclang -include-pch -Xclang DIR/cmake_pch.hxx.pch -Xclang
# -include -Xclang DIR/cmake_pch.hxx.
CMAKE_PCH = re.compile(r"(?<![^\s])(?:-Winvalid-pch|(?:-Xclang\s+)?-include(?:-pch)?\s+(?:-Xclang\s+)?"
                       r"\S*cmake_pch\.hxx(?:\.pch|\.gch)?)(?![^\s])")


def without_cmake_pch(command):
    """The compile command without CMake's precompiled header: a file given a
    precompiled preamble of its own (the mutant suite's) can read only one."""
    return CMAKE_PCH.sub("", command)


class OverlayError(Exception):
    """The build cannot be replayed this way (not Ninja, or a command not understood)."""


def ninja_commands(build_dir, target):
    try:
        done = subprocess.run(["ninja", "-C", str(build_dir), "-t", "commands", target], capture_output=True,
                              stdin=subprocess.DEVNULL)
    except OSError as e:
        raise OverlayError(f"cannot run ninja: {e.strerror}")
    if done.returncode != 0:
        raise OverlayError(f"ninja cannot list the commands of {target}")
    return done.stdout.decode("utf-8", errors="replace").splitlines()


def compile_parts(command):
    """(source, object) of a compile command, or None for any other command."""
    try:
        words = shlex.split(command)
    except ValueError:
        return None
    if "-c" not in words or "-o" not in words or words[0] == ":":
        return None
    return words[words.index("-c") + 1], words[words.index("-o") + 1]


def substitute(command, replacements):
    """The command with each whole-word path replaced."""
    for old, new in replacements.items():
        command = re.sub(rf"(?<![^\s]){re.escape(old)}(?![^\s])", new.replace("\\", "\\\\"), command)
    return command


def run_shell(command, cwd):
    done = subprocess.run(["sh", "-c", command], cwd=cwd, capture_output=True, stdin=subprocess.DEVNULL)
    return done.returncode, (done.stdout + done.stderr).decode("utf-8", errors="replace")


def rebuild(root, build_dir, target, failed_objects, stubbed, folder=FOLDER, commands=None, prefix=None):
    """(path of the rebuilt program, None) or (None, compile log of a failure).
    `failed_objects`: object paths (as Ninja names them) whose compile failed;
    `stubbed`: {path relative to root: stubbed text} of the files to replace;
    `folder`: the overlay, relative to build_dir (an object already compiled into it is
    used again: two programs of one lab share their library's objects);
    `commands`: the target's `ninja -t commands`, where the caller has them already;
    `prefix`: {path relative to root: a header to -include first} for files replaced
    (the mutant suite's precompiled preambles)."""
    root, build_dir = Path(root).resolve(), Path(build_dir).resolve()
    overlay = build_dir / folder
    include = overlay / "lib"
    for rel, text in stubbed.items():
        target_file = overlay / rel
        target_file.parent.mkdir(parents=True, exist_ok=True)
        target_file.write_text(text)
    commands = ninja_commands(build_dir, target) if commands is None else commands
    replaced, compiles = {}, []
    for command in commands:
        parts = compile_parts(command)
        if not parts or parts[1] not in failed_objects:
            continue
        source, obj = parts
        new_obj = f"{folder}/obj/{obj}"
        replaced[obj] = new_obj
        if (build_dir / new_obj).is_file():
            continue
        (build_dir / new_obj).parent.mkdir(parents=True, exist_ok=True)
        words = {obj: new_obj, obj + ".d": new_obj + ".d"}
        try:
            rel = Path(source).resolve().relative_to(root).as_posix()
        except ValueError:
            rel = None
        if rel in stubbed:
            words[source] = shlex.quote(str(overlay / rel))
        new = substitute(command, words)
        first_include = re.search(r"(?<![^\s])-I", new)
        if not first_include:
            raise OverlayError(f"a compile command of {target} without -I")
        first = f"-I{shlex.quote(str(include))} "
        if prefix and prefix.get(rel):
            new = without_cmake_pch(new)
            first += f"-include {shlex.quote(str(prefix[rel]))} "
        compiles.append((new[:first_include.start()] + first + new[first_include.start():], build_dir / new_obj))
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        for (code, log), (_, obj) in zip(pool.map(lambda c: run_shell(c[0], build_dir), compiles), compiles):
            if code != 0:
                obj.unlink(missing_ok=True)  # a half-written object is never used again
                return None, log.replace(str(overlay) + "/", str(root) + "/")
    missing = set(failed_objects) - set(replaced)
    if missing:
        raise OverlayError(f"no command of {target} builds {sorted(missing)[0]}")
    program = None
    for command in commands:
        if compile_parts(command):
            continue
        archive = ARCHIVE.search(command)
        if archive and any(re.search(rf"(?<![^\s]){re.escape(o)}(?![^\s])", command) for o in replaced):
            lib = archive.group(1)
            replaced[lib] = f"{folder}/{lib}"
            (build_dir / replaced[lib]).parent.mkdir(parents=True, exist_ok=True)
            code, log = run_shell(substitute(command, replaced), build_dir)
            if code != 0:
                raise OverlayError(f"cannot archive {lib} again: {log.strip()[-300:]}")
        linked = re.search(r"(?<![^\s])-o\s+(\S*bin/" + re.escape(target) + r")(?![^\s])", command)
        if linked:
            program = f"{folder}/bin/{target}"
            (build_dir / program).parent.mkdir(parents=True, exist_ok=True)
            code, log = run_shell(substitute(command, {**replaced, linked.group(1): program}), build_dir)
            if code != 0:
                return None, log
    if program is None:
        raise OverlayError(f"no link command for {target}")
    return build_dir / program, None


def clear(build_dir):
    shutil.rmtree(Path(build_dir) / FOLDER, ignore_errors=True)
