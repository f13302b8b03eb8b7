#pragma once
#include "gi/report/outputs.hpp"

namespace gi {

// The process that is running now, as a lesson's record names it while it runs.
RunProcess this_process();

// Whether the process a record names is still running: the same id *and* the same
// start stamp, so that a killed run whose id the system has given to a new process
// is not taken for alive. A record without a stamp (none could be read) falls back
// on the id alone.
bool still_running(const RunProcess& process);

}  // namespace gi
