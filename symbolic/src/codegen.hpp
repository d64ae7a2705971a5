// C++ kernels and LaTeX from canonical expressions: common subexpressions hoisted into temporaries named
// in order of first use, constants as exact Scalar(p)/Scalar(q), math through using-declarations.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

namespace impact3d::symbolic {

struct KernelArg {
  std::string decl;  // "const Mat3<Scalar>& K"
  std::string doc;   // "coefficient matrix of eq 9 (3x3)"
};

struct Kernel {
  std::string name;
  std::string doc;                                      // what it computes, from which equations
  std::string returns;                                  // C++ return type, e.g. "Vec3<Scalar>"
  std::string returns_doc;
  std::vector<KernelArg> args;
  std::map<std::string, std::string> symbol_code;       // GiNaC symbol name -> C++ expression
  // Named intermediate results, in order (the names must also be in symbol_code).
  std::vector<std::pair<std::string, GiNaC::ex>> locals;
  std::vector<std::pair<std::string, GiNaC::ex>> outputs;  // "out(0)" -> expression
};

// The whole function template, with its docstring and operation count.
std::string print_kernel(const Kernel& k);

// LaTeX of one expression, operands in canonical order; symbols renamed through `names`.
std::string latex(const GiNaC::ex& e, const std::map<std::string, std::string>& names);

}  // namespace impact3d::symbolic
