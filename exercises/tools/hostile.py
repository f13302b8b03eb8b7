"""hostile: submissions that try to cheat the autograder, each one a test of it (the
threat model in exercises/README.md). Run by ctest as hostile_submissions:

    hostile.py WORK

WORK is a copy of the tree with a build (the mutant suite's): each submission costs a
recompile of the files it changes. Each submission is a lab 1 kit whose regions hold
an attack (written with everything an attacker could know: the autograder's paths,
the results file) or the reference, and each is graded exactly as Gradescope does,
by run_autograder on an unpacked autograder zip. Checked for every one: exercise 1.1
and 1.2 score what their functions earn and nothing more; no output a student sees
holds a line of a hidden test or of the reference solution, an absolute path into the
autograder's folders, or a variable of the grader's environment; no count in the
visible summary includes the hidden tests; the instructor's tree is unchanged; the
results file is the grader's and stays so after grading; no process the attack
started is alive. Some attacks are graded again with the sandbox's namespaces
switched off (GI_SANDBOX_OFF=pidns,mount: a container that forbids them), and two
through exercises/grade in a student's own tree.
"""
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import grade       # noqa: E402
import kit         # noqa: E402
import regions     # noqa: E402
import sandbox     # noqa: E402
import submission  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
CANARY = "GI_GRADER_SECRET_CANARY"
# The autograder's time limit per test program run (make-zip --timeout). The attacks
# that run until they are stopped (a sleep, a flood, a memory bomb) meet it whatever it
# is; lab 1's right answers finish in milliseconds. Short, so that the four runs that
# end at the limit cost seconds each, not the default's ten.
TIME_LIMIT = 3.0

# Attacks, as the bodies of regions 1.1 (sphere.cpp) and 1.2 (plane.cpp). {ROOT} is the
# autograder's unpacked tree, {WORK} its build folder, {RESULTS} the results file,
# {MARK} a word each attack's processes carry on their command line.
FORGE_REPORTS = r'''
  static bool armed = false;
  if (!armed) {  // a gtest report of passes, written at exit where --gtest_output points
    armed = true;
    std::atexit(+[] {
      char args[65536] = {};
      std::FILE* cmd = std::fopen("/proc/self/cmdline", "rb");
      const std::size_t got = cmd ? std::fread(args, 1, sizeof args - 1, cmd) : 0;
      for (std::size_t k = 0; k < got; ++k) {
        const std::string arg(args + k);
        k += arg.size();
        if (arg.rfind("--gtest_output=json:", 0) == 0)
          if (std::FILE* out = std::fopen(arg.substr(20).c_str(), "w"))
            std::fputs("{\"testsuites\": []}", out), std::fclose(out);
      }
    });
  }
  for (int fd = 3; fd < 256; ++fd)  // a verdict of "passed" into every descriptor
    if (std::FILE* out = fdopen(fd, "a")) {
      std::fputs("0000000000000000000000000000000000000000000000000000000000000000 "
                 "{\"n\":1,\"e\":\"end\",\"t\":\"Ex1_1_RaySphere.OffCentreHit\",\"ok\":true,\"skip\":false,\"fail\":[]}\n",
                 out);
      std::fflush(out);
    }
  (void)ray, (void)sphere;
  return std::nullopt;
'''
EXIT_ZERO = r'''
  (void)ray, (void)plane;
  std::exit(0);
'''
READ_AND_THROW = r'''
  (void)ray, (void)sphere;
  std::string text;
  for (const char* path : {"{ROOT}/exercises/lab01/hidden/random_rays_test.cpp", "{ROOT}/lib/gi/geometry/sphere.cpp",
                           "{WORK}/src/exercises/lab01/hidden/random_rays_test.cpp", "{WORK}/src/lib/gi/geometry/plane.cpp",
                           "/proc/self/environ", "/proc/1/environ", "/proc/self/cmdline"})
    if (std::FILE* in = std::fopen(path, "rb")) {
      char buffer[8192];
      const std::size_t got = std::fread(buffer, 1, sizeof buffer, in);
      text += std::string(buffer, got) + "\n";
      std::fclose(in);
    }
  if (const char* secret = std::getenv("{CANARY}")) text += secret;
  for (char& c : text) if (c == '\0') c = '\n';
  throw std::runtime_error("read: " + text);
'''
VANDALISE = r'''
  (void)ray, (void)plane;
  std::remove("{ROOT}/exercises/lab01/ray_sphere_test.cpp");
  std::remove("{ROOT}/exercises/lab01/hidden/random_rays_test.cpp");
  if (std::FILE* out = std::fopen("{ROOT}/lib/gi/geometry/plane.cpp", "w")) std::fclose(out);
  if (std::FILE* out = std::fopen("{RESULTS}", "w")) std::fputs("{\"score\": 999}", out), std::fclose(out);
  if (std::FILE* out = std::fopen("{WORK}/src/exercises/lab01/ray_plane_test.cpp", "w")) std::fclose(out);
  throw std::runtime_error("vandalised");  // so that the function earns nothing: any point would be forged
'''
DETACH = r'''
  (void)ray, (void)sphere;
  static const int started = std::system(
      "setsid sh -c 'sleep 4; echo {MARK} > /dev/null; printf \"{\\\"score\\\": 999}\" > {RESULTS}' "
      ">/dev/null 2>&1 &");
  (void)started;
  throw std::runtime_error("attacked");  // so that the function earns nothing
'''
SLEEP_PAST_THE_LIMIT = r'''
  (void)ray, (void)plane;
  static const int slept = std::system("sleep 600 {MARK} 2>/dev/null; sleep 600");
  (void)slept;
  return std::nullopt;
'''
FLOOD = r'''
  (void)ray, (void)sphere;
  for (;;) std::fputs("an endless line of output, to fill the disk ", stdout);
'''
MEMORY_BOMB = r'''
  (void)ray, (void)plane;
  for (;;) {
    char* block = new char[1 << 28];
    for (int k = 0; k < (1 << 28); k += 4096) block[k] = 1;
  }
'''
FORK_BOMB = r'''
  (void)ray, (void)sphere;
  static const int bombed = std::system("sh -c 'f() { f | f & }; f' {MARK} >/dev/null 2>&1");
  (void)bombed;
  throw std::runtime_error("attacked");  // so that the function earns nothing
'''
INCLUDE_HIDDEN = '#include "{ROOT}/exercises/lab01/hidden/random_rays_test.cpp"\n  return std::nullopt;\n'
ESCAPE_THE_FUNCTION = r'''
  (void)ray, (void)plane;
  return std::nullopt;
}
struct Forge {
  Forge() { std::atexit(+[] { std::puts("[  PASSED  ] 18 tests."); }); }
} forge;
std::optional<Hit> never_called(const Ray& ray, const Plane& plane) {
  (void)ray, (void)plane;
  return std::nullopt;
'''
ASM = '  asm volatile("" ::: "memory");\n  (void)ray, (void)sphere;\n  return std::nullopt;\n'
# A function-local entry in .preinit_array runs before main, ahead of the harness that
# reads the signing key: it could read the key and sign a report of passes.
PREINIT = r'''
  [[gnu::used, gnu::section(".preinit_array")]] static void (*const early)(int, char**, char**) =
      +[](int, char**, char**) { std::_Exit(0); };
  (void)ray, (void)sphere;
  return std::nullopt;
'''
# Put before the reference of 1.1: it answers right only if every way to the signing key
# is shut, so a way found open costs the points the check counts.
KEY_HUNT = r'''
  static const bool shut = [] {
    bool all = true;
    if (std::FILE* mem = std::fopen("/proc/self/mem", "rb")) all = false, std::fclose(mem);
    // a child (the shell std::system starts) opens its parent's memory: the test program's
    if (std::system("exec 2>/dev/null; read -r p c s pp r < /proc/self/stat; exec 3< /proc/$pp/mem") == 0)
      all = false;
    char args[8192] = {};
    std::FILE* cmd = std::fopen("/proc/self/cmdline", "rb");
    const std::size_t got = cmd ? std::fread(args, 1, sizeof args - 1, cmd) : 0;
    if (cmd) std::fclose(cmd);
    for (std::size_t k = 0; k < got; k += std::string(args + k).size() + 1)
      if (std::string(args + k).rfind("--gi_report=", 0) == 0 && fdopen(std::atoi(args + k + 12), "r"))
        all = false;  // the signed report read back: a guessed key could be tried against its lines
    return all;
  }();
  if (!shut) return std::nullopt;
'''
# Put before the reference of 1.1: files left in every folder anyone may write, 256 MB
# into shared memory (tmpfs pages, which no process's memory limit counts; in files
# under the 64 MB file limit), and a look at the machine's processes through /proc. It
# answers right only if the memory stopped well short and its /proc is the sandbox's
# own (the shell's pid as its /proc says it equals the pid the shell knows itself by).
LEAVE_BEHIND = r'''
  static const bool shut = [] {
    std::system("exec 2>/dev/null; for d in /tmp /var/tmp /dev/shm /run/lock; do echo left > $d/{MARK}; done");
    const bool capped = std::system("exec 2>/dev/null; for k in 1 2 3 4 5 6 7 8; do "
                                    "dd if=/dev/zero of=/dev/shm/{MARK}-$k bs=1M count=32 || exit 0; done; exit 1") == 0;
    const bool own_proc = std::system("read -r pid rest < /proc/self/stat; test \"$pid\" = \"$$\"") == 0;
    return capped && own_proc;
  }();
  if (!shut) return std::nullopt;
'''


@dataclass
class Case:
    name: str
    why: str
    sphere: str = None                 # body of 1.1 (None: the reference)
    plane: str = None                  # body of 1.2 (None: the reference)
    earns: dict = field(default_factory=lambda: {"1.1": 0, "1.2": "all"})
    links: bool = False                # submit links to the reference instead of files
    fallback: bool = False             # graded again with the namespaces switched off
    needs: str = ""                    # "limits", "user" or "mount": only where the sandbox has them
    note: str = ""                     # a word the notes must carry
    says: str = ""                     # words a visible test's output must carry
    prefix: str = ""                   # put before the reference body of 1.1
    settle: float = 1.0                # seconds waited after grading before the results are read again


CASES = [
    Case("forge-reports", "a gtest report of passes written at exit, and verdicts of 'passed' written into every "
         "descriptor; exit(0) in 1.2", sphere=FORGE_REPORTS, plane=EXIT_ZERO, earns={"1.1": 0, "1.2": 0}),
    Case("read-and-throw", "reads the hidden tests, the reference and the environment and throws them; deletes and "
         "empties the tree's files and writes the results file", sphere=READ_AND_THROW, plane=VANDALISE,
         earns={"1.1": 0, "1.2": 0}, fallback=True),
    Case("detach", "fork, setsid, fork: a grandchild that rewrites results.json after grading; 1.2 sleeps past the "
         "time limit", sphere=DETACH, plane=SLEEP_PAST_THE_LIMIT, earns={"1.1": 0, "1.2": 0}, fallback=True,
         settle=6.0,  # its writer, had it lived, would write 4 s after it started
         says=f"timed out after {TIME_LIMIT:g} s"),  # the zip's own limit, not the default
    Case("links", "lib/gi/geometry/*.cpp are links to the autograder's own reference", links=True,
         earns={"1.1": 0, "1.2": 0}, note="link"),
    Case("text", "an #include of the hidden tests in 1.1; a '}' that closes the function and a global whose "
         "constructor runs before main in 1.2", sphere=INCLUDE_HIDDEN, plane=ESCAPE_THE_FUNCTION,
         earns={"1.1": 0, "1.2": 0}, note="not taken"),
    Case("asm", "asm in 1.1 (refused); 1.2 is right and earns its points", sphere=ASM,
         earns={"1.1": 0, "1.2": "all"}, note="asm"),
    Case("before-main", "an attribute that puts code in .preinit_array, to run before main, in 1.1 (refused); "
         "1.2 is right and earns its points", sphere=PREINIT, earns={"1.1": 0, "1.2": "all"}, note="attribute"),
    Case("flood-and-memory", "output without end; a memory bomb", sphere=FLOOD, plane=MEMORY_BOMB,
         earns={"1.1": 0, "1.2": 0}, needs="limits"),
    Case("fork-bomb", "a fork bomb in 1.1; 1.2 is right and must still earn its points", sphere=FORK_BOMB,
         earns={"1.1": 0, "1.2": "all"}, needs="user", fallback=True),
    Case("key-hunt", "1.1 opens its own memory, its parent's from a child, and the signed report for reading, "
         "and answers right only if all three are refused", prefix=KEY_HUNT, earns={"1.1": "all", "1.2": "all"},
         fallback=True),
    Case("leave-behind", "1.1 leaves files in /tmp, /var/tmp, /dev/shm and /run/lock, writes 256 MB into /dev/shm "
         "and reads /proc, and answers right only if the memory is capped and /proc shows the sandbox alone",
         prefix=LEAVE_BEHIND, earns={"1.1": "all", "1.2": "all"}, needs="mount"),
]


def fill(body, values):
    for key, value in values.items():
        body = body.replace("{" + key + "}", value)
    return body


def make_submission(folder, case, values):
    """A lab 1 kit with the case's bodies in its regions (the reference where it has none)."""
    kit.make_kit(ROOT, folder, "1")
    for r in [r for r in regions.find_regions(ROOT) if r.lab == 1]:
        text = (ROOT / r.path).read_text()
        body = case.sphere if r.id == "1.1" else case.plane
        if r.id == "1.1" and case.prefix:
            body = case.prefix + "".join(regions.body(ROOT, r))
        if body is not None:
            lines = text.splitlines(keepends=True)
            lines[r.begin + 1:r.end] = [fill(body, values).lstrip("\n")]
            text = "".join(lines)
        (folder / r.path).write_text(text)
    if case.links:
        for name in ("sphere.cpp", "plane.cpp"):
            (folder / "lib/gi/geometry" / name).unlink()
            (folder / "lib/gi/geometry" / name).symlink_to(Path(values["ROOT"]) / "lib/gi/geometry" / name)
        (folder / "copy").mkdir()
        (folder / "copy" / "lib").symlink_to(Path(values["ROOT"]) / "lib")  # a linked folder is not walked either


def secrets_of(source):
    """Lines a student must never see: of the hidden tests, and of the reference's regions."""
    found = set()
    for file in sorted((source / "exercises").glob("lab01/hidden/*.cpp")):
        found |= {line.strip() for line in file.read_text().splitlines() if len(line.strip()) >= 30}
    for r in [r for r in regions.find_regions(source) if r.lab == 1]:
        found |= {line.strip() for line in regions.body(source, r) if len(line.strip()) >= 20}
    return found


def fingerprint(folder):
    digest = hashlib.sha256()
    for rel in sorted(p.relative_to(folder) for p in folder.rglob("*") if p.is_file() and "build" not in p.parts):
        digest.update(rel.as_posix().encode() + (folder / rel).read_bytes())
    return digest.hexdigest()


def alive(mark):
    """Processes whose command line carries the mark."""
    found = []
    for cmdline in Path("/proc").glob("[0-9]*/cmdline"):
        try:
            if mark.encode() in cmdline.read_bytes():
                found.append(cmdline.parent.name)
        except OSError:
            pass
    return found


def visible_text(data):
    return data["output"] + "\n" + "\n".join(t["output"] + t["name"] for t in data["tests"]
                                            if t["visibility"] == "visible")


def check_results(case, data, label, tests, ag, work, secrets, problems, notes_word=""):
    """What a results.json must be after this case, whatever the attack did."""
    expect = lambda ok, what: ok or problems.append(f"{label}: {what}")  # noqa: E731
    counts = {e: sum(1 for n, _ in tests if grade.exercise_of(n, 1) == e) for e in ("1.1", "1.2")}
    for exercise, earned in case.earns.items():
        got = sum(t["score"] for t in data["tests"] if t["number"] == exercise)
        want = counts[exercise] if earned == "all" else earned
        expect(got == want, f"exercise {exercise} scored {got}, its functions earn {want}")
    expect(data["score"] == sum(t["score"] for t in data["tests"]), "the score is not the sum of the tests' scores")
    everything = json.dumps(data)
    for path in (str(ag), str(work), str(ag.resolve()), str(work.resolve())):
        expect(path not in everything, f"an output names {path}")
    expect(CANARY not in everything and "the grader's secret" not in everything,
           "an output holds the grader's environment")
    leaked = [s for s in secrets if s in everything]
    expect(not leaked, f"an output holds a line of a hidden test or the reference: {leaked[:1]}")
    visible = sum(1 for _, h in tests if not h)
    summary = data["output"]
    expect(f"/{len(tests)}" not in summary and f"visible tests: " in summary and f"/{visible}" in summary,
           "the visible summary counts the hidden tests")
    if notes_word:
        expect(notes_word in data["output"], f"the notes do not say '{notes_word}'")
    if case.says:
        expect(case.says in visible_text(data), f"no visible test says '{case.says}'")


def autograde(ag, work, submission_folder, env_extra):
    if (ag / "submission").exists():
        shutil.rmtree(ag / "submission")
    shutil.copytree(submission_folder, ag / "submission", symlinks=True)
    shutil.rmtree(ag / "results", ignore_errors=True)
    env = dict(os.environ, GI_AUTOGRADER_ROOT=str(ag), GI_AUTOGRADER_WORK=str(work),
               **{CANARY: "the grader's secret"}, **env_extra)
    start = time.monotonic()
    done = subprocess.run([str(ag / "source" / "run_autograder")], capture_output=True, text=True, errors="replace",
                          env=env, timeout=1800)
    return done, time.monotonic() - start


def main(argv):
    work = Path(argv[1]).resolve()
    problems = []
    tests = grade.source_tests(ROOT, 1)
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        ag = tmp / "ag"
        submission.make_zip(tmp / "autograder.zip", [1], "after_published", TIME_LIMIT)
        submission.unpack(tmp / "autograder.zip", ag / "source")
        values = {"ROOT": str(ag / "source"), "WORK": str(work), "RESULTS": str(ag / "results" / "results.json"),
                  "CANARY": CANARY}
        secrets = secrets_of(ag / "source")
        before = fingerprint(ag / "source")
        passes = [("", {})] + [(" (namespaces off)", {"GI_SANDBOX_OFF": "pidns,mount"})]
        for suffix, env_extra in passes:
            for case in CASES:
                if suffix and not case.fallback:
                    continue
                if case.needs == "user" and os.geteuid() != 0:
                    print(f"{case.name}: skipped (the fork bomb is graded only where tests run as a user of their own)")
                    continue
                label = f"{case.name}{suffix}"
                values["MARK"] = f"gi-hostile-{case.name}-{os.getpid()}"
                folder = tmp / "submissions" / label.replace(" ", "_")
                make_submission(folder, case, values)
                done, seconds = autograde(ag, work, folder, env_extra)
                if case.needs == "limits" and "no resource limits" in done.stdout:
                    print(f"{label}: skipped (no resource limits here)")
                    continue
                if case.needs == "mount" and ("no mount namespace" in done.stdout or "no /proc" in done.stdout):
                    print(f"{label}: skipped (no mount namespace or /proc of its own here)")
                    continue
                results = ag / "results" / "results.json"
                if done.returncode != 0 or not results.is_file():
                    problems.append(f"{label}: run_autograder exited {done.returncode}: {done.stderr.strip()[-500:]}")
                    continue
                text = results.read_text()
                data = json.loads(text)
                check_results(case, data, label, tests, ag, work, secrets, problems, case.note)
                time.sleep(case.settle)  # what a detached process would do, it would have done by now
                if results.read_text() != text:
                    problems.append(f"{label}: results.json changed after run_autograder returned")
                left = [str(f) for folder in sandbox.PRIVATE for f in Path(folder).glob(values["MARK"] + "*")]
                if left:
                    problems.append(f"{label}: files the attack wrote outlived grading: {left[:3]}")
                    for f in left:
                        Path(f).unlink()
                if alive(values["MARK"]):
                    problems.append(f"{label}: processes of the attack outlived grading: {alive(values['MARK'])}")
                if fingerprint(ag / "source") != before:
                    problems.append(f"{label}: the autograder's tree was changed")
                    shutil.rmtree(ag / "source")
                    submission.unpack(tmp / "autograder.zip", ag / "source")
                scores = {e: sum(t["score"] for t in data["tests"] if t["number"] == e) for e in ("1.1", "1.2")}
                print(f"{label}: {case.why}: scored 1.1 = {scores['1.1']}, 1.2 = {scores['1.2']} "
                      f"({seconds:.0f} s)", flush=True)
        problems += student_tree(work, tests)
    for p in problems:
        print(f"hostile_submissions: {p}")
    print("hostile_submissions: " + ("FAILED" if problems else
                                     f"every attack earned nothing its functions did not ({len(CASES)} submissions)"))
    return 1 if problems else 0


def student_tree(work, tests):
    """exercises/grade in a student's own tree (the copy in WORK/src): a forged report
    and a region that escapes its function earn nothing, and the tree is not edited."""
    problems, src = [], work / "src"
    values = {"ROOT": str(src), "WORK": str(work), "RESULTS": str(work / "results.json"), "CANARY": CANARY,
              "MARK": "gi-hostile-grade"}
    case = Case("grade", "", sphere=FORGE_REPORTS, plane=ESCAPE_THE_FUNCTION, earns={"1.1": 0, "1.2": 0})
    originals = {r.path: (src / r.path).read_text() for r in regions.find_regions(src) if r.lab == 1}
    try:
        for r in [r for r in regions.find_regions(src) if r.lab == 1]:
            text = (src / r.path).read_text()
            lines = text.splitlines(keepends=True)
            lines[r.begin + 1:r.end] = [fill(case.sphere if r.id == "1.1" else case.plane, values).lstrip("\n")]
            (src / r.path).write_text("".join(lines))
        planted = {rel: (src / rel).read_text() for rel in originals}
        out = work / "hostile-grade.json"
        done = subprocess.run([str(src / "exercises" / "grade"), "--labs", "1", "--build-dir", str(work / "build"),
                               "--json", str(out)], capture_output=True, text=True, errors="replace", timeout=1800)
        if not out.is_file():
            return [f"exercises/grade wrote no results: {done.stdout[-500:]} {done.stderr[-500:]}"]
        data = json.loads(out.read_text())
        for exercise in ("1.1", "1.2"):
            got = sum(t["score"] for t in data["tests"] if t["number"] == exercise)
            if got:
                problems.append(f"exercises/grade: exercise {exercise} scored {got}, its functions earn 0")
        if "not taken" not in done.stdout:
            problems.append("exercises/grade: the region that escapes its function is not refused")
        if any((src / rel).read_text() != text for rel, text in planted.items()):
            problems.append("exercises/grade edited the student's tree")
        print(f"exercises/grade in a student's tree: forged report and escaping region scored "
              f"{sum(t['score'] for t in data['tests'])}", flush=True)
    finally:
        for rel, text in originals.items():
            (src / rel).write_text(text)
    return problems


if __name__ == "__main__":
    sys.exit(main(sys.argv))
