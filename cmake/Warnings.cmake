# One interface target carries the project's compile flags, so every library,
# lesson and test is built the same way.
add_library(gi_flags INTERFACE)
target_compile_options(gi_flags INTERFACE -Wall -Wextra -Wpedantic)
# Maths functions need not set errno (nobody reads it): sqrt and floor can then be
# inlined instead of called. Results are unchanged -- this is not -ffast-math.
target_compile_options(gi_flags INTERFACE -fno-math-errno)
if(GI_WERROR)
  target_compile_options(gi_flags INTERFACE -Werror)
endif()
if(GI_SANITIZE)
  target_compile_options(gi_flags INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                                            -fno-sanitize-recover=undefined)
  target_link_options(gi_flags INTERFACE -fsanitize=address,undefined)
endif()
# GCC 12 reports false -Wstringop-overflow/-overread warnings inside libstdc++'s
# std::string when LTO inlines across files (GCC bugs 105329, 105651); they are
# silenced for the link step of optimised builds only.
target_link_options(gi_flags INTERFACE $<$<CONFIG:Release>:-Wno-stringop-overflow -Wno-stringop-overread>)
