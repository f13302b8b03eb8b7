#include "gi/core/platform/program.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <sstream>
#include <stdexcept>

#if defined(_WIN32)
#include <windows.h>

#include <thread>
#else
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>

extern char** environ;
#endif

namespace gi::platform {

namespace {

using Clock = std::chrono::steady_clock;

Clock::time_point deadline_after(double seconds) {
  return Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

std::runtime_error too_long(const std::string& program, double time_limit) {
  return std::runtime_error(program + " did not finish within " + (std::ostringstream() << time_limit).str() +
                            " s and was stopped");
}

}  // namespace

#if defined(_WIN32)

namespace {

std::wstring wide(const std::string& text) {
  const int n = ::MultiByteToWideChar(CP_UTF8, 0, text.data(), static_cast<int>(text.size()), nullptr, 0);
  std::wstring out(static_cast<std::size_t>(n), L'\0');
  ::MultiByteToWideChar(CP_UTF8, 0, text.data(), static_cast<int>(text.size()), out.data(), n);
  return out;
}

// One argument as the program's C runtime splits its command line back into argv: in
// quotes where it holds a blank or a quote or is empty; a quote escaped with \, and
// the backslashes just before a quote doubled.
std::wstring quoted(const std::string& argument) {
  const std::wstring a = wide(argument);
  if (!a.empty() && a.find_first_of(L" \t\n\v\"") == std::wstring::npos) return a;
  std::wstring q = L"\"";
  for (std::size_t i = 0;; ++i) {
    std::size_t backslashes = 0;
    for (; i < a.size() && a[i] == L'\\'; ++i) ++backslashes;
    if (i == a.size()) {
      q.append(2 * backslashes, L'\\');
      break;
    }
    q.append(a[i] == L'"' ? 2 * backslashes + 1 : backslashes, L'\\');
    q += a[i];
  }
  return q + L"\"";
}

// A killed program ends with this code, which no program here exits with.
constexpr UINT killed_code = 0x6b111ed;

// Starts the command with stdout and stderr on `output` (the null device if none) and
// returns its process; throws if it cannot be started.
HANDLE start(const std::vector<std::string>& command, HANDLE output) {
  std::wstring line;
  for (const std::string& word : command) line += (line.empty() ? L"" : L" ") + quoted(word);
  SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
  const HANDLE null = ::CreateFileW(L"NUL", GENERIC_READ | GENERIC_WRITE, FILE_SHARE_READ | FILE_SHARE_WRITE, &inherit,
                                    OPEN_EXISTING, 0, nullptr);
  STARTUPINFOW startup{};
  startup.cb = sizeof startup;
  startup.dwFlags = STARTF_USESTDHANDLES;
  startup.hStdInput = null;
  startup.hStdOutput = startup.hStdError = output ? output : null;
  PROCESS_INFORMATION process{};
  const BOOL started =
      ::CreateProcessW(nullptr, line.data(), nullptr, nullptr, TRUE, 0, nullptr, nullptr, &startup, &process);
  const DWORD error = ::GetLastError();
  ::CloseHandle(null);
  if (!started) throw std::runtime_error("cannot start " + command.at(0) + " (Windows error " + std::to_string(error) + ")");
  ::CloseHandle(process.hThread);
  return process.hProcess;
}

}  // namespace

ProgramRun run_program(const std::vector<std::string>& command, double time_limit) {
  const auto deadline = deadline_after(time_limit);
  SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
  HANDLE from_child = nullptr, to_us = nullptr;
  if (!::CreatePipe(&from_child, &to_us, &inherit, 0)) throw std::runtime_error("cannot make a pipe");
  ::SetHandleInformation(from_child, HANDLE_FLAG_INHERIT, 0);
  HANDLE process = nullptr;
  try {
    process = start(command, to_us);
  } catch (...) {
    ::CloseHandle(to_us);
    ::CloseHandle(from_child);
    throw;
  }
  ::CloseHandle(to_us);  // the child holds its own copy: reading ends when it exits
  std::string output;
  std::thread reader([&] {  // a pipe cannot be waited on with a time-out: read it aside
    char buffer[4096];
    DWORD n = 0;
    while (::ReadFile(from_child, buffer, sizeof buffer, &n, nullptr) && n > 0) output.append(buffer, n);
  });
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
  const bool finished = ::WaitForSingleObject(process, static_cast<DWORD>(std::max<long long>(left, 0))) == WAIT_OBJECT_0;
  if (!finished) {
    ::TerminateProcess(process, killed_code);
    ::WaitForSingleObject(process, INFINITE);
  }
  reader.join();
  ::CloseHandle(from_child);
  DWORD code = 0;
  ::GetExitCodeProcess(process, &code);
  ::CloseHandle(process);
  if (!finished) throw too_long(command.at(0), time_limit);
  // The C runtime of the program wrote each \n of its text output as \r\n.
  std::string text;
  for (std::size_t i = 0; i < output.size(); ++i)
    if (!(output[i] == '\r' && i + 1 < output.size() && output[i + 1] == '\n')) text += output[i];
  return {code == killed_code ? -1 : static_cast<int>(code), text};
}

StartedProgram::StartedProgram(const std::vector<std::string>& command)
    : process_(reinterpret_cast<long long>(start(command, nullptr))),
      id_(static_cast<long long>(::GetProcessId(reinterpret_cast<HANDLE>(process_)))) {}

bool StartedProgram::kill() {
  if (done_) return false;
  done_ = true;
  const auto process = reinterpret_cast<HANDLE>(process_);
  const bool killed = ::TerminateProcess(process, killed_code) != 0;  // fails once it has ended
  ::WaitForSingleObject(process, INFINITE);
  DWORD code = 0;
  ::GetExitCodeProcess(process, &code);
  ::CloseHandle(process);
  return killed && code == killed_code;
}

#else

namespace {

// Starts the command with stdout and stderr on `output` (/dev/null if -1) and returns
// its pid; throws if it cannot be started.
pid_t start(const std::vector<std::string>& command, int output) {
  std::vector<std::string> words = command;
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  if (output >= 0) {
    posix_spawn_file_actions_adddup2(&actions, output, 1);  // dup2 clears close-on-exec
    posix_spawn_file_actions_adddup2(&actions, output, 2);
  } else {
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
  }
  pid_t child = 0;
  const int spawned = ::posix_spawnp(&child, argv.at(0), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error("cannot start " + command.at(0) + ": " + std::strerror(spawned));
  return child;
}

// Everything the child writes until it closes its end of the pipe (it exits), or
// until the deadline; false if the deadline came first.
bool read_until_closed(int from_child, Clock::time_point deadline, std::string& output) {
  char buffer[4096];
  while (true) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) return false;
    pollfd ready{from_child, POLLIN, 0};
    const int polled = ::poll(&ready, 1, static_cast<int>(std::min<long long>(left.count(), 1'000'000)));
    if (polled < 0 && errno == EINTR) continue;
    if (polled <= 0) return false;  // the deadline, or a poll that failed: stop the child either way
    const ssize_t n = ::read(from_child, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return true;  // closed (or broken: the child is gone either way)
    output.append(buffer, static_cast<std::size_t>(n));
  }
}

int wait_for(pid_t child) {
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

}  // namespace

ProgramRun run_program(const std::vector<std::string>& command, double time_limit) {
  const auto deadline = deadline_after(time_limit);
  int ends[2];  // [0] we read, [1] the child writes; neither is left open in other children
  if (::pipe(ends) != 0) throw std::runtime_error("cannot make a pipe: " + std::string(std::strerror(errno)));
  ::fcntl(ends[0], F_SETFD, FD_CLOEXEC);
  ::fcntl(ends[1], F_SETFD, FD_CLOEXEC);
  pid_t child = 0;
  try {
    child = start(command, ends[1]);
  } catch (...) {
    ::close(ends[0]);
    ::close(ends[1]);
    throw;
  }
  ::close(ends[1]);
  ProgramRun run{-1, ""};
  const bool finished = read_until_closed(ends[0], deadline, run.output);
  ::close(ends[0]);
  if (!finished) ::kill(child, SIGKILL);
  const int status = wait_for(child);
  if (!finished) throw too_long(command.at(0), time_limit);
  run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

StartedProgram::StartedProgram(const std::vector<std::string>& command) : process_(start(command, -1)), id_(process_) {}

bool StartedProgram::kill() {
  if (done_) return false;
  done_ = true;
  const auto child = static_cast<pid_t>(process_);
  ::kill(child, SIGKILL);
  const int status = wait_for(child);
  return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
}

#endif

StartedProgram::~StartedProgram() { kill(); }

}  // namespace gi::platform
