#pragma once
// Processes by number, on POSIX (Linux, macOS) and on Windows: the one file that knows
// both. AtomicFile names its temporaries after the process writing them, so that a
// later run can tell a killed run's leftovers from a running one's; a lesson's record
// names the process running it, so that the index can tell a killed run from a live one.
#include <string>

namespace gi::platform {

// This process's number (getpid; GetCurrentProcessId on Windows).
long long current_process_id();

// False only where the system says no process of that number is running; a process
// that exists but is not ours to signal still counts. Numbers are reused, so a
// leftover can look alive for a while: it is then cleared by a later run.
bool process_exists(long long id);

// When the running process of that number started, as text that stays the same while
// it runs and differs for a later process given the same number: on Linux the boot's
// id and the start time in /proc/<id>/stat, on Windows the creation time. Empty for a
// process that has ended, and where the system does not say (macOS has no /proc).
std::string process_start_stamp(long long id);

}  // namespace gi::platform
