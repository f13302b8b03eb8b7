#include "external_program.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace gi {

namespace fs = std::filesystem;

std::optional<fs::path> find_on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  std::string_view folders(path);
  while (true) {
    const std::size_t end = std::min(folders.find(':'), folders.size());
    // An empty entry is the current folder, as POSIX shells read it.
    const fs::path candidate = fs::path(end == 0 ? "." : std::string(folders.substr(0, end))) / program;
    std::error_code error;
    if (fs::is_regular_file(candidate, error) && ::access(candidate.c_str(), X_OK) == 0) return candidate;
    if (end == folders.size()) return std::nullopt;
    folders.remove_prefix(end + 1);
  }
}

namespace {

// Everything the child writes until it closes its end of the pipe (it exits), or
// until the deadline; false if the deadline came first.
bool read_until_closed(int from_child, std::chrono::steady_clock::time_point deadline, std::string& output) {
  char buffer[4096];
  while (true) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
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

}  // namespace

ProgramRun run_program(const fs::path& program, const std::vector<std::string>& args, double time_limit) {
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(time_limit));
  int ends[2];  // [0] we read, [1] the child writes
  if (::pipe2(ends, O_CLOEXEC) != 0) throw std::runtime_error("cannot make a pipe: " + std::string(strerror(errno)));
  std::vector<std::string> words{program.string()};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, ends[1], 1);  // dup2 clears close-on-exec
  posix_spawn_file_actions_adddup2(&actions, ends[1], 2);
  pid_t child = 0;
  const int spawned = ::posix_spawn(&child, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(ends[1]);
  if (spawned != 0) {
    ::close(ends[0]);
    throw std::runtime_error("cannot start " + program.string() + ": " + strerror(spawned));
  }

  ProgramRun run{-1, ""};
  const bool finished = read_until_closed(ends[0], deadline, run.output);
  ::close(ends[0]);
  if (!finished) ::kill(child, SIGKILL);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (!finished)
    throw std::runtime_error(program.string() + " did not finish within " + (std::ostringstream() << time_limit).str() +
                             " s and was stopped");
  run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

std::string debian_package_of(const fs::path& program) {
  const std::optional<fs::path> dpkg_query = find_on_path("dpkg-query");
  std::error_code error;
  const fs::path file = fs::canonical(program, error);
  if (!dpkg_query || error) return "";
  try {
    // "tachyon-bin-nox: /usr/bin/tachyon-nox": the package is what comes before ": ".
    const ProgramRun owner = run_program(*dpkg_query, {"-S", file.string()}, 30);
    const std::size_t colon = owner.output.find(": ");
    if (owner.status != 0 || colon == std::string::npos) return "";
    const std::string package = owner.output.substr(0, colon);
    const ProgramRun version = run_program(*dpkg_query, {"-W", "-f=${Version}", package}, 30);
    if (version.status != 0 || version.output.empty()) return "";
    return package + " " + version.output;
  } catch (const std::runtime_error&) {
    return "";  // a dpkg-query that hangs or cannot start knows nothing to tell
  }
}

TemporaryFolder::TemporaryFolder(const std::string& prefix) {
  std::error_code error;
  std::string pattern = (fs::temp_directory_path(error) / (prefix + "XXXXXX")).string();
  if (error || !::mkdtemp(pattern.data()))
    throw std::runtime_error("cannot make a temporary folder " + pattern + ": " +
                             (error ? error.message() : std::string(strerror(errno))));
  path_ = pattern;
}

TemporaryFolder::~TemporaryFolder() {
  std::error_code error;
  fs::remove_all(path_, error);  // nothing to do about a failure while leaving
}

}  // namespace gi
