#pragma once
// gi::wide, the type for sums that want more digits than double: long double, which
// on x86-64 with GCC or Clang keeps a 64-bit mantissa (three decimal digits more than
// double). On Apple silicon and with MSVC long double is double itself; a build with
// GI_WIDE_IS_DOUBLE (the CMake option of that name) computes as those machines do,
// so that the code written with gi::wide is tested there too.
//
// The contract of every function that uses it: its stated accuracy holds in double.
// The extra digits, where they exist, are a margin, never something a result needs.
#include <numbers>

namespace gi {

#ifdef GI_WIDE_IS_DOUBLE
using wide = double;
#else
using wide = long double;
#endif

inline constexpr wide pi_wide = std::numbers::pi_v<wide>;

}  // namespace gi
