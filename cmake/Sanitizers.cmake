# Sanitizer and fuzzing builds (used by .ci/sanitize). The flags go on every target this project
# compiles (our libraries, tests, fuzzers); the Debian libraries (Simbody, urdfdom, ...) stay
# uninstrumented, so ASan checks our code and the allocations it shares with them.
#
#   -DGRASPSIM_SANITIZE=address,undefined   sanitizers, comma-separated (empty: none)
#   -DGRASPSIM_FUZZ=ON                      also build the libFuzzer targets of tests/fuzz (clang)

set(GRASPSIM_SANITIZE "" CACHE STRING "Sanitizers for graspsim's own code, e.g. address,undefined (empty: none)")
option(GRASPSIM_FUZZ "Build the libFuzzer targets in tests/fuzz (needs clang)" OFF)

if(GRASPSIM_SANITIZE)
  # Every report is fatal, so a test that triggers one fails; -g1 gives reports file:line.
  add_compile_options(-fsanitize=${GRASPSIM_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer -g1)
  add_link_options(-fsanitize=${GRASPSIM_SANITIZE})
  # Code that redirects stderr (io/filtered_stderr.h) leaves it alone: a sanitizer report must
  # reach the terminal.
  add_compile_definitions(GRASPSIM_SANITIZED)
  if(GRASPSIM_SANITIZE MATCHES "undefined")
    # Two checks are exempted, each only in the Simbody header code that trips it (reasons in
    # cmake/ubsan-ignorelist.txt): 'bool' in SimTK::Value<bool>, whose default constructor leaves
    # the bool uninitialized before Simbody copies it with every State, and 'object-size' in
    # Simbody's small-matrix headers, whose strided row views nominally overrun the matrix.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
      # The older spelling of -fsanitize-ignorelist: ccache 4.7 (Debian 12) hashes the list's
      # content only for this one, so editing the list rebuilds rather than reusing stale objects.
      add_compile_options(-fsanitize-blacklist=${CMAKE_CURRENT_LIST_DIR}/ubsan-ignorelist.txt)
    else()
      # GCC has no per-function ignore list: the bool check goes for all code (GCC does not
      # report the object-size one).
      message(WARNING "GRASPSIM_SANITIZE with ${CMAKE_CXX_COMPILER_ID}: -fno-sanitize=bool everywhere "
                      "(use clang to exempt only SimTK::Value<bool>, see cmake/ubsan-ignorelist.txt)")
      add_compile_options(-fno-sanitize=bool)
    endif()
  endif()
endif()

if(GRASPSIM_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "GRASPSIM_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  # Coverage feedback for libFuzzer from all our code; only the fuzz targets link libFuzzer
  # itself (-fsanitize=fuzzer, tests/fuzz), the other programs get the sanitizers' no-op hooks.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
