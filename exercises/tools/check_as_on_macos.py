"""check_as_on_macos: the grader where Linux's sandbox layers and parts of Python are
missing, as on a Mac. Run by ctest as grade_as_on_macos:

    check_as_on_macos.py BUILD_DIR LABS

Grades the built tree's LABS with every layer of the sandbox switched off
(GI_SANDBOX_OFF=all: no namespaces, no user of its own, no subreaper, no seccomp) and
with Python's os.pipe2 and resource module hidden (as_on_macos/sitecustomize.py, read
by every Python process the grader starts). Passes when the reference scores full
marks and the grader says, in one line each, that it has no resource limits and no
user of its own: what it cannot enforce is said, and grading goes on.
"""
import os
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
SAID = ("no resource limits", "no user of its own")


def main(argv):
    if len(argv) != 3:
        print("usage: check_as_on_macos.py BUILD_DIR LABS", file=sys.stderr)
        return 2
    env = dict(os.environ, GI_SANDBOX_OFF="all", PYTHONPATH=str(HERE / "as_on_macos"))
    done = subprocess.run([sys.executable, str(HERE / "grade.py"), "--no-build", "--build-dir", argv[1],
                           "--labs", argv[2], "--expect", "full"], env=env, capture_output=True, text=True,
                          errors="replace", stdin=subprocess.DEVNULL)
    output = done.stdout + done.stderr
    print(output[-3000:])
    problems = [f"the grader exited {done.returncode}: the reference does not score full marks"] if done.returncode else []
    problems += [f"the grader does not say '{words}'" for words in SAID if words not in output]
    for p in problems:
        print(f"grade_as_on_macos: {p}")
    print("grade_as_on_macos: " + ("FAILED" if problems else "full marks, and what cannot be enforced is said"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
