# GLM, stb and GoogleTest come from the system's packages (Debian: libglm-dev,
# libstb-dev, libgtest-dev). Nothing is downloaded: a missing package stops the
# configure step with one line that names it.

find_package(Threads REQUIRED)

find_package(glm CONFIG QUIET)
if(NOT TARGET glm::glm)
  message(FATAL_ERROR "GLM not found: install it with 'apt-get install libglm-dev'")
endif()

find_path(GI_STB_INCLUDE_DIR NAMES stb_image_write.h PATH_SUFFIXES stb)
if(NOT GI_STB_INCLUDE_DIR)
  message(FATAL_ERROR "stb not found: install it with 'apt-get install libstb-dev'")
endif()
add_library(gi_stb INTERFACE)
target_include_directories(gi_stb SYSTEM INTERFACE ${GI_STB_INCLUDE_DIR})

if(GI_BUILD_TESTS)
  find_package(GTest CONFIG QUIET)
  if(NOT TARGET GTest::gtest_main)
    message(FATAL_ERROR "GoogleTest not found: install it with 'apt-get install libgtest-dev'")
  endif()
  include(GoogleTest)
endif()
