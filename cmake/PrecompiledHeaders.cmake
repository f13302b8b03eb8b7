# Precompiled headers: most of a file's compile time here is reading headers, not
# compiling its own code. A test file at -O3 takes 2.9 s, of which 1.8 s is parsing, and
# 1.5 s of that is GoogleTest and exercises/support/print.hpp alone; a library file
# spends about four fifths of its compile parsing the standard library and GLM.
# Each kind of program reads its heavy headers once from one precompiled file:
#
#   gi_precompile(TARGET library)  the library's topics: GLM and the standard library
#                                  (never a header of lib/, so that a file the grader
#                                  stubs is read afresh); library_plain and lessons, the
#                                  same for the topics compiled without link-time
#                                  optimisation and for the lessons and benches (each
#                                  kind is compiled with flags of its own)
#   gi_precompile(TARGET tests)    the unit tests: GoogleTest and support/print.hpp, which
#                                  every test file sees first
#   gi_precompile(TARGET graded)   the labs' graded programs: GoogleTest only (the lab's
#                                  headers are read as the student wrote them)
#
# The first target of a kind makes the precompiled header; the others reuse it (they
# are compiled with the same flags).
#
# On by default in Release builds and in every Clang build (-DGI_PCH=ON/OFF to choose;
# the trees the grader and the mutant suite build at -O1 turn it on). GCC reports,
# inside the standard library's headers read from a precompiled header, false warnings
# that it keeps quiet when it reads them as text; cmake/Warnings.cmake silences those
# where headers are precompiled. GCC's sanitizer build, which treats warnings as errors
# in CI, reads every header as text and keeps every warning; Clang warns alike either
# way, so its sanitizer build (CI's) reads them precompiled. Off on a Windows host,
# where GCC's precompiled headers can fail to load at another address ("had to
# relocate PCH").
# The mutant suite compiles a mutated file with a precompiled preamble of its own in
# place of this one (exercises/tools/overlay.py, without_cmake_pch).
if((CMAKE_BUILD_TYPE STREQUAL "Release" OR CMAKE_CXX_COMPILER_ID MATCHES "Clang") AND NOT CMAKE_HOST_WIN32)
  option(GI_PCH "Precompiled headers for the library, the lessons and the tests" ON)
else()
  option(GI_PCH "Precompiled headers for the library, the lessons and the tests" OFF)
endif()

set(gi_pch_library <glm/glm.hpp> <algorithm> <array> <cmath> <cstdint> <functional> <iostream>
    <limits> <memory> <optional> <sstream> <string> <utility> <vector>)
set(gi_pch_library_plain ${gi_pch_library})  # the topics not optimised across files
set(gi_pch_lessons ${gi_pch_library})  # the lessons and benches (LTO's intermediate code only)
set(gi_pch_tests <gtest/gtest.h> ${PROJECT_SOURCE_DIR}/exercises/support/print.hpp)
set(gi_pch_graded <gtest/gtest.h>)

function(gi_precompile target kind)
  if(NOT GI_PCH)
    return()
  endif()
  get_property(owner GLOBAL PROPERTY GI_PCH_OWNER_${kind})
  if(owner)
    target_precompile_headers(${target} REUSE_FROM ${owner})
  else()
    target_precompile_headers(${target} PRIVATE ${gi_pch_${kind}})
    set_property(GLOBAL PROPERTY GI_PCH_OWNER_${kind} ${target})
  endif()
endfunction()
