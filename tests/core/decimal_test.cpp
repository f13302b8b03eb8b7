// The decimal reader the scene files, OBJ meshes and --camera share (decimal.hpp):
// what it takes and refuses, its range errors, round trips of every kind of double, and
// agreement with std::from_chars where the standard library has it for double.
#include "gi/core/decimal.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <clocale>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

#include "gi/core/rng.hpp"

namespace {

struct Read {
  double value;
  std::ptrdiff_t length;
  std::errc error;
};

Read read(const std::string& text, double before = -7.0) {
  double v = before;
  const auto [end, error] = gi::read_decimal(text.data(), text.data() + text.size(), v);
  return {v, end - text.data(), error};
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

}  // namespace

TEST(ReadDecimal, ReadsDecimalNumbersToTheNearestDouble) {
  const struct {
    const char* text;
    double value;
  } cases[] = {{"0.1", 0.1},
               {"-0", -0.0},
               {"0", 0.0},
               {"1e-300", 1e-300},
               {"39.30764811610661", 39.30764811610661},
               {"123456789012345678", 123456789012345678.0},
               {"1.", 1.0},
               {".5", 0.5},
               {"-.5", -0.5},
               {"00012", 12.0},
               {"2.5E+3", 2500.0},
               {"0e999999", 0.0},
               {"1.7976931348623157e308", std::numeric_limits<double>::max()},
               {"4.9e-324", std::numeric_limits<double>::denorm_min()},
               {"2.2250738585072011e-308", 2.2250738585072011e-308},  // the largest subnormal
               {"9007199254740993", 9007199254740992.0}};             // 2^53 + 1: a tie, to even
  for (const auto& c : cases) {
    const Read r = read(c.text);
    EXPECT_EQ(r.error, std::errc()) << c.text;
    EXPECT_EQ(r.length, static_cast<std::ptrdiff_t>(std::strlen(c.text))) << c.text;
    EXPECT_TRUE(same_bits(r.value, c.value)) << c.text << " read as " << r.value;
  }
}

TEST(ReadDecimal, StopsWhereTheNumberEnds) {
  const struct {
    const char* text;
    std::ptrdiff_t length;
    double value;
  } cases[] = {{"1e", 1, 1.0}, {"1e+", 1, 1.0}, {"1E-x", 1, 1.0}, {"1e5x", 3, 1e5},
               {"0x10", 1, 0.0}, {"2,5", 1, 2.0}, {"1.5.2", 3, 1.5}, {"7 seconds", 1, 7.0}};
  for (const auto& c : cases) {
    const Read r = read(c.text);
    EXPECT_EQ(r.error, std::errc()) << c.text;
    EXPECT_EQ(r.length, c.length) << c.text;
    EXPECT_TRUE(same_bits(r.value, c.value)) << c.text << " read as " << r.value;
  }
}

// No digits, a plus sign, a leading space, hex, inf and nan: nothing read, the value
// untouched.
TEST(ReadDecimal, RefusesWhatIsNotADecimalNumber) {
  for (const char* text : {"", "-", ".", "-.", ".e5", "+1", " 1", "\t1", "x", "inf", "-inf", "Infinity", "nan",
                           "NaN", "nan(1)", "e5", "-e5"}) {
    const Read r = read(text);
    EXPECT_EQ(r.error, std::errc::invalid_argument) << "'" << text << "'";
    EXPECT_EQ(r.length, 0) << "'" << text << "'";
    EXPECT_TRUE(same_bits(r.value, -7.0)) << "'" << text << "'";
  }
}

// Past the largest double, or below half the smallest subnormal (which rounds to zero):
// out of range, the whole number consumed, the value untouched.
TEST(ReadDecimal, NumbersADoubleCannotHoldAreOutOfRange) {
  for (const char* text : {"1e400", "-1e999", "1.8e308", "1.7976931348623159e308", "1e-400", "-1e-400", "2e-324",
                           "0.0000000000000000000000000000000000001e-290", "1e99999999999999999999"}) {
    const Read r = read(text);
    EXPECT_EQ(r.error, std::errc::result_out_of_range) << text;
    EXPECT_EQ(r.length, static_cast<std::ptrdiff_t>(std::strlen(text))) << text;
    EXPECT_TRUE(same_bits(r.value, -7.0)) << text;
  }
  EXPECT_EQ(read("3e-324").error, std::errc()) << "above half the smallest subnormal: rounds up to it";
}

// Every double printed with 17 significant digits reads back as itself: random bit
// patterns cover subnormals, huge and tiny exponents. A decimal of 15 digits or fewer
// (DBL_DIG) printed again from the double read must come back the same, if that double
// is the nearest (outside the subnormals, which hold fewer digits).
TEST(ReadDecimal, RoundTripsRandomDoubles) {
  gi::Rng rng(29);
  int checked = 0;
  for (int i = 0; i < 200000; ++i) {
    const double x = std::bit_cast<double>(std::uint64_t{rng.next_u32()} << 32 | rng.next_u32());
    if (!std::isfinite(x)) continue;
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", x);
    const Read r = read(text);
    ASSERT_EQ(r.error, std::errc()) << text;
    ASSERT_TRUE(same_bits(r.value, x)) << text << " read as " << r.value;
    if (std::abs(x) < std::numeric_limits<double>::min()) continue;
    const int digits = 1 + i % 15;
    char shorter[64], again[64];
    std::snprintf(shorter, sizeof shorter, "%.*e", digits - 1, x);
    const Read s = read(shorter);
    if (s.error == std::errc::result_out_of_range) continue;  // rounded past the largest double, or to 0
    std::snprintf(again, sizeof again, "%.*e", digits - 1, s.value);
    ASSERT_STREQ(again, shorter) << "the double read from " << shorter << " is not the nearest";
    ++checked;
  }
  EXPECT_GT(checked, 180000);
}

// Where the standard library can read a double with from_chars (libstdc++, newer
// libc++), the two agree on random decimal texts: the value to the bit, the length
// read and the error.
#if defined(__cpp_lib_to_chars)
TEST(ReadDecimal, AgreesWithFromChars) {
  gi::Rng rng(7);
  const char pieces[] = "0123456789012345678901234567890123456789.-eE+x ";
  for (int i = 0; i < 200000; ++i) {
    std::string text;
    const int size = 1 + static_cast<int>(rng.below(24));
    for (int k = 0; k < size; ++k) text += pieces[rng.below(sizeof pieces - 1)];
    if (i % 3 == 0) text = std::to_string(rng.uniform() * 1e6) + "e" + std::to_string(static_cast<int>(rng.below(700)) - 350);
    double ours = -7, theirs = -7;
    const auto a = gi::read_decimal(text.data(), text.data() + text.size(), ours);
    const auto b = std::from_chars(text.data(), text.data() + text.size(), theirs);
    ASSERT_EQ(a.ec, b.ec) << "'" << text << "'";
    ASSERT_EQ(a.ptr, b.ptr) << "'" << text << "'";
    ASSERT_TRUE(same_bits(ours, theirs)) << "'" << text << "': " << ours << " against " << theirs;
  }
}
#endif

// A program that changed its locale to one with a decimal comma reads the same numbers.
TEST(ReadDecimal, ReadsThePointWhateverTheLocale) {
  const std::string before = std::setlocale(LC_NUMERIC, nullptr);
  const char* comma = nullptr;
  for (const char* name : {"de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8", "de_DE", "German_Germany.1252"})
    if (std::setlocale(LC_NUMERIC, name)) {
      comma = name;
      break;
    }
  if (!comma) GTEST_SKIP() << "no locale with a decimal comma is installed (Debian: the locales package)";
  const Read r = read("2.5");
  std::setlocale(LC_NUMERIC, before.c_str());
  EXPECT_EQ(r.error, std::errc()) << comma;
  EXPECT_EQ(r.value, 2.5) << comma;
  EXPECT_EQ(r.length, 3) << comma;
}
