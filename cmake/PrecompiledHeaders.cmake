# Precompiled headers. Parsing the standard library, nlohmann/json and GLM is about 5 s of a
# typical file's 12 s compile here (tests/core/parameters_test.cpp: 5.1 s for its includes alone,
# 12.1 s in all at -O2), and nearly every file includes them: each target parses them once into
# a precompiled header instead. -DLPVLAB_PRECOMPILED_HEADERS=OFF compiles every file on its own
# includes (a missing #include then shows; the headers below hide one).
option(LPVLAB_PRECOMPILED_HEADERS "Precompile the headers most files include, once per target" ON)

set(LPVLAB_COMMON_HEADERS
    <algorithm> <array> <cmath> <cstddef> <cstdint> <filesystem> <fstream> <functional>
    <iostream> <map> <memory> <optional> <random> <sstream> <string> <vector>
    <glm/glm.hpp> <nlohmann/json.hpp>)

# lpvlab_precompile(<target> [TESTS] [OWN]): the common headers (and GoogleTest's for TESTS) as the
# C++ target's precompiled header, compiled once for all libraries (by lpvlab_core) and once for
# all test binaries (by test_core) and reused: those targets share their compile flags, and none
# of lpvlab's definitions is read by these headers. OWN: the target compiles its own, for a
# target with flags of its own (clang refuses a precompiled header built with other language
# options, such as -fopenmp-simd or a sanitizer left out).
function(lpvlab_precompile target)
  cmake_parse_arguments(P "TESTS;OWN" "" "" ${ARGN})
  if(NOT LPVLAB_PRECOMPILED_HEADERS)
    return()
  endif()
  if(P_TESTS)
    set(owner test_core)
    set(headers ${LPVLAB_COMMON_HEADERS} <gtest/gtest.h>)
  else()
    set(owner lpvlab_core)
    set(headers ${LPVLAB_COMMON_HEADERS})
  endif()
  if(target STREQUAL owner OR P_OWN)
    target_precompile_headers(${target} PRIVATE ${headers})
  else()
    target_precompile_headers(${target} REUSE_FROM ${owner})
  endif()
endfunction()
