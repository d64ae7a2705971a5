// Stronge's impact followed through the normal impulse p, from m', K and V_ri (eq 9), to the end that
// the restitution law sets, its decisions by the engine's forms of the sliding map (generated_forms.hpp,
// direct/stronge_forms.hpp). The contact slides (a Taylor series step, sliding_series.hpp, of order
// ceil(-ln eps / 2) + 1 and the step that makes its next term eps, Jorba and Zou's rule; below kApproach
// of the approach speed or while the sliding speed falls, in the regular variable tau,
// approach_series.hpp, and within reach of the invariant direction a stop settles on, the rest in closed
// form, stop_series.hpp) until sliding stops; from then on the impulse rate is constant (sticking, or
// sliding out along an invariant direction, tangential_map.hpp) and every event is a closed form.
// Events inside a step are the roots of its polynomials, to the last bit.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>

#include "impact3d/mechanics/stronge/approach_series.hpp"
#include "impact3d/mechanics/stronge/generated_forms.hpp"
#include "impact3d/mechanics/stronge/history.hpp"
#include "impact3d/mechanics/stronge/real_roots.hpp"
#include "impact3d/mechanics/stronge/sliding_series.hpp"
#include "impact3d/mechanics/stronge/stop_series.hpp"
#include "impact3d/mechanics/stronge/tangential_map.hpp"

namespace impact3d::stronge {

// Limits on one integration (docs/limits.md): Taylor steps, and impulse over m' v0.
inline constexpr int kMaxSteps = 4096;
inline constexpr double kMaxImpulse = 1e6;
// Below this sliding speed (over the approach speed) the slide is followed in tau (approach_series.hpp).
inline constexpr double kApproach = 1.0 / 16;

template <typename Scalar>
int taylor_order() {
  return static_cast<int>(std::ceil(-std::log(to_double(std::numeric_limits<Scalar>::epsilon())) / 2)) + 1;
}

namespace detail {

template <typename Scalar, typename Forms>
struct Follow {
  const Mat3<Scalar>& K;
  Vec3<Scalar> U_i;
  Scalar mu, e;
  RestitutionLaw law;
  bool record;
  TangentialMap<Scalar> map = TangentialMap<Scalar>::of(K);
  Scalar eps = std::numeric_limits<Scalar>::epsilon();
  Scalar x{0}, a{0}, b{0}, W{0};  // the impulse so far over m' v0, and the normal work over m' v0^2
  bool compressing = true, sliding = true;
  Scalar f_t{0}, f_z{0};  // the tangential impulse rate once it is constant
  Scalar x_c{0}, W_c{0};
  std::optional<Scalar> c_prev, s_prev;  // the sliding direction at the last step's end
  std::optional<std::array<Scalar, 2>> u_carried;  // the sliding velocity, while followed in tau
  std::optional<std::vector<Direction<Scalar>>> directions;  // the map's invariant directions, once needed
  // Where the closed form last failed (rho, |delta|) and in which phase: it is tried again once the slide
  // has halved one of them or the phase has changed, not at every step on the way.
  std::optional<std::array<Scalar, 2>> failed_at;
  bool failed_compressing = true;
  History<Scalar> h;
  ApproachSeries<Scalar> tau_series;  // the tau step's series, their storage kept from step to step
  std::vector<Scalar> speed_buffer;

  Follow(const Mat3<Scalar>& K_, const Vec3<Scalar>& U_i_, const Scalar& mu_, const Scalar& e_, RestitutionLaw law_, bool record_)
      : K(K_), U_i(U_i_), mu(mu_), e(e_), law(law_), record(record_) {}

  Vec3<Scalar> U() const { return U_i - K * Vec3<Scalar>(x, a, b); }

  void trace(const Scalar& x_, const Scalar& a_, const Scalar& b_, const Scalar& W_, const Vec3<Scalar>& U_) {
    if (record) h.path.push_back({Vec3<Scalar>(x_, a_, b_), U_, W_});
  }
  // The path through a step of length H at `points` points, at(h) giving x, a, b, W and U h into it.
  template <typename At>
  void trace_step(const Scalar& H, At at, int points = kPathPoints) {
    trace_step(Scalar(0), H, at, points);
  }
  // The same from `from` to `to` into a step.
  template <typename At>
  void trace_step(const Scalar& from, const Scalar& to, At at, int points = kPathPoints) {
    if (!record || !(to > from)) return;
    for (int i = 1; i <= points; ++i) {
      const auto q = at(Scalar(from + (to - from) * Scalar(i) / Scalar(points)));
      trace(q[0], q[1], q[2], q[3], Vec3<Scalar>(q[4], q[5], q[6]));
    }
  }

  void event(EventKind kind, const Vec3<Scalar>& U_now) {
    if (record) h.events.push_back({kind, x, U_now, W});
  }
  // The end condition's value: positive until the impact ends (after compression).
  Scalar end_value(const Scalar& x_now, const Scalar& W_now, const Scalar& U_n) const {
    switch (law) {
      case RestitutionLaw::energetic: return W_now - (Scalar(1) - e * e) * W_c;
      case RestitutionLaw::poisson: return (Scalar(1) + e) * x_c - x_now;
      case RestitutionLaw::newton: return U_n + e * U_i(0);
    }
    return Scalar(0);
  }
  // The rounding of the value whose root ends the phase, at the point reached: a few eps of its terms'
  // size (U_n = U_i,n - K_n . P; the normal work, whose restitution is released from W_c; x).
  Scalar end_value_rounding() const {
    using std::abs;
    if (compressing || law == RestitutionLaw::newton)
      return Scalar(4) * eps * (abs(U_i(0)) + abs(K(0, 0) * x) + abs(K(0, 1) * a) + abs(K(0, 2) * b));
    if (law == RestitutionLaw::energetic) return Scalar(4) * eps * (abs(W_c) + abs(W));
    return Scalar(4) * eps * x;
  }
  // How far a rounding d of that value moves its root, where the value changes at `rate` and `curvature`
  // per unit of x: d / |rate|, and at most sqrt(2 d / |curvature|) where the rate vanishes (the
  // energetic end of a nearly plastic impact, W flat in x as V_n nears 0). Added to the bound as the
  // impulse's move, (1, f) times it. Compression's end moves only Poisson's end, (1 + e) times as far:
  // the energetic law's W is flat there (V_n = 0) and Newton's ends by V_n alone.
  void add_location_rounding(const Scalar& rate, const Scalar& curvature) {
    using std::abs;
    using std::sqrt;
    if (compressing && law != RestitutionLaw::poisson) return;
    const Scalar d = end_value_rounding();
    Scalar dx = abs(rate) > Scalar(0) ? Scalar(d / abs(rate)) : std::numeric_limits<Scalar>::infinity();
    if (abs(curvature) > Scalar(0)) dx = std::min(dx, Scalar(sqrt(Scalar(2) * d / abs(curvature))));
    if (!(dx < std::numeric_limits<Scalar>::infinity())) dx = Scalar(1) + x;  // no rate: the impact's scale
    const Scalar carried = compressing && law == RestitutionLaw::poisson ? Scalar(Scalar(1) + e) : Scalar(1);
    h.error_bound += dx * (Scalar(1) + mu) * carried;
  }
  // The same for a root at H of a step's polynomial p in its variable, whose x advances as xs.
  void add_location_rounding(const std::vector<Scalar>& p, const std::vector<Scalar>& xs, const Scalar& H) {
    const Scalar dx_dh = polynomial_at(derivative(xs), H);
    const std::vector<Scalar> dp = derivative(p);
    const Scalar rate = polynomial_at(dp, H) / dx_dh;
    add_location_rounding(rate, Scalar(polynomial_at(derivative(dp), H) / (dx_dh * dx_dh)));
  }

  void end_compression(const Vec3<Scalar>& U_now) {
    compressing = false;
    x_c = x, W_c = W;
    h.work_compression = W;
    event(EventKind::compression_end, U_now);
  }

  // u has reached zero: stick if Coulomb's cone holds the ratio that keeps it there, else slide out
  // along the fastest-growing invariant direction (the others named by their count).
  bool from_rest(bool at_start) {
    using std::atan2;
    sliding = false;
    // The tangential block is positive definite for any K of bodies (K = I + m' sum ...); a K that is not
    // cannot decide between sticking and sliding out.
    const auto r = K(1, 1) * K(2, 2) - K(1, 2) * K(2, 1) > Scalar(0) ? Forms::stick_ratio(K) : std::nullopt;
    if (!r) return fail("the tangential block of K is singular: the contact cannot stick or slide out");
    if ((*r)[0] * (*r)[0] + (*r)[1] * (*r)[1] <= mu * mu) {
      f_t = (*r)[0], f_z = (*r)[1];
      event(EventKind::stick, U());
      return true;
    }
    const auto& dirs = invariant();
    std::optional<Direction<Scalar>> best;
    int outward = 0;
    for (const auto& d : dirs)
      if (d.growth > Scalar(0)) {
        ++outward;
        if (!best || d.growth > best->growth) best = d;
      }
    h.diverging_directions = outward;
    if (!best) return fail("sliding stopped, the contact cannot stick, and no direction lets it slide out");
    f_t = mu * best->c, f_z = mu * best->s;
    h.final_direction_deg = degrees(Scalar(atan2(best->s, best->c)));
    event(at_start ? EventKind::slip : EventKind::reversal, U());
    return true;
  }

  const std::vector<Direction<Scalar>>& invariant() {
    if (!directions) directions = invariant_directions<Forms>(K, mu);
    return *directions;
  }

  // Within reach of the invariant direction the slide settles on, the rest of the slide in closed form
  // (stop_series.hpp), when no phase can end within it: true when taken, the contact then at rest.
  bool stop_in_closed_form(int order) {
    using std::abs;
    using std::atan2;
    using std::cos;
    using std::sin;
    using std::sqrt;
    const Scalar ut = (*u_carried)[0], uz = (*u_carried)[1];
    const Scalar rho = sqrt(ut * ut + uz * uz);
    const Scalar c0 = ut / rho, s0 = uz / rho;
    const auto rates0 = Forms::direction_rates(K, mu, c0, s0);
    const Scalar f0 = rates0[1];
    if (stop_beyond_end(rho, rates0[0], c0, s0)) return false;
    // The direction turns towards the first invariant direction ahead of it in f's sense; delta is the
    // angle still to turn, negated (th0 - th*). Every direction is invariant when the list is empty.
    const Scalar pi2 = Scalar(2) * pi<Scalar>();
    Scalar c = c0, s = s0, delta(0);
    if (!invariant().empty()) {
      std::optional<Scalar> nearest;
      for (const auto& d : invariant()) {
        Scalar da = atan2(d.c * s0 - d.s * c0, d.c * c0 + d.s * s0);
        // Within rounding of a direction f0's sign is noise: that direction, whichever side.
        if (abs(da) > Scalar(64) * eps) {
          if (f0 > Scalar(0) && da > Scalar(0)) da -= pi2;
          if (f0 < Scalar(0) && da < Scalar(0)) da += pi2;
        }
        if (!nearest || abs(da) < abs(*nearest)) nearest = da, c = d.c, s = d.s;
      }
      delta = *nearest;
    }
    constexpr double kReach = 1;  // radians: farther, the series would need more terms than a step
    if (failed_at && failed_compressing == compressing && rho > (*failed_at)[0] / Scalar(2) &&
        abs(delta) > (*failed_at)[1] / Scalar(2))
      return false;
    const auto failed = [&] {
      failed_at = {rho, Scalar(abs(delta))}, failed_compressing = compressing;
      return false;
    };
    if (!(abs(delta) <= Scalar(kReach))) return false;  // cheap to find again: not a failure to remember
    // The rest is rho F: to eps of the impact's scale, F is needed to eps / rho.
    const StopTail<Scalar> tail = stop_tail(K, map, mu, c, s, delta, Scalar(eps / rho), order);
    if (!tail.converged) return failed();
    // No phase ends within the rest. On the way U_n = U_n(stop) + rho K_n . F(th) with rho falling from
    // its value now, so U_n lies within rho (K_n . F_0 -+ variation) of U_n(stop); x only grows, and W
    // only falls while U_n <= 0.
    if (!tail.shrinking) return failed();
    const Vec3<Scalar> P_stop = Vec3<Scalar>(x, a, b) + tail.F * rho;
    const Scalar U_n_stop = (U_i - K * P_stop)(0);
    const Scalar dx = rho * tail.F(0);
    const Scalar W_stop = W + U_n_stop * dx + rho * rho * tail.G;
    const Scalar U_n_low = U_n_stop - rho * std::max(Scalar(0), Scalar(tail.normal_variation - tail.KnF0));
    const Scalar U_n_high = U_n_stop + rho * std::max(Scalar(0), Scalar(tail.KnF0 + tail.normal_variation));
    bool clear = false;
    if (compressing) clear = U_n_low > Scalar(0);
    else if (law == RestitutionLaw::energetic) clear = U_n_high <= Scalar(0) && end_value(P_stop(0), W_stop, U_n_stop) > Scalar(0);
    else if (law == RestitutionLaw::poisson) clear = end_value(P_stop(0), W_stop, U_n_stop) > Scalar(0);
    else clear = end_value(P_stop(0), W_stop, U_n_low) > Scalar(0);
    if (!clear) return failed();
    // The path on the way, from the closed form: at angles delta (1 - i / k) (by rho when the direction
    // does not turn); at the hardware precisions, which the figures draw (100 digits has no exp).
    if constexpr (std::is_floating_point_v<Scalar>) if (record) {
      constexpr int kPoints = 4 * kPathPoints;  // one closed form over what may be the whole slide
      const bool turns = delta != Scalar(0) && tail.f_n[1] < Scalar(0);
      const std::vector<Scalar> hs = turns ? radius_series(tail) : std::vector<Scalar>{};
      for (int i = 1; i < kPoints; ++i) {
        const Scalar w = Scalar(1) - Scalar(i) / Scalar(kPoints);
        Scalar r = rho * w, G_i = tail.G;
        Vec3<Scalar> F_i = tail.F;
        Scalar th = atan2(s, c);
        if (turns) {
          const auto q = rest_at(tail, hs, delta, Scalar(delta * w));
          r = rho * q[0], F_i = Vec3<Scalar>(q[1], q[2], q[3]), G_i = q[4], th += delta * w;
        }
        const Vec3<Scalar> P_i = P_stop - F_i * r;
        const Scalar U_n_i = (U_i - K * P_i)(0);
        const Scalar W_i = W_stop - U_n_stop * r * F_i(0) - r * r * G_i;
        trace(P_i(0), P_i(1), P_i(2), W_i, Vec3<Scalar>(U_n_i, Scalar(r * cos(th)), Scalar(r * sin(th))));
      }
    }
    x = P_stop(0), a = P_stop(1), b = P_stop(2), W = W_stop;
    h.error_bound += std::max(rho, Scalar(rho * rho)) * tail.last + eps * (Scalar(1) + x);  // rho F, rho^2 G
    turn_to(c, s);
    trace(x, a, b, W, U());
    u_carried.reset(), c_prev.reset(), s_prev.reset();
    return true;
  }

  // Whether, at the rates now, the slide would stop beyond the phase's end: its speed rho falling
  // at `growth` takes about rho / |growth| of impulse, the phase's end within a bound on what is left
  // (compression: V_n over its rate; the energetic end: the work left over |V_n|, or over the rate's
  // square root where V_n is 0). Only a guide for whether the closed form is worth trying (on the
  // benchmark's collisions it spares 9 of 10 attempts on slides that never stop, and costs those that
  // stop no step); the steps try again as the slide slows.
  bool stop_beyond_end(const Scalar& rho, const Scalar& growth, const Scalar& c, const Scalar& s) const {
    using std::sqrt;
    if (!(growth < Scalar(0))) return false;
    const Scalar U_n = U()(0);
    const Scalar s_n = K(0, 0) + mu * (K(0, 1) * c + K(0, 2) * s);  // -dV_n/dp along the slide
    if (!(s_n > Scalar(0))) return false;
    // The end condition's value, falling at s_n (V_n, Newton's) or 1 (x, Poisson's) or as the work.
    const Scalar v = std::max(Scalar(0), compressing ? U_n : end_value(x, W, U_n));
    Scalar left = compressing || law == RestitutionLaw::newton ? Scalar(v / s_n) : v;
    if (!compressing && law == RestitutionLaw::energetic) {
      left = sqrt(Scalar(2) * v / s_n);
      if (U_n < Scalar(0)) left = std::min(left, Scalar(v / -U_n));
    }
    return rho / -growth > left;
  }

  bool fail(const char* why) {
    h.failure = why;
    return false;
  }

  // The constant-rate phase to the end: closed forms.
  bool constant_rate() {
    using std::sqrt;
    const Vec3<Scalar> g = -(K * Vec3<Scalar>(Scalar(1), f_t, f_z));  // dU/dx
    if (!(g(0) < Scalar(0)))
      return fail("the normal relative velocity does not decrease while the contact sticks or slides out (friction "
                  "jams the contact)");
    const Scalar s = -g(0);
    auto advance = [&](const Scalar& d) {
      const Scalar U_n = U()(0);
      trace_step(d, [&](const Scalar& t) {
        const Vec3<Scalar> U_t = U() + g * t;
        return std::array<Scalar, 7>{x + t, a + f_t * t, b + f_z * t, W + U_n * t - s * t * t / Scalar(2), U_t(0), U_t(1), U_t(2)};
      }, 4 * kPathPoints);  // one closed form over what may be most of the impact
      W += U_n * d - s * d * d / Scalar(2);
      x += d, a += f_t * d, b += f_z * d;
    };
    if (compressing) {
      advance(Scalar(std::max(Scalar(0), Scalar(U()(0) / s))));
      add_location_rounding(Scalar(-s), Scalar(0));
      end_compression(U());
    }
    const Scalar U_n = U()(0);
    Scalar d(0);
    switch (law) {
      case RestitutionLaw::energetic: {
        const Scalar left = W - (Scalar(1) - e * e) * W_c;  // the work still to release
        if (left > Scalar(0)) d = Scalar(2) * left / (sqrt(U_n * U_n + Scalar(2) * s * left) - U_n);
        break;
      }
      case RestitutionLaw::poisson: d = std::max(Scalar(0), Scalar((Scalar(1) + e) * x_c - x)); break;
      case RestitutionLaw::newton: d = std::max(Scalar(0), Scalar((U_n + e * U_i(0)) / s)); break;
    }
    advance(d);
    if (law == RestitutionLaw::energetic) add_location_rounding(U()(0), Scalar(-s));  // dW/dx = U_n
    else add_location_rounding(law == RestitutionLaw::newton ? Scalar(-s) : Scalar(-1), Scalar(0));
    return true;
  }

  // The first root in (lo, hi] of the polynomial c whose value at lo is positive, if it has one there.
  std::optional<Scalar> first_root(const std::vector<Scalar>& c, const Scalar& lo, const Scalar& hi) const {
    constexpr std::size_t kSamples = 4;
    std::array<Scalar, kSamples> at;
    for (std::size_t i = 0; i < kSamples; ++i)
      at[i] = lo + (hi - lo) * Scalar(static_cast<double>(i + 1)) / Scalar(static_cast<double>(kSamples));
    const std::array<Scalar, kSamples> value = polynomial_at_points(c, at);
    for (std::size_t i = 0; i < kSamples; ++i)
      if (!(value[i] > Scalar(0))) return bisect_root(c, i == 0 ? lo : at[i - 1], at[i]);
    return std::nullopt;
  }
  std::optional<Scalar> first_root(const std::vector<Scalar>& c, const Scalar& H) const { return first_root(c, Scalar(0), H); }

  void turn_to(const Scalar& c, const Scalar& s) {
    using std::abs;
    using std::atan2;
    if (c_prev) h.swerve_deg += degrees(Scalar(abs(atan2(*c_prev * s - *s_prev * c, *c_prev * c + *s_prev * s))));
    c_prev = c, s_prev = s;
  }

  // The end condition as a polynomial of a step, positive now: from the step's series of x, W and U_n.
  std::vector<Scalar> ending_polynomial(const std::vector<Scalar>& x_series, const std::vector<Scalar>& W_series,
                                        const std::vector<Scalar>& U_n_series) const {
    if (compressing) return U_n_series;
    std::vector<Scalar> ending;
    if (law == RestitutionLaw::energetic) {
      ending = W_series;
      ending[0] -= (Scalar(1) - e * e) * W_c;
    } else if (law == RestitutionLaw::poisson) {
      ending.resize(x_series.size());
      for (std::size_t j = 0; j < x_series.size(); ++j) ending[j] = -x_series[j];
      ending[0] += (Scalar(1) + e) * x_c;
    } else {
      ending = U_n_series;
      ending[0] += e * U_i(0);
    }
    return ending;
  }

  // The step whose last two terms of every series (each relative to its scale) are eps, Jorba and Zou's
  // rule; the logarithm in Scalar, for at 100 digits the terms pass double's range near a stop.
  double step_size(std::initializer_list<std::pair<const std::vector<Scalar>*, Scalar>> series, double cap) const {
    using std::abs;
    using std::log;
    const std::size_t n = series.begin()->first->size();
    std::optional<Scalar> exponent;
    for (std::size_t j = n - 2; j < n; ++j) {
      Scalar c(0);
      for (const auto& [v, scale] : series) c = std::max(c, Scalar(abs((*v)[j]) / scale));
      if (c > Scalar(0)) {
        const Scalar e_j = (log_eps - log(c)) / Scalar(static_cast<double>(j));
        if (!exponent || e_j < *exponent) exponent = e_j;
      }
    }
    return exponent ? std::min(cap, std::exp(to_double(*exponent))) : cap;
  }
  const Scalar log_eps = [] { using std::log; return Scalar(log(std::numeric_limits<Scalar>::epsilon())); }();

  // The phase's end reached inside a step: compression's end, or the impact's.
  bool phase_ended(const Vec3<Scalar>& U_now) {
    if (compressing) {
      end_compression(U_now);
      if (!(end_value(x, W, U_now(0)) > Scalar(0))) return finish_sliding(U_now), false;
      return true;
    }
    return finish_sliding(U_now), false;
  }

  // One step of a slide slower than kApproach of the approach speed or slowing, in tau (approach_series.hpp), to
  // sliding at 16 eps of it, where the contact is taken to stop: the slide that skips is at most
  // 16 eps over the growth, added to the bound with the steps' truncation.
  bool approach_step(int order) {
    using std::abs;
    using std::sqrt;
    if (!u_carried) {
      const Vec3<Scalar> U_now = U();
      u_carried = {U_now(1), U_now(2)};
    }
    if ((*u_carried)[0] != Scalar(0) || (*u_carried)[1] != Scalar(0))
      if (stop_in_closed_form(order)) return false;
    ApproachSeries<Scalar>& ser = tau_series;
    approach_series_into(ser, speed_buffer, K, U_i, mu, x, a, b, W, (*u_carried)[0], (*u_carried)[1], order);
    const std::size_t n = ser.x.size();
    const Scalar rho0 = sqrt(ser.u_t[0] * ser.u_t[0] + ser.u_z[0] * ser.u_z[0]);
    if (!(rho0 > Scalar(0))) return u_carried.reset(), c_prev.reset(), s_prev.reset(), false;  // at rest already
    // u to eps of itself (the carried direction), the impulse and the work to eps of the impact's scale:
    // W's terms carry rho^2, whose series grows twice as fast.
    Scalar H(step_size({{&ser.u_t, rho0}, {&ser.u_z, rho0}, {&ser.x, Scalar(1)}, {&ser.W, Scalar(1)}, {&ser.a, Scalar(1)}, {&ser.b, Scalar(1)}}, 1e6));
    const auto along = [&](const Scalar& t) {
      return std::array<Scalar, 7>{polynomial_at(ser.x, t), polynomial_at(ser.a, t), polynomial_at(ser.b, t), polynomial_at(ser.W, t),
                                   polynomial_at(ser.U_n, t), polynomial_at(ser.u_t, t), polynomial_at(ser.u_z, t)};
    };
    // The truncation of the step as far as it went: its last term there.
    const auto truncation = [&](const Scalar& to) {
      Scalar last(0);
      for (const auto* v : {&ser.x, &ser.a, &ser.b, &ser.W, &ser.u_t, &ser.u_z}) last = std::max(last, Scalar(abs((*v)[n - 1])));
      Scalar Hn(1);
      for (std::size_t j = 0; j + 1 < n; ++j) Hn *= to;
      h.error_bound += last * Hn + eps * (Scalar(1) + x);
      ++h.steps;
    };
    // The state `t` into the step; its direction turned to.
    const auto reach = [&](const Scalar& t) {
      const auto q = polynomials_at<6>({&ser.x, &ser.a, &ser.b, &ser.W, &ser.u_t, &ser.u_z}, t);
      x = q[0], a = q[1], b = q[2], W = q[3];
      u_carried = {q[4], q[5]};
      const Scalar rho = sqrt(q[4] * q[4] + q[5] * q[5]);
      if (rho > Scalar(0)) turn_to(Scalar(q[4] / rho), Scalar(q[5] / rho));
    };
    bool ends = false;
    Scalar from(0);
    std::vector<Scalar> ending = ending_polynomial(ser.x, ser.W, ser.U_n);
    std::optional<Scalar> root = first_root(ending, H);
    if (root && compressing) {
      // Compression ends inside the step; the same series carries the slide on into restitution, to the
      // step's end or the impact's.
      trace_step(*root, along);
      reach(*root);
      add_location_rounding(ending, ser.x, *root);
      if (!phase_ended(U())) return truncation(*root), u_carried.reset(), false;  // no restitution
      from = *root;
      ending = ending_polynomial(ser.x, ser.W, ser.U_n);
      root = first_root(ending, from, H);
    }
    if (root) H = *root, ends = true;
    truncation(H);
    trace_step(from, H, along);
    reach(H);
    const Vec3<Scalar> U_now = U();
    const Scalar ut = (*u_carried)[0], uz = (*u_carried)[1];
    const Scalar rho = sqrt(ut * ut + uz * uz);
    if (ends) {
      add_location_rounding(ending, ser.x, H);
      phase_ended(U_now);  // the impact's end
      return u_carried.reset(), false;
    }
    if (rho <= Scalar(16) * eps) {
      u_carried.reset();
      const Scalar g = rho > Scalar(0) ? Forms::direction_rates(K, mu, Scalar(ut / rho), Scalar(uz / rho))[0] : Scalar(-1);
      // The slide skipped: Delta x <= rho / |g|, the tangential impulse's change of rate at most 2 mu.
      h.error_bound += g < Scalar(0) ? Scalar(rho * (Scalar(1) + Scalar(2) * mu / -g)) : Scalar(1);
      c_prev.reset(), s_prev.reset();
      return false;
    }
    return true;
  }

  // One Taylor step of the sliding phase; false when the phase is over (sliding stopped or the impact
  // ended) or failed.
  bool slide_step(int order) {
    using std::abs;
    using std::sqrt;
    {
      const Vec3<Scalar> U_now = U();
      const Scalar ut = u_carried ? (*u_carried)[0] : U_now(1), uz = u_carried ? (*u_carried)[1] : U_now(2);
      // In tau below kApproach, and wherever the slide shrinks: its steps in x only approach a stop
      // geometrically (their radius is the distance to it), those in tau an e-fold at a time.
      const Scalar rho = sqrt(ut * ut + uz * uz);
      if (rho <= Scalar(kApproach) || Forms::direction_rates(K, mu, Scalar(ut / rho), Scalar(uz / rho))[0] < Scalar(0)) return approach_step(order);
      u_carried.reset();
    }
    const SlidingSeries<Scalar> ser = sliding_series(K, U_i, mu, x, a, b, W, order);
    const std::size_t n = ser.a.size();
    // At most 1 + x, so that a series that ends (no swerve) still steps through the impact's scale.
    Scalar H(step_size({{&ser.a, Scalar(1)}, {&ser.b, Scalar(1)}}, to_double(Scalar(Scalar(1) + x))));
    if (!(H > eps * (Scalar(1) + x))) return fail("the sliding phase's step fell below the precision"), false;
    // The events the step may hold, each a polynomial positive now.
    std::vector<Scalar> radial(n);  // u(h) . u(0)
    for (std::size_t j = 0; j < n; ++j) radial[j] = ser.u_t[j] * ser.u_t[0] + ser.u_z[j] * ser.u_z[0];
    std::vector<Scalar> x_series(n, Scalar(0));
    x_series[0] = x, x_series[1] = Scalar(1);
    const std::vector<Scalar> ending = ending_polynomial(x_series, ser.W, ser.U_n);
    enum { none, stop, phase } what = none;
    const auto ends = first_root(ending, H);
    if (ends) H = *ends, what = phase;
    const auto stops = first_root(radial, H);
    Scalar rho_at_stop(0);
    if (stops) {
      const Scalar ut = polynomial_at(ser.u_t, *stops), uz = polynomial_at(ser.u_z, *stops);
      rho_at_stop = sqrt(ut * ut + uz * uz);
      // At u = 0 within rounding, a stop (a slide straight to rest); below kApproach the step ends there
      // and the slide is followed in tau from it; a crossing farther out is the direction turning past a
      // right angle within the step: no event.
      if (rho_at_stop <= Scalar(64) * eps) H = *stops, what = stop;
      else if (rho_at_stop <= Scalar(kApproach)) H = *stops, what = none;
    }
    // The truncation of this step: its last term at H.
    Scalar last(0);
    for (const auto* v : {&ser.a, &ser.b, &ser.W}) last = std::max(last, Scalar(abs((*v)[n - 1])));
    Scalar Hn(1);
    for (std::size_t j = 0; j + 1 < n; ++j) Hn *= H;
    h.error_bound += last * Hn + eps * (Scalar(1) + x);
    ++h.steps;
    trace_step(H, [&](const Scalar& t) {
      return std::array<Scalar, 7>{x + t, polynomial_at(ser.a, t), polynomial_at(ser.b, t), polynomial_at(ser.W, t),
                                   polynomial_at(ser.U_n, t), polynomial_at(ser.u_t, t), polynomial_at(ser.u_z, t)};
    });
    const auto at_H = polynomials_at<3>({&ser.a, &ser.b, &ser.W}, H);
    x += H, a = at_H[0], b = at_H[1], W = at_H[2];
    if (what == phase) add_location_rounding(ending, x_series, H);
    if (what == stop) {
      // The direction it arrived along: minus the velocity's derivative there.
      const Scalar vt = -polynomial_at(derivative(ser.u_t), H), vz = -polynomial_at(derivative(ser.u_z), H);
      const Scalar len = sqrt(vt * vt + vz * vz);
      if (len > Scalar(0)) turn_to(Scalar(vt / len), Scalar(vz / len));
      // The slide left at the root: at most rho over the speed's rate len, the rate of P_t changing by 2 mu.
      h.error_bound += len > Scalar(0) ? Scalar(rho_at_stop * (Scalar(1) + Scalar(2) * mu / len)) : Scalar(1);
      c_prev.reset(), s_prev.reset();
      return false;
    }
    const Vec3<Scalar> U_now = U();
    const Scalar rho = sqrt(U_now(1) * U_now(1) + U_now(2) * U_now(2));
    turn_to(Scalar(U_now(1) / rho), Scalar(U_now(2) / rho));
    if (what == phase) return phase_ended(U_now);
    return true;
  }

  void finish_sliding(const Vec3<Scalar>& U_now) {
    using std::atan2;
    // The carried velocity where the slide was followed in tau: U_i - K P is rounding there.
    const Scalar ut = u_carried ? (*u_carried)[0] : U_now(1), uz = u_carried ? (*u_carried)[1] : U_now(2);
    h.final_direction_deg = degrees(Scalar(atan2(uz, ut)));
    ended = true;
  }
  bool ended = false;

  History<Scalar> run() {
    using std::sqrt;
    const int order = taylor_order<Scalar>();
    const Scalar rho_i = sqrt(U_i(1) * U_i(1) + U_i(2) * U_i(2));
    trace(x, a, b, W, U_i);
    if (rho_i <= Scalar(1024) * eps) {
      h.error_bound += rho_i;
      if (!from_rest(true)) return h;
    } else {
      event(EventKind::slip, U());
      c_prev = U_i(1) / rho_i, s_prev = U_i(2) / rho_i;
      while (slide_step(order)) {
        if (h.steps >= kMaxSteps) return fail("the sliding phase took more than 4096 steps"), h;
        if (x > Scalar(kMaxImpulse)) return fail("the impact does not end within 10^6 m' |V_ri| of normal impulse"), h;
      }
      if (h.failure) return h;
      if (!ended && !from_rest(false)) return h;
    }
    if (!ended && !constant_rate()) return h;
    const Vec3<Scalar> U_f = U();
    h.work_restitution = W_c - W;
    event(EventKind::end, U_f);
    return h;
  }
};

}  // namespace detail

// The impact followed from m', K, V_ri (contact axes, V_rn > 0) at friction mu and restitution e; the
// events are recorded when `record` (a report), else only the end. A failure leaves the impulse unset.
template <typename Scalar, typename Forms = GeneratedForms>
History<Scalar> integrate(const Mat3<Scalar>& K, const Scalar& m_prime, const Vec3<Scalar>& V_ri, const Scalar& mu,
                          const Scalar& e, RestitutionLaw law, bool record = true) {
  const Scalar v0 = V_ri.norm();
  detail::Follow<Scalar, Forms> f(K, Vec3<Scalar>(V_ri / v0), mu, e, law, record);
  History<Scalar> h = f.run();
  if (h.failure) return h;
  const Scalar p0 = m_prime * v0;
  h.P_C = Vec3<Scalar>(f.x, f.a, f.b) * p0;
  h.relative_error = h.error_bound * p0 / h.P_C.norm();
  h.V_rf = f.U() * v0;
  for (auto& ev : h.events) ev.p *= p0, ev.V_C *= v0, ev.normal_work *= p0 * v0;
  for (auto& q : h.path) q.P_C *= p0, q.V_C *= v0, q.normal_work *= p0 * v0;
  h.work_compression *= p0 * v0, h.work_restitution *= p0 * v0;
  return h;
}

}  // namespace impact3d::stronge
