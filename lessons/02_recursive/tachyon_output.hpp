#pragma once
// What Tachyon (John E. Stone's ray tracer, Debian's tachyon-bin-nox) prints about a
// render, read back by 02_tachyon_bench. A run of 0.99b6 prints, on stdout:
//
//   Tachyon Parallel/Multiprocessor Ray Tracer   Version 0.99
//   ...
//   Scene Parsing Time:     0.0001 seconds
//   Rendering Progress:  ...% complete       (many times, each ending in '\r')
//     Ray Tracing Time:     0.0971 seconds
//       Image I/O Time:     0.0018 seconds
//
// A render that fails (no scene file, a syntax error) prints why and "Aborting
// render.", and still exits with status 0: the missing "Ray Tracing Time" line is
// the only sure sign.
#include <stdexcept>
#include <string>

namespace gi {

struct TachyonReport {
  std::string version;         // as Tachyon prints it ("0.99"); empty if it printed none
  double ray_tracing_seconds;  // its own clock of the render alone, without parsing or image I/O
};

// Tachyon's output that says no render happened, or says it in a form we do not
// know: the message quotes the line that explains it.
struct TachyonOutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Reads Tachyon's stdout (and stderr, if mixed in): lines end in '\n' or '\r'. Needs
// exactly one "Ray Tracing Time: <number> seconds" line, the number finite and not
// negative; throws TachyonOutputError otherwise.
TachyonReport parse_tachyon_output(const std::string& text);

}  // namespace gi
