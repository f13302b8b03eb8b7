# GLM, stb, nlohmann's JSON and GoogleTest come from the system's packages (Debian:
# libglm-dev, libstb-dev, nlohmann-json3-dev, libgtest-dev; macOS: Homebrew's glm,
# nlohmann-json and googletest, and stb's two headers in a folder named by
# GI_STB_INCLUDE_DIR). Nothing is downloaded: a missing package stops the configure step
# with one line that names it.

find_package(Threads REQUIRED)

# A cross build (cmake/toolchains/) compiles for another system, whose headers are not
# the build machine's /usr/include. GLM, stb and nlohmann's JSON are headers only, so
# the build machine's packages serve any target: each is shown to the compiler through
# a folder of its own (a link to it), never /usr/include as a whole, which holds the
# build machine's C library.
function(gi_host_headers target folder)
  set(view ${CMAKE_BINARY_DIR}/host-headers/${target})
  if(NOT EXISTS /usr/include/${folder})
    return()
  endif()
  file(MAKE_DIRECTORY ${view})
  if(NOT EXISTS ${view}/${folder})
    file(CREATE_LINK /usr/include/${folder} ${view}/${folder} SYMBOLIC)
  endif()
  set(${target}_HOST_VIEW ${view} PARENT_SCOPE)
endfunction()

# The imported target a package's CMake files would have made, from the build
# machine's headers, when a cross build's own search found none.
function(gi_host_header_target target folder)
  if(NOT TARGET ${target} AND CMAKE_CROSSCOMPILING)
    gi_host_headers(${folder} ${folder})
    if(${folder}_HOST_VIEW)
      add_library(${target} INTERFACE IMPORTED)
      target_include_directories(${target} SYSTEM INTERFACE ${${folder}_HOST_VIEW})
    endif()
  endif()
endfunction()

find_package(glm CONFIG QUIET)
gi_host_header_target(glm::glm glm)
if(NOT TARGET glm::glm)
  message(FATAL_ERROR "GLM not found: install it with 'apt-get install libglm-dev' (macOS: 'brew install glm')")
endif()

if(CMAKE_CROSSCOMPILING AND NOT GI_STB_INCLUDE_DIR)
  gi_host_headers(stb stb)
  if(stb_HOST_VIEW)
    set(GI_STB_INCLUDE_DIR ${stb_HOST_VIEW}/stb CACHE PATH "The folder holding stb_image.h and stb_image_write.h")
  endif()
endif()
find_path(GI_STB_INCLUDE_DIR NAMES stb_image_write.h PATH_SUFFIXES stb)
if(NOT GI_STB_INCLUDE_DIR)
  message(FATAL_ERROR "stb not found: install it with 'apt-get install libstb-dev' (elsewhere: put stb_image.h and "
                      "stb_image_write.h from github.com/nothings/stb in a folder and name it with "
                      "-DGI_STB_INCLUDE_DIR=FOLDER)")
endif()
add_library(gi_stb INTERFACE)
target_include_directories(gi_stb SYSTEM INTERFACE ${GI_STB_INCLUDE_DIR})

# JSON reading: out/index.html is made from the lessons' outputs.json files, and the
# tests read the viewer's data back.
find_package(nlohmann_json 3 CONFIG QUIET)
gi_host_header_target(nlohmann_json::nlohmann_json nlohmann)
if(NOT TARGET nlohmann_json::nlohmann_json)
  message(FATAL_ERROR "nlohmann's JSON not found: install it with 'apt-get install nlohmann-json3-dev' "
                      "(macOS: 'brew install nlohmann-json')")
endif()

# GoogleTest: the installed library, or built here from its sources where the installed
# one was made for another standard library (libc++) or another system (a cross build):
# GI_GTEST_SOURCE_DIR names them (Debian's googletest package puts them in
# /usr/src/googletest; the presets that need it set it).
if(GI_BUILD_TESTS)
  set(GI_GTEST_SOURCE_DIR "" CACHE PATH "Build GoogleTest from these sources instead of using the installed library")
  if(GI_GTEST_SOURCE_DIR)
    if(NOT EXISTS ${GI_GTEST_SOURCE_DIR}/CMakeLists.txt)
      message(FATAL_ERROR "GoogleTest's sources not found in ${GI_GTEST_SOURCE_DIR}: install them with "
                          "'apt-get install googletest'")
    endif()
    set(BUILD_GMOCK OFF CACHE BOOL "" FORCE)
    set(INSTALL_GTEST OFF CACHE BOOL "" FORCE)
    add_subdirectory(${GI_GTEST_SOURCE_DIR} ${CMAKE_BINARY_DIR}/googletest EXCLUDE_FROM_ALL SYSTEM)
    # GoogleTest's own std::string code meets GCC 12's false -Wrestrict as ours does
    # (cmake/Warnings.cmake says which): silenced there too, for optimised builds only.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION MATCHES "^12\\.")
      target_compile_options(gtest PRIVATE $<$<CONFIG:Release>:-Wno-restrict>)
    endif()
  else()
    find_package(GTest CONFIG QUIET)
  endif()
  if(NOT TARGET GTest::gtest_main)
    message(FATAL_ERROR "GoogleTest not found: install it with 'apt-get install libgtest-dev' "
                        "(macOS: 'brew install googletest')")
  endif()
  include(GoogleTest)
endif()
