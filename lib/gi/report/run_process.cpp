#include "gi/report/run_process.hpp"

#include "gi/core/platform/process.hpp"

namespace gi {

RunProcess this_process() {
  const long id = static_cast<long>(platform::current_process_id());
  return {id, platform::process_start_stamp(id)};
}

bool still_running(const RunProcess& process) {
  if (process.id <= 0) return false;
  if (process.started.empty()) return platform::process_exists(process.id);
  return platform::process_start_stamp(process.id) == process.started;
}

}  // namespace gi
