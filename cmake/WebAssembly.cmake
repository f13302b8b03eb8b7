# What a WebAssembly build (cmake/toolchains/emscripten.cmake, the wasm preset) needs
# beyond the toolchain file: read only when CMAKE_SYSTEM_NAME is Emscripten.
#
# An optimised link (-O1 and above) runs Emscripten's JavaScript optimiser, a Node.js
# script that needs the parser `acorn`. Debian's emscripten package brings it as
# node-acorn, in /usr/share/nodejs, where Debian's own Node.js looks but a Node.js
# from elsewhere (nodejs.org, NodeSource) does not; a copy in the build folder
# (npm install --prefix build/wasm acorn) serves any Node.js. The first folder below
# that holds it is given to each link as NODE_PATH; without one, the configure step
# stops with one line saying how to get it (a link would fail later with "Cannot find
# module 'acorn'").
set(gi_node_path_candidates ${CMAKE_BINARY_DIR}/node_modules)
if(DEFINED ENV{NODE_PATH})
  string(REPLACE ":" ";" gi_env_node_path "$ENV{NODE_PATH}")
  list(APPEND gi_node_path_candidates ${gi_env_node_path})
endif()
list(APPEND gi_node_path_candidates /usr/share/nodejs)
if(NOT GI_ACORN_NODE_PATH OR NOT EXISTS ${GI_ACORN_NODE_PATH}/acorn)
  unset(GI_ACORN_NODE_PATH CACHE)
  foreach(folder ${gi_node_path_candidates})
    execute_process(COMMAND ${CMAKE_COMMAND} -E env NODE_PATH=${folder} ${GI_NODE} -e "require('acorn')"
                    RESULT_VARIABLE found OUTPUT_QUIET ERROR_QUIET)
    if(found EQUAL 0)
      set(GI_ACORN_NODE_PATH ${folder} CACHE PATH "The folder holding Node.js's acorn, for Emscripten's optimised links")
      break()
    endif()
  endforeach()
endif()
if(NOT GI_ACORN_NODE_PATH)
  message(FATAL_ERROR "acorn (for Emscripten's optimised links) not found: install it with "
                      "'npm install --prefix ${CMAKE_BINARY_DIR} acorn' (Debian: 'apt-get install node-acorn')")
endif()
set(CMAKE_CXX_LINKER_LAUNCHER ${CMAKE_COMMAND} -E env NODE_PATH=${GI_ACORN_NODE_PATH})
