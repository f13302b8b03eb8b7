"""The check of what a graded program runs before main (before_main.py), on small
programs compiled here: one laid out as the harness lays itself out, and ones that add
entries to .preinit_array and .init_array as a submission's code could (ctest:
exercise_tools)."""
import shutil
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import before_main  # noqa: E402
import grade        # noqa: E402
import gtest_run    # noqa: E402

# The harness's layout: its key reader alone in .preinit_array, a global whose
# constructor the compiler registers in .init_array.
HONEST = r"""
#include <string>
namespace {
void read_key(int, char**, char**) {}
[[gnu::used, gnu::section(".preinit_array")]] void (*read_key_before_any_constructor)(int, char**, char**) = read_key;
}
std::string greeting(3, 'a');
int main() { return static_cast<int>(greeting.size()) - 3; }
"""
EARLY = r"""
void early(int, char**, char**) {}
[[gnu::used, gnu::section(".preinit_array")]] static void (*also)(int, char**, char**) = early;
"""
CONSTRUCTOR = r"""
int forge() {
  [[gnu::used, gnu::section(".init_array")]] static void (*entry)() = +[] {};
  return 0;
}
"""
COMPILER = shutil.which("g++") or shutil.which("c++")


@unittest.skipUnless(sys.platform.startswith("linux") and COMPILER, "ELF programs, compiled here with g++")
class BeforeMain(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.folder = Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def program(self, name, text, *flags):
        source = self.folder / f"{name}.cpp"
        source.write_text(text)
        binary = self.folder / name
        subprocess.run([COMPILER, "-std=c++17", "-O1", *flags, str(source), "-o", str(binary)], check=True,
                       capture_output=True)
        return binary

    def test_the_harness_and_the_compiler_alone_pass(self):
        binary = self.program("honest", HONEST)
        self.assertEqual(before_main.refusal(binary), "")
        self.assertEqual(subprocess.run([str(binary)]).returncode, 0)
        self.assertEqual(before_main.refusal(self.program("honest_pie", HONEST, "-fPIE", "-pie")), "")
        self.assertEqual(before_main.refusal(self.program("honest_static", HONEST, "-no-pie")), "")

    def test_a_second_entry_before_the_key_reader_is_refused_by_name(self):
        why = before_main.refusal(self.program("early", HONEST + EARLY))
        self.assertIn(".preinit_array", why)
        self.assertIn("early", why)

    def test_an_entry_of_init_array_that_no_global_needs_is_refused(self):
        why = before_main.refusal(self.program("constructor", HONEST + CONSTRUCTOR))
        self.assertIn(".init_array", why)
        self.assertNotIn("_GLOBAL__sub_I_", why)

    def test_no_key_reader_is_refused(self):
        why = before_main.refusal(self.program("plain", "int main() { return 0; }\n"))
        self.assertIn("no key reader", why)

    def test_a_stripped_program_cannot_be_checked_and_other_files_are_not_its_business(self):
        self.assertIn("no symbol table", before_main.refusal(self.program("stripped", HONEST, "-s")))
        text = self.folder / "program.exe"
        text.write_bytes(b"MZ\x90\x00 not an ELF file")
        self.assertEqual(before_main.refusal(text), "", "a Windows program is not this check's")
        broken = self.folder / "broken"
        broken.write_bytes(b"\x7fELF\x02\x01\x01" + b"\x00" * 20)
        self.assertIn("well-formed", before_main.refusal(broken))

    def test_the_grader_runs_no_test_of_a_refused_program(self):
        binary = self.program("early", HONEST + EARLY)
        tests = [("Ex99_1_A.One", False), ("Ex99_1_A.Two", False)]
        with gtest_run.Runner() as runner:
            results, problem = grade.grade_program(runner, binary, 99, tests, 5.0, {}, False)
        self.assertIn(".preinit_array", problem)
        self.assertTrue(results and not any(r.passed for r in results))


if __name__ == "__main__":
    unittest.main()
