#include "gi/report/run_process.hpp"

#include <fstream>
#include <sstream>
#include <string>

#ifdef _WIN32
#include <windows.h>
#else
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#endif

namespace gi {

namespace {

#ifdef _WIN32

// The process's creation time, in 100 ns ticks since 1601 (GetProcessTimes).
std::string start_stamp(long id) {
  const HANDLE process = OpenProcess(PROCESS_QUERY_LIMITED_INFORMATION, FALSE, static_cast<DWORD>(id));
  if (!process) return "";
  FILETIME created, exited, kernel, user;
  std::string stamp;
  DWORD code = 0;
  if (GetProcessTimes(process, &created, &exited, &kernel, &user) && GetExitCodeProcess(process, &code) &&
      code == STILL_ACTIVE)
    stamp = std::to_string((static_cast<unsigned long long>(created.dwHighDateTime) << 32) | created.dwLowDateTime);
  CloseHandle(process);
  return stamp;
}

long current_id() { return static_cast<long>(GetCurrentProcessId()); }
bool id_alive(long id) { return !start_stamp(id).empty(); }

#else

// Linux: the boot's id and field 22 of /proc/<id>/stat, the process's start time in
// clock ticks since boot; empty for a process that has ended (a zombie, state Z or X,
// keeps its entry until its parent reaps it) and where there is no /proc.
std::string start_stamp(long id) {
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

long current_id() { return static_cast<long>(::getpid()); }
bool id_alive(long id) { return id > 0 && (::kill(static_cast<pid_t>(id), 0) == 0 || errno == EPERM); }

#endif

}  // namespace

RunProcess this_process() {
  const long id = current_id();
  return {id, start_stamp(id)};
}

bool still_running(const RunProcess& process) {
  if (process.id <= 0) return false;
  if (process.started.empty()) return id_alive(process.id);
  return start_stamp(process.id) == process.started;
}

}  // namespace gi
