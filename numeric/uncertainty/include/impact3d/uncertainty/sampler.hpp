// The inputs of one Monte Carlo sample: one uniform draw per input at counter (sample, input), made
// into normal scores, correlated through the Gaussian copula (z = L w with L the Cholesky factor of the
// normal-score correlation matrix), and mapped back through each input's distribution. A sample's
// values depend on the seed and its index only, so any split of the samples over threads gives the
// same values.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "impact3d/uncertainty/distribution.hpp"

namespace impact3d::uncertainty {

// A correlation between inputs a and b (their places in the file): rho is the correlation of their
// normal scores, in (-1, 1).
struct Correlation {
  std::size_t a, b;
  double rho;
};

// The lower Cholesky factor of the n x n symmetric matrix `c` (row-major), in place; returns n, or the
// first column whose pivot is not positive (the leading k + 1 inputs' correlations are then not
// positive definite). Plain loops in a fixed order: the same bits everywhere.
std::size_t cholesky(std::vector<double>& c, std::size_t n);

// The correlations cannot be met: `input` is the first input (in file order, among the correlated ones)
// whose correlations with the earlier ones make the matrix not positive definite.
struct NotPositiveDefinite : std::invalid_argument {
  std::size_t input;
  explicit NotPositiveDefinite(std::size_t i)
      : std::invalid_argument("the correlation matrix is not positive definite"), input(i) {}
};

class Sampler {
 public:
  // Throws NotPositiveDefinite, or std::invalid_argument for a correlation of an input with itself or
  // with none.
  Sampler(std::vector<Distribution> inputs, const std::vector<Correlation>& correlations, std::uint64_t seed);

  std::size_t size() const { return inputs_.size(); }
  // values[i] = input i's value in sample `sample`.
  void draw(std::uint64_t sample, double* values) const;

 private:
  double value(std::size_t input, double u) const;  // quantile(inputs_[input], u)

  std::vector<Distribution> inputs_;
  std::vector<TruncatedWindow> windows_;  // per input; a truncated normal's, computed once
  std::vector<std::size_t> correlated_;  // the inputs in a correlation, in file order
  std::vector<double> L_;                // their Cholesky factor, row-major
  std::uint64_t seed_;
};

}  // namespace impact3d::uncertainty
