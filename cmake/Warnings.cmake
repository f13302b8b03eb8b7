# One interface target carries the project's compile flags, so every library,
# lesson and test is built the same way.
add_library(gi_flags INTERFACE)
target_compile_options(gi_flags INTERFACE -Wall -Wextra -Wpedantic)
# A backslash at the end of a // comment, even with blanks after it, splices the next
# line into the comment: code that seems to run does not, or text that seems commented
# out runs. Always an error, so that the compiler and the grader's text check of the
# exercise regions (exercises/tools/cpp_text.py, which splices as GCC does) never
# disagree about what a region holds.
target_compile_options(gi_flags INTERFACE -Werror=comment)
# Maths functions need not set errno (nobody reads it): sqrt and floor can then be
# inlined instead of called. Results are unchanged -- this is not -ffast-math.
target_compile_options(gi_flags INTERFACE -fno-math-errno)
# No fused multiply-add behind the code's back: a * b + c is rounded twice, as written,
# on every processor. ARM64 (and x86-64 built for FMA) would otherwise fuse it into
# one rounding where the compiler sees fit, so the pictures would differ in their last
# bits from x86-64's, and the four-lane sphere test from the scalar one it must equal.
# The x86-64 baseline has no FMA: there this changes nothing.
target_compile_options(gi_flags INTERFACE -ffp-contract=off)
if(GI_PORTABLE_SIMD)
  target_compile_definitions(gi_flags INTERFACE GI_PORTABLE_SIMD)
endif()
# Library, lessons, tests and exercises alike: gi::wide is part of the library's
# interface (quadrature.hpp), so every file must agree on what it is.
if(GI_WIDE_IS_DOUBLE)
  target_compile_definitions(gi_flags INTERFACE GI_WIDE_IS_DOUBLE)
endif()
if(GI_WERROR)
  target_compile_options(gi_flags INTERFACE -Werror)
endif()
if(GI_SANITIZE)
  # At -O1 rather than the debug build's -O0: the sanitized suite runs twice as fast,
  # and AddressSanitizer still reports each bad access at its line (its own
  # documentation suggests -O1 for the same reason). Line tables only (-g1): the
  # reports' file:line is all the sanitizers read, and objects a third the size of
  # full debug information compile and link sooner.
  target_compile_options(gi_flags INTERFACE -O1 -g1 -fsanitize=address,undefined -fno-omit-frame-pointer
                                            -fno-sanitize-recover=undefined)
  target_link_options(gi_flags INTERFACE -fsanitize=address,undefined)
endif()
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION MATCHES "^12\\.")
  # GCC 12 reports false -Wstringop-overflow/-overread warnings inside libstdc++'s
  # std::string when LTO inlines across files (GCC bugs 105329, 105651); they are
  # silenced for the link step of optimised builds only.
  target_link_options(gi_flags INTERFACE $<$<CONFIG:Release>:-Wno-stringop-overflow -Wno-stringop-overread>)
  # The same false warnings at compile time, and a false -Warray-bounds of the same
  # std::string code ("forming offset [32, 39] is out of the bounds [0, 32]"): GCC
  # reports them inside the standard library's headers when it reads those from a
  # precompiled header, where it would otherwise keep quiet. Only where headers are
  # precompiled (cmake/PrecompiledHeaders.cmake): the sanitizer build and Clang still warn.
  if(GI_PCH)
    target_compile_options(gi_flags INTERFACE -Wno-stringop-overflow -Wno-stringop-overread -Wno-array-bounds)
  endif()
  # And a false -Wrestrict where std::string's operator+ is inlined at -O2 and -O3
  # ("accessing 9223372036854775810 or more bytes ... may overlap", GCC bug 105329):
  # silenced for GCC 12's optimised builds only; Clang and GCC's debug builds still warn.
  target_compile_options(gi_flags INTERFACE $<$<CONFIG:Release>:-Wno-restrict>)
endif()
