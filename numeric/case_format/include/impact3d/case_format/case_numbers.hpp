// The numeric inputs of a read case, named by their JSON paths, with pointers to their numbers in it:
// what Monte Carlo samples write into and what a sensitivity differentiates with respect to.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "impact3d/case_format/case_spec.hpp"

namespace impact3d::case_format {

// The numbers of a read case that the reader checks one at a time, by a range (> 0, >= 0, [0, 1], the
// magnitude limits): a sample may write these straight into a copy of the case. An inertia tensor
// (symmetric, positive definite), an orientation matrix and contact vectors are checked together with
// their neighbours, and are left to the reader.
std::vector<std::pair<std::string, Number*>> single_numbers(CaseSpec& spec);

// An input a sensitivity differentiates: its path and the numbers that move with it (an off-diagonal
// product of inertia moves its mirror, so that the tensor stays symmetric).
struct CaseInput {
  std::string path;
  std::vector<Number*> numbers;
};

struct CaseInputs {
  std::vector<CaseInput> inputs;  // in the order the case format lists them
  // Inputs not differentiated, each with why: the entries of an orientation matrix cannot move one at
  // a time and stay a rotation.
  std::vector<std::pair<std::string, std::string>> fixed;
};

// Every numeric input of the case, written or defaulted (an absent angular velocity is an input at 0).
CaseInputs case_inputs(CaseSpec& spec);

}  // namespace impact3d::case_format
