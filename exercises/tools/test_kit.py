"""make-kit and the grader's results file under bad destinations, a full disk and a
kill in the middle (ctest: exercise_tools). A full disk and a read-only folder are
made with small tmpfs mounts; where mounting is not allowed those tests are skipped
with a message.
"""
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import kit      # noqa: E402
import regions  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
MAKE_KIT = [str(ROOT / "exercises" / "make-kit")]  # as an instructor runs it

SOURCE = """#include "gi/core/not_implemented.hpp"
double twice(double x) {
  // BEGIN EXERCISE 3.1 doubling
  const double doubled_value = x + x;
  return doubled_value;
  // END EXERCISE 3.1
}
"""


def small_tree(doc_text="Nothing to see.\n"):
    """A made-up project with one exercise, outside git."""
    root = Path(tempfile.mkdtemp())
    (root / "lib").mkdir()
    (root / "docs").mkdir()
    (root / "exercises" / "lab03" / "hidden").mkdir(parents=True)
    (root / "exercises" / "mutants").mkdir()
    (root / "lib" / "twice.cpp").write_text(SOURCE)
    (root / "docs" / "page.md").write_text(doc_text)
    (root / "exercises" / "lab03" / "twice_test.cpp").write_text("TEST(Ex3_1_Twice, Two) {}\n")
    (root / "exercises" / "lab03" / "hidden" / "secret_test.cpp").write_text("TEST(Ex3_1_Secret, Three) {}\n")
    (root / "exercises" / "mutants" / "lab03.mut").write_text("# mutants\n")
    return root


class Mount:
    """A tmpfs of `size` at a new folder, read-only if asked; None where not allowed."""

    def __init__(self, options):
        self.folder = Path(tempfile.mkdtemp())
        done = subprocess.run(["mount", "-t", "tmpfs", "-o", options, "tmpfs", str(self.folder)], capture_output=True)
        self.mounted = done.returncode == 0

    def close(self):
        if self.mounted:
            subprocess.run(["umount", str(self.folder)], capture_output=True)
        os.rmdir(self.folder)


class Destinations(unittest.TestCase):
    def make_kit(self, *args):
        done = subprocess.run(MAKE_KIT + list(args), capture_output=True, text=True, timeout=300)
        self.assertNotIn("Traceback", done.stderr)
        return done

    def assert_refused(self, done, status=2):
        self.assertEqual(done.returncode, status, done.stdout + done.stderr)
        self.assertEqual(len(done.stderr.strip().splitlines()), 1, done.stderr)

    def test_refuses_empty_and_unknown_lab_lists(self):
        with tempfile.TemporaryDirectory() as tmp:
            for labs in (",", "", " , ", "99", "one"):
                self.assert_refused(self.make_kit(f"{tmp}/kit", "--labs", labs))
                self.assertFalse(Path(f"{tmp}/kit").exists(), f"--labs '{labs}' made a kit")

    def test_refuses_the_repository_its_parent_and_folders_inside_it(self):
        for dest in (ROOT, ROOT.parent, ROOT / "lib" / "kit"):
            self.assert_refused(self.make_kit(str(dest), "--force"))

    def test_refuses_a_file_and_a_folder_that_is_not_empty(self):
        with tempfile.TemporaryDirectory() as tmp:
            Path(f"{tmp}/file").write_text("x")
            self.assert_refused(self.make_kit(f"{tmp}/file"))
            Path(f"{tmp}/full").mkdir()
            Path(f"{tmp}/full/keep").write_text("x")
            self.assert_refused(self.make_kit(f"{tmp}/full"))
            self.assertEqual(Path(f"{tmp}/full/keep").read_text(), "x")

    def test_force_replaces_only_a_kit_it_made(self):
        with tempfile.TemporaryDirectory() as tmp:
            home = Path(tmp) / "home"
            (home / ".ssh").mkdir(parents=True)
            (home / ".ssh" / "id_ed25519").write_text("a key")
            done = self.make_kit(str(home), "--labs", "1", "--force")
            self.assert_refused(done)
            self.assertIn("is no kit", done.stderr)
            self.assertEqual((home / ".ssh" / "id_ed25519").read_text(), "a key")
            kit_dir = Path(tmp) / "kit"
            self.assertEqual(self.make_kit(str(kit_dir), "--labs", "1").returncode, 0)
            self.assert_refused(self.make_kit(str(kit_dir), "--labs", "1"))  # a kit, but no --force
            (kit_dir / "mine.txt").write_text("mine")
            self.assertEqual(self.make_kit(str(kit_dir), "--labs", "2", "--force").returncode, 0)
            self.assertIn("2.1", (kit_dir / "exercises" / "KIT").read_text())

    def test_refuses_an_empty_destination(self):
        with tempfile.TemporaryDirectory() as tmp:
            (Path(tmp) / "keep").write_text("x")
            done = subprocess.run(MAKE_KIT + ["", "--force"], capture_output=True, text=True, cwd=tmp, timeout=300)
            self.assert_refused(done)
            self.assertNotIn("kit written", done.stdout)
            self.assertEqual(sorted(p.name for p in Path(tmp).iterdir()), ["keep"])

    def test_a_stale_partial_folder_it_did_not_make_is_left_alone(self):
        with tempfile.TemporaryDirectory() as tmp:
            mine = Path(tmp) / ".kit.partial-mine"
            mine.mkdir()
            (mine / "notes").write_text("not a kit")
            self.assertEqual(self.make_kit(f"{tmp}/kit", "--labs", "1").returncode, 0)
            self.assertEqual((mine / "notes").read_text(), "not a kit")

    def test_read_only_destination(self):
        mount = Mount("ro,size=64k")
        try:
            if not mount.mounted:
                self.skipTest("cannot mount a read-only tmpfs here (needs root)")
            done = self.make_kit(str(mount.folder / "kit"), "--labs", "1")
            self.assert_refused(done, 1)
            self.assertIn("Read-only", done.stderr)
        finally:
            mount.close()

    def test_full_disk_leaves_no_kit(self):
        mount = Mount("size=256k")
        try:
            if not mount.mounted:
                self.skipTest("cannot mount a small tmpfs here (needs root)")
            done = self.make_kit(str(mount.folder / "kit"), "--labs", "1")
            self.assert_refused(done, 1)
            self.assertIn("No space left", done.stderr)
            self.assertEqual(list(mount.folder.iterdir()), [], "a failed kit must leave nothing behind")
        finally:
            mount.close()

    def test_signals_it_can_catch_leave_nothing_behind(self):
        for sig in (signal.SIGTERM, signal.SIGHUP, signal.SIGINT):
            with tempfile.TemporaryDirectory() as tmp:
                for delay in (0.5, 1.0, 2.0):
                    run = subprocess.Popen(MAKE_KIT + [f"{tmp}/kit", "--labs", "1", "--force"],
                                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
                    time.sleep(delay)
                    run.send_signal(sig)
                    _, err = run.communicate(timeout=120)
                    self.assertNotIn("Traceback", err)
                    left = sorted(p.name for p in Path(tmp).iterdir())
                    self.assertIn(left, ([], ["kit"]), f"{sig.name} after {delay} s left {left}")

    def test_a_signal_as_it_ends_says_one_true_thing(self):
        # Timed from a run's own length, so that some signals land as the kit is done:
        # then the new kit is whole and said to be (status 0), or the run says it made
        # none (130) and the kit made before it stays as it was, with no partial copy.
        with tempfile.TemporaryDirectory() as tmp:
            start = time.monotonic()
            self.assertEqual(self.make_kit(f"{tmp}/kit", "--labs", "1", "--force").returncode, 0)
            length = time.monotonic() - start
            for fraction in (0.9, 0.95, 0.98, 1.0, 1.02):
                run = subprocess.Popen(MAKE_KIT + [f"{tmp}/kit", "--labs", "1", "--force"],
                                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
                time.sleep(length * fraction)
                run.send_signal(signal.SIGTERM)
                out, err = run.communicate(timeout=120)
                self.assertNotIn("Traceback", err)
                if run.returncode == 0:
                    self.assertIn("kit written to", out)
                    self.assertTrue((Path(tmp) / "kit" / "exercises" / "KIT").is_file())
                else:
                    self.assertEqual(run.returncode, 130, err)
                    self.assertEqual(err.strip().splitlines(), ["make-kit: interrupted; no kit was made"])
                    self.assertEqual(sorted(p.name for p in Path(tmp).iterdir()), ["kit"])
                    self.assertTrue((Path(tmp) / "kit" / "exercises" / "KIT").is_file())

    def test_killed_runs_never_leave_a_kit_with_solutions(self):
        with tempfile.TemporaryDirectory() as tmp:
            dest = Path(tmp) / "kit"
            for delay in (0.3, 0.6, 1.0):
                run = subprocess.Popen(MAKE_KIT + [str(dest), "--labs", "1"], stdout=subprocess.DEVNULL,
                                       stderr=subprocess.DEVNULL, start_new_session=True)
                time.sleep(delay)
                os.killpg(run.pid, signal.SIGKILL)  # kill -9 of the job: the script and the Python it runs
                run.wait()
                time.sleep(0.2)  # the kernel is done with them
                if dest.exists():  # it finished before the kill: then it is a whole, checked kit
                    self.assertTrue((dest / "exercises" / "KIT").is_file())
                    self.assertIn("throw gi::NotImplemented", (dest / "lib/gi/geometry/sphere.cpp").read_text())
                    break
            done = self.make_kit(str(dest), "--labs", "1", "--force")
            self.assertEqual(done.returncode, 0, done.stderr)
            self.assertEqual([p.name for p in Path(tmp).iterdir()], ["kit"], "stale partial kits are cleaned up")


class Contents(unittest.TestCase):
    def test_instructor_files_stay_behind_and_the_kit_records_its_labs(self):
        root = small_tree()
        with tempfile.TemporaryDirectory() as tmp:
            kit.make_kit(root, Path(tmp) / "kit", "3")
            made = Path(tmp) / "kit"
            self.assertEqual((made / "exercises" / "KIT").read_text(), "3.1 doubling\n")
            self.assertTrue((made / "exercises" / "lab03" / "twice_test.cpp").is_file())
            self.assertFalse((made / "exercises" / "lab03" / "hidden").exists())
            self.assertFalse((made / "exercises" / "mutants").exists())
            self.assertNotIn("doubled_value", (made / "lib" / "twice.cpp").read_text())

    def test_a_solution_left_in_the_docs_stops_the_kit(self):
        root = small_tree("Try: `const double doubled_value = x + x;`\n\n    return doubled_value;\n")
        with tempfile.TemporaryDirectory() as tmp:
            with self.assertRaisesRegex(kit.KitError, r"solution text of exercise 3.1 left at docs/page.md:3"):
                kit.make_kit(root, Path(tmp) / "kit", "all")
            self.assertEqual(list(Path(tmp).iterdir()), [], "no kit, and no partial kit, is left")

    def test_code_hidden_with_an_exercise_leaves_with_it(self):
        root = small_tree()
        (root / "lib" / "fast.cpp").write_text(
            '#include "gi/core/not_implemented.hpp"\n'
            "double quickly(double x) {\n"
            "  // BEGIN KIT-HIDDEN WITH 3.1 the fast doubling\n"
            "  const double shifted_twice = 2.0 * x;\n"
            "  return shifted_twice;\n"
            "  // END KIT-HIDDEN WITH 3.1\n"
            "}\n")
        with tempfile.TemporaryDirectory() as tmp:
            kit.make_kit(root, Path(tmp) / "kit", "3")
            text = (Path(tmp) / "kit" / "lib" / "fast.cpp").read_text()
            self.assertNotIn("shifted_twice", text)
            self.assertIn('throw gi::NotImplemented("the fast doubling, left out of the kit with exercise 3.1,", x);',
                          text)
            self.assertEqual((Path(tmp) / "kit" / "exercises" / "KIT").read_text(), "3.1 doubling\n",
                             "hidden code is no exercise of its own")
        (root / "lib" / "fast.cpp").write_text((root / "lib" / "fast.cpp").read_text().replace("3.1", "3.2"))
        with tempfile.TemporaryDirectory() as tmp:
            with self.assertRaisesRegex(regions.RegionError, r"lib/fast.cpp:3: KIT-HIDDEN WITH 3.2: no such exercise"):
                kit.make_kit(root, Path(tmp) / "kit", "all")

    def test_lab_lists(self):
        self.assertEqual(regions.parse_labs("all", {1, 2}), {1, 2})
        self.assertEqual(regions.parse_labs(None, {1, 2}), {1, 2})
        self.assertEqual(regions.parse_labs("2", {1, 2}), {2})
        for bad in (",", "", "1,7", "one"):
            with self.assertRaises(regions.RegionError):
                regions.parse_labs(bad, {1, 2})


class ResultsFile(unittest.TestCase):
    def test_a_full_disk_gives_one_line_and_no_half_written_results(self):
        mount = Mount("size=12k")
        try:
            if not mount.mounted:
                self.skipTest("cannot mount a small tmpfs here (needs root)")
            (mount.folder / "filler").write_bytes(b"x" * 8192)
            import grade
            temp = grade.open_json(str(mount.folder / "results.json"))
            with self.assertRaises(Exception) as caught:
                grade.write_json(temp, mount.folder / "results.json", {"tests": ["x" * 200] * 100})
            self.assertIn("No space left", str(caught.exception))
            self.assertFalse((mount.folder / "results.json").exists())
            self.assertEqual(sorted(p.name for p in mount.folder.iterdir()), ["filler"])
        finally:
            mount.close()


if __name__ == "__main__":
    unittest.main()
