// The Monte Carlo sampler (uncertainty/sampler.hpp): its Cholesky factor against Eigen's LLT on seeded
// random correlation matrices; correlated draws with the correlations asked for (normal scores'
// Pearson correlation, and for other marginals the rank correlation the Gaussian copula implies,
// (6/pi) asin(rho/2)); a matrix that is not positive definite refused, naming the input; and draws that
// depend on the seed and the sample's index only.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <catch2/catch.hpp>

#include "impact3d/uncertainty/philox.hpp"
#include "impact3d/uncertainty/sampler.hpp"

namespace check_sampler {

namespace {

using namespace impact3d::uncertainty;
using Kind = Distribution::Kind;

Distribution normal(double mean, double sd) {
  Distribution d;
  d.kind = Kind::normal, d.mean = mean, d.sd = sd;
  return d;
}
Distribution uniform(double lo, double hi) {
  Distribution d;
  d.kind = Kind::uniform, d.min = lo, d.max = hi;
  return d;
}
Distribution triangular(double lo, double mode, double hi) {
  Distribution d;
  d.kind = Kind::triangular, d.min = lo, d.mode = mode, d.max = hi;
  return d;
}

double pearson(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n, my = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx), syy += (y[i] - my) * (y[i] - my);
  return sxy / std::sqrt(sxx * syy);
}

std::vector<double> ranks(const std::vector<double>& x) {
  std::vector<std::size_t> order(x.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  std::vector<double> r(x.size());
  for (std::size_t i = 0; i < order.size(); ++i) r[order[i]] = static_cast<double>(i);
  return r;
}

}  // namespace

TEST_CASE("cholesky agrees with Eigen's LLT on random correlation matrices, and finds the failing column") {
  std::mt19937_64 g(5);
  std::normal_distribution<double> n01;
  int checked = 0;
  for (int t = 0; t < 200; ++t) {
    const int n = 2 + t % 9;
    Eigen::MatrixXd a(n, n + 3);
    for (int i = 0; i < a.size(); ++i) a.data()[i] = n01(g);
    Eigen::MatrixXd c = a * a.transpose();
    const Eigen::VectorXd s = c.diagonal().cwiseSqrt().cwiseInverse();
    c = s.asDiagonal() * c * s.asDiagonal();  // a correlation matrix
    std::vector<double> mine(static_cast<std::size_t>(n * n));
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) mine[static_cast<std::size_t>(i * n + j)] = c(i, j);
    REQUIRE(cholesky(mine, static_cast<std::size_t>(n)) == static_cast<std::size_t>(n));
    const Eigen::MatrixXd L = c.llt().matrixL();
    // Two Cholesky factorizations of a well-conditioned matrix agree to a few eps times n (each is
    // backward stable; the entries are at most 1): 16 n eps.
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) CHECK(std::fabs(mine[static_cast<std::size_t>(i * n + j)] - L(i, j)) <= 16 * n * 0x1p-52);
    ++checked;
  }
  CHECK(checked == 200);
  // rho = 0.9, 0.9, -0.9 among three: not positive definite, found at the third column.
  std::vector<double> bad = {1, 0.9, -0.9, 0.9, 1, 0.9, -0.9, 0.9, 1};
  CHECK(cholesky(bad, 3) == 2);
}

TEST_CASE("the sampler's correlated draws have the correlations asked for") {
  const std::vector<Distribution> inputs = {normal(1500, 60), uniform(0.05, 0.2), normal(11.176, 0.3), triangular(85, 90, 95)};
  const Sampler s(inputs, {{0, 2, 0.5}, {1, 3, 0.7}}, 42);
  const int n = 100000;
  std::vector<std::vector<double>> x(4, std::vector<double>(n));
  double v[4];
  for (int i = 0; i < n; ++i) {
    s.draw(static_cast<std::uint64_t>(i), v);
    for (int k = 0; k < 4; ++k) x[static_cast<std::size_t>(k)][static_cast<std::size_t>(i)] = v[k];
  }
  // Standard errors: a sample correlation's is (1 - rho^2) / sqrt(n), a mean's sd / sqrt(n); a rank
  // correlation's is below 1 / sqrt(n). Five of them is a one-in-a-million miss, fixed by the seed.
  const double root_n = std::sqrt(double(n));
  CHECK(std::fabs(pearson(x[0], x[2]) - 0.5) < 5 * 0.75 / root_n);
  const double spearman = pearson(ranks(x[1]), ranks(x[3]));
  CHECK(std::fabs(spearman - 6 / M_PI * std::asin(0.35)) < 5 / root_n);
  CHECK(std::fabs(pearson(x[0], x[1])) < 5 / root_n);  // not correlated
  CHECK(std::fabs(std::accumulate(x[0].begin(), x[0].end(), 0.0) / n - 1500) < 5 * 60 / root_n);
  CHECK(*std::min_element(x[1].begin(), x[1].end()) >= 0.05);
  CHECK(*std::max_element(x[3].begin(), x[3].end()) <= 95);
}

TEST_CASE("a sample's values depend on the seed and its index only; uncorrelated inputs are their own draws") {
  const std::vector<Distribution> inputs = {normal(0, 1), uniform(-1, 1), normal(5, 2)};
  const Sampler s(inputs, {{0, 2, -0.3}}, 7), again(inputs, {{0, 2, -0.3}}, 7), other(inputs, {{0, 2, -0.3}}, 8);
  double a[3], b[3], c[3];
  int checked = 0;
  for (std::uint64_t i = 1000; i-- > 0;) {  // in reverse, against a second sampler in order
    s.draw(i, a);
    again.draw(999 - i, b);
    again.draw(i, b);
    other.draw(i, c);
    CHECK((a[0] == b[0] && a[1] == b[1] && a[2] == b[2]));
    CHECK(a[0] != c[0]);
    CHECK(a[1] == quantile(inputs[1], uniform_open(7, i, 1)));
    ++checked;
  }
  CHECK(checked == 1000);
}

TEST_CASE("correlations that are not positive definite are refused, naming the input") {
  const std::vector<Distribution> inputs = {normal(0, 1), normal(0, 1), uniform(0, 1), normal(0, 1)};
  try {
    Sampler s(inputs, {{0, 1, 0.9}, {1, 3, 0.9}, {0, 3, -0.9}}, 1);
    FAIL("accepted");
  } catch (const NotPositiveDefinite& e) {
    CHECK(e.input == 3);
  }
  CHECK_THROWS_AS(Sampler(inputs, {{0, 0, 0.5}}, 1), std::invalid_argument);
  CHECK_THROWS_AS(Sampler(inputs, {{0, 4, 0.5}}, 1), std::invalid_argument);
}

}  // namespace check_sampler
