#pragma once
#include <stdexcept>
#include <string>

namespace gi {

// Thrown by the stubs in a student kit: "exercise 1.2 ray-sphere intersection".
// Lessons catch it and say which exercise is still to do. A stub passes the
// function's parameters too, `throw gi::NotImplemented("exercise 1.1 ...", ray, sphere)`:
// they are ignored, and so used, so that a kit compiles without "unused parameter"
// warnings.
struct NotImplemented : std::logic_error {
  template <class... Parameters>
  explicit NotImplemented(const std::string& what, const Parameters&...)
      : std::logic_error(what + " is not implemented yet (see exercises/)") {}
};

}  // namespace gi
