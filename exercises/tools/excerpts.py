"""Code excerpts in docs/*.md that must stay identical to the source.

In a doc page, a line

    <!-- excerpt: lib/gi/geometry/sphere.cpp | std::optional<Hit> intersect(const Ray& ray, const Sphere& sphere) { -->

is followed by a ```cpp fenced block holding the source from the first line that
starts with that text (leading spaces ignored) through the line that closes it: the
first later line equal to the start line's indentation plus "}" or "};".
Usage: excerpts.py check ROOT | excerpts.py fix ROOT
"""
import difflib
import re
import sys
from pathlib import Path

MARKER = re.compile(r"^<!-- excerpt: (\S+) \| (.+?) -->\s*$")


class ExcerptError(Exception):
    pass


def extract(root, source, prefix):
    """The excerpt's lines from the source file, with their common indentation removed."""
    path = Path(root) / source
    if not path.is_file():
        raise ExcerptError(f"no source file {source}")
    lines = path.read_text().splitlines()
    for start, line in enumerate(lines):
        if line.lstrip().startswith(prefix):
            indent = line[: len(line) - len(line.lstrip())]
            for end in range(start + 1, len(lines)):
                if lines[end] in (indent + "}", indent + "};"):
                    return [l[len(indent):] if l.startswith(indent) else l for l in lines[start:end + 1]]
            raise ExcerptError(f"{source}: no closing brace after '{prefix}'")
    raise ExcerptError(f"{source}: no line starts with '{prefix}'")


def blocks(doc_lines):
    """(marker index, source, prefix, first code line index, closing fence index) per excerpt."""
    for i, line in enumerate(doc_lines):
        m = MARKER.match(line)
        if not m:
            continue
        if i + 1 >= len(doc_lines) or not doc_lines[i + 1].startswith("```"):
            raise ExcerptError(f"line {i + 1}: an excerpt marker must be followed by a ``` block")
        close = next((j for j in range(i + 2, len(doc_lines)) if doc_lines[j].startswith("```")), None)
        if close is None:
            raise ExcerptError(f"line {i + 1}: the excerpt's code block is not closed")
        yield i, m.group(1), m.group(2), i + 2, close


def process(root, fix):
    """Checks (or rewrites) every excerpt under root/docs; returns a list of problems."""
    problems = []
    for doc in sorted((Path(root) / "docs").glob("*.md")):
        lines = doc.read_text().splitlines()
        changed = False
        try:
            found = list(blocks(lines))
        except ExcerptError as e:
            problems.append(f"{doc.name}: {e}")
            continue
        for marker, source, prefix, first, close in reversed(found):
            try:
                want = extract(root, source, prefix)
            except ExcerptError as e:
                problems.append(f"{doc.name}:{marker + 1}: {e}")
                continue
            have = lines[first:close]
            if have == want:
                continue
            if fix:
                lines[first:close] = want
                changed = True
            else:
                diff = "\n".join(difflib.unified_diff(have, want, "doc", source, lineterm="", n=1))
                problems.append(f"{doc.name}:{marker + 1}: excerpt of {source} is stale\n{diff}")
        if changed:
            doc.write_text("\n".join(lines) + "\n")
    return problems


def main(argv):
    if len(argv) != 3 or argv[1] not in ("check", "fix"):
        print("usage: excerpts.py check|fix ROOT", file=sys.stderr)
        return 2
    problems = process(argv[2], fix=argv[1] == "fix")
    for p in problems:
        print(p)
    if argv[1] == "check":
        print(f"docs excerpts: {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
