#pragma once
// Processes by number, on POSIX (Linux, macOS) and on Windows: the one file that knows
// both. AtomicFile names its temporaries after the process writing them, so that a
// later run can tell a killed run's leftovers from a running one's.

namespace gi::platform {

// This process's number (getpid; GetCurrentProcessId on Windows).
long long current_process_id();

// False only where the system says no process of that number is running; a process
// that exists but is not ours to signal still counts. Numbers are reused, so a
// leftover can look alive for a while: it is then cleared by a later run.
bool process_exists(long long id);

}  // namespace gi::platform
