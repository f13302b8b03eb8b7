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
Tables are compared cell by cell, so a wider time column does not matter. A figure
that legitimately differs between compilers or standard libraries (a floor of rounding
noise) is compared by value within a stated tolerance: "| near: float 25%" after the
skip words compares the column headed "float" within 25% of the larger value.

Numbers in the prose that quote a lesson are checked too. A line

    <!-- quotes: 13_hierarchical --threshold 1e-2 | derived: 38% = 100 * 0.3494; 7.7 = 4.12e-2 / 5.33e-3 | not: 1991 -->

is followed by a paragraph (up to the next blank line) in which every number must
be one the lesson prints (in the same run, compared by value: 13.0 is 13), or be
derived from printed numbers as the marker says -- the expression, whose operands
are printed numbers or whole numbers up to 1000, must round to the prose's number
in its last digit -- or be listed after "not:" (a year, a setting, a constant of
the lecture). Numbers in `code`, link targets, lesson, lab and exercise numbers and
times (a number before " ms", " s" or " us") are not quotes; 10⁻⁴ reads as 1e-4.
Usage: outputs.py check|fix ROOT BIN_DIR     (fix rewrites stale blocks from the run)
"""
import difflib
import re
import subprocess
import sys
import tempfile
from pathlib import Path

MARKER = re.compile(r"^<!-- output: (\S+)((?: [^|]*?)?)(?: \| skip: (.+?))?(?: \| near: (\S+) (\d+(?:\.\d+)?)%)? -->\s*$")
TIME_COLUMN = re.compile(r"(^|\W)(ms|us|s)(\W|$)|Mrays/s|GB/s|speedup|efficiency|per second|x the bound")
TIME_NUMBER = re.compile(r"\d+(\.\d+)?(?= (ms|s|us)\b)")
NUMBER = r"-?\d+(\.\d+)?(e[-+]?\d+)?"
CELLS = re.compile(r"\s{2,}")


QUOTES = re.compile(r"^<!-- quotes: (\S+)((?: [^|]*?)?)(?: \| derived: (.+?))?(?: \| not: (.+?))? -->\s*$")
# A number in prose: digits grouped by spaces ("100 000"), a decimal part, an exponent.
PROSE_NUMBER = re.compile(r"(?<![\w.^/-])-?\d{1,3}(?:[ \u202f\u2009]\d{3})+(?![\w.])|(?<![\w.^/-])-?\d+(?:\.\d+)?"
                          r"(?:e[-+]?\d+)?(?![\w/^]|\.\d)")
OUTPUT_NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?")
NOT_QUOTES = re.compile(r"`[^`]*`|\]\([^)]*\)|\b(?:[Ll]essons?|[Ll]abs?|[Ee]xercises?|docs/)\s*\d+(?:[.,–-]\d+)*"
                        r"|\d+(?:\.\d+)?(?= (?:ms|s|us|µs)\b)")
SUPERSCRIPT = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺", "0123456789-+")


class OutputError(Exception):
    pass


def prose_numbers(text):
    """The numbers a paragraph of prose states, as written (spaces between digit
    groups removed), leaving out those that are not quotes of a lesson."""
    text = re.sub(r"10([⁻⁺]?[⁰¹²³⁴⁵⁶⁷⁸⁹]+)", lambda m: "1e" + m.group(1).translate(SUPERSCRIPT), text)
    text = text.replace("−", "-")
    text = NOT_QUOTES.sub(" ", text)
    return [re.sub(r"[ \u202f\u2009]", "", m.group(0)) for m in PROSE_NUMBER.finditer(text)]


def same_value(a, b):
    return abs(float(a) - float(b)) <= 1e-12 * max(abs(float(a)), abs(float(b)))


def last_digit(text):
    """Half the unit of the last digit written: 7.7 -> 0.05, 1.8e-2 -> 5e-4, 38 -> 0.5."""
    mantissa, _, exponent = text.lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 0.5 * 10 ** (-decimals + (int(exponent) if exponent else 0))


def check_quotes(text, printed, derived, not_quotes):
    """Problems with the numbers of one paragraph against the lesson's printed numbers."""
    problems = []
    for name, expression in derived.items():
        operands = OUTPUT_NUMBER.findall(expression)
        unknown = [o for o in operands if not any(same_value(o, p) for p in printed)
                   and not (o.isdigit() and int(o) <= 1000)]
        if unknown or all(o.isdigit() and int(o) <= 1000 for o in operands):
            problems.append(f"derived {name} = {expression}: {', '.join(unknown) or 'no printed number'} "
                            "not among the printed numbers")
            continue
        if not re.fullmatch(r"[-+*/()0-9.e ]+", expression):
            problems.append(f"derived {name} = {expression}: only numbers and + - * / ( ) may be used")
            continue
        value = eval(expression, {"__builtins__": {}})  # noqa: S307 -- digits and operators only
        if abs(value - float(name)) > last_digit(name) * (1 + 1e-9):
            problems.append(f"derived {name} = {expression} gives {value:.6g}")
    for number in prose_numbers(text):
        if number in not_quotes or any(same_value(number, d) for d in derived) or \
                any(same_value(number, p) for p in printed):
            continue
        problems.append(f"{number} is not a number the lesson prints (quote it as printed, or derive it)")
    return problems


def quote_markers(doc_lines):
    """(marker index, command, derived {prose: expression}, not-quotes, paragraph text)."""
    for i, line in enumerate(doc_lines):
        m = QUOTES.match(line)
        if not m:
            continue
        end = next((j for j in range(i + 1, len(doc_lines)) if not doc_lines[j].strip()), len(doc_lines))
        if end == i + 1:
            raise OutputError(f"line {i + 1}: a quotes marker must be followed by its paragraph")
        derived = {}
        for item in (m.group(3) or "").split(";"):
            if item.strip():
                name, _, expression = item.partition("=")
                derived[name.strip().rstrip("%×x").strip()] = expression.strip()
        not_quotes = [n.strip() for n in (m.group(4) or "").split(",") if n.strip()]
        yield i, [m.group(1)] + m.group(2).split(), derived, not_quotes, " ".join(doc_lines[i + 1:end])


def normalise(lines, skip_words, near=None):
    """The lines with every machine-dependent number replaced by '*'; table rows as
    ' | '-joined cells, so that column widths do not matter; a cell of the column
    `near` names (column, tolerance) marked with '~', to be compared by value."""
    out, columns, in_table = [], None, False
    for i, line in enumerate(lines):
        if i + 1 < len(lines) and re.fullmatch(r"-{3,}", lines[i + 1]) and line.strip():
            columns = [c for c in CELLS.split(line.strip())]
            skipped = [bool(TIME_COLUMN.search(c)) or c in skip_words for c in columns]
            by_value = [bool(near) and c == near[0] for c in columns]
            out.append(" | ".join(columns))
            in_table = True
            continue
        if in_table and re.fullmatch(r"-{3,}", line):
            out.append("---")
            continue
        cells = CELLS.split(line.strip()) if in_table and line.strip() else None
        if cells and len(cells) == len(columns):
            out.append(" | ".join("*" if s else "~" + c if v else c for c, s, v in zip(cells, skipped, by_value)))
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
        near = (m.group(4), float(m.group(5)) / 100) if m.group(4) else None
        yield i, [m.group(1)] + m.group(2).split(), skip, near, i + 2, close


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


def same_line(a, b, near):
    """Two normalised lines alike: equal, or equal but for '~' cells within the tolerance."""
    if a == b:
        return True
    cells_a, cells_b = a.split(" | "), b.split(" | ")
    if not near or len(cells_a) != len(cells_b):
        return False
    for x, y in zip(cells_a, cells_b):
        if x == y:
            continue
        try:
            u, v = float(x[1:]), float(y[1:])
        except ValueError:
            return False
        if not (x[:1] == y[:1] == "~" and abs(u - v) <= near[1] * max(abs(u), abs(v))):
            return False
    return True


def locate(block, output, skip, near=None):
    """Where the block's lines sit in the output (start, end), or None."""
    want, have = normalise(block, skip, near), normalise(output, skip, near)
    for start in range(len(have) - len(want) + 1):
        if all(same_line(w, h, near) for w, h in zip(want, have[start:start + len(want)])):
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
        for marker, command, skip, near, first, close in reversed(found):
            try:
                output = run_lesson(bin_dir, command, cache)
            except (OutputError, subprocess.TimeoutExpired) as e:
                problems.append(f"{doc.name}:{marker + 1}: {e}")
                continue
            block = lines[first:close]
            if locate(block, output, skip, near):
                continue
            new = refreshed(block, output, skip) if fix else None
            if new is not None:
                lines[first:close] = new
                changed = True
                continue
            diff = "\n".join(difflib.unified_diff(normalise(block, skip, near), normalise(output, skip, near),
                                                  "doc",
                                                  " ".join(command), lineterm="", n=1))
            problems.append(f"{doc.name}:{marker + 1}: output of {' '.join(command)} is stale\n{diff}")
        try:
            quoted = list(quote_markers(lines))
        except OutputError as e:
            problems.append(f"{doc.name}: {e}")
            quoted = []
        for marker, command, derived, not_quotes, text in quoted:
            try:
                output = run_lesson(bin_dir, command, cache)
            except (OutputError, subprocess.TimeoutExpired) as e:
                problems.append(f"{doc.name}:{marker + 1}: {e}")
                continue
            printed = [n for line in normalise(output, []) for n in OUTPUT_NUMBER.findall(line)]
            for problem in check_quotes(text, printed, derived, not_quotes):
                problems.append(f"{doc.name}:{marker + 1}: prose quoting {' '.join(command)}: {problem}")
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
