#pragma once
#include <string>
#include <string_view>

namespace gi {

// How a number the workbench reads must be spelled, checked on the text before it
// is converted, so that what is accepted is a property of the grammar and not of
// whichever routine turns digits into a double (strtod also takes "0x10", " 5",
// "+5", "inf" and "nan"; from_chars takes "inf" and "nan"). Decimal and ASCII only:
//
//   whole number   -?[0-9]+                                  7   -3   0
//   real number    -?([0-9]+(.[0-9]*)?|.[0-9]+)([eE][+-]?[0-9]+)?
//                                                            2   -0.5   .5   5.   1e-3
//
// Not numbers: "+5" (no sign but '-'), " 5" and "5 " (no spaces), "0x10" (no hex),
// "inf", "nan", "1e" (an exponent needs digits), "" and digits of other scripts
// such as "٣". JSON has a grammar of its own, stricter still (json.hpp).
bool is_whole_number_text(std::string_view text);
bool is_real_number_text(std::string_view text);

// A double read from such text is refused when it is not finite (1e999) or when it
// is subnormal: a value below 2.2250738585072014e-308 in size but not 0 (-1e-320) has lost digits
// already, and what is computed from it loses more. -0 is kept as 0.
enum class RealProblem { None, NotFinite, Subnormal };
RealProblem real_problem(double v);
// The sentence for a problem, as "must be ...": "must be a finite number".
std::string real_problem_text(RealProblem problem);

// Text a user typed, cut to quote in a one-line message: at most 40 characters (UTF-8
// characters whole), then "...". A lesson's every message leaves through run_lesson,
// which writes control characters as \xNN (printable, utf8.hpp), so that a quoted
// escape sequence or newline cannot rewrite the terminal or split the line.
std::string quoted_text(std::string_view text);

}  // namespace gi
