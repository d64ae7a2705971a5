// C++ kernels and LaTeX from canonical expressions: common subexpressions hoisted into temporaries named
// in order of first use, constants as exact Scalar(p)/Scalar(q), math through using-declarations. The
// layout is SymForce's: docstring with Args and Returns and their shapes, one parameter a line, the body
// in sections (intermediate terms, output terms), statements wrapped at 120 columns.
#pragma once

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

namespace impact3d::symbolic {

struct KernelArg {
  std::string decl;  // "const Eigen::Matrix<Scalar, 3, 3>& K"
  std::string doc;   // "coefficient matrix of eq 9"; the docstring adds the shape from decl
};

struct Kernel {
  std::string name;
  std::string doc;                                      // what it computes, from which equations
  std::vector<std::string> equations;                   // audit ids it evaluates: "eq24", "A.c3"
  std::string returns;                                  // C++ return type, e.g. "Vec3<Scalar>"
  std::string returns_doc;
  std::vector<KernelArg> args;
  std::map<std::string, std::string> symbol_code;       // GiNaC symbol name -> C++ expression
  // Named intermediate results, in order (the names must also be in symbol_code).
  std::vector<std::pair<std::string, GiNaC::ex>> locals;
  std::vector<std::pair<std::string, GiNaC::ex>> outputs;  // "out(0)" -> expression
};

struct PrintedKernel {
  std::string text;              // the function template with its docstring
  long operations = 0;           // additions, multiplications, divisions and calls
  int intermediate_terms = 0;    // named locals and hoisted temporaries
  int output_terms = 0;
  std::set<std::string> calls;   // math functions called (through using std::f)
};

// The whole function template, with its docstring and operation count.
PrintedKernel print_kernel(const Kernel& k);

// "3x3", "3x1" for an Eigen::Matrix<Scalar, R, C> in a declaration or return type, "scalar" for Scalar.
std::string shape_of(const std::string& type);

// LaTeX of one expression, operands in canonical order; symbols renamed through `names`.
std::string latex(const GiNaC::ex& e, const std::map<std::string, std::string>& names);

}  // namespace impact3d::symbolic
