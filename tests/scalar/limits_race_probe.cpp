// A fresh process whose first use of the multiprecision numbers' std::numeric_limits comes from two
// threads at once (check_limits_threads runs it many times): exit 0 if both threads read the values the
// main thread reads afterwards, 1 (naming the value) if either read another. Boost 1.74 fills float100's
// values on first call and marks them filled first; the scalar library fills them at start-up
// (multiprecision.hpp's limits_filled, defined in thread_caches.cpp).
#include <atomic>
#include <cstdio>
#include <thread>

#include "impact3d/scalar/multiprecision.hpp"

namespace {

std::atomic<int> waiting{2};

template <typename T>
struct Limits {
  T values[6];
  static Limits read() {
    using L = std::numeric_limits<T>;
    return {{L::epsilon(), L::round_error(), (L::min)(), (L::max)(), L::infinity(), L::quiet_NaN()}};
  }
};

template <typename T>
bool same(const T& a, const T& b) {
  return (boost::multiprecision::isnan(a) && boost::multiprecision::isnan(b)) || a == b;
}

template <typename T>
int differing(const Limits<T> (&got)[2], const char* type) {
  static const char* const names[] = {"epsilon", "round_error", "min", "max", "infinity", "quiet_NaN"};
  const Limits<T> after = Limits<T>::read();
  int bad = 0;
  for (const Limits<T>& g : got)
    for (int i = 0; i < 6; ++i)
      // Named, not printed: a value copied while another thread was writing it may not be a valid number.
      if (!same(g.values[i], after.values[i])) std::printf("%s %s differs\n", type, names[i]), ++bad;
  return bad;
}

}  // namespace

int main() {
  using impact3d::mp::float100, impact3d::mp::float50;
  Limits<float100> hundred[2];
  Limits<float50> fifty[2];
  auto reader = [&](int i) {
    --waiting;
    while (waiting.load() > 0) {}  // both threads released together
    hundred[i] = Limits<float100>::read();
    fifty[i] = Limits<float50>::read();
  };
  std::thread a(reader, 0), b(reader, 1);
  a.join(), b.join();
  const int bad = differing(hundred, "float100") + differing(fifty, "float50");
  // The values themselves, from another route than numeric_limits: epsilon is 2^(1 - digits).
  const bool eps_ok = hundred[0].values[0] == ldexp(float100(1), 1 - std::numeric_limits<float100>::digits) &&
                      fifty[0].values[0] == ldexp(float50(1), 1 - std::numeric_limits<float50>::digits);
  if (!eps_ok) std::printf("epsilon is not 2^(1 - digits)\n");
  return bad == 0 && eps_ok ? 0 : 1;
}
