"""make-kit: copy the project with exercises punched out, for students.

    exercises/make-kit DEST [--labs 1,2|all]

Every marked region of the chosen labs becomes a stub that throws
gi::NotImplemented; the docs' code excerpts are refreshed from the stubbed source,
so no solution survives there either. exercises/KIT lists the punched exercises.
"""
import argparse
import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import excerpts  # noqa: E402
import regions   # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
SKIP = {"build", "out", ".git", "__pycache__"}


def project_files(root):
    """The files a kit copies: git's tracked and untracked-but-not-ignored files in a
    checkout, otherwise everything outside build products."""
    root = Path(root)
    try:
        listed = subprocess.run(["git", "ls-files", "--cached", "--others", "--exclude-standard", "-z"],
                                cwd=root, check=True, capture_output=True).stdout.decode()
        return sorted({Path(p) for p in listed.split("\0") if p and (root / p).is_file()})
    except (OSError, subprocess.CalledProcessError):
        return sorted(p.relative_to(root) for p in root.rglob("*")
                      if p.is_file() and not SKIP & set(p.relative_to(root).parts))


def make_kit(root, dest, labs_spec):
    root, dest = Path(root).resolve(), Path(dest).resolve()
    if dest.exists() and any(dest.iterdir()):
        raise regions.RegionError(f"{dest} exists and is not empty")
    if dest.is_relative_to(root) and not dest.is_relative_to(root / "build"):
        raise regions.RegionError(f"{dest} is inside the project; put the kit outside it or under build/")
    all_regions = regions.find_regions(root)
    labs = regions.parse_labs(labs_spec, {r.lab for r in all_regions})
    punched = [r for r in all_regions if r.lab in labs]

    for rel in project_files(root):
        target = dest / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(root / rel, target)
    by_file = {}
    for r in punched:
        by_file.setdefault(r.path, []).append(r)
    for rel, file_regions in by_file.items():
        path = dest / rel
        path.write_text(regions.stub_text(path.read_text(), file_regions))
    excerpts.process(dest, fix=True)
    (dest / "exercises" / "KIT").write_text("".join(f"{r.id} {r.title}\n" for r in punched))
    return punched


def main(argv):
    parser = argparse.ArgumentParser(prog="make-kit", description="Write a student kit with exercises punched out.")
    parser.add_argument("dest", help="folder to create (must not exist, or be empty)")
    parser.add_argument("--labs", default="all", help="labs to punch out: 'all' or a list like 1,2")
    args = parser.parse_args(argv)
    try:
        punched = make_kit(ROOT, args.dest, args.labs)
    except regions.RegionError as e:
        print(f"make-kit: error: {e}", file=sys.stderr)
        return 2
    for lab in sorted({r.lab for r in punched}):
        ids = ", ".join(r.id for r in punched if r.lab == lab)
        print(f"lab {lab}: stubbed {ids}")
    print(f"kit written to {args.dest}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
