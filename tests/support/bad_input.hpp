// The malformed-input corpus (tests/program/bad_input/): each file's line, which the program prints
// after "impact3d: error: FILE: ", from expected.tsv (reviewed by hand).
#pragma once

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace impact3d::test {

inline std::map<std::string, std::string> expected_lines() {
  std::map<std::string, std::string> m;
  std::ifstream in(std::filesystem::path(IMPACT3D_BAD_INPUT_DIR) / "expected.tsv");
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const auto tab = line.find('\t');
    m[line.substr(0, tab)] = line.substr(tab + 1);
  }
  return m;
}

}  // namespace impact3d::test
