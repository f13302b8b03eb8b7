#include "gi/report/lesson.hpp"

#include <exception>
#include <iostream>

#include "gi/core/not_implemented.hpp"
#include "gi/report/options.hpp"

namespace gi {

int run_lesson(const std::string& name, const std::function<int()>& body) {
  try {
    return body();
  } catch (const OptionError& e) {
    std::cerr << name << ": error: " << e.what() << " (try --help)\n";
    return 2;
  } catch (const NotImplemented& e) {
    std::cerr << name << ": " << e.what() << '\n';
    return 3;
  } catch (const std::exception& e) {
    std::cerr << name << ": error: " << e.what() << '\n';
    return 1;
  }
}

}  // namespace gi
