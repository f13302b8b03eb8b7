"""hand-in: the zip a student uploads, holding only the source files with exercises.

    exercises/hand-in [OUT.zip]        (default: hand-in.zip in the kit's top folder)

The autograder takes the code between each exercise's BEGIN/END markers from the
files of lib/ that hold them, so those files -- and exercises/KIT, which says which
labs the kit is for -- are all it needs: a few hundred kilobytes, never the build/
folder (a hundred megabytes of objects and programs). Links are not followed (the
autograder takes regular files only). The zip is written under a temporary name and
renamed: it is whole or absent. It lists what it took.
"""
import os
import stat
import sys
import tempfile
import zipfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import regions  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]


class HandInError(Exception):
    pass


def files_to_hand_in(root):
    """The files of lib/ holding an exercise region, and exercises/KIT if there is one."""
    links = [p for p in sorted((root / "lib").rglob("*")) if p.is_symlink() and p.suffix in regions.SOURCE_SUFFIXES]
    if links:
        raise HandInError(f"{links[0].relative_to(root)} is a link: the autograder takes regular files only")
    found = sorted({r.path for r in regions.find_regions(root)})
    if (root / "exercises" / "KIT").is_file():
        found.append(Path("exercises/KIT"))
    for rel in found:
        if not stat.S_ISREG((root / rel).lstat().st_mode):
            raise HandInError(f"{rel} is a link or not a file: hand in the file itself")
    return found


def write_zip(root, out):
    out = Path(os.path.abspath(out))
    if out.is_relative_to(root / "lib"):
        raise HandInError("write the zip outside lib/")
    if os.path.lexists(out) and not stat.S_ISREG(out.lstat().st_mode):
        raise HandInError(f"{out} exists and is not a regular file")
    files = files_to_hand_in(root)
    fd, temp = tempfile.mkstemp(prefix=f".{out.name}.", dir=out.parent)
    os.close(fd)
    try:
        with zipfile.ZipFile(temp, "w", zipfile.ZIP_DEFLATED) as z:
            for rel in files:
                z.write(root / rel, rel.as_posix())
        os.replace(temp, out)
    except OSError:
        Path(temp).unlink(missing_ok=True)
        raise
    return out, files


def main(argv):
    if len(argv) > 1 or (argv and argv[0].startswith("-")):
        print("usage: exercises/hand-in [OUT.zip]", file=sys.stderr)
        return 2
    try:
        out, files = write_zip(ROOT, argv[0] if argv else ROOT / "hand-in.zip")
    except (HandInError, regions.RegionError) as e:
        print(f"hand-in: error: {e}", file=sys.stderr)
        return 1
    except OSError as e:
        print(f"hand-in: error: cannot write the zip: {e.strerror}", file=sys.stderr)
        return 1
    size = out.stat().st_size
    print(f"hand-in: {len(files)} files ({size // 1024} KB) written to {out}: upload this zip")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
