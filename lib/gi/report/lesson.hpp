#pragma once
#include <functional>
#include <string>

namespace gi {

// Runs a lesson's body and turns what it throws into one readable line on stderr
// and an exit status: 2 for a bad command line, 3 for an exercise not done yet,
// 1 for any other error. The body returns the status on success (normally 0).
int run_lesson(const std::string& name, const std::function<int()>& body);

}  // namespace gi
