# GLM, stb, nlohmann's JSON and GoogleTest come from the system's packages (Debian:
# libglm-dev, libstb-dev, nlohmann-json3-dev, libgtest-dev). Nothing is downloaded:
# a missing package stops the configure step with one line that names it.

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

# JSON reading: out/index.html is made from the lessons' outputs.json files, and the
# tests read the viewer's data back.
find_package(nlohmann_json 3 CONFIG QUIET)
if(NOT TARGET nlohmann_json::nlohmann_json)
  message(FATAL_ERROR "nlohmann's JSON not found: install it with 'apt-get install nlohmann-json3-dev'")
endif()

if(GI_BUILD_TESTS)
  find_package(GTest CONFIG QUIET)
  if(NOT TARGET GTest::gtest_main)
    message(FATAL_ERROR "GoogleTest not found: install it with 'apt-get install libgtest-dev'")
  endif()
  include(GoogleTest)
endif()
