// Compiled with -ffp-contract=off, as portable_math.cpp is.
#include "impact3d/uncertainty/sampler.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "impact3d/uncertainty/philox.hpp"
#include "impact3d/uncertainty/portable_math.hpp"

namespace impact3d::uncertainty {

std::size_t cholesky(std::vector<double>& c, std::size_t n) {
  for (std::size_t j = 0; j < n; ++j) {
    double d = c[j * n + j];
    for (std::size_t k = 0; k < j; ++k) d -= c[j * n + k] * c[j * n + k];
    if (!(d > 0)) return j;
    const double root = std::sqrt(d);
    c[j * n + j] = root;
    for (std::size_t i = j + 1; i < n; ++i) {
      double s = c[i * n + j];
      for (std::size_t k = 0; k < j; ++k) s -= c[i * n + k] * c[j * n + k];
      c[i * n + j] = s / root;
    }
    for (std::size_t i = 0; i < j; ++i) c[i * n + j] = 0;  // the upper triangle: zeros
  }
  return n;
}

Sampler::Sampler(std::vector<Distribution> inputs, const std::vector<Correlation>& correlations, std::uint64_t seed)
    : inputs_(std::move(inputs)), seed_(seed) {
  for (const Distribution& d : inputs_)
    windows_.push_back(d.kind == Distribution::Kind::truncated_normal ? truncated_window(d) : TruncatedWindow{});
  for (const Correlation& c : correlations) {
    if (c.a >= inputs_.size() || c.b >= inputs_.size() || c.a == c.b) throw std::invalid_argument("a correlation names no pair of inputs");
    correlated_.push_back(c.a);
    correlated_.push_back(c.b);
  }
  std::sort(correlated_.begin(), correlated_.end());
  correlated_.erase(std::unique(correlated_.begin(), correlated_.end()), correlated_.end());
  const std::size_t n = correlated_.size();
  L_.assign(n * n, 0);
  for (std::size_t i = 0; i < n; ++i) L_[i * n + i] = 1;
  auto place = [&](std::size_t input) {
    return static_cast<std::size_t>(std::lower_bound(correlated_.begin(), correlated_.end(), input) - correlated_.begin());
  };
  for (const Correlation& c : correlations) {
    const std::size_t i = place(c.a), j = place(c.b);
    L_[i * n + j] = L_[j * n + i] = c.rho;
  }
  if (const std::size_t k = cholesky(L_, n); k < n) throw NotPositiveDefinite(correlated_[k]);
}

double Sampler::value(std::size_t i, double u) const {
  const Distribution& d = inputs_[i];
  return d.kind == Distribution::Kind::truncated_normal ? truncated_normal(d, windows_[i], u) : quantile(d, u);
}

void Sampler::draw(std::uint64_t sample, double* values) const {
  const std::size_t n = correlated_.size();
  // Normal scores of the correlated inputs, then z = L w in place from the last row up.
  double w[64];
  std::vector<double> heap;
  double* z = w;
  if (n > 64) heap.resize(n), z = heap.data();
  for (std::size_t i = 0; i < n; ++i) z[i] = normal_quantile(uniform_open(seed_, sample, static_cast<std::uint32_t>(correlated_[i])));
  for (std::size_t i = n; i-- > 0;) {
    double s = 0;
    for (std::size_t k = 0; k <= i; ++k) s += L_[i * n + k] * z[k];
    z[i] = s;
  }
  std::size_t next = 0;
  for (std::size_t i = 0; i < inputs_.size(); ++i) {
    const Distribution& d = inputs_[i];
    if (next < n && correlated_[next] == i) {
      const double score = z[next++];
      // The normal family takes the score itself; the others its probability.
      if (d.kind == Distribution::Kind::normal) values[i] = d.mean + d.sd * score;
      else if (d.kind == Distribution::Kind::lognormal) values[i] = d.median * portable_exp(d.sigma * score);
      else {
        const double u = normal_cdf(score);
        values[i] = value(i, std::clamp(u, 0x1p-53, 1 - 0x1p-53));
      }
    } else {
      values[i] = value(i, uniform_open(seed_, sample, static_cast<std::uint32_t>(i)));
    }
  }
}

}  // namespace impact3d::uncertainty
