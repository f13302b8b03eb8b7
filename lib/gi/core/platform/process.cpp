#include "gi/core/platform/process.hpp"

#if defined(_WIN32)
#include <windows.h>
#else
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <sstream>
#endif

namespace gi::platform {

#if defined(_WIN32)

long long current_process_id() { return static_cast<long long>(::GetCurrentProcessId()); }

bool process_exists(long long id) {
  if (id < 0 || id > 0xffffffffLL) return false;
  const HANDLE process = ::OpenProcess(PROCESS_QUERY_LIMITED_INFORMATION, FALSE, static_cast<DWORD>(id));
  if (!process) return ::GetLastError() != ERROR_INVALID_PARAMETER;  // access denied: it exists
  DWORD code = 0;
  // An ended process lives on as long as someone holds a handle to it, with its exit code.
  const bool running = ::GetExitCodeProcess(process, &code) && code == STILL_ACTIVE;
  ::CloseHandle(process);
  return running;
}

// The creation time, in 100 ns ticks since 1601 (GetProcessTimes).
std::string process_start_stamp(long long id) {
  if (id <= 0 || id > 0xffffffffLL) return "";
  const HANDLE process = ::OpenProcess(PROCESS_QUERY_LIMITED_INFORMATION, FALSE, static_cast<DWORD>(id));
  if (!process) return "";
  FILETIME created, exited, kernel, user;
  std::string stamp;
  DWORD code = 0;
  if (::GetProcessTimes(process, &created, &exited, &kernel, &user) && ::GetExitCodeProcess(process, &code) &&
      code == STILL_ACTIVE)
    stamp = std::to_string((static_cast<unsigned long long>(created.dwHighDateTime) << 32) | created.dwLowDateTime);
  ::CloseHandle(process);
  return stamp;
}

#else

long long current_process_id() { return static_cast<long long>(::getpid()); }

bool process_exists(long long id) {
  const auto pid = static_cast<pid_t>(id);
  if (id <= 0 || pid != id) return false;
  return ::kill(pid, 0) == 0 || errno != ESRCH;  // signal 0: only asks whether it could be sent
}

// Field 22 of /proc/<id>/stat, the start time in clock ticks since boot, after the
// boot's id; empty for a process that has ended (a zombie, state Z or X, keeps its
// entry until its parent reaps it) and where there is no /proc.
std::string process_start_stamp(long long id) {
  if (id <= 0) return "";
  std::ifstream stat("/proc/" + std::to_string(id) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return "";
  // The second field, the command's name in parentheses, may hold spaces: count from
  // the last ')'.
  const std::size_t close = line.rfind(')');
  if (close == std::string::npos) return "";
  std::istringstream fields(line.substr(close + 1));
  std::string field;
  for (int i = 3; i <= 22 && fields >> field; ++i)
    if (i == 3 && (field == "Z" || field == "X")) {
      return "";
    } else if (i == 22) {
      std::string boot;
      std::getline(std::ifstream("/proc/sys/kernel/random/boot_id") >> std::ws, boot);
      return boot + ":" + field;
    }
  return "";
}

#endif

}  // namespace gi::platform
