#include "gi/core/decimal.hpp"

#include <algorithm>
#include <clocale>
#include <cmath>
#include <cstdlib>
#include <string>

namespace gi {

std::from_chars_result read_decimal(const char* first, const char* last, double& value) {
  const auto is_digit = [](char c) { return c >= '0' && c <= '9'; };
  const char* p = first;
  if (p != last && *p == '-') ++p;
  const char* mantissa = p;
  p = std::find_if_not(p, last, is_digit);
  if (p != last && *p == '.') p = std::find_if_not(p + 1, last, is_digit);
  if (std::none_of(mantissa, p, is_digit)) return {first, std::errc::invalid_argument};
  const bool zero = std::all_of(mantissa, p, [](char c) { return c == '0' || c == '.'; });
  if (p != last && (*p == 'e' || *p == 'E')) {
    const char* exponent = p + 1;
    if (exponent != last && (*exponent == '+' || *exponent == '-')) ++exponent;
    const char* end = std::find_if_not(exponent, last, is_digit);
    if (end != exponent) p = end;
  }
  // strtod rounds to nearest on every C library the workbench builds with. It reads the
  // decimal point of the C locale in force: a program starts in the "C" locale ('.'),
  // and one that changed it (to ',' in much of Europe) reads the same numbers, as the
  // point is given in the locale's own spelling.
  std::string text(first, p);
  const char point = *std::localeconv()->decimal_point;
  std::replace(text.begin(), text.end(), '.', point);
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return {first, std::errc::invalid_argument};  // a locale strtod cannot read
  if (std::isinf(v) || (v == 0 && !zero)) return {p, std::errc::result_out_of_range};
  value = v;
  return {p, std::errc()};
}

}  // namespace gi
