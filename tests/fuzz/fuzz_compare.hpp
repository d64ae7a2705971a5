// The compare harnesses: the fuzzed bytes become the other tool's results file, compared against a
// reference result of the suite, and then the reference itself; bad input must be one CaseError, never
// a crash or a leak of memory.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/verification/compare.hpp"

inline int fuzz_compare(const std::uint8_t* data, std::size_t size, const char* extension) {
  static const bool quiet = std::freopen("/dev/null", "w", stdout) != nullptr;  // compare prints its table
  (void)quiet;
  const std::string path = "/tmp/impact3d-fuzz-" + std::to_string(::getpid()) + extension;
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  try {
    impact3d::verification::CompareOptions o;
    (void)impact3d::verification::compare(IMPACT3D_FUZZ_REFERENCE, path, o);
    o.subset = true;
    (void)impact3d::verification::compare(IMPACT3D_FUZZ_REFERENCE, path, o);
  } catch (const impact3d::case_format::CaseError&) {
  }
  try {
    (void)impact3d::verification::compare(path, IMPACT3D_FUZZ_REFERENCE, impact3d::verification::CompareOptions{});
  } catch (const impact3d::case_format::CaseError&) {
  }
  std::remove(path.c_str());
  return 0;
}
