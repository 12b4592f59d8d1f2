# Reliability builds (docs/reliability.md), each in a build directory of its own:
#   -DPENUMBRA_SANITIZE=address,undefined   host code and its tests under ASan + UBSan (g++ or
#                                           clang); viz tests are left out
#   -DPENUMBRA_FUZZ=ON                      libFuzzer targets in tests/fuzz (needs clang: the
#                                           main build's g++ has no libFuzzer)
set(PENUMBRA_SANITIZE "" CACHE STRING "Sanitizers for host code and tests, e.g. address,undefined")
option(PENUMBRA_FUZZ "Build the libFuzzer targets (clang only)" OFF)

if(PENUMBRA_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "PENUMBRA_FUZZ needs clang (CXX=clang++-14); this is "
                        "${CMAKE_CXX_COMPILER_ID}")
  endif()
  # Every object is instrumented for coverage and checked by ASan + UBSan; only the fuzz targets
  # link libFuzzer's main.
  if(NOT PENUMBRA_SANITIZE)
    set(PENUMBRA_SANITIZE address,undefined)
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

if(PENUMBRA_SANITIZE)
  # A UB report stops the test (no recovery), so ctest sees it as a failure, not a log line.
  add_compile_options(-fsanitize=${PENUMBRA_SANITIZE} -fno-sanitize-recover=all
                      -fno-omit-frame-pointer)
  # A report names the file and line of every frame, which needs only the line tables: clang
  # writes those alone (-gline-tables-only, the last -g flag wins over the build type's -g), and
  # compiles about an eighth faster than with the full debug information; g++ keeps -g.
  add_compile_options($<IF:$<CXX_COMPILER_ID:Clang>,-gline-tables-only,-g>)
  add_link_options(-fsanitize=${PENUMBRA_SANITIZE})
  if(PENUMBRA_SANITIZE MATCHES "address" AND PENUMBRA_SANITIZE MATCHES "undefined")
    # UBSan's object-size check, beside ASan: ASan's redzones already catch an access past a heap,
    # stack or global object at run time, while the check's instrumentation keeps clang from
    # inlining Eigen's expression templates, which makes the host tests several times slower
    # (docs/reliability.md).
    add_compile_options(-fno-sanitize=object-size)
  endif()
  # UBSan's alignment, null and pointer-overflow checks together make Eigen's small expression
  # functions (a row's `+=`, a dot product) too large for clang's inliner, so each becomes a call
  # in the host library's hot loops. Eigen inlines them by force there, as it does on MSVC: the
  # checks stay, inlined with the code they guard, and the sanitized ctest takes 0.6 of the time
  # (docs/reliability.md). The library only: the tests' own code is not where the time goes, and
  # forcing it there compiles them 40 % slower. Clang only, where it was measured: g++ treats an
  # always_inline it cannot honour as an error.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    set(PENUMBRA_SANITIZE_HOST_DEFINITIONS
        "EIGEN_STRONG_INLINE=__attribute__((always_inline)) inline")
  endif()
  # Every program that links the host library (penumbra, the tests, the fuzzers, the benches)
  # starts with the sanitizer options of tests/sanitizer_defaults.cpp.
  set(PENUMBRA_SANITIZER_DEFAULTS ${CMAKE_SOURCE_DIR}/tests/sanitizer_defaults.cpp)
endif()
