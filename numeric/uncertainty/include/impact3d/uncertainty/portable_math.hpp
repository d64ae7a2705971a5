// The transforms that turn uniform draws into samples, written with +, -, *, / and sqrt, which IEEE 754
// rounds the same way everywhere, and frexp, ldexp, floor and fabs, which are exact, in a file compiled without fused multiply-adds
// (-ffp-contract=off): so a seed gives the same samples, bit for bit, on every platform and standard
// library. std::log, std::exp and the <random> distributions differ between libraries; these do not.
#pragma once

namespace impact3d::uncertainty {

// ln x for x > 0 (NaN below 0, -infinity at 0), within 1 ulp in the tests (check_sampling.cpp):
// x = m 2^e with m in [sqrt(1/2), sqrt(2)), ln x = e ln 2 + 2 atanh((m - 1) / (m + 1)).
double portable_log(double x);

// e^x, within 2 ulps in the tests; 0 below -745.13, infinity above 709.78.
double portable_exp(double x);

// The standard normal quantile Phi^-1(p) for p in (0, 1): Wichura's AS241 (PPND16), Applied Statistics
// 37 (1988) 477-484, whose rational approximations are accurate to about 1e-16; within 8 ulps in the
// tests, where Phi at 50 digits judges it (4.9 the worst seen): ten orders of magnitude below the
// sampling error of any Monte Carlo run. NaN outside (0, 1).
double normal_quantile(double p);

// The standard normal distribution function Phi(x), and its upper tail Q(x) = Phi(-x) = 1 - Phi(x),
// each with a small relative error where it is small (the tail is not 1 minus something): within 16
// ulps in the tests, which judge it by 50-digit erfc, down to Phi = 1e-300.
double normal_cdf(double x);
double normal_upper_tail(double x);

// Mills' ratio M(x) = Q(x) / phi(x) for x >= 0 (NaN below), 0 at infinity: the tail without its
// Gaussian factor, so that tails far beyond the smallest double (Q(38.5) ~ 1e-324) keep their digits,
// as log Q(x) = -x^2/2 - ln sqrt(2 pi) + ln M(x). M decreases from sqrt(pi/2), M(x) ~ 1/x, and
// M' = x M - 1.
double normal_mills_ratio(double x);

}  // namespace impact3d::uncertainty
