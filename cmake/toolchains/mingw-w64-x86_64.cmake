# 64-bit Windows, built on a Debian machine with MinGW-w64's GCC in its POSIX-threads
# variant (g++-mingw-w64-x86-64-posix: std::thread needs it) and run there by Wine
# (wine64): ctest, the lessons target and the tests run the .exe files through wine.
# The programs are linked statically, so that they need no DLL beside them. The mingw
# preset uses this file.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_C_COMPILER x86_64-w64-mingw32-gcc-posix)  # GoogleTest's project asks for C as well
set(CMAKE_CXX_COMPILER x86_64-w64-mingw32-g++-posix)
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)

set(CMAKE_FIND_ROOT_PATH /usr/x86_64-w64-mingw32)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)  # programs (python3, wine) are the build machine's
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

set(CMAKE_EXE_LINKER_FLAGS_INIT -static)

find_program(GI_WINE wine)
if(NOT GI_WINE)
  message(FATAL_ERROR "wine not found: install it with 'apt-get install wine64'")
endif()
# Quiet (Wine's own diagnostics off), and no offer to install .NET or a browser engine
# when Wine makes its prefix on the first run.
set(CMAKE_CROSSCOMPILING_EMULATOR /usr/bin/env WINEDEBUG=-all WINEDLLOVERRIDES=mscoree,mshtml= ${GI_WINE})

# Debian's libgtest-dev is built for Linux; its sources are built here instead.
set(GI_GTEST_SOURCE_DIR /usr/src/googletest CACHE PATH "GoogleTest's sources, built with the project")
