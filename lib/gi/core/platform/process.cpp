#include "gi/core/platform/process.hpp"

#if defined(_WIN32)
#include <windows.h>
#else
#include <signal.h>
#include <unistd.h>

#include <cerrno>
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

#else

long long current_process_id() { return static_cast<long long>(::getpid()); }

bool process_exists(long long id) {
  const auto pid = static_cast<pid_t>(id);
  if (id <= 0 || pid != id) return false;
  return ::kill(pid, 0) == 0 || errno != ESRCH;  // signal 0: only asks whether it could be sent
}

#endif

}  // namespace gi::platform
