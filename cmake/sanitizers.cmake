# Sanitizer and fuzzing builds (docs/fuzzing.md). Flags go on every target, so the libraries the
# tests and fuzz targets link are checked too, not only the test code.
set(RADIANT_SANITIZE "" CACHE STRING
  "Sanitizers for every target: address,undefined or thread (empty: none)")
option(RADIANT_FUZZ "Build the libFuzzer targets in tests/fuzz (clang; implies address,undefined)"
  OFF)

if(RADIANT_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "RADIANT_FUZZ needs clang (libFuzzer): -DCMAKE_CXX_COMPILER=clang++")
  endif()
  if(NOT RADIANT_SANITIZE)
    set(RADIANT_SANITIZE address,undefined)
  endif()
  # Coverage for libFuzzer in every library; only the fuzz targets link libFuzzer's main, so the
  # unit tests of the same build run as an ASan+UBSan build.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

if(RADIANT_SANITIZE)
  # A finding stops the test that caused it (UBSan would otherwise print and go on).
  add_compile_options(-fsanitize=${RADIANT_SANITIZE} -fno-sanitize-recover=all
    -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${RADIANT_SANITIZE})
endif()
