#!/usr/bin/env python3
"""costs: where a build's time and a test run's time go.

    .ci/costs.py build BUILD_DIR     from BUILD_DIR/.ninja_log: compile against link,
                                     per folder, the ten slowest steps
    .ci/costs.py tests BUILD_DIR     from the last ctest run in BUILD_DIR: per label,
                                     the ten slowest tests

Seconds are those of each step or test alone: on two cores a build's steps run two at a
time, so their sum is about twice the wall-clock time, which is printed beside it.
"""
import json
import re
import shutil
import signal
import subprocess
import sys
from collections import defaultdict
from pathlib import Path


def ninja_steps(build):
    """{output: seconds} of each step as last built, and the wall-clock seconds of the last
    run of ninja (its log restarts its clock at every run)."""
    log = Path(build) / ".ninja_log"
    if not log.is_file():
        raise SystemExit(f"costs: error: {log} not found: build the tree first")
    steps, runs, last_end = {}, [[]], 0
    for line in log.read_text().splitlines():
        fields = line.split("\t")
        if line.startswith("#") or len(fields) != 5:
            continue
        start, end, output = int(fields[0]), int(fields[1]), fields[3]
        if end < last_end:  # steps are logged as they end: an earlier end opens a new run
            runs.append([])
        runs[-1].append((start, end))
        steps[output] = (end - start) / 1000
        last_end = end
    wall = (max(e for _, e in runs[-1]) - min(s for s, _ in runs[-1])) / 1000 if runs[-1] else 0.0
    return steps, wall


def kind_and_folder(output):
    """('compile' or 'link', the source folder or the program's kind) of one output."""
    path = Path(output)
    if "CMakeFiles" in path.parts and path.suffix in (".o", ".obj", ".gch", ".pch"):
        return "compile", "/".join(path.parts[:path.parts.index("CMakeFiles")]) or "."
    name = path.name
    if name.startswith("test_"):
        return "link", "tests (programs)"
    if name.startswith("lab") or name == "graded_harness_check":
        return "link", "exercises (programs)"
    if name[:2].isdigit():
        return "link", "lessons (programs)"
    if path.suffix in (".a", ".lib"):
        return "link", "libraries (archives)"
    return "link", "other"


def build_costs(build):
    steps, wall = ninja_steps(build)
    by_kind, by_folder = defaultdict(float), defaultdict(float)
    for output, seconds in steps.items():
        kind, folder = kind_and_folder(output)
        by_kind[kind] += seconds
        by_folder[(kind, folder)] += seconds
    total = sum(steps.values())
    print(f"build: {len(steps)} steps, {total:.0f} s of steps, the last run {wall:.0f} s of wall-clock time")
    for kind in ("compile", "link"):
        print(f"  {kind:<8}{by_kind[kind]:8.0f} s  {100 * by_kind[kind] / max(total, 1e-9):5.1f}%")
    print("per folder:")
    for (kind, folder), seconds in sorted(by_folder.items(), key=lambda kv: -kv[1]):
        print(f"  {seconds:8.1f} s  {kind:<8}{folder}")
    print("the ten slowest steps:")
    for output, seconds in sorted(steps.items(), key=lambda kv: -kv[1])[:10]:
        print(f"  {seconds:8.1f} s  {output}")


def test_times(build):
    """{test: seconds} of the last ctest run, from its log."""
    log = Path(build) / "Testing" / "Temporary" / "LastTest.log"
    if not log.is_file():
        raise SystemExit(f"costs: error: {log} not found: run ctest first")
    times, name = {}, None
    for line in log.read_text(errors="replace").splitlines():
        opened = re.match(r"^\d+/\d+ Test: (.+)$", line)  # "12/923 Test: NAME"
        if opened:
            name = opened.group(1).strip()
        elif line.startswith('Test time =') and name:
            times[name] = float(line.split("=")[1].split()[0])
            name = None
    return times


def test_labels(build):
    """{test: [labels]} as ctest lists them. Listing writes a new, empty LastTest.log:
    the last run's is put back afterwards."""
    log = Path(build) / "Testing" / "Temporary" / "LastTest.log"
    kept = log.with_name("LastTest.log.costs")
    shutil.copyfile(log, kept)
    try:
        listed = subprocess.run(["ctest", "--show-only=json-v1"], cwd=build, capture_output=True, text=True)
    finally:
        shutil.move(kept, log)
    if listed.returncode != 0:
        raise SystemExit(f"costs: error: ctest --show-only failed in {build}")
    labels = {}
    for test in json.loads(listed.stdout).get("tests", []):
        found = [p["value"] for p in test.get("properties", []) if p["name"] == "LABELS"]
        labels[test["name"]] = found[0] if found else []
    return labels


def test_costs(build):
    times, labels = test_times(build), test_labels(build)
    by_label, count = defaultdict(float), defaultdict(int)
    for name, seconds in times.items():
        for label in labels.get(name) or ["(none)"]:
            by_label[label] += seconds
            count[label] += 1
    print(f"tests: {len(times)} run, {sum(times.values()):.0f} s of tests")
    for label, seconds in sorted(by_label.items(), key=lambda kv: -kv[1]):
        print(f"  {seconds:8.1f} s  {count[label]:5d} tests  {label}")
    print("the ten slowest tests:")
    for name, seconds in sorted(times.items(), key=lambda kv: -kv[1])[:10]:
        print(f"  {seconds:8.1f} s  {name}  [{', '.join(labels.get(name, []))}]")


def main(argv):
    if hasattr(signal, "SIGPIPE"):  # `costs.py build DIR | head` stops quietly
        signal.signal(signal.SIGPIPE, signal.SIG_DFL)
    if len(argv) != 2 or argv[0] not in ("build", "tests"):
        print("usage: .ci/costs.py build|tests BUILD_DIR", file=sys.stderr)
        return 2
    if not Path(argv[1]).is_dir():
        print(f"costs: error: {argv[1]} is not a folder", file=sys.stderr)
        return 2
    (build_costs if argv[0] == "build" else test_costs)(argv[1])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
