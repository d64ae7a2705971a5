// Reads a case with the installed library and prints the first strategy's normal impulse.
#include <fstream>
#include <iostream>
#include <sstream>

#include "impact3d/io/read_case.hpp"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  std::ifstream in(argv[1]);
  std::stringstream ss;
  ss << in.rdbuf();
  const auto spec = impact3d::io::read_case(ss.str());
  const auto a = impact3d::analyze(impact3d::io::to_scene<double>(spec), impact3d::io::to_strategies<double>(spec));
  std::cout << impact3d::io::scalar_to_text(a.solutions.at(0).impulse.P_C.x()) << "\n";
  return 0;
}
