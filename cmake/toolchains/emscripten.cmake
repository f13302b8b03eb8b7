# WebAssembly, built by Emscripten's em++ (Debian: apt-get install emscripten). Each
# lesson becomes one file, build/wasm/bin/01_rays.js, which two hosts run:
#
#   node docs/live/node_run.js build/wasm/bin/01_rays.js --out /tmp/out/01_rays
#
# writes the same files the native program writes, on the real file system; and the
# lesson's page in a browser (docs/live/, made by the `live_pages` target) runs the
# same file in a Web Worker, on an in-memory file system. The wasm preset uses this file.
#
# Emscripten's own CMake platform file does the work (compilers, the .js suffix, its
# sysroot); this file finds it and adds what the lessons need:
#   -fexceptions      a bad option is reported by a thrown OptionError; Emscripten's
#                     default aborts at the first throw instead of catching it
#   SINGLE_FILE       the .wasm module is kept inside the .js file: the default loader
#                     fetches a separate .wasm by URL, which fails under Node.js 20 and
#                     in a page opened from file://
#   MODULARIZE        the file defines one function, gi_lesson(settings), that starts
#                     a fresh run each time it is called: the arguments, where printed
#                     lines go, and what to do before main (node_run.js mounts the real
#                     file system there; the page writes the reference pictures)
#   ENVIRONMENT       runs in a page's Web Worker and in Node.js
#   FS, -lnodefs.js   the in-memory file system, handed to the host, and Node.js's
#                     (used only under Node.js)
#   ALLOW_MEMORY_GROWTH  a lesson takes the memory it needs, as a native program does
#   EXIT_RUNTIME      main's return value is the run's exit status, in both hosts
# No -pthread: the programs run single-threaded, and gi::parallel_for runs every task
# on the calling thread (lib/gi/core/parallel.cpp).
if(NOT GI_EMSCRIPTEN_PLATFORM_FILE)
  find_program(GI_EM_CONFIG em-config)
  if(GI_EM_CONFIG)
    execute_process(COMMAND ${GI_EM_CONFIG} EMSCRIPTEN_ROOT OUTPUT_VARIABLE gi_emscripten_root
                    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  endif()
  find_file(GI_EMSCRIPTEN_PLATFORM_FILE Emscripten.cmake
            PATHS ${gi_emscripten_root} $ENV{EMSDK}/upstream/emscripten /usr/share/emscripten /usr/lib/emscripten
            PATH_SUFFIXES cmake/Modules/Platform NO_DEFAULT_PATH)
  if(NOT GI_EMSCRIPTEN_PLATFORM_FILE)
    message(FATAL_ERROR "Emscripten not found: install it with 'apt-get install emscripten' "
                        "(elsewhere: emsdk, and its emsdk_env.sh sourced)")
  endif()
endif()
include(${GI_EMSCRIPTEN_PLATFORM_FILE})

set(CMAKE_CXX_FLAGS_INIT "-fexceptions")
set(CMAKE_EXE_LINKER_FLAGS_INIT
    "-fexceptions -sSINGLE_FILE=1 -sMODULARIZE=1 -sEXPORT_NAME=gi_lesson -sENVIRONMENT=web,worker,node \
-sFORCE_FILESYSTEM=1 -sEXPORTED_RUNTIME_METHODS=FS -lnodefs.js -sALLOW_MEMORY_GROWTH=1 -sEXIT_RUNTIME=1")
# -O2, not the -O3 of a native Release build: at -O3 Emscripten's link also runs
# Binaryen's slowest passes, for little speed in these programs.
set(CMAKE_CXX_FLAGS_RELEASE "-O2 -DNDEBUG" CACHE STRING "Flags of a Release build (WebAssembly: -O2)")

# The .js programs run under Node.js, through docs/live/node_run.js: ctest, the lessons
# target and the tests' own runs of the lessons start them that way.
find_program(GI_NODE node)
if(NOT GI_NODE)
  message(FATAL_ERROR "node not found: install it with 'apt-get install nodejs'")
endif()
get_filename_component(gi_node_run ${CMAKE_CURRENT_LIST_DIR}/../../docs/live/node_run.js ABSOLUTE)
set(CMAKE_CROSSCOMPILING_EMULATOR ${GI_NODE} ${gi_node_run})
