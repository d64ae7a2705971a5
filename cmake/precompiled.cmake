# The third-party and standard headers nearly every translation unit parses (Eigen, Boost's
# multiprecision numbers, fmt, the standard library; Catch2 and nlohmann's JSON in the tests): parsed
# once per kind of object and loaded by every target of that kind, rather than parsed again in each of
# some 250 objects (BENCHMARKS.md, "Build times"). Only headers of other
# projects: none of impact3d's, so that editing the library rebuilds no header image, and nothing a
# header image holds depends on a macro impact3d's targets set. One image per kind, for the compiler
# refuses an image made with other code-generation flags: position-independent code for the libraries
# (-fPIC where the Python module asks for it), executables' (-fPIE then), and the tests' set (their
# options, with Catch2 and JSON). In a fuzzers' tree the library image carries libFuzzer's coverage,
# as the libraries of IMPACT3D_FUZZ_COVERED and the harnesses do; the program's library, which does
# not, builds without an image.
option(IMPACT3D_PRECOMPILED_HEADERS "Precompile the common third-party headers (GCC, clang)" ON)
set(impact3d_precompiled_common
    <algorithm> <array> <atomic> <charconv> <cmath> <cstdint> <cstring> <filesystem> <fstream> <functional> <limits> <map>
    <memory> <optional> <random> <sstream> <stdexcept> <string> <string_view> <utility> <variant> <vector>
    <fmt/format.h> <Eigen/Core> <Eigen/Dense> <boost/math/constants/constants.hpp>)
if(IMPACT3D_MULTIPRECISION)
  # Not Boost's MPFR numbers: that header defines an object whose destructor calls MPFR, which every
  # program and library would then link, whether or not it computes with MPFR.
  list(APPEND impact3d_precompiled_common <boost/multiprecision/cpp_bin_float.hpp> <boost/multiprecision/cpp_int.hpp>
       <boost/multiprecision/float128.hpp>)
endif()
set(impact3d_precompiled_enabled OFF)
if(IMPACT3D_PRECOMPILED_HEADERS AND CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  set(impact3d_precompiled_enabled ON)
endif()

# The image of `kind` (library, executable, test), made by a target of its own on first use.
function(impact3d_precompiled_host kind)
  set(host impact3d_precompiled_${kind})
  if(TARGET ${host})
    return()
  endif()
  if(kind STREQUAL "library")
    add_library(${host} OBJECT ${PROJECT_SOURCE_DIR}/cmake/precompiled_host.cpp)
    if(IMPACT3D_BUILD_FUZZ)
      impact3d_fuzz_coverage(${host})
    endif()
  else()
    add_executable(${host} EXCLUDE_FROM_ALL ${PROJECT_SOURCE_DIR}/cmake/precompiled_main.cpp)
  endif()
  # Include directories only: a target linked here would bring its compile definitions. fmt's
  # (FMT_SHARED) are fmt's headers' own: the host and every target loading its image define them.
  target_compile_definitions(${host} PRIVATE $<TARGET_PROPERTY:fmt::fmt,INTERFACE_COMPILE_DEFINITIONS>)
  target_include_directories(${host} SYSTEM PRIVATE $<TARGET_PROPERTY:Eigen3::Eigen,INTERFACE_INCLUDE_DIRECTORIES>
                                                    $<TARGET_PROPERTY:fmt::fmt,INTERFACE_INCLUDE_DIRECTORIES>)
  set(headers ${impact3d_precompiled_common})
  if(kind STREQUAL "test")
    list(APPEND headers <catch2/catch.hpp> <nlohmann/json.hpp>)
    target_compile_options(${host} PRIVATE ${IMPACT3D_TEST_COMPILE_OPTIONS})  # the tests' own (CMakeLists.txt)
  endif()
  target_precompile_headers(${host} PRIVATE ${headers})
endfunction()

# `target` loads the image of its kind: a test program (linking the tests' main), another program, or
# a library's objects.
function(impact3d_precompiled target)
  if(NOT impact3d_precompiled_enabled)
    return()
  endif()
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "EXECUTABLE")
    set(kind executable)
    if(ARGV1 STREQUAL "test")
      set(kind test)
    endif()
  elseif(IMPACT3D_BUILD_FUZZ AND NOT (target IN_LIST IMPACT3D_FUZZ_COVERED OR target MATCHES "^harness_"))
    return()
  else()
    set(kind library)
  endif()
  impact3d_precompiled_host(${kind})
  target_precompile_headers(${target} REUSE_FROM impact3d_precompiled_${kind})
  target_compile_definitions(${target} PRIVATE $<TARGET_PROPERTY:fmt::fmt,INTERFACE_COMPILE_DEFINITIONS>)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # An image GCC refuses would leave the build correct and slow again, unnoticed (clang stops).
    target_compile_options(${target} PRIVATE -Werror=invalid-pch)
    if(kind STREQUAL "test")
      # GCC 12 loses the system-header status of the standard library's code inlined from an image, and
      # reports its string copies in the tests' strings (false positives the tests never showed).
      target_compile_options(${target} PRIVATE -Wno-stringop-overflow -Wno-stringop-overread)
    endif()
  endif()
endfunction()

# Every library and program of the current directory loads its kind's image (`kind` test: the tests'
# programs), but for the layer probes, whose compile errors are the test (tests/layers/), and the
# objects compiled for one instruction set (-m...), which the image is not made for.
function(impact3d_precompiled_directory)
  get_property(targets DIRECTORY PROPERTY BUILDSYSTEM_TARGETS)
  foreach(t IN LISTS targets)
    get_target_property(type ${t} TYPE)
    if(t MATCHES "^layer_probe_|^impact3d_precompiled_" OR NOT type MATCHES "^(EXECUTABLE|STATIC_LIBRARY|OBJECT_LIBRARY)$")
      continue()
    endif()
    if(ARGV0 STREQUAL "test" AND NOT type STREQUAL "EXECUTABLE")
      continue()  # the tests' main: Catch2's own code, compiled once
    endif()
    get_target_property(options ${t} COMPILE_OPTIONS)
    if(options MATCHES "(^|;)-m")
      continue()
    endif()
    impact3d_precompiled(${t} ${ARGV0})
  endforeach()
endfunction()
