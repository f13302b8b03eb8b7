"""Unit tests of the exercise tools on small made-up trees, and checks of the graded
tests and handouts themselves (ctest: exercise_tools)."""
import re
import shutil
import subprocess
import sys
import tempfile
import unittest
import zipfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import build     # noqa: E402
import cpp_text  # noqa: E402
import excerpts  # noqa: E402
import hand_in   # noqa: E402
import grade     # noqa: E402
import mutants   # noqa: E402
import overlay   # noqa: E402
import regions   # noqa: E402

ROOT = Path(__file__).resolve().parents[2]

SOURCE = """#include "gi/core/not_implemented.hpp"
double twice(double x) {
  // BEGIN EXERCISE 3.1 doubling
  const double y = x + x;
  return y;
  // END EXERCISE 3.1
}
"""


class Regions(unittest.TestCase):
    def test_finds_region_and_stubs_it(self):
        found = regions.regions_in(SOURCE, "a.cpp")
        self.assertEqual([(r.id, r.title, r.begin, r.end) for r in found], [("3.1", "doubling", 2, 5)])
        stubbed = regions.stub_text(SOURCE, found)
        self.assertIn('  throw gi::NotImplemented("exercise 3.1 doubling", x);\n', stubbed,
                      "the stub passes the function's parameters, so that a kit has no unused-parameter warning")
        self.assertNotIn("x + x", stubbed)
        self.assertIn("// END EXERCISE 3.1", stubbed)

    def test_malformed_markers_name_the_line(self):
        with self.assertRaisesRegex(regions.RegionError, r"a.cpp:3: exercise 3.1 has no END"):
            regions.regions_in(SOURCE.replace("  // END EXERCISE 3.1\n", ""), "a.cpp")
        with self.assertRaisesRegex(regions.RegionError, r"a.cpp:6: END EXERCISE 3.2 closes exercise 3.1"):
            regions.regions_in(SOURCE.replace("END EXERCISE 3.1", "END EXERCISE 3.2"), "a.cpp")
        with self.assertRaisesRegex(regions.RegionError, "not_implemented.hpp"):
            regions.regions_in(SOURCE.replace('#include "gi/core/not_implemented.hpp"', ""), "a.cpp")

    def test_lab_lists(self):
        self.assertEqual(regions.parse_labs("all", {1, 2}), {1, 2})
        self.assertEqual(regions.parse_labs("2", {1, 2}), {2})
        for bad in ("\u0661", "\uff12", "1,\u0662", "0x1", "+1", "1.0", "1e0"):
            with self.assertRaisesRegex(regions.RegionError, "takes numbers"):
                regions.parse_labs(bad, {1, 2})
        with self.assertRaisesRegex(regions.RegionError, "no lab 7"):
            regions.parse_labs("1,7", {1, 2})
        with self.assertRaisesRegex(regions.RegionError, "names no lab"):
            regions.parse_labs(",", {1, 2})


class RegionText(unittest.TestCase):
    """What the autograder and the grader accept between a region's markers: statements
    of the function it sits in, nothing that leaves it (cpp_text.py)."""

    ACCEPTED = [
        "  double t = 1'000.5e-3, u = 0x1p-3;\n  return t + u;\n",
        '  auto s = R"x(}}} # %> )x"; char c = \'}\'; // } #include\n  /* } %> */ return 0;\n',
        "  if (x) {\n    for (int i = 0; i < 3; ++i) { y += i; }\n  }\n  auto f = [&](int k) { return k; };\n",
        '  std::string hash = "#define"; auto q = u8"%:";\n',
        "  static const int table[] = {1, 2, 3};  // a static local: built on the first call, inside the function\n",
        "  [[maybe_unused]] const int k = 1;\n  switch (k) { case 1: x = 1; [[fallthrough]]; default: break; }\n",
        "  int a[2] = {0, 1};\n  a[a[0]] = 1;  // two brackets, not an attribute\n",
        "  x = 1;  // a comment \\  \n  } as GCC reads it: the blanks after the backslash end the line, spliced\n",
    ]
    REFUSED = {
        "  return 1;\n}\nstatic int x = f();\nvoid g() {\n": "closes the function",
        "  return 1;\n%>\nint y;\n<%\n": "closes the function",
        "  return {};\n}\n[[gnu::constructor]] void forge() {\n": "closes the function",
        '#include "/autograder/source/lib/gi/geometry/sphere.cpp"\n': "preprocessor",
        "  %:define X 1\n": "preprocessor",
        "  x = 1;\n  #\\\ninclude <cstdio>\n": "preprocessor",
        "  _Pragma(\"GCC poison x\")\n": "_Pragma",
        '  asm volatile("nop");\n': "asm",
        '  __asm__("nop");\n': "__asm__",
        "  x = 1; /* a comment left open\n": "not closed",
        '  auto s = "a string left open;\n': "not closed",
        '  auto s = R"(a raw string left open;\n': "not closed",
        "  if (x) {\n": "not closed",
        "  x = 1; \\\n": "line splice",
        "  import std;\n": "module",
        '  [[gnu::used, gnu::section(".preinit_array")]] static void (*entry)() = forge;\n': "attribute 'gnu'",
        "  [[using gnu: constructor]] static int y;\n": "attribute 'using'",
        "  <:<:gnu::used:>:> static int w;\n": "attribute 'gnu'",
        '  __attribute__((section(".init_array"))) static int z;\n': "__attribute__",
        "  __declspec(allocate(\".CRT$XCU\")) static int v;\n": "__declspec",
        "  x = 1; // \\ \t\n": "line splice",
        # GCC splices the backslash-and-blanks: the first '{' is comment, the '}' closes
        # the function, and the last '}' (comment too) leaves rest() open.
        "  // \\ \n  {\n  }\n  int g = evil();\n  void rest() {\n  x = 1; // \\ \n  }\n": "closes the function",
    }

    def test_statements_are_accepted(self):
        for text in self.ACCEPTED:
            cpp_text.check_body(text)

    def test_what_leaves_the_function_is_refused_with_the_reason(self):
        for text, why in self.REFUSED.items():
            with self.assertRaisesRegex(cpp_text.TextError, why, msg=text):
                cpp_text.check_body(text)

    def test_every_region_of_the_reference_is_a_function_body(self):
        for r in regions.find_regions(ROOT):
            cpp_text.check_body("".join(regions.body(ROOT, r)))

    def test_the_parameters_of_the_function_a_region_sits_in(self):
        text = ("std::optional<Hit> intersect(const Ray& ray, const Sphere& sphere) {\n  // BEGIN EXERCISE 1.1 x\n"
                "  // END EXERCISE 1.1\n}\n"
                "auto f(int n, std::vector<std::pair<int, int>> pairs, const double = 1.0, Rng& rng) -> int {\n"
                "  for (int i = 0; i < n; ++i) {\n    // here\n  }\n}\n"
                "void g(const Sphere) {\n  auto h = [&](double t) {\n    // here\n  };\n}\n")
        self.assertEqual(cpp_text.enclosing_parameters(text, 1), ["ray", "sphere"])
        self.assertEqual(cpp_text.enclosing_parameters(text, 6), ["n", "pairs", "rng"])
        self.assertEqual(cpp_text.enclosing_parameters(text, 11), ["t"], "inside a lambda: its own parameters only")
        self.assertEqual(cpp_text.enclosing_parameters(text, 0), [])


class HandIn(unittest.TestCase):
    def test_the_zip_holds_the_files_with_exercises_and_no_build_product(self):
        root = Path(tempfile.mkdtemp())
        (root / "lib").mkdir()
        (root / "lib" / "a.cpp").write_text(SOURCE)
        (root / "lib" / "b.cpp").write_text("int b() { return 1; }\n")
        (root / "exercises").mkdir()
        (root / "exercises" / "KIT").write_text("3.1 doubling\n")
        (root / "build" / "release").mkdir(parents=True)
        (root / "build" / "release" / "big.o").write_bytes(b"x" * 100000)
        out, files = hand_in.write_zip(root, root / "hand-in.zip")
        with zipfile.ZipFile(out) as z:
            self.assertEqual(sorted(z.namelist()), ["exercises/KIT", "lib/a.cpp"])
        (root / "lib" / "a.cpp").unlink()
        (root / "lib" / "a.cpp").symlink_to("/etc/hostname")
        with self.assertRaisesRegex((hand_in.HandInError, regions.RegionError, OSError), "."):
            hand_in.write_zip(root, root / "hand-in.zip")


class Excerpts(unittest.TestCase):
    def make_tree(self, code_in_doc):
        root = Path(tempfile.mkdtemp())
        (root / "lib").mkdir()
        (root / "docs").mkdir()
        (root / "lib" / "a.cpp").write_text(SOURCE)
        (root / "docs" / "page.md").write_text(
            "Text\n<!-- excerpt: lib/a.cpp | double twice( -->\n```cpp\n" + code_in_doc + "```\nMore\n")
        return root

    def test_matching_excerpt_passes_and_stale_one_is_reported_and_fixed(self):
        fresh = "".join(SOURCE.splitlines(keepends=True)[1:])
        self.assertEqual(excerpts.process(self.make_tree(fresh), fix=False), [])
        root = self.make_tree("double twice(double x) { return 2 * x; }\n")
        problems = excerpts.process(root, fix=False)
        self.assertEqual(len(problems), 1)
        self.assertIn("page.md:2: excerpt of lib/a.cpp is stale", problems[0])
        excerpts.process(root, fix=True)
        self.assertEqual(excerpts.process(root, fix=False), [])

    def test_missing_prefix_is_reported(self):
        root = self.make_tree("x\n")
        (root / "docs" / "page.md").write_text("<!-- excerpt: lib/a.cpp | int nothing( -->\n```cpp\n```\n")
        self.assertIn("no line starts with", excerpts.process(root, fix=False)[0])


class BuildErrors(unittest.TestCase):
    def tree(self):
        root = Path(tempfile.mkdtemp())
        (root / "lib").mkdir()
        (root / "lib" / "a.cpp").write_text(SOURCE)
        (root / "lib" / "b.cpp").write_text("int b() { return 1; }\n")
        return root

    def test_compile_errors_name_the_region_they_fall_in(self):
        root = self.tree()
        log = (f"[1/3] Building CXX object a.o\nFAILED: a.o\n{root}/lib/a.cpp:4:30: error: expected ';' before 'return'\n"
               f"{root}/lib/a.cpp:9:1: error: expected '}}' at end of input\n")
        self.assertEqual(build.broken_regions(root, log), {"3.1": "lib/a.cpp:4: error: expected ';' before 'return'"})
        self.assertEqual(build.first_error(log), f"{root}/lib/a.cpp:4:30: error: expected ';' before 'return'")

    def test_errors_outside_any_region_stub_none(self):
        root = self.tree()
        self.assertEqual(build.broken_regions(root, f"{root}/lib/b.cpp:1:5: error: nope\n"), {})
        self.assertEqual(build.first_error("x.o: in function `f':\nx.cpp:(.text+0x5): undefined reference to `g'\n"),
                         "x.cpp:(.text+0x5): undefined reference to `g'")

    def test_restub_puts_the_stub_back(self):
        root = self.tree()
        build.restub(root, {"3.1"})
        self.assertIn('throw gi::NotImplemented("exercise 3.1 doubling", x);', (root / "lib" / "a.cpp").read_text())


class OlderPython(unittest.TestCase):
    """The tools a student runs on their own machine run on Python 3.9, macOS's own:
    no syntax of a later Python, and no `X | None` evaluated at run time (in an
    annotation it is, unless the module postpones them with `from __future__ import
    annotations`)."""

    LATER = {"itertools.pairwise": "3.10", "contextlib.chdir": "3.11", "datetime.UTC": "3.11", ".bit_count": "3.10",
             "tomllib": "3.11", "typing.Self": "3.11", "asyncio.TaskGroup": "3.11"}

    def test_the_tools_read_as_python_3_9(self):
        import ast
        # The grading tools, and the book's, which the lessons target runs.
        tools = sorted(Path(__file__).resolve().parent.glob("*.py")) + sorted((ROOT / "docs/book").glob("*.py"))
        for path in tools + [ROOT / "tests/bad_input/campaign.py", ROOT / "tests/wasm/wasm_test.py"]:
            text = path.read_text()
            tree = ast.parse(text, str(path), feature_version=(3, 9))  # SyntaxError for match, with (...), ...
            postponed = "from __future__ import annotations" in text
            for node in ast.walk(tree):
                annotation = getattr(node, "annotation", None) or getattr(node, "returns", None)
                if not postponed and isinstance(annotation, ast.BinOp) and isinstance(annotation.op, ast.BitOr):
                    self.fail(f"{path.name}:{node.lineno}: 'X | Y' in an annotation needs Python 3.10")
                if isinstance(node, ast.keyword) and node.arg == "strict":
                    self.fail(f"{path.name}:{node.lineno}: zip(..., strict=) needs Python 3.10")
                names = []
                if isinstance(node, ast.Attribute):
                    names = ["." + node.attr] + ([f"{node.value.id}.{node.attr}"] if isinstance(node.value, ast.Name)
                                                 else [])
                elif isinstance(node, ast.alias):
                    names = [node.name]
                for name in names:
                    if name in self.LATER:
                        self.fail(f"{path.name}: {name.lstrip('.')} needs Python {self.LATER[name]}")


class TreeCopies(unittest.TestCase):
    """build.sync_tree: the grading trees are copies of the project, kept up to date by
    copying only what differs; a file's mode is part of it (exercises/grade is a script)."""

    def test_the_copy_takes_the_text_and_the_mode(self):
        with tempfile.TemporaryDirectory() as tmp:
            root, copy = Path(tmp) / "root", Path(tmp) / "copy"
            (root / "exercises").mkdir(parents=True)
            script = root / "exercises" / "grade"
            script.write_text("#!/bin/sh\n")
            script.chmod(0o644)
            self.assertEqual(build.sync_tree(root, copy, [Path("exercises/grade")]), [Path("exercises/grade")])
            script.chmod(0o755)  # the same text, made executable: copied without being "changed"
            self.assertEqual(build.sync_tree(root, copy, [Path("exercises/grade")]), [])
            self.assertEqual((copy / "exercises" / "grade").stat().st_mode & 0o777, 0o755)


class Mutants(unittest.TestCase):
    TEXT = """# a comment
== 3.1 triple
Triples instead of doubling.
@ a.cpp
- const double y = x + x;
+ const double y = x + x + x;
"""

    def test_parses_and_applies_inside_the_region_ignoring_indentation(self):
        [m] = mutants.parse(self.TEXT, "t.mut")
        self.assertEqual((m.exercise, m.name, m.file, m.why), ("3.1", "triple", "a.cpp", "Triples instead of doubling."))
        self.assertIn("  const double y = x + x + x;\n", mutants.apply(SOURCE, m))

    def test_fails_loudly_when_it_no_longer_applies(self):
        [m] = mutants.parse(self.TEXT.replace("x + x;", "x * 2;"), "t.mut")
        with self.assertRaisesRegex(mutants.MutantError, "no longer applies.*found 0 times"):
            mutants.apply(SOURCE, m)
        [m] = mutants.parse(self.TEXT.replace("== 3.1", "== 3.2"), "t.mut")
        with self.assertRaisesRegex(mutants.MutantError, "no region for exercise 3.2"):
            mutants.apply(SOURCE, m)
        outside = SOURCE.replace("double twice(double x) {", "double twice(double x) {\n  const double y = x + x;")
        [m] = mutants.parse(self.TEXT, "t.mut")
        self.assertIn("x + x + x", mutants.apply(outside, m), "only the line inside the region counts")

    def test_the_first_failing_test_must_be_the_named_one(self):
        [m] = mutants.parse(self.TEXT.replace("@ a.cpp", "> Ex3_1_Twice.Doubles\n@ a.cpp"), "t.mut")
        self.assertEqual(m.first, "Ex3_1_Twice.Doubles")
        named = mutants.Verdict(m, ["Ex3_1_Twice.Doubles", "Ex3_1_Twice.Zero"], [], "doubles")
        self.assertEqual(named.wrong_first, "")
        misled = mutants.Verdict(m, ["Ex3_1_Twice.Zero", "Ex3_1_Twice.Doubles"], [], "zero")
        self.assertEqual(misled.wrong_first, "Ex3_1_Twice.Zero", "another test's hint is read first")
        self.assertEqual(mutants.Verdict(m, [], [], "").wrong_first, "", "not caught is said elsewhere")

    def test_every_mutant_in_the_repository_names_its_first_failing_test(self):
        tests = {}
        for m in mutants.load(sorted((ROOT / "exercises" / "mutants").glob("*.mut"))):
            self.assertRegex(m.first, rf"^Ex{m.exercise.replace('.', '_')}_\w+\.\w+$", m.id)
            if m.lab not in tests:
                tests[m.lab] = {name for name, _ in grade.source_tests(ROOT, m.lab)}
            self.assertIn(m.first, tests[m.lab], f"{m.id}: no graded test of that name")

    def test_malformed_files(self):
        for bad in ("stray text\n", "== 3.1\n", "== 3.1 x\n@ a.cpp\n", "== 3.1 x\n- y\n",
                    "== 3.1 x\n> A.B\n> A.C\n@ a.cpp\n- y\n", "== 3.1 x\n@ a.cpp\n- y\n> A.B\n"):
            with self.assertRaises(mutants.MutantError):
                mutants.parse(bad, "t.mut")

    def test_every_mutant_in_the_repository_applies(self):
        for m in mutants.load(sorted((ROOT / "exercises" / "mutants").glob("*.mut"))):
            self.assertNotEqual(mutants.apply((ROOT / m.file).read_text(), m), (ROOT / m.file).read_text(), m.id)


LIBRARY = {
    "CMakeLists.txt": "cmake_minimum_required(VERSION 3.20)\nproject(t CXX)\nset(CMAKE_RUNTIME_OUTPUT_DIRECTORY "
                      "${CMAKE_BINARY_DIR}/bin)\nadd_library(twice STATIC lib/twice.cpp lib/other.cpp)\n"
                      "target_include_directories(twice PUBLIC lib)\nadd_executable(lab03_graded main.cpp)\n"
                      "target_link_libraries(lab03_graded twice)\n",
    "lib/twice.hpp": "#pragma once\n#include <vector>\ndouble twice(double x);\ndouble other();\n",
    "lib/twice.cpp": '#include "twice.hpp"\n\n#include <string>\n' + SOURCE,
    "lib/gi/core/not_implemented.hpp": "#pragma once\n",
    "lib/other.cpp": '#include "twice.hpp"\ndouble other() { return 1; }\n',
    "main.cpp": '#include <cstdio>\n#include "twice.hpp"\nint main() { std::printf("%g\\n", twice(2) + other()); }\n',
}


@unittest.skipUnless(shutil.which("cmake") and shutil.which("ninja") and shutil.which("c++"), "needs cmake, ninja, c++")
class MutantBuilds(unittest.TestCase):
    """A mutant is built in an overlay of its own, with and without its file's
    precompiled preamble, and the reference's build is left as it was."""

    def test_an_overlay_holds_the_mutant_and_the_reference_build_is_untouched(self):
        with tempfile.TemporaryDirectory() as tmp:
            work = Path(tmp)
            for rel, text in LIBRARY.items():
                (work / "src" / rel).parent.mkdir(parents=True, exist_ok=True)
                (work / "src" / rel).write_text(text)
            for argv in (["cmake", "-S", work / "src", "-B", work / "build", "-G", "Ninja"],
                         ["cmake", "--build", work / "build"]):
                subprocess.run(argv, check=True, capture_output=True)
            [m] = mutants.parse(Mutants.TEXT.replace("a.cpp", "lib/twice.cpp"), "t.mut")
            [broken] = mutants.parse(Mutants.TEXT.replace("a.cpp", "lib/twice.cpp").replace("x + x + x", "x +"),
                                     "t.mut")
            reference = mutants.Reference(work)
            preambles, plain = mutants.Preambles(work, [m, broken]), mutants.Preambles(work, [m])
            plain.made[m.file] = None  # as for a header: no preamble
            self.assertEqual(mutants.leading_includes(LIBRARY["lib/twice.cpp"]),
                             '#include "twice.hpp"\n\n#include <string>\n#include "gi/core/not_implemented.hpp"\n')
            for k, made in enumerate((preambles, plain)):
                program, problem = mutants.build_program(m, "lab03_graded", reference, f"overlays/{k}", made)
                self.assertEqual(problem, "")
                self.assertEqual(subprocess.run([program], capture_output=True, text=True).stdout, "7\n", "3 x 2 + 1")
                made.done_with(m.file)
            header = preambles.made[m.file]
            self.assertIsNotNone(header, "the preamble was made")
            self.assertTrue(Path(f"{header}.gch").is_file())
            program, problem = mutants.build_program(broken, "lab03_graded", reference, "overlays/2", preambles)
            self.assertIsNone(program)
            self.assertRegex(problem, r"^does not compile: .*twice\.cpp:\d+:\d*:? ?error")
            preambles.done_with(broken.file)
            self.assertFalse(Path(f"{header}.gch").exists(), "removed after its file's last mutant")
            self.assertEqual(subprocess.run([work / "build" / "bin" / "lab03_graded"], capture_output=True,
                                            text=True).stdout, "5\n", "the reference's program is the reference's")
            done = subprocess.run(["ninja", "-C", work / "build", "-n"], capture_output=True, text=True)
            self.assertIn("no work to do", done.stdout, "the reference's build is not changed")


class CMakePrecompiledHeader(unittest.TestCase):
    """A mutated file reads its own precompiled preamble: CMake's precompiled header
    leaves its compile line, whichever compiler wrote it, and nothing else does."""

    def test_gcc_and_clang_lines_lose_it_and_keep_the_rest(self):
        gcc = ("/usr/bin/c++ -DX=\\\"/a b\\\" -I/src/lib -O1 -Winvalid-pch -include "
               "/b/lib/gi/core/CMakeFiles/gi_core.dir/cmake_pch.hxx -MD -MT o.o -MF o.o.d -o o.o -c /src/lib/x.cpp")
        clang = ("clang++ -I/src/lib -Xclang -include-pch -Xclang /b/d/cmake_pch.hxx.pch -Xclang -include "
                 "-Xclang /b/d/cmake_pch.hxx -include /src/own.hpp -c /src/lib/x.cpp")
        self.assertEqual(overlay.without_cmake_pch(gcc).split(),
                         ["/usr/bin/c++", "-DX=\\\"/a", "b\\\"", "-I/src/lib", "-O1", "-MD", "-MT", "o.o", "-MF",
                          "o.o.d", "-o", "o.o", "-c", "/src/lib/x.cpp"])
        self.assertEqual(overlay.without_cmake_pch(clang).split(),
                         ["clang++", "-I/src/lib", "-include", "/src/own.hpp", "-c", "/src/lib/x.cpp"])
        plain = "c++ -I/src/lib -include /src/lib/gi/core/math.hpp -c /src/lib/x.cpp"
        self.assertEqual(overlay.without_cmake_pch(plain), plain, "a header of the project's own stays")


class ArchiveCommands(unittest.TestCase):
    """The overlay writes a library's archive again from the command that wrote it: it
    must know that command however CMake wrote the archiver (an archive missed is an
    old archive linked, and code graded that the student no longer has)."""

    def test_every_archiver_is_found_quoted_or_not(self):
        for command in ("/usr/bin/ar qc lib/gi/libgi_core.a a.o b.o",
                        ': && /usr/bin/cmake -E rm -f lib/gi/libgi_core.a && "/usr/bin/gcc-ar-12" cr lib/gi/libgi_core.a '
                        " a.o && /usr/bin/gcc-ranlib-12 lib/gi/libgi_core.a && :",
                        "/usr/bin/llvm-ar-14 qc lib/gi/libgi_core.a a.o", "x86_64-w64-mingw32-ar qc lib/gi/libgi_core.a a.o"):
            found = overlay.ARCHIVE.search(command)
            self.assertIsNotNone(found, command)
            self.assertEqual(found.group(1), "lib/gi/libgi_core.a", command)
        self.assertIsNone(overlay.ARCHIVE.search("/usr/bin/c++ -o bin/star a.o lib/gi/libgi_core.a"))


MACRO = re.compile(r"\b(EXPECT|ASSERT)_[A-Z_]+\s*\(")


def assertions(text):
    """(line, whole statement, what follows the macro's parentheses) of each assertion."""
    for m in MACRO.finditer(text):
        i, depth = m.end(), 1
        while depth and i < len(text):
            depth += {"(": 1, ")": -1}.get(text[i], 0)
            i += 1
        yield text.count("\n", 0, m.start()) + 1, text[m.start():text.find(";", i)], text[i:text.find(";", i)]


class GradedTests(unittest.TestCase):
    """The graded tests themselves: what every one of them must do for a student."""

    def files(self):
        return sorted((ROOT / "exercises").glob("lab[0-9][0-9]/**/*_test.cpp"))

    def test_every_assertion_carries_a_hint(self):
        missing = [f"{path.relative_to(ROOT)}:{line}: {statement.splitlines()[0]}" for path in self.files()
                   for line, statement, rest in assertions(path.read_text()) if "<<" not in rest]
        self.assertEqual(missing, [], "a failing assertion without a message leaves the student with gtest's text")

    def test_suites_name_an_exercise_of_their_lab_and_tests_print_readably(self):
        ids = {r.id for r in regions.find_regions(ROOT)}
        for path in self.files():
            text = path.read_text()
            self.assertIn('#include "support/print.hpp"', text, f"{path.name}: include the printers")
            lab = int(path.relative_to(ROOT / "exercises").parts[0][3:])
            for suite, test in re.findall(r"^TEST\((\w+), (\w+)\)", text, re.M):
                found = re.match(r"Ex(\d+)_(\d+)_", suite)
                self.assertTrue(found, f"{path.name}: suite {suite} does not name its exercise (Ex{lab}_N_...)")
                self.assertEqual(int(found.group(1)), lab, f"{path.name}: {suite} belongs to another lab")
                self.assertIn(f"{found.group(1)}.{found.group(2)}", ids, f"{path.name}: {suite}: no such exercise")

    def test_handouts_give_each_exercise_its_number_of_points(self):
        for lab in grade.labs_in(ROOT):
            handout = (ROOT / "exercises" / f"lab{lab:02d}" / "README.md").read_text()
            counts = {}
            for name, hidden in grade.source_tests(ROOT, lab):
                if not hidden:
                    counts[grade.exercise_of(name, lab)] = counts.get(grade.exercise_of(name, lab), 0) + 1
            for exercise, count in counts.items():
                self.assertRegex(handout, rf"## Exercise {re.escape(exercise)} .*\({count} points?\)",
                                 f"lab {lab}: the handout's points for {exercise} are not its {count} tests")
                self.assertRegex(handout, rf"\| {re.escape(exercise)} \| .* \| {count} \|",
                                 f"lab {lab}: the handout's table gives {exercise} another number of points")
            self.assertIn(f"`score: X/{sum(counts.values())}`", handout, f"lab {lab}: the handout's total is wrong")
            hidden = sum(1 for _, h in grade.source_tests(ROOT, lab) if h)
            count = f"{sum(counts.values())}" + (f" (+{hidden})" if hidden else "")
            self.assertRegex((ROOT / "exercises" / "README.md").read_text(), rf"\| {lab} \| \[lab{lab:02d}/.* \| {re.escape(count)} \|",
                             f"exercises/README.md: lab {lab} has {count} graded tests")
            self.assertIn(f"--target lab{lab:02d}_graded\n    exercises/grade --labs {lab}\n", handout,
                          f"lab {lab}: the handout must give the two commands to build and grade the lab")


if __name__ == "__main__":
    unittest.main()
