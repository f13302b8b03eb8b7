#pragma once
#include <stdexcept>
#include <string>

namespace gi {

// Thrown by the stubs in a student kit: "exercise 1.2 ray-sphere intersection".
// Lessons catch it and say which exercise is still to do.
struct NotImplemented : std::logic_error {
  explicit NotImplemented(const std::string& what)
      : std::logic_error(what + " is not implemented yet (see exercises/)") {}
};

}  // namespace gi
