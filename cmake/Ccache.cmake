# Compile through ccache when it is installed. base_dir makes the cache key use paths
# relative to the source tree, so a fresh clone in another directory (CI) hits the cache
# that an earlier build filled.
find_program(CCACHE_PROGRAM ccache)
option(WIREGRAIN_USE_CCACHE "Compile through ccache when found" ON)
if(CCACHE_PROGRAM AND WIREGRAIN_USE_CCACHE)
  set(_ccache_launcher
      ${CMAKE_COMMAND} -E env
      CCACHE_BASEDIR=${CMAKE_SOURCE_DIR}
      CCACHE_NOHASHDIR=1
      CCACHE_SLOPPINESS=time_macros,include_file_mtime,include_file_ctime
      ${CCACHE_PROGRAM})
  set(CMAKE_C_COMPILER_LAUNCHER ${_ccache_launcher})
  set(CMAKE_CXX_COMPILER_LAUNCHER ${_ccache_launcher})
  message(STATUS "wiregrain: compiling through ${CCACHE_PROGRAM}")
endif()
