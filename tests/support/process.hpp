#pragma once
// Command lines for the programs tests run (gi/core/platform/program.hpp runs them):
// split as a shell would split them, and run through the emulator where the build runs
// its programs so (an ARM64 build tested on x86-64 under qemu-user).
#include <string>
#include <vector>

namespace gi_test {

// The words of a command line as a POSIX shell splits them: blanks separate, '...'
// quotes everything, "..." quotes all but \" and \\, and \ escapes the next character.
// "--out ''" is {"--out", ""}.
std::vector<std::string> shell_words(const std::string& text);

// `command`, after the emulator the build runs its programs with (none natively).
std::vector<std::string> emulated(const std::vector<std::string>& command);

// A program of the system's own that exits at once with status 0 (the shell's `exit 0`;
// cmd.exe's on Windows): a process that has ended, for tests of process numbers.
std::vector<std::string> exits_at_once();

}  // namespace gi_test
