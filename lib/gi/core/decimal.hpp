#pragma once
// Reading a decimal number out of text, the same on every platform. std::from_chars is
// what the scene readers want (no locale, no leading spaces, a range error), but the
// libc++ of Xcode before 15 and of Debian 12 has it for integers only, not for double.
// This is that call, for the decimal numbers the readers take.
#include <charconv>
#include <system_error>

namespace gi {

// As std::from_chars(first, last, value) for a double in the general format, decimal
// only: an optional '-', digits with an optional decimal point (a digit at least), and
// an optional exponent (e or E, an optional sign, digits; without digits the 'e' is not
// part of the number). Leading spaces, '+', hex, inf and nan are not numbers here:
// ptr == first and errc::invalid_argument. A number too large for a double, or too small
// to be anything but zero, is errc::result_out_of_range with ptr past it and `value`
// unchanged. Otherwise `value` is the double nearest the number and ptr points past it.
std::from_chars_result read_decimal(const char* first, const char* last, double& value);

}  // namespace gi
