"""scores: the grader's score table and Gradescope's results.json, from its results."""
import textwrap

import regions


def titles(root):
    try:
        return {r.id: r.title for r in regions.find_regions(root)}
    except regions.RegionError:
        return {}


def order(exercise):
    return [int(x) if x.isdigit() else 99 for x in exercise.split(".")]


def report(results, names, show_hidden=True):
    """The score table, per lab and exercise, with each failure's hint."""
    lines = []
    for lab in sorted({r.lab for r in results}):
        lines.append(f"Lab {lab}")
        for exercise in sorted({r.exercise for r in results if r.lab == lab}, key=order):
            mine = [r for r in results if r.exercise == exercise and r.lab == lab]
            score = f"{sum(r.passed for r in mine)}/{len(mine)}"
            lines.append(f"  {exercise:<5} {names.get(exercise, ''):<60} {score:>6}")
            for r in mine:
                if r.passed or (r.hidden and not show_hidden):
                    continue
                wrapped = textwrap.wrap(f"{r.name.split('.', 1)[-1]}: {r.hint}", 100) or [""]
                lines += [f"        {'failed: ' if k == 0 else '        '}{text}" for k, text in enumerate(wrapped)]
            hidden = [r for r in mine if r.hidden]
            if hidden and not show_hidden:
                lines.append(f"        and {len(hidden)} hidden test{'s' if len(hidden) > 1 else ''}: results shown when the grades "
                             "are published")
        mine = [r for r in results if r.lab == lab]
        lines.append(f"  {'lab total':<66} {sum(r.passed for r in mine):>3}/{len(mine)}")
    return "\n".join(lines)


def gradescope(results, names, hidden_visibility):
    """Gradescope's results.json: one entry per test, hidden ones kept out of the summary."""
    score, total = sum(r.passed for r in results), len(results)
    return {
        "score": score,
        "output": report(results, names, show_hidden=False) + f"\nscore: {score}/{total}",
        "stdout_visibility": "hidden",
        "tests": [{"name": f"{r.exercise} {names.get(r.exercise, '')}: {r.name}", "number": r.exercise,
                   "score": int(r.passed), "max_score": 1,
                   "output": "passed" if r.passed else f"{r.hint}\n\n{r.detail}".strip(),
                   "visibility": hidden_visibility if r.hidden else "visible"} for r in results],
    }
