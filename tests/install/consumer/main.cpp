// Reads a case with the installed library and prints the first strategy's normal impulse.
#include <fstream>
#include <iostream>
#include <sstream>

#include "impact3d/case_format/read_case.hpp"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  std::ifstream in(argv[1]);
  std::stringstream ss;
  ss << in.rdbuf();
  const auto spec = impact3d::case_format::read_case(ss.str());
  const auto a = impact3d::analyze(impact3d::case_format::to_scene<double>(spec), impact3d::case_format::to_strategies<double>(spec));
  std::cout << impact3d::case_format::scalar_to_text(a.solutions.at(0).impulse.P_C.x()) << "\n";
  return 0;
}
