# ccache, when it is installed and no other launcher is named: a second build of the
# same sources (CI on a machine that has built the tree, a student switching branches
# and back) takes its objects from the cache instead of compiling them again.
# -DGI_CCACHE=OFF turns it off.
#
# Depend mode: on a miss ccache hashes the headers the compiler reports (-MD) instead of
# running the preprocessor first, so a cold build costs what it costs without ccache
# (measured: +10% per test file without it). The sloppiness lets it cache the files
# that read a precompiled header.
option(GI_CCACHE "Compile through ccache when it is installed" ON)
if(GI_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  find_program(GI_CCACHE_PROGRAM ccache)
  if(GI_CCACHE_PROGRAM)
    set(CMAKE_CXX_COMPILER_LAUNCHER ${CMAKE_COMMAND} -E env CCACHE_DEPEND=1
        CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime ${GI_CCACHE_PROGRAM})
  endif()
endif()
