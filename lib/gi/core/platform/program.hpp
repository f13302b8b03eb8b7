#pragma once
// Running another program, directly (no shell: nothing in its arguments is
// interpreted) with stdin empty: its output captured and the run stopped if it takes
// too long, or left running to be killed midway, as the tests kill lessons to see
// what a killed run leaves. posix_spawn on POSIX (Linux, macOS), CreateProcess on
// Windows: the one file that knows both.
#include <string>
#include <vector>

namespace gi::platform {

struct ProgramRun {
  int status;          // its exit status, or -1 if it was killed (a signal, or TerminateProcess)
  std::string output;  // stdout and stderr together, in the order written
};

// Runs command[0] (a path, or a name looked up on PATH) with the rest as its
// arguments and waits for it. Throws std::runtime_error if it cannot be started, or
// has not finished after `time_limit` seconds (it is then killed).
ProgramRun run_program(const std::vector<std::string>& command, double time_limit);

// A program started and left running, its output thrown away.
class StartedProgram {
 public:
  // Throws std::runtime_error if it cannot be started.
  explicit StartedProgram(const std::vector<std::string>& command);
  ~StartedProgram();  // kills it if it is still running
  StartedProgram(const StartedProgram&) = delete;
  StartedProgram& operator=(const StartedProgram&) = delete;

  // Kills it at once, as a power cut or the task manager would (SIGKILL;
  // TerminateProcess), and waits for it: true if it was killed, false if it had
  // already finished.
  bool kill();

  // Its process number, as current_process_id() (process.hpp) gives it to the program.
  long long id() const { return id_; }

 private:
  long long process_ = -1;  // the pid (POSIX) or the process's handle (Windows)
  long long id_ = -1;
  bool done_ = false;
};

}  // namespace gi::platform
