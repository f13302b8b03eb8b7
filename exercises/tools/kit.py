"""make-kit: copy the project with exercises punched out, for students.

    exercises/make-kit DEST [--labs 1,2|all] [--force]

Every marked region of the chosen labs becomes a stub that throws
gi::NotImplemented; the docs' code excerpts are refreshed from the stubbed source,
so no solution survives there either; exercises/KIT lists the stubbed exercises (the
grader grades those labs). Instructor-only files (mutants, autograder, hidden tests,
the kit maker) stay behind.

The kit is written into a temporary folder beside DEST and checked -- every chosen
region is exactly its stub, and no distinctive line of any of their solutions is
left anywhere in it -- before it is renamed to DEST. An interrupted run, a full disk
or a failed check leaves no DEST: a half-made kit, which could hold solutions, is
never where a kit is expected.
"""
import argparse
import os
import shutil
import signal
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import build     # noqa: E402
import excerpts  # noqa: E402
import regions   # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
# Kept out of kits: how the course tests its tests, grades with hidden tests, and makes kits.
INSTRUCTOR_ONLY = ("exercises/mutants/", "exercises/autograder/", "exercises/make-kit", "exercises/tools/kit.py",
                   "exercises/tools/check_kit.py", "exercises/tools/check_autograder.py", "exercises/tools/mutants.py",
                   "exercises/tools/submission.py", "exercises/tools/check_harness.py", "exercises/support/harness_check.cpp",
                   "exercises/tools/hostile.py",
                   "exercises/tools/test_")


class KitError(Exception):
    """A failure while writing the kit: one line, exit status 1."""


class UsageError(KitError):
    """A bad command line or destination: one line, exit status 2."""


class Interrupted(Exception):
    """A signal asked make-kit to stop: the partial copy is removed on the way out."""


# A partial kit carries this file from its first moment, so that a later run removes
# only stale partial copies it made itself.
PARTIAL_MARK = ".make-kit-partial"


def is_kit(folder):
    """A folder make-kit wrote: it records its exercises in exercises/KIT."""
    return (folder / "exercises" / "KIT").is_file() and not (folder / "exercises" / "KIT").is_symlink()


def instructor_only(rel):
    text = rel.as_posix()
    return text.startswith(INSTRUCTOR_ONLY) or (text.startswith("exercises/lab") and "/hidden/" in text)


def distinctive_lines(root, secret_regions):
    """Per region, the lines of its body that appear nowhere else in the source (outside
    the given regions): finding one of them in a kit means that solution leaked."""
    inside = {(r.path, i) for r in secret_regions for i in range(r.begin + 1, r.end)}
    outside = set()
    for rel in build.project_files(root):
        if rel.suffix not in regions.SOURCE_SUFFIXES:
            continue  # docs quote solutions in excerpts; a kit's must not, so they cannot vouch
        try:
            lines = (root / rel).read_text().splitlines()
        except UnicodeDecodeError:
            continue
        outside |= {line.strip() for i, line in enumerate(lines) if (rel, i) not in inside}
    secrets = {}  # an exercise and its KIT-HIDDEN companions share one id
    for r in secret_regions:
        secrets.setdefault(r.id, []).extend(line.strip() for line in regions.body(root, r)
                                            if len(line.strip()) >= 12 and line.strip() not in outside)
    return secrets


def leaks(kit_dir, secrets):
    """(file:line, exercise) wherever a distinctive solution line occurs in the kit."""
    wanted = {line: ident for ident, lines in secrets.items() for line in lines}
    found = []
    for rel in build.project_files(kit_dir):
        try:
            lines = (kit_dir / rel).read_text().splitlines()
        except UnicodeDecodeError:
            continue
        found += [(f"{rel}:{i + 1}", wanted[line.strip()]) for i, line in enumerate(lines) if line.strip() in wanted]
    return found


def check_destination(root, dest, force):
    if dest == root or root.is_relative_to(dest):
        raise UsageError(f"{dest} holds the project itself; choose a new folder")
    if dest.is_relative_to(root) and not dest.is_relative_to(root / "build"):
        raise UsageError(f"{dest} is inside the project; put the kit outside it or under build/")
    if dest.is_symlink() or (dest.exists() and not dest.is_dir()):
        raise UsageError(f"{dest} exists and is not a folder")
    if dest.is_dir() and any(dest.iterdir()):
        if not is_kit(dest):
            raise UsageError(f"{dest} exists, is not empty and is no kit: make-kit replaces only a kit it made")
        if not force:
            raise UsageError(f"{dest} holds a kit (--force replaces it)")


def write_kit(root, folder, punched, hidden=()):
    """Copies the project into `folder` and punches the regions out (the exercises and
    their KIT-HIDDEN companions)."""
    for rel in build.project_files(root):
        if instructor_only(rel):
            continue
        target = folder / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(root / rel, target)
    out = list(punched) + list(hidden)
    for rel in sorted({r.path for r in out}):
        path = folder / rel
        path.write_text(regions.stub_text(path.read_text(), [r for r in out if r.path == rel]))
    problems = excerpts.process(folder, fix=True)
    if problems:
        raise KitError(f"the docs' code excerpts cannot be refreshed: {problems[0].splitlines()[0]}")
    (folder / "exercises" / "KIT").write_text("".join(f"{r.id} {r.title}\n" for r in punched))


def check_kit_text(root, folder, punched, hidden=()):
    """Raises KitError unless every punched region is its stub and no solution is left."""
    stubbed = {r.id: r for r in regions.find_regions(folder)}
    for r in punched:
        if r.id not in stubbed or regions.body(folder, stubbed[r.id]) != [r.stub()]:
            raise KitError(f"exercise {r.id} is not stubbed in the kit")
    # Matched by their order in each file: stubbing moves the lines.
    in_kit = regions.find_companions(folder, stubbed.values())
    for path in sorted({r.path for r in hidden}):
        mine = [r for r in hidden if r.path == path]
        theirs = [regions.body(folder, r) for r in in_kit if r.path == path] + [None] * len(mine)
        for r, body in zip(mine, theirs):
            if body != [r.stub()]:
                raise KitError(f"{r.path}:{r.begin + 1}: the code hidden with exercise {r.id} is left in the kit")
    found = leaks(folder, distinctive_lines(root, list(punched) + list(hidden)))
    if found:
        where, ident = found[0]
        raise KitError(f"solution text of exercise {ident} left at {where} ({len(found)} line(s) in all)")


def move_into_place(temp, dest):
    """Renames the finished kit to dest; an existing dest goes if empty, or if it is a
    kit make-kit wrote (--force, checked before any work began)."""
    (temp / PARTIAL_MARK).unlink()
    if not dest.exists():
        os.rename(temp, dest)
        return
    if not any(dest.iterdir()):
        dest.rmdir()
        os.rename(temp, dest)
        return
    if not is_kit(dest):  # it changed while the kit was written: leave it alone
        raise KitError(f"{dest} is no longer a kit; no kit was made")
    # From the old kit's rename to its removal no signal may stop the switch halfway:
    # the new kit is then in place and the old one beside it, and the run would say
    # it made none.
    with signals_held():
        old = Path(tempfile.mkdtemp(prefix=f".{dest.name}.old-", dir=dest.parent))
        os.rename(dest, old / "kit")
        os.rename(temp, dest)
        shutil.rmtree(old, ignore_errors=True)


def make_kit(root, dest, labs_spec, force=False):
    """Writes the kit; returns the punched regions."""
    if not str(dest).strip():
        raise UsageError("the destination is empty; name a new folder for the kit")
    root, dest = Path(root).resolve(), Path(os.path.abspath(dest))
    check_destination(root, dest.resolve(), force)
    all_regions = regions.find_regions(root)
    try:
        labs = regions.parse_labs(labs_spec, {r.lab for r in all_regions})
    except regions.RegionError as e:
        raise UsageError(str(e))
    punched = [r for r in all_regions if r.lab in labs]
    hidden = [r for r in regions.find_companions(root, all_regions) if r.lab in labs]
    temp = None
    try:
        try:
            dest.parent.mkdir(parents=True, exist_ok=True)
            for stale in dest.parent.glob(f".{dest.name}.partial-*"):  # left by a run that was killed
                if (stale / PARTIAL_MARK).is_file() and not stale.is_symlink():
                    shutil.rmtree(stale, ignore_errors=True)
            for stale in dest.parent.glob(f".{dest.name}.old-*"):  # a replaced kit a kill -9 left
                if not stale.is_symlink() and is_kit(stale / "kit"):
                    shutil.rmtree(stale, ignore_errors=True)
            temp = Path(tempfile.mkdtemp(prefix=f".{dest.name}.partial-", dir=dest.parent))
            (temp / PARTIAL_MARK).write_text("a kit being written by make-kit; removed when it is done\n")
        except OSError as e:
            raise KitError(f"cannot write in {dest.parent}: {e.strerror}")
        try:
            write_kit(root, temp, punched, hidden)
            check_kit_text(root, temp, punched, hidden)
            move_into_place(temp, dest)
        except OSError as e:
            raise KitError(f"cannot write the kit in {dest.parent}: {e.strerror}; no kit was made")
    finally:
        if temp is not None:
            with signals_held():
                shutil.rmtree(temp, ignore_errors=True)
    return punched


class signals_held:
    """While the partial copy is removed, a second signal must not cut the removal short."""
    NAMES = ("SIGTERM", "SIGHUP", "SIGINT", "SIGQUIT")

    def __enter__(self):
        self.saved = {n: signal.signal(getattr(signal, n), signal.SIG_IGN) for n in self.NAMES if hasattr(signal, n)}

    def __exit__(self, *_):
        for name, handler in self.saved.items():
            signal.signal(getattr(signal, name), handler)


class OneLineParser(argparse.ArgumentParser):
    # No abbreviations: '--build' must not quietly mean '--build-dir' and start a build there.
    def __init__(self, *args, **kwargs):
        super().__init__(*args, allow_abbrev=False, **kwargs)

    def error(self, message):
        raise UsageError(f"{message} (try --help)")


def stop(signum, frame):
    raise Interrupted(signal.Signals(signum).name)


def ignore_signals():
    """From here on a signal cannot interrupt: the kit is whole, or its copy is being removed."""
    for name in signals_held.NAMES:
        if hasattr(signal, name):
            signal.signal(getattr(signal, name), signal.SIG_IGN)


def main(argv):
    for name in signals_held.NAMES:  # each cleans the partial copy up on its way out
        if hasattr(signal, name):
            signal.signal(getattr(signal, name), stop)
    parser = OneLineParser(prog="make-kit", description="Write a student kit with exercises punched out.")
    parser.add_argument("dest", help="folder to create (must not exist, or be empty)")
    parser.add_argument("--labs", default="all", help="labs to punch out: 'all' or a list like 1,2")
    parser.add_argument("--force", action="store_true", help="replace a DEST that holds a kit make-kit wrote")
    try:
        args = parser.parse_args(argv)
        punched = make_kit(ROOT, args.dest, args.labs, args.force)
        ignore_signals()  # the kit is in place: a signal now must not say it was not made
    except (KitError, regions.RegionError) as e:
        ignore_signals()
        print(f"make-kit: error: {e}", file=sys.stderr)
        return 2 if isinstance(e, UsageError) else 1
    except (KeyboardInterrupt, Interrupted):
        ignore_signals()
        print("make-kit: interrupted; no kit was made", file=sys.stderr)
        return 130
    for lab in sorted({r.lab for r in punched}):
        ids = ", ".join(r.id for r in punched if r.lab == lab)
        print(f"lab {lab}: stubbed {ids}")
    print(f"kit written to {args.dest}")
    return 0


if __name__ == "__main__":
    # A signal that comes as main returns ends the run as one during it would: one
    # line, status 130, never a traceback from the exit.
    try:
        status = main(sys.argv[1:])
    except (KeyboardInterrupt, Interrupted):
        ignore_signals()
        print("make-kit: interrupted; no kit was made", file=sys.stderr)
        status = 130
    sys.exit(status)
