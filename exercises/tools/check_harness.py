"""check_harness: the graded programs' harness (support/graded_main.cpp) against code
that leaves something behind, forges a verdict or goes for the key that signs them
(support/harness_check.cpp), run by the grader exactly as a lab's tests are. Run by
ctest as graded_harness:

    check_harness.py PROGRAM

Each Leaves*/Forges* test must fail with its reason, each After* test (run in the new
process the grader starts) and JoinsItsThreads must pass, and each way to the key
must be found shut. Three times: with the whole sandbox; with its seccomp filter off
(the harness's own non-dumpable flag alone keeps other processes out of its memory,
and it notices the flag turned back); with every layer off (the harness's checks do
not depend on the sandbox -- but a program that runs as root may read any memory,
so there, as root, the ways to the memory are expected open: the threat model says so).
"""
import os
import sys
from pathlib import Path
from unittest import mock

sys.path.insert(0, str(Path(__file__).resolve().parent))
import grade      # noqa: E402
import gtest_run  # noqa: E402

EXPECTED = {
    "LeavesAThread": "left a thread running",
    "LeavesAChild": "left a child process",
    "LeavesASignalHandler": "handler installed for signal",
    "LeavesATimer": "left a timer set",
    "LeavesAnotherRoundingMode": "rounding mode changed",
    "LeavesATerminateHandler": "terminate handler",
    "ForgesVerdictsIntoEveryDescriptor": "wrote into the grader's report",
    "ForgesAPassByExitingAtTheFirstFailure": "ended in the middle of this test",
    "HidesAThreadFromTheCount": "left a thread running",
}
PASSING = ["JoinsItsThreads", "AfterAThread", "AfterAChild", "AfterASignalHandler", "AfterATimer",
           "AfterARoundingMode", "AfterATerminateHandler", "AfterForgedVerdicts", "AfterAnExit",
           "TheKeyWasGoneBeforeAnyConstructor", "SignsFromAForkedCopy", "ReadsTheReportBack", "AfterDumpable",
           "AfterAHiddenThread", "PutsTheDefaultHandlerBack"]
MEMORY = ["OpensItsOwnMemory", "TracesItsParentFromAChild"]  # shut unless the program runs as root
ORDER = ["JoinsItsThreads", "LeavesAThread", "AfterAThread", "LeavesAChild", "AfterAChild", "LeavesASignalHandler",
         "AfterASignalHandler", "LeavesATimer", "AfterATimer", "LeavesAnotherRoundingMode", "AfterARoundingMode",
         "LeavesATerminateHandler", "AfterATerminateHandler", "ForgesVerdictsIntoEveryDescriptor",
         "AfterForgedVerdicts", "ForgesAPassByExitingAtTheFirstFailure", "AfterAnExit",
         "TheKeyWasGoneBeforeAnyConstructor", "OpensItsOwnMemory", "TracesItsParentFromAChild",
         "SignsFromAForkedCopy", "ReadsTheReportBack", "PutsTheDefaultHandlerBack", "LeavesItselfDumpable", "AfterDumpable",
         "HidesAThreadFromTheCount", "AfterAHiddenThread"]


def check(program, problems, label):
    tests = [(f"Ex99_1_Harness.{name}", False) for name in ORDER]
    # As the grader does: no memory limit on a sanitized build, whose shadow memory
    # alone is larger than any limit a test should have (the program is in BUILD/bin).
    memory = None if grade.slow_build(program.parent.parent) else gtest_run.MEMORY
    with gtest_run.Runner(memory=memory) as runner:
        results, problem = grade.grade_program(runner, program, 99, tests, 20.0, {}, False)
        missing = set(runner.missing)
    if problem:
        problems.append(f"{label}: {problem}")
    found = {r.name.split(".")[1]: r for r in results}
    as_root = os.geteuid() == 0 and "user" in missing
    failing = dict(EXPECTED)
    passing = list(PASSING) + ([] if as_root else MEMORY)
    if "seccomp" in missing:
        failing["LeavesItselfDumpable"] = "made dumpable again"  # the harness notices the flag turned back
    else:
        passing.append("LeavesItselfDumpable")  # the filter refuses to turn it back
    for name, reason in failing.items():
        r = found.get(name)
        if r is None or r.passed or reason not in r.hint:
            problems.append(f"{label}: {name} should fail with '{reason}', got "
                            f"{'a pass' if r and r.passed else repr(r.hint if r else None)}")
    for name in passing:
        if not (found.get(name) and found[name].passed):
            problems.append(f"{label}: {name} should pass, got {found[name].hint if name in found else 'nothing'}")
    if as_root:
        print(f"{label}: the program ran as root: its memory is open to it ({', '.join(MEMORY)} not expected shut)")
    print(f"{label}: {sum(r.passed for r in results)} of {len(results)} passed, as expected"
          if not problems else f"{label}: checked")


def main(argv):
    program, problems = Path(argv[1]).resolve(), []
    check(program, problems, "sandboxed")
    with mock.patch.dict(os.environ, {"GI_SANDBOX_OFF": "seccomp"}):
        check(program, problems, "no seccomp filter")
    with mock.patch.dict(os.environ, {"GI_SANDBOX_OFF": "all"}):
        check(program, problems, "no sandbox")
    for p in problems:
        print(f"graded_harness: {p}")
    print("graded_harness: " + ("FAILED" if problems else "every trick is caught by the harness, with its reason"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
