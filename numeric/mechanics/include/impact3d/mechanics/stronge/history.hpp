// What Stronge's integrated impulse reports beside the impulse: the impact as it happens, through the
// normal impulse p (Stronge, Impact Mechanics, ch. 5; J. Appl. Mech. 58 (1991) 1049).
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "impact3d/scalar/types.hpp"

namespace impact3d::stronge {

// How the impact ends, given the case's restitution e (Stronge's energetic coefficient, Poisson's, or
// Newton's).
enum class RestitutionLaw { energetic, poisson, newton };

inline constexpr std::string_view law_names[] = {"energetic", "poisson", "newton"};

inline std::string_view law_name(RestitutionLaw law) { return law_names[static_cast<int>(law)]; }

// slip: sliding begins (at p = 0, or from rest along an invariant direction when the contact cannot
// stick); stick: sliding stops and the contact sticks; reversal: sliding stops and resumes along an
// invariant direction of the tangential map; compression end: V_n = 0; end: the law's end of impact.
enum class EventKind { slip, stick, reversal, compression_end, end };

inline constexpr std::string_view event_names[] = {"slip", "stick", "reversal", "compression end", "end"};

inline std::string_view event_name(EventKind k) { return event_names[static_cast<int>(k)]; }

template <typename Scalar>
struct Event {
  EventKind kind;
  Scalar p;              // normal impulse so far [N s]
  Vec3<Scalar> V_C;      // relative velocity there, contact axes (n, t, z) [m/s]
  Scalar normal_work;    // integral of V_n dp from the start [J]: positive while compressing
};

// A point on the way, for figures: the polynomials of each step (and the closed forms after sliding
// stops) evaluated at kPathPoints points a step (four times as many through the closed form), and the
// closed-form rest of a slide at 32 points (at double and long double, which the figures draw; else its end).
template <typename Scalar>
struct PathPoint {
  Vec3<Scalar> P_C;      // impulse so far, contact axes [N s]; P_C(0) is p
  Vec3<Scalar> V_C;      // relative velocity there [m/s]
  Scalar normal_work;    // [J]
};

inline constexpr int kPathPoints = 8;

template <typename Scalar>
struct History {
  Vec3<Scalar> P_C;                 // the impulse on vehicle 1 at the end, contact axes
  Vec3<Scalar> V_rf;                // the relative velocity at the end, contact axes
  std::vector<Event<Scalar>> events;  // in order of p
  std::vector<PathPoint<Scalar>> path;  // recorded with the events: from p = 0 to the end
  Scalar swerve_deg = Scalar(0);    // total turning of the sliding direction while it slides
  std::optional<Scalar> final_direction_deg;  // the sliding direction at the end (from t toward z), if sliding
  Scalar work_compression = Scalar(0);  // normal work of compression [J]
  Scalar work_restitution = Scalar(0);  // normal work released in restitution [J], >= 0
  // Invariant directions along which sliding could resume at the last reversal or slip from rest that
  // Coulomb's law allows; more than one means the choice (the fastest growing) was not forced.
  int diverging_directions = 0;
  int steps = 0;                    // Taylor steps of the sliding phase
  // Bound on the integration's error, relative to |V_ri| (velocities) and m' |V_ri| (impulses): the
  // truncation of every step, the events' location and a contact taken to have stopped sliding.
  Scalar error_bound = Scalar(0);
  Scalar relative_error = Scalar(0);  // the same relative to |P_C|
  const char* failure = nullptr;    // why the impact could not be followed, when it could not
};

}  // namespace impact3d::stronge
