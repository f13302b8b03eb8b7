#include "gi/core/number_text.hpp"

#include <cfloat>
#include <cmath>

namespace gi {

namespace {

bool digit(char c) { return c >= '0' && c <= '9'; }

// Reads [0-9]* from `at`; returns how many digits it passed.
std::size_t digits(std::string_view text, std::size_t& at) {
  const std::size_t start = at;
  while (at < text.size() && digit(text[at])) ++at;
  return at - start;
}

}  // namespace

bool is_whole_number_text(std::string_view text) {
  std::size_t at = !text.empty() && text[0] == '-' ? 1 : 0;
  return digits(text, at) > 0 && at == text.size();
}

bool is_real_number_text(std::string_view text) {
  std::size_t at = !text.empty() && text[0] == '-' ? 1 : 0;
  std::size_t mantissa = digits(text, at);
  if (at < text.size() && text[at] == '.') {
    ++at;
    mantissa += digits(text, at);
  }
  if (mantissa == 0) return false;
  if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
    ++at;
    if (at < text.size() && (text[at] == '+' || text[at] == '-')) ++at;
    if (digits(text, at) == 0) return false;
  }
  return at == text.size();
}

RealProblem real_problem(double v) {
  if (!std::isfinite(v)) return RealProblem::NotFinite;
  if (v != 0 && std::abs(v) < DBL_MIN) return RealProblem::Subnormal;
  return RealProblem::None;
}

std::string real_problem_text(RealProblem problem) {
  switch (problem) {
    case RealProblem::None: return "";
    case RealProblem::NotFinite: return "must be a finite number";
    case RealProblem::Subnormal: return "must be 0 or at least 2.2250738585072014e-308 in size (a smaller double has lost digits)";
  }
  return "";
}

std::string quoted_text(std::string_view text) {
  const std::size_t most = 40;
  std::size_t end = 0;
  for (std::size_t characters = 0; end < text.size() && characters < most; ++characters)
    do ++end;  // a character and its UTF-8 continuation bytes
    while (end < text.size() && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80);
  return std::string(text.substr(0, end)) + (end < text.size() ? "..." : "");
}

}  // namespace gi
