"""Printed output in docs/*.md that must stay what the lessons print.

In a doc page, a line

    <!-- output: 10_southwell --sweeps 12 | skip: ratio -->

is followed by a ``` block holding lines the lesson prints (its stdout) when run with
those arguments from an empty folder (so its files go to out/<lesson>/ there). The
block must appear, line for line, as consecutive lines of that output, except for
what depends on the machine:
  - table columns whose header names a time or a speed (ms, us, s, Mrays/s, GB/s,
    speedup, efficiency, per second, x the bound) or a word listed after "skip:";
  - in other lines, a number followed by " ms", " s" or " us", or following a word
    listed after "skip:" ("ratio 110").
Tables are compared cell by cell, so a wider time column does not matter.
Usage: outputs.py check|fix ROOT BIN_DIR     (fix rewrites stale blocks from the run)
"""
import difflib
import re
import subprocess
import sys
import tempfile
from pathlib import Path

MARKER = re.compile(r"^<!-- output: (\S+)((?: [^|]*?)?)(?: \| skip: (.+?))? -->\s*$")
TIME_COLUMN = re.compile(r"(^|\W)(ms|us|s)(\W|$)|Mrays/s|GB/s|speedup|efficiency|per second|x the bound")
TIME_NUMBER = re.compile(r"\d+(\.\d+)?(?= (ms|s|us)\b)")
NUMBER = r"-?\d+(\.\d+)?(e[-+]?\d+)?"
CELLS = re.compile(r"\s{2,}")


class OutputError(Exception):
    pass


def normalise(lines, skip_words):
    """The lines with every machine-dependent number replaced by '*'; table rows as
    ' | '-joined cells, so that column widths do not matter."""
    out, columns, in_table = [], None, False
    for i, line in enumerate(lines):
        if i + 1 < len(lines) and re.fullmatch(r"-{3,}", lines[i + 1]) and line.strip():
            columns = [c for c in CELLS.split(line.strip())]
            skipped = [bool(TIME_COLUMN.search(c)) or c in skip_words for c in columns]
            out.append(" | ".join(columns))
            in_table = True
            continue
        if in_table and re.fullmatch(r"-{3,}", line):
            out.append("---")
            continue
        cells = CELLS.split(line.strip()) if in_table and line.strip() else None
        if cells and len(cells) == len(columns):
            out.append(" | ".join("*" if s else c for c, s in zip(cells, skipped)))
            continue
        in_table = False
        masked = TIME_NUMBER.sub("*", line.rstrip())
        for word in skip_words:
            masked = re.sub(re.escape(word) + " " + NUMBER, word + " *", masked)
        out.append(masked)
    return out


def markers(doc_lines):
    """(marker index, command arguments, skip words, first line index, closing fence index)."""
    for i, line in enumerate(doc_lines):
        m = MARKER.match(line)
        if not m:
            continue
        if i + 1 >= len(doc_lines) or doc_lines[i + 1].strip() != "```":
            raise OutputError(f"line {i + 1}: an output marker must be followed by a plain ``` block")
        close = next((j for j in range(i + 2, len(doc_lines)) if doc_lines[j].startswith("```")), None)
        if close is None:
            raise OutputError(f"line {i + 1}: the output block is not closed")
        skip = [w.strip() for w in (m.group(3) or "").split(",") if w.strip()]
        yield i, [m.group(1)] + m.group(2).split(), skip, i + 2, close


def run_lesson(bin_dir, command, cache):
    """The lesson's stdout lines, run once per command line from an empty folder."""
    key = tuple(command)
    if key not in cache:
        program = (Path(bin_dir) / command[0]).resolve()
        if not program.is_file():
            raise OutputError(f"no lesson {program} (build it first)")
        with tempfile.TemporaryDirectory() as folder:
            done = subprocess.run([str(program)] + command[1:], cwd=folder, capture_output=True, text=True,
                                  timeout=600)
        if done.returncode != 0:
            raise OutputError(f"{' '.join(command)} exited {done.returncode}: {done.stderr.strip()[-300:]}")
        cache[key] = done.stdout.splitlines()
    return cache[key]


def locate(block, output, skip):
    """Where the block's lines sit in the output (start, end), or None."""
    want, have = normalise(block, skip), normalise(output, skip)
    for start in range(len(have) - len(want) + 1):
        if have[start:start + len(want)] == want:
            return start, start + len(want)
    return None


def refreshed(block, output, skip):
    """The lines that replace a stale block: the output from the line matching the
    block's first line to the one matching its last (None if either is gone), with
    the block's own text kept where only times differ -- times measured on a quiet
    machine are not overwritten by a busy one's."""
    want, have = normalise(block, skip), normalise(output, skip)
    if not want:
        return None
    for start in (i for i, line in enumerate(have) if line == want[0]):
        end = next((j for j in range(start, len(have)) if have[j] == want[-1]), None)
        if end is None:
            continue
        new, window = [], have[start:end + 1]
        for op, a0, a1, b0, b1 in difflib.SequenceMatcher(None, want, window, autojunk=False).get_opcodes():
            new += block[a0:a1] if op == "equal" else output[start + b0:start + b1]
        return new
    return None


def process(root, bin_dir, fix):
    """Checks (or rewrites) every output block under root/docs; returns a list of problems."""
    problems, cache = [], {}
    for doc in sorted((Path(root) / "docs").glob("*.md")):
        lines = doc.read_text().splitlines()
        changed = False
        try:
            found = list(markers(lines))
        except OutputError as e:
            problems.append(f"{doc.name}: {e}")
            continue
        for marker, command, skip, first, close in reversed(found):
            try:
                output = run_lesson(bin_dir, command, cache)
            except (OutputError, subprocess.TimeoutExpired) as e:
                problems.append(f"{doc.name}:{marker + 1}: {e}")
                continue
            block = lines[first:close]
            if locate(block, output, skip):
                continue
            new = refreshed(block, output, skip) if fix else None
            if new is not None:
                lines[first:close] = new
                changed = True
                continue
            diff = "\n".join(difflib.unified_diff(normalise(block, skip), normalise(output, skip), "doc",
                                                  " ".join(command), lineterm="", n=1))
            problems.append(f"{doc.name}:{marker + 1}: output of {' '.join(command)} is stale\n{diff}")
        if changed:
            doc.write_text("\n".join(lines) + "\n")
    return problems


def main(argv):
    if len(argv) != 4 or argv[1] not in ("check", "fix"):
        print("usage: outputs.py check|fix ROOT BIN_DIR", file=sys.stderr)
        return 2
    problems = process(argv[2], argv[3], fix=argv[1] == "fix")
    for p in problems:
        print(p)
    if argv[1] == "check":
        print(f"docs outputs: {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
