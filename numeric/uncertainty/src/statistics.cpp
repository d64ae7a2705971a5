#include "impact3d/uncertainty/statistics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace impact3d::uncertainty {

namespace {

// Neumaier's compensated sum, in the order given: the result does not depend on how the samples were
// split over threads because the values arrive sorted.
class Sum {
 public:
  void add(double x) {
    const double t = s_ + x;
    c_ += std::fabs(s_) >= std::fabs(x) ? (s_ - t) + x : (x - t) + s_;
    s_ = t;
  }
  double value() const { return s_ + c_; }

 private:
  double s_ = 0, c_ = 0;
};

// The mean and standard deviation, summed in the order given (two passes: the squares of deviations,
// not the difference of two large sums).
void moments(const std::vector<double>& x, Summary& s) {
  const double n = static_cast<double>(x.size());
  Sum sum;
  for (double v : x) sum.add(v);
  s.mean = sum.value() / n;
  Sum squares;
  for (double v : x) squares.add((v - s.mean) * (v - s.mean));
  s.sd = x.size() > 1 ? std::sqrt(squares.value() / (n - 1)) : 0.0;
  s.mean_se = s.sd / std::sqrt(n);
}

// The probabilities each percentile and its standard error read the order statistics at.
struct Reads {
  std::array<double, 9> p, lo, hi, half;
};
Reads reads(std::size_t count) {
  Reads r;
  const double n = static_cast<double>(count);
  for (std::size_t k = 0; k < kPercentiles.size(); ++k) {
    r.p[k] = kPercentiles[k] / 100;
    r.half[k] = std::sqrt(r.p[k] * (1 - r.p[k]) / n);
    r.lo[k] = std::max(0.0, r.p[k] - r.half[k]);
    r.hi[k] = std::min(1.0, r.p[k] + r.half[k]);
  }
  return r;
}

// The percentiles, min and max from values whose order statistics at the positions they read stand in
// place (sorted, or selected by select_order_statistics).
void percentiles(const std::vector<double>& x, const Reads& r, Summary& s) {
  for (std::size_t k = 0; k < kPercentiles.size(); ++k) {
    s.percentile[k] = percentile_type7(x, r.p[k]);
    s.percentile_se[k] =
        r.hi[k] > r.lo[k] ? (percentile_type7(x, r.hi[k]) - percentile_type7(x, r.lo[k])) * (r.half[k] / (r.hi[k] - r.lo[k])) : 0.0;
  }
}

// The positions percentile_type7 reads at probability q: floor(h) and the one after, h = (n - 1) q.
void positions(std::size_t n, double q, std::vector<std::size_t>& out) {
  const auto i = static_cast<std::size_t>(std::floor(static_cast<double>(n - 1) * q));
  out.push_back(std::min(i, n - 1));
  out.push_back(std::min(i + 1, n - 1));
}

// Puts the k-th smallest value at position k for every k of [kb, ke) (sorted, within [first, last)
// shifted by `offset`), and nothing else in order: each selection splits the range for the next, so
// the cost is about n log(positions) rather than a sort's n log n. The value at each position is the
// order statistic itself, whatever the algorithm's choices: the result is the same everywhere.
void select_positions(double* first, double* last, const std::size_t* kb, const std::size_t* ke, std::size_t offset) {
  while (kb != ke && last - first > 1) {
    const std::size_t* km = kb + (ke - kb) / 2;
    double* at = first + (*km - offset);
    std::nth_element(first, at, last);
    select_positions(first, at, kb, km, offset);
    offset += static_cast<std::size_t>(at - first) + 1;
    first = at + 1;
    kb = km + 1;
  }
}

// The order statistics at the sorted, distinct positions [kb, ke) of the n values at x (finite), into
// out[0 .. ke - kb); x is left as it was. Where there are many values they are first counted into bins
// of equal width between their min and max: a value's bin is a non-decreasing function of the value,
// so bin b holds the order statistics from the count below it on, and only the bins holding a wanted
// position are gathered and selected in (again by bins, where one bin still holds most of them). The
// values chosen are the order statistics themselves, so the result is select_positions' exactly, at
// about three passes over the values instead of log2 of the positions.
void order_statistics(const double* x, std::size_t n, const std::size_t* kb, const std::size_t* ke, double* out,
                      int depth = 0) {
  constexpr std::size_t kBins = 4096, kFew = 4096;
  constexpr int kDepth = 3;
  if (kb == ke) return;
  const auto [lo_it, hi_it] = std::minmax_element(x, x + n);
  const double lo = *lo_it, hi = *hi_it;
  const double scale = static_cast<double>(kBins) / (hi - lo);
  if (n <= kFew || depth >= kDepth || lo == hi || !std::isfinite(scale) || !(scale > 0)) {
    if (lo == hi) {
      std::fill(out, out + (ke - kb), lo);
      return;
    }
    std::vector<double> work(x, x + n);
    select_positions(work.data(), work.data() + n, kb, ke, 0);
    for (const std::size_t* k = kb; k != ke; ++k) out[k - kb] = work[*k];
    return;
  }
  auto bin = [&](double v) { return std::min(kBins - 1, static_cast<std::size_t>((v - lo) * scale)); };
  std::vector<std::uint16_t> of(n);
  std::vector<std::size_t> start(kBins + 1, 0);
  for (std::size_t i = 0; i < n; ++i) ++start[(of[i] = static_cast<std::uint16_t>(bin(x[i]))) + 1];
  for (std::size_t b = 0; b < kBins; ++b) start[b + 1] += start[b];
  // The wanted bins, each with its run of positions, and where its values go in `gathered`.
  struct Wanted {
    std::size_t bin, at;
    const std::size_t *kb, *ke;
  };
  std::vector<Wanted> wanted;
  std::vector<std::size_t> place(kBins, SIZE_MAX);
  std::size_t total = 0;
  for (const std::size_t* k = kb; k != ke;) {
    const std::size_t b = static_cast<std::size_t>(std::upper_bound(start.begin(), start.end(), *k) - start.begin()) - 1;
    const std::size_t* e = k;
    while (e != ke && *e < start[b + 1]) ++e;
    wanted.push_back({b, total, k, e});
    place[b] = total;
    total += start[b + 1] - start[b];
    k = e;
  }
  std::vector<double> gathered(total);
  for (std::size_t i = 0; i < n; ++i)
    if (place[of[i]] != SIZE_MAX) gathered[place[of[i]]++] = x[i];
  std::vector<std::size_t> local;
  for (const Wanted& w : wanted) {
    const std::size_t count = start[w.bin + 1] - start[w.bin];
    local.assign(w.kb, w.ke);
    for (std::size_t& k : local) k -= start[w.bin];
    order_statistics(gathered.data() + w.at, count, local.data(), local.data() + local.size(), out + (w.kb - kb), depth + 1);
  }
}

// Into (-180, 180]: x is in (-540, 540], so one step of 360 at most.
double wrap_deg(double x) {
  if (x > 180) return x - 360;
  if (x <= -180) return x + 360;
  return x;
}

}  // namespace

double percentile_type7(const std::vector<double>& sorted, double p) {
  const double h = static_cast<double>(sorted.size() - 1) * p;
  const auto i = static_cast<std::size_t>(std::floor(h));
  if (i + 1 >= sorted.size()) return sorted.back();
  const double f = h - static_cast<double>(i);
  // x_i + f (x_{i+1} - x_i), exact at f = 0 and equal to x_{i+1} at f = 1 only up to rounding: the
  // difference form keeps the result inside [x_i, x_{i+1}].
  return sorted[i] + f * (sorted[i + 1] - sorted[i]);
}

Summary summarize(std::vector<double>& values) {
  Summary s;
  s.count = values.size();
  if (values.empty()) return s;
  moments(values, s);  // in the order given: the samples' order
  const Reads r = reads(values.size());
  std::vector<std::size_t> at = {0, values.size() - 1};
  for (std::size_t k = 0; k < kPercentiles.size(); ++k)
    positions(values.size(), r.p[k], at), positions(values.size(), r.lo[k], at), positions(values.size(), r.hi[k], at);
  std::sort(at.begin(), at.end());
  at.erase(std::unique(at.begin(), at.end()), at.end());
  // The order statistics written at their own positions: all that percentiles() reads.
  std::vector<double> stats(at.size());
  order_statistics(values.data(), values.size(), at.data(), at.data() + at.size(), stats.data());
  for (std::size_t j = 0; j < at.size(); ++j) values[at[j]] = stats[j];
  s.min = values.front();
  s.max = values.back();
  percentiles(values, r, s);
  return s;
}

Summary summarize_angle_deg(std::vector<double>& values, bool from_zero) {
  for (double v : values)
    if (!(v >= -360 && v <= 360)) throw std::invalid_argument("an angle outside [-360, 360] degrees");
  for (double& v : values) v = wrap_deg(v);
  std::sort(values.begin(), values.end());
  if (values.size() < 2) {
    if (from_zero)
      for (double& v : values) v = v < 0 ? v + 360 : v;
    return summarize(values);
  }
  // The widest gap: between neighbours, or the one across +-180 (from the last to the first).
  const std::size_t n = values.size();
  std::size_t cut = n;  // the first value of the unwrapped run; n: the gap across +-180 is widest
  double widest = values.front() + 360 - values.back();
  for (std::size_t i = 0; i + 1 < n; ++i)
    if (values[i + 1] - values[i] > widest) widest = values[i + 1] - values[i], cut = i + 1;
  if (cut < n) {
    std::rotate(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(cut), values.end());
    for (std::size_t i = n - cut; i < n; ++i) values[i] += 360;  // those below the gap, now after it
  }
  // Sorted, so the moments are summed in sorted order here (the samples' order is lost to the unwrapping).
  Summary s;
  s.count = n;
  moments(values, s);
  s.min = values.front();
  s.max = values.back();
  percentiles(values, reads(n), s);
  const auto back = [from_zero](double x) {
    x = wrap_deg(x);
    return from_zero && x < 0 ? x + 360 : x;
  };
  s.mean = back(s.mean);
  s.min = back(s.min);
  s.max = back(s.max);
  for (double& p : s.percentile) p = back(p);
  return s;
}

}  // namespace impact3d::uncertainty
