// Every real root of a polynomial of low degree, at the scalar's precision: the roots of its derivative
// split the line into intervals on which it is monotone, and each interval whose ends differ in sign
// holds one root, found by bisection. Nothing is missed but roots of even multiplicity that the
// arithmetic cannot tell from a near miss (a critical value within rounding of zero counts as a root).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "impact3d/scalar/types.hpp"

namespace impact3d::stronge {

// c[0] + c[1] x + ... at x, by Horner.
template <typename Scalar>
Scalar polynomial_at(const std::vector<Scalar>& c, const Scalar& x) {
  Scalar y(0);
  for (std::size_t i = c.size(); i-- > 0;) y = y * x + c[i];
  return y;
}

// The derivative's coefficients (a constant's derivative is the zero polynomial).
template <typename Scalar>
std::vector<Scalar> derivative(const std::vector<Scalar>& c) {
  std::vector<Scalar> d(c.size() > 1 ? c.size() - 1 : 1, Scalar(0));
  for (std::size_t j = 1; j < c.size(); ++j) d[j - 1] = c[j] * Scalar(static_cast<long long>(j));
  return d;
}

// Several polynomials of one length at x, their Horner chains interleaved (each would wait on its own
// multiply-add's latency).
template <std::size_t N, typename Scalar>
std::array<Scalar, N> polynomials_at(const std::array<const std::vector<Scalar>*, N>& c, const Scalar& x) {
  std::array<Scalar, N> y;
  y.fill(Scalar(0));
  for (std::size_t i = c[0]->size(); i-- > 0;)
    for (std::size_t k = 0; k < N; ++k) y[k] = y[k] * x + (*c[k])[i];
  return y;
}

// One polynomial at several points, interleaved likewise.
template <std::size_t N, typename Scalar>
std::array<Scalar, N> polynomial_at_points(const std::vector<Scalar>& c, const std::array<Scalar, N>& x) {
  std::array<Scalar, N> y;
  y.fill(Scalar(0));
  for (std::size_t i = c.size(); i-- > 0;)
    for (std::size_t k = 0; k < N; ++k) y[k] = y[k] * x[k] + c[i];
  return y;
}

// The root of c in [lo, hi], where c(lo) and c(hi) differ in sign, to the last bit: Newton's steps kept
// inside the bracket that each value shrinks, a bisection wherever a step would leave it or fall short of
// halving the step before (Numerical Recipes' rtsafe), until the bracket cannot be split or Newton's step
// is below the last bit; at most `kIterations` (128 more than the widest scalar's bits).
template <typename Scalar>
Scalar bisect_bracket(const std::vector<Scalar>& c, Scalar lo, Scalar hi) {
  using std::abs;
  constexpr int kIterations = 128 + 400;
  const bool lo_negative = polynomial_at(c, lo) < Scalar(0);
  Scalar x = (lo + hi) / Scalar(2), step_before = hi - lo, step = step_before;
  for (int i = 0; i < kIterations; ++i) {
    Scalar y(0), d(0);
    for (std::size_t k = c.size(); k-- > 0;) d = d * x + y, y = y * x + c[k];
    if (y == Scalar(0)) return x;
    if ((y < Scalar(0)) == lo_negative) lo = x;
    else hi = x;
    Scalar next = x;
    const bool newton = d != Scalar(0) && abs(Scalar(Scalar(2) * y)) < abs(Scalar(step_before * d));
    if (newton) {
      next = x - y / d;
      // A step below the last bit: Newton has converged (from one side, which bisection would close).
      if (abs(Scalar(next - x)) <= std::numeric_limits<Scalar>::epsilon() * abs(x)) return next > lo && next < hi ? next : x;
    }
    if (!newton || !(next > lo && next < hi)) next = (lo + hi) / Scalar(2);
    if (!(next > lo && next < hi) || next == x) break;  // the bracket is two neighbours
    step_before = step, step = abs(Scalar(next - x));
    x = next;
  }
  return x;
}

// One Newton step from a root found to the last bit: its value unchanged, and for a dual number the
// derivative of the root, -dc/dtheta / c'(x), implicit differentiation at the root (bisection's
// midpoints carry none).
template <typename Scalar>
Scalar with_root_derivative(const std::vector<Scalar>& c, const Scalar& x) {
  if constexpr (!is_dual_v<Scalar>) {
    return x;
  } else {
    Scalar d(0);
    for (std::size_t i = c.size(); i-- > 1;) d = d * x + c[i] * Scalar(static_cast<double>(i));
    if (!(d != Scalar(0))) return x;
    // The Newton correction's derivative alone: its value, c(x) / c'(x), would move the root off the
    // value the other precisions find (far, at a nearly tangent crossing).
    Scalar correction = polynomial_at(c, x) / d;
    correction.value() = 0;
    return x - correction;
  }
}

// bisect_bracket's root, with its derivative for a dual number.
template <typename Scalar>
Scalar bisect_root(const std::vector<Scalar>& c, const Scalar& lo, const Scalar& hi) {
  return with_root_derivative(c, bisect_bracket(c, lo, hi));
}

// The real roots of c (c.back() != 0), in increasing order; `zero` is the size of a critical value
// counted as a root (the rounding of the polynomial's values).
template <typename Scalar>
std::vector<Scalar> real_roots(std::vector<Scalar> c, const Scalar& zero) {
  using std::abs;
  while (c.size() > 1 && c.back() == Scalar(0)) c.pop_back();
  const std::size_t degree = c.size() - 1;
  if (degree == 0) return {};
  if (degree == 1) return {Scalar(-c[0] / c[1])};
  const std::vector<Scalar> d = derivative(c);
  // Cauchy's bound: every root lies within 1 + max |c_i / c_n|.
  Scalar bound(0);
  for (std::size_t i = 0; i < degree; ++i) bound = std::max(bound, Scalar(abs(c[i] / c[degree])));
  bound = bound + Scalar(1);
  std::vector<Scalar> ends{Scalar(-bound)};
  for (const Scalar& x : real_roots(d, zero))
    if (x > -bound && x < bound) ends.push_back(x);
  ends.push_back(bound);
  std::vector<Scalar> roots;
  for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
    const Scalar a = polynomial_at(c, ends[i]), b = polynomial_at(c, ends[i + 1]);
    if (i > 0 && abs(a) <= zero) {
      if (roots.empty() || roots.back() != ends[i]) roots.push_back(ends[i]);
    } else if ((a < Scalar(0)) != (b < Scalar(0)) && abs(b) > zero) {
      roots.push_back(bisect_root(c, ends[i], ends[i + 1]));
    }
  }
  return roots;
}

}  // namespace impact3d::stronge
