"""Exercise regions: the reference solutions marked in lib/.

    // BEGIN EXERCISE 1.2 ray-plane intersection
    ...reference code...
    // END EXERCISE 1.2

A student kit keeps both marker lines and replaces what is between them by one
line that throws gi::NotImplemented naming the exercise.
"""
import re
from dataclasses import dataclass
from pathlib import Path

BEGIN = re.compile(r"^(\s*)// BEGIN EXERCISE (\d+)\.(\d+) (.+?)\s*$")
END = re.compile(r"^\s*// END EXERCISE (\d+)\.(\d+)\s*$")
SOURCE_SUFFIXES = {".cpp", ".hpp", ".h", ".cc"}


class RegionError(Exception):
    """A malformed marker: the message names file:line."""


@dataclass
class Region:
    path: Path        # relative to the project root
    begin: int        # index of the BEGIN line (0-based)
    end: int          # index of the END line
    lab: int
    number: int
    title: str
    indent: str

    @property
    def id(self):
        return f"{self.lab}.{self.number}"

    def stub(self):
        return f'{self.indent}throw gi::NotImplemented("exercise {self.id} {self.title}");\n'


def regions_in(text, path):
    """The regions of one file's text, checked for pairing."""
    found, open_region = [], None
    for i, line in enumerate(text.splitlines()):
        begin, end = BEGIN.match(line), END.match(line)
        if begin:
            if open_region:
                raise RegionError(f"{path}:{i + 1}: BEGIN EXERCISE inside exercise {open_region.id}")
            indent, lab, number, title = begin.groups()
            open_region = Region(path, i, -1, int(lab), int(number), title, indent)
        elif end:
            ident = f"{int(end.group(1))}.{int(end.group(2))}"
            if not open_region:
                raise RegionError(f"{path}:{i + 1}: END EXERCISE {ident} without a BEGIN")
            if ident != open_region.id:
                raise RegionError(f"{path}:{i + 1}: END EXERCISE {ident} closes exercise {open_region.id}")
            open_region.end = i
            found.append(open_region)
            open_region = None
    if open_region:
        raise RegionError(f"{path}:{open_region.begin + 1}: exercise {open_region.id} has no END EXERCISE line")
    if found and '#include "gi/core/not_implemented.hpp"' not in text:
        raise RegionError(f'{path}: holds exercises but does not #include "gi/core/not_implemented.hpp"')
    return found


def find_regions(root):
    """Every exercise region under root/lib, sorted by id; ids must be unique."""
    root = Path(root)
    result = []
    for file in sorted((root / "lib").rglob("*")):
        if file.suffix in SOURCE_SUFFIXES and file.is_file():
            result += regions_in(file.read_text(), file.relative_to(root))
    seen = {}
    for region in result:
        if region.id in seen:
            raise RegionError(f"{region.path}:{region.begin + 1}: exercise {region.id} also marked in {seen[region.id]}")
        seen[region.id] = region.path
    return sorted(result, key=lambda r: (r.lab, r.number))


def body(root, region):
    """The reference code of a region (the lines between its markers)."""
    lines = (Path(root) / region.path).read_text().splitlines(keepends=True)
    return lines[region.begin + 1:region.end]


def stub_text(text, regions):
    """text with the given regions' bodies replaced by their stubs."""
    lines = text.splitlines(keepends=True)
    for region in sorted(regions, key=lambda r: r.begin, reverse=True):
        lines[region.begin + 1:region.end] = [region.stub()]
    return "".join(lines)


def parse_labs(spec, available):
    """'all' or '1,2' -> the set of lab numbers, checked against those available."""
    if spec is None or spec.strip() == "all":
        return set(available)
    try:
        labs = {int(part) for part in spec.split(",") if part.strip()}
    except ValueError:
        raise RegionError(f"--labs takes numbers like 1,2 or 'all', got '{spec}'")
    if not labs:
        raise RegionError(f"--labs '{spec}' names no lab; give numbers like 1,2 or 'all'")
    unknown = labs - set(available)
    if unknown:
        raise RegionError(f"no lab {', '.join(map(str, sorted(unknown)))}; labs are {', '.join(map(str, sorted(available)))}")
    return labs
