# ARM64 Linux (the processor of Apple silicon, the Raspberry Pi 4 and 5, Graviton),
# built on an x86-64 Debian machine with Debian's cross compiler (g++-aarch64-linux-gnu)
# and run there by qemu-user (qemu-user): ctest, the lessons target and the tests'
# own runs of the lessons go through qemu-aarch64, with the ARM64 C library Debian
# installs in /usr/aarch64-linux-gnu. The aarch64 preset uses this file.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)  # GoogleTest's project asks for C as well
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)

set(CMAKE_FIND_ROOT_PATH /usr/aarch64-linux-gnu)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)  # programs (python3, qemu) are the build machine's
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

find_program(GI_QEMU_AARCH64 qemu-aarch64)
if(NOT GI_QEMU_AARCH64)
  message(FATAL_ERROR "qemu-aarch64 not found: install it with 'apt-get install qemu-user'")
endif()
set(CMAKE_CROSSCOMPILING_EMULATOR ${GI_QEMU_AARCH64} -L /usr/aarch64-linux-gnu)

# Debian's libgtest-dev is built for the build machine; its sources are built here instead.
set(GI_GTEST_SOURCE_DIR /usr/src/googletest CACHE PATH "GoogleTest's sources, built with the project")
