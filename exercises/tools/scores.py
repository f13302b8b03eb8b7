"""scores: the grader's score table and Gradescope's results.json, from its results."""
import textwrap
from pathlib import Path

import regions


def titles(root):
    try:
        return {r.id: r.title for r in regions.find_regions(root)}
    except regions.RegionError:
        return {}


def order(exercise):
    return [int(x) if x.isdigit() else 99 for x in exercise.split(".")]


def report(results, names, show_hidden=True):
    """The score table, per lab and exercise, with each failure's hint. Without
    `show_hidden` (what a student sees before the grades are published) the hidden
    tests are left out of every count and every line: only how many there are is said."""
    lines = []
    shown = [r for r in results if show_hidden or not r.hidden]
    for lab in sorted({r.lab for r in results}):
        lines.append(f"Lab {lab}")
        for exercise in sorted({r.exercise for r in results if r.lab == lab}, key=order):
            mine = [r for r in shown if r.exercise == exercise and r.lab == lab]
            score = f"{sum(r.passed for r in mine)}/{len(mine)}"
            lines.append(f"  {exercise:<5} {names.get(exercise, ''):<60} {score:>6}")
            for r in mine:
                if r.passed:
                    continue
                wrapped = textwrap.wrap(f"{r.name.split('.', 1)[-1]}: {r.hint}", 100) or [""]
                lines += [f"        {'failed: ' if k == 0 else '        '}{text}" for k, text in enumerate(wrapped)]
        mine = [r for r in shown if r.lab == lab]
        hidden = sum(1 for r in results if r.lab == lab and r.hidden)
        label = "lab total" if show_hidden or not hidden else "lab total, visible tests"
        lines.append(f"  {label:<66} {sum(r.passed for r in mine):>3}/{len(mine)}")
        if hidden and not show_hidden:
            lines.append(f"  and {hidden} hidden test{'s' if hidden > 1 else ''}: results shown when the grades are "
                         "published")
    return "\n".join(lines)


def relative(text, root):
    return text.replace(str(Path(root).resolve()) + "/", "") if root else text


def gradescope(results, names, hidden_visibility, root=None):
    """Gradescope's results.json: one entry per test. The summary a student sees counts
    the visible tests only (Gradescope keeps the total hidden while hidden tests are)."""
    score = sum(r.passed for r in results)
    visible = [r for r in results if not r.hidden]
    hidden = len(results) - len(visible)
    summary = (f"visible tests: {sum(r.passed for r in visible)}/{len(visible)}"
               + (f" (and {hidden} hidden: shown when the grades are published)" if hidden else ""))
    return {
        "score": score,
        "output": relative(report(results, names, show_hidden=False) + f"\n{summary}", root),
        "stdout_visibility": "hidden",
        "tests": [{"name": f"{r.exercise} {names.get(r.exercise, '')}: {r.name}", "number": r.exercise,
                   "score": int(r.passed), "max_score": 1,
                   "output": relative("passed" if r.passed else f"{r.hint}\n\n{r.detail}".strip(), root),
                   "visibility": hidden_visibility if r.hidden else "visible"} for r in results],
    }
