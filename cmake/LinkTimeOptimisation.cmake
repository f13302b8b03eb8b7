# Link-time optimisation (LTO) for the programs whose speed is measured, and quick
# links for everything else.
#
# gi_fast_code(TARGET): the library's topics that run in inner loops.
# gi_fast_program(TARGET): the lessons and the benches.
# gi_plain_link(TARGET): the unit tests and the graded programs.
#
# With GCC the objects of the library's inner-loop topics (lib/CMakeLists.txt) are
# "fat": each holds GCC's intermediate code, which an LTO link optimises across files,
# and ordinary machine code, which a plain link uses as it is. A lesson's link then
# optimises the whole program while a test's link (-fno-lto) only joins the objects: a
# few tenths of a second instead of a lesson's 8 to 22. Clang has no fat objects, so
# there the whole Release build links with LTO (GI_LTO=OFF turns it off).
include(CheckIPOSupported)
check_ipo_supported(RESULT gi_ipo_supported LANGUAGES CXX)
set(gi_lto OFF)
if(gi_ipo_supported AND GI_LTO AND CMAKE_BUILD_TYPE STREQUAL "Release")
  set(gi_lto ON)
endif()
set(gi_fat_lto OFF)
if(gi_lto AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  set(gi_fat_lto ON)
  # What CMake adds to an LTO target's compile line: fat objects instead of its
  # default -fno-fat-lto-objects.
  set(CMAKE_CXX_COMPILE_OPTIONS_IPO -flto=auto -ffat-lto-objects)
elseif(gi_lto)
  set(CMAKE_INTERPROCEDURAL_OPTIMIZATION_RELEASE ON)
endif()

function(gi_fast_code target)
  if(gi_fat_lto)
    set_property(TARGET ${target} PROPERTY INTERPROCEDURAL_OPTIMIZATION ON)
  endif()
endfunction()

# gi_plain_code(SOURCE...): files of a fast topic that only set a program up. Compiled
# to machine code alone, a lesson's link takes them as they are: it would gain nothing
# by optimising them again (scene files and their JSON alone are a third of what each
# lesson's link would otherwise optimise).
function(gi_plain_code)
  if(gi_lto)
    set_property(SOURCE ${ARGN} APPEND PROPERTY COMPILE_OPTIONS -fno-lto)
  endif()
endfunction()

# gi_fast_program(TARGET): a lesson or a bench. Its own objects are only ever linked
# with LTO, so they hold GCC's intermediate code alone ("slim"): their machine code
# would never be used (a lesson's file compiles in about 40% less time).
function(gi_fast_program target)
  gi_fast_code(${target})
  if(gi_fat_lto)
    target_compile_options(${target} PRIVATE -fno-fat-lto-objects)
  endif()
endfunction()

function(gi_plain_link target)
  if(gi_fat_lto)
    # Without it GCC's linker plugin would find the intermediate code in the
    # library's objects and optimise the whole test program anyway.
    target_link_options(${target} PRIVATE -fno-lto)
  endif()
endfunction()
