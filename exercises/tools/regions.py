"""Exercise regions: the reference solutions marked in lib/.

    // BEGIN EXERCISE 1.2 ray-plane intersection
    ...reference code...
    // END EXERCISE 1.2

A student kit keeps both marker lines and replaces what is between them by one
line that throws gi::NotImplemented naming the exercise and passing the function's
parameters (so that a stub uses them: no "unused parameter" warnings in a kit).
"""
import re
from dataclasses import dataclass, field
from pathlib import Path

import cpp_text

BEGIN = re.compile(r"^(\s*)// BEGIN EXERCISE (\d+)\.(\d+) (.+?)\s*$")
END = re.compile(r"^\s*// END EXERCISE (\d+)\.(\d+)\s*$")
# Code that is no exercise but would show a student the answer to one (a production
# version of the same algorithm) is marked as its companion: left out of a kit that
# punches that exercise, its stub saying why, and never graded:
#     // BEGIN KIT-HIDDEN WITH 5.2 the production BVH walk (use --accel bvh)
#     ...
#     // END KIT-HIDDEN WITH 5.2
HIDDEN_BEGIN = re.compile(r"^(\s*)// BEGIN KIT-HIDDEN WITH (\d+)\.(\d+) (.+?)\s*$")
HIDDEN_END = re.compile(r"^\s*// END KIT-HIDDEN WITH (\d+)\.(\d+)\s*$")
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

    companion: bool = False  # KIT-HIDDEN WITH this exercise, not an exercise itself
    parameters: list = field(default_factory=list)  # of the function the region sits in

    def stub(self):
        what = (f"{self.title}, left out of the kit with exercise {self.id}," if self.companion
                else f"exercise {self.id} {self.title}")
        passed = "".join(f", {name}" for name in self.parameters)
        return f'{self.indent}throw gi::NotImplemented("{what}"{passed});\n'


def regions_in(text, path, companions=False):
    """The exercise regions of one file's text (with companions=True: the KIT-HIDDEN
    ones instead), checked for pairing."""
    begin_re, end_re, word, noun = ((HIDDEN_BEGIN, HIDDEN_END, "KIT-HIDDEN WITH", "hidden code of")
                                    if companions else (BEGIN, END, "EXERCISE", "exercise"))
    found, open_region = [], None
    for i, line in enumerate(text.splitlines()):
        begin, end = begin_re.match(line), end_re.match(line)
        if begin:
            if open_region:
                raise RegionError(f"{path}:{i + 1}: BEGIN {word} inside {noun} {open_region.id}")
            indent, lab, number, title = begin.groups()
            open_region = Region(path, i, -1, int(lab), int(number), title, indent, companions,
                                 cpp_text.enclosing_parameters(text, i))
        elif end:
            ident = f"{int(end.group(1))}.{int(end.group(2))}"
            if not open_region:
                raise RegionError(f"{path}:{i + 1}: END {word} {ident} without a BEGIN")
            if ident != open_region.id:
                raise RegionError(f"{path}:{i + 1}: END {word} {ident} closes {noun} {open_region.id}")
            open_region.end = i
            found.append(open_region)
            open_region = None
    if open_region:
        raise RegionError(f"{path}:{open_region.begin + 1}: {noun} {open_region.id} has no END {word} line")
    if found and '#include "gi/core/not_implemented.hpp"' not in text:
        raise RegionError(f'{path}: holds {noun} regions but does not #include "gi/core/not_implemented.hpp"')
    return found


def source_files(root):
    root = Path(root)
    return [f for f in sorted((root / "lib").rglob("*")) if f.suffix in SOURCE_SUFFIXES and f.is_file()]


def find_regions(root):
    """Every exercise region under root/lib, sorted by id; ids must be unique."""
    root = Path(root)
    result = []
    for file in source_files(root):
        result += regions_in(file.read_text(), file.relative_to(root))
    seen = {}
    for region in result:
        if region.id in seen:
            raise RegionError(f"{region.path}:{region.begin + 1}: exercise {region.id} also marked in {seen[region.id]}")
        seen[region.id] = region.path
    return sorted(result, key=lambda r: (r.lab, r.number))


def find_companions(root, exercises):
    """Every KIT-HIDDEN region under root/lib; each must name one of `exercises`."""
    root = Path(root)
    ids = {r.id for r in exercises}
    result = []
    for file in source_files(root):
        for region in regions_in(file.read_text(), file.relative_to(root), companions=True):
            if region.id not in ids:
                raise RegionError(f"{region.path}:{region.begin + 1}: KIT-HIDDEN WITH {region.id}: no such exercise")
            result.append(region)
    return result


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
    """'all' or '1,2' -> the set of lab numbers, checked against those available.
    Numbers are ASCII decimal digits only ('١' is no lab number here)."""
    if spec is None or spec.strip() == "all":
        return set(available)
    parts = [part.strip() for part in spec.split(",") if part.strip()]
    if any(not re.fullmatch(r"[0-9]+", part) for part in parts):
        raise RegionError(f"--labs takes numbers like 1,2 or 'all', got '{spec}'")
    labs = {int(part) for part in parts}
    if not labs:
        raise RegionError(f"--labs '{spec}' names no lab; give numbers like 1,2 or 'all'")
    unknown = labs - set(available)
    if unknown:
        raise RegionError(f"no lab {', '.join(map(str, sorted(unknown)))}; labs are {', '.join(map(str, sorted(available)))}")
    return labs
