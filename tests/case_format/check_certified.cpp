// Certified results (issue 14) by substitution: the balls of the certified solve hold the exact
// fractions of the suite's rational cases (both engines), hold the 100-digit solve of seeded random
// cases within that solve's own rounding bound, and narrow by the factor that doubling the bits
// promises.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <flint/fmpq.h>
#include <fmt/format.h>

#include "impact3d/mechanics/certified.hpp"
#include "impact3d/mechanics/exact_analysis.hpp"
#include "impact3d/scalar/multiprecision.hpp"
#include "case_files.hpp"

namespace check_certified {

using namespace impact3d;
using namespace impact3d::test;

namespace {

// The suite's cases whose rotations are rational (as exam_exact lists them), and Figure 8's.
const char* kRational[] = {"planar_right_angle.json", "restitution_zero.json", "restitution_one.json",
                           "hard_lever_arms_near_zero.json", "exact_rational_rotations.json"};

bool holds(const Ball& b, const rational& q) {
  fmpq_t f;
  fmpq_init(f);
  const std::string text = boost::multiprecision::numerator(q).str() + "/" + boost::multiprecision::denominator(q).str();
  fmpq_set_str(f, text.c_str(), 10);
  const bool in = arb_contains_fmpq(b.get(), f);
  fmpq_clear(f);
  return in;
}

struct Tally {
  int checked = 0;
  void vec(const Vec3<Ball>& b, const Vec3<rational>& q) {
    for (int k = 0; k < 3; ++k) one(b[k], q[k]);
  }
  void one(const Ball& b, const rational& q) {
    INFO(q);
    CHECK(holds(b, q));
    ++checked;
  }
};

template <typename T>
Scene<T> widen(const Scene<double>& s) {
  Scene<T> t;
  auto v = [](const Vec3<double>& x) { return Vec3<T>(T(x.x()), T(x.y()), T(x.z())); };
  auto m = [](const Mat3<double>& x) {
    Mat3<T> r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r(i, j) = T(x(i, j));
    return r;
  };
  for (int i = 0; i < 2; ++i) {
    const auto& b = s.body[i];
    t.body[i].mass = T(b.mass);
    t.body[i].J_B = m(b.J_B);
    t.body[i].R_WB = m(b.R_WB);
    t.body[i].v_W = v(b.v_W);
    t.body[i].w_B = v(b.w_B);
    t.body[i].p_CgIc_B = v(b.p_CgIc_B);
  }
  t.R_WC = m(s.R_WC);
  t.restitution = T(s.restitution);
  return t;
}

template <typename T>
std::vector<Strategy<T>> widen(const std::vector<Strategy<double>>& st) {
  std::vector<Strategy<T>> out;
  auto o = [](const std::optional<double>& x) { return x ? std::optional<T>(T(*x)) : std::nullopt; };
  for (const auto& s : st) {
    if (const auto* p = std::get_if<PcCrash<double>>(&s)) out.push_back(PcCrash<T>{T(p->mu)});
    else if (const auto* w = std::get_if<Wach<double>>(&s)) out.push_back(Wach<T>{T(w->mu), w->limit});
    else {
      const auto& b = std::get<Brach<double>>(s);
      out.push_back(Brach<T>{o(b.mu_t), o(b.mu_z)});
    }
  }
  return out;
}

// x100 as a ball widened by `allowance` (the 100-digit solve's own error), then whether it meets b.
bool meets(const Ball& b, const mp::float100& x100, const mp::float100& allowance) {
  const BallBits bits(512);
  Ball x(x100.str(110, std::ios_base::scientific));
  Ball a(allowance.str(10, std::ios_base::scientific));
  arb_add_error(x.get(), a.get());
  return arb_overlaps(b.get(), x.get());
}

// Both impulse centres on the normal line, a 3-4-5 direction (the frame's entries are not dyadic, so the
// balls carry radii), the bodies approaching along it with no sliding: K n is parallel to n.
case_format::CaseSpec case_on_345_normal(const std::string& restitution, const std::string& strategies) {
  return case_format::read_case(R"({"name": "no sliding along a 3-4-5 normal", "units": "SI",
    "vehicles": [
      {"name": "A", "mass": 1450, "inertia": {"Ixx": 520, "Iyy": 2200, "Izz": 2400},
       "orientation_deg": {"yaw": 0, "pitch": 0, "roll": 0}, "velocity": [7.8, 10.4, 0],
       "impulse_center": [1.2, 1.6, 0], "angular_velocity": [0, 0, 0]},
      {"name": "B", "mass": 1700, "inertia": {"Ixx": 650, "Iyy": 2900, "Izz": 3100},
       "orientation_deg": {"yaw": 0, "pitch": 0, "roll": 0}, "velocity": [0, 0, 0],
       "impulse_center": [-0.9, -1.2, 0], "angular_velocity": [0, 0, 0]}],
    "contact": {"normal": [-3, -4, 0], "tangent": [4, -3, 0]}, "restitution": )" + restitution + R"(,
    "strategy": )" + strategies + "}");
}

}  // namespace

TEST_CASE("certified balls hold the exact fractions of every rational case", "[certified]") {
  Tally tally;
  int cases = 0;
  std::vector<std::string> paths;
  for (const char* name : kRational) paths.push_back(std::string(IMPACT3D_CASES_DIR) + "/" + name);
  paths.push_back(example("fig8_side_impact.json"));
  for (const auto& path : paths) {
    INFO(path);
    const case_format::CaseSpec c = load_spec(path);
    for (Engine engine : kEngines) {
      const ExactAnalysis x = exact_analyze(case_format::to_scene<rational>(c), case_format::to_strategies<rational>(c), engine);
      const BallBits bits(128);
      const CertifiedAnalysis b = certified_analyze(case_format::to_scene<Ball>(c), case_format::to_strategies<Ball>(c), engine);
      ++cases;
      tally.one(b.analysis.m_prime, x.m_prime);
      for (int k = 0; k < 3; ++k) tally.vec(Vec3<Ball>(b.analysis.K.row(k).transpose()), Vec3<rational>(x.K.row(k).transpose()));
      tally.vec(b.analysis.V_ri, x.V_ri);
      tally.vec(b.analysis.space.P_max_loss, x.P_max_loss);
      for (std::size_t k = 0; k < x.results.size(); ++k) {
        if (!x.results[k].solution) continue;
        const auto& q = *x.results[k].solution;
        const auto& s = b.analysis.solutions[k];
        tally.vec(s.impulse.P_C, q.impulse.P_C);
        tally.vec(s.P_W, q.P_W);
        tally.vec(s.V_rf, q.V_rf);
        for (int i = 0; i < 2; ++i) {
          tally.vec(s.after[i].v_W, q.after[i].v_W);
          tally.vec(s.after[i].w_B, q.after[i].w_B);
          tally.vec(s.change[i].dv_W, q.change[i].dv_W);
        }
        tally.one(s.energy_loss, q.energy_loss);
        for (const auto& [ball, exact] : {std::pair{&s.impulse.mu, &q.impulse.mu}, std::pair{&s.impulse.gir, &q.impulse.gir},
                                          std::pair{&s.impulse.cir, &q.impulse.cir}})
          if (*ball && *exact) tally.one(**ball, **exact);
        // What the balls could not decide on a rational case can only be an exact tie.
        const auto ties = exact_ties(b.decisions[k], case_format::to_strategies<rational>(c)[k], q, s);
        for (const auto& d : b.decisions[k]) {
          INFO(d.name << ": " << d.detail);
          if (d.status == DecisionStatus::undecided) CHECK(std::find(ties.begin(), ties.end(), d.name) != ties.end());
        }
      }
    }
  }
  CHECK(cases == 12);
  CHECK(tally.checked > 1000);
}

TEST_CASE("with no sliding and a zero cap, the balls' undecided plane, axis and ratio are exact ties", "[certified]") {
  // A constructed rational case (case_on_345_normal): each lever arm along n, so K n is parallel to n,
  // K_tn = K_zn = 0 and, with no sliding, both caps are exactly zero (eqs 19-20), as are the ratio Wach
  // uses and, for pc-crash, the Full Impact's contact-plane part. The balls hold 0 with a radius and
  // cannot decide; exact arithmetic says each is a tie. Each undecided decision named below must be
  // among the undecided, or the case did not reach what it tests.
  const case_format::CaseSpec c = case_on_345_normal("0.1", R"([{"name": "wach", "mu": 0.3, "limit": "cir"},
    {"name": "wach", "mu": 0, "limit": "gir"}, {"name": "pc-crash", "mu": 0.5}])");
  namespace n = decision_names;
  // The ratio Wach uses at mu = 0 is the cap's ball only when the cap's (undecided) comparison caps it;
  // else it is mu's exact zero, a tie by the balls themselves: which, the engine's midpoint says. At
  // mu = 0.3 it is capped (0.3 exceeds the cap's ball).
  const std::vector<std::vector<const char*>> expected = {{n::plane_direction, n::fallback_direction, n::ratio_sign},
                                                          {n::plane_direction, n::fallback_direction},
                                                          {n::plane_direction}};
  int checked = 0;
  for (Engine engine : kEngines) {
    const ExactAnalysis x = exact_analyze(case_format::to_scene<rational>(c), case_format::to_strategies<rational>(c), engine);
    const BallBits bits(128);
    const CertifiedAnalysis b = certified_analyze(case_format::to_scene<Ball>(c), case_format::to_strategies<Ball>(c), engine);
    for (std::size_t k = 0; k < 3; ++k) {
      INFO("engine " << static_cast<int>(engine) << ", strategy " << k);
      REQUIRE(x.results[k].solution);
      const auto ties = exact_ties(b.decisions[k], case_format::to_strategies<rational>(c)[k], *x.results[k].solution,
                                   b.analysis.solutions[k]);
      for (const char* name : expected[k]) {
        INFO(name);
        const auto d = std::find_if(b.decisions[k].begin(), b.decisions[k].end(), [&](const Decision& e) { return e.name == name; });
        REQUIRE(d != b.decisions[k].end());
        CHECK(d->status == DecisionStatus::undecided);
        ++checked;
      }
      for (const auto& d : b.decisions[k]) {
        INFO(d.name << ": " << d.detail);
        if (d.status == DecisionStatus::undecided) CHECK(std::find(ties.begin(), ties.end(), d.name) != ties.end());
      }
      // An undecided comparison that may choose the impulse and is no tie, just after the plane's: the
      // balls may have gone where the exact solve did not, so the plane stays a tie and nothing after it is.
      auto guarded = b.decisions[k];
      const auto plane =
          std::find_if(guarded.begin(), guarded.end(), [](const Decision& e) { return e.name == n::plane_direction; });
      REQUIRE(plane != guarded.end());
      guarded.insert(plane + 1, Decision{n::unnamed, DecisionStatus::undecided, "inserted by the test"});
      CHECK(exact_ties(guarded, case_format::to_strategies<rational>(c)[k], *x.results[k].solution, b.analysis.solutions[k]) ==
            std::vector<std::string>{n::plane_direction});
    }
  }
  CHECK(checked == 2 * 6);
}

TEST_CASE("a decision that asks several questions is a tie only where each one left open is exactly zero", "[certified]") {
  // The 3-4-5 case above, pc-crash sticking (mu = 5 against a GIR of 0): V_rf's contact-plane part is
  // exactly zero, as is V_ri's, and V_rf's normal part is -e V_rn, with e so small that at 24 bits its
  // ball holds 0 too. The volume (Figure 2) asks of all three: two exact zeros and one nonzero left open
  // is no tie, though either zero alone once made it one. The swerve asks whether the initial sliding
  // is zero, which it is exactly: a tie. (The sliding along z, exactly zero in balls too, is no question.)
  const case_format::CaseSpec c = case_on_345_normal("0.000000001", R"([{"name": "pc-crash", "mu": 5}])");
  namespace n = decision_names;
  int checked = 0;
  for (Engine engine : kEngines) {
    INFO("engine " << static_cast<int>(engine));
    const ExactAnalysis x = exact_analyze(case_format::to_scene<rational>(c), case_format::to_strategies<rational>(c), engine);
    REQUIRE(x.results[0].solution);
    const auto& q = *x.results[0].solution;
    REQUIRE(q.V_rf.x() != rational(0));
    REQUIRE(q.V_rf.y() == rational(0));  // what made the volume a tie before
    const BallBits bits(24);
    const CertifiedAnalysis b = certified_analyze(case_format::to_scene<Ball>(c), case_format::to_strategies<Ball>(c), engine);
    const auto& s = b.analysis.solutions[0];
    REQUIRE(s.V_rf.x().contains_zero());
    auto status = [&](const char* name) {
      const auto d = std::find_if(b.decisions[0].begin(), b.decisions[0].end(), [&](const Decision& e) { return e.name == name; });
      REQUIRE(d != b.decisions[0].end());
      return d->status;
    };
    REQUIRE(status(n::volume) == DecisionStatus::undecided);
    REQUIRE(status(n::swerve) == DecisionStatus::undecided);
    const auto ties = exact_ties(b.decisions[0], case_format::to_strategies<rational>(c)[0], q, s);
    CHECK(std::find(ties.begin(), ties.end(), n::volume) == ties.end());
    CHECK(std::find(ties.begin(), ties.end(), n::swerve) != ties.end());
    CHECK(std::find(ties.begin(), ties.end(), n::plane_direction) != ties.end());
    ++checked;
  }
  CHECK(checked == 2);
}

TEST_CASE("certified balls hold the 100-digit solve of seeded random cases", "[certified]") {
  std::mt19937_64 g(20261125);
  int cases = 0, compared = 0, undecided = 0;
  for (int n = 0; n < 12; ++n) {
    const Scene<double> s = random_scene(g);
    const auto st = every_strategy(0.45);
    const Analysis<mp::float100> a100 = analyze(widen<mp::float100>(s), widen<mp::float100>(st));
    const BallBits bits(256);
    const CertifiedAnalysis b = certified_analyze(widen<Ball>(s), widen<Ball>(st));
    ++cases;
    for (std::size_t k = 0; k < st.size(); ++k) {
      bool decided = true;
      for (const auto& d : b.decisions[k]) decided = decided && d.status != DecisionStatus::undecided;
      if (!decided) {
        ++undecided;
        continue;
      }
      const auto& s100 = a100.solutions[k];
      const auto& sb = b.analysis.solutions[k];
      // The 100-digit solve is within its rounding bound (rounding.hpp) of the exact value, relative to
      // the size of what is compared; the ball holds the exact value.
      const mp::float100 scale_P = s100.impulse.P_C.norm(), scale_v = velocity_scale(widen<mp::float100>(s));
      for (int i = 0; i < 3; ++i) {
        INFO("case " << n << " strategy " << k << " component " << i);
        CHECK(meets(sb.impulse.P_C[i], s100.impulse.P_C[i], s100.rounding_bound * scale_P));
        CHECK(meets(sb.V_rf[i], s100.V_rf[i], s100.rounding_bound * scale_v));
        for (int v = 0; v < 2; ++v) CHECK(meets(sb.after[v].v_W[i], s100.after[v].v_W[i], s100.rounding_bound * scale_v));
        compared += 4;
      }
      CHECK(sb.impulse.regime == s100.impulse.regime);
    }
  }
  CHECK(cases == 12);
  CHECK(undecided == 0);
  CHECK(compared == 12 * 10 * 12);
}

namespace {

// A seeded 3D case as a file would give it: decimal angles (so the rotations are orthonormal in exact
// arithmetic, as the constraint rows assume), products of inertia, angular velocities, pitch and roll.
case_format::CaseSpec random_3d_case(std::mt19937_64& g, const std::string& restitution, const std::string& strategies) {
  std::uniform_int_distribution<int> i(-999, 999);
  const auto d = [&](double scale) { return fmt::format("{:.3f}", scale * i(g) / 1000.0); };
  const auto vehicle = [&](double vx) {
    const std::string j01 = d(40);
    return fmt::format(R"({{"name": "v", "mass": {}, "inertia": [[{}, {}, 0], [{}, {}, 0], [0, 0, {}]],
      "orientation_deg": {{"yaw": {}, "pitch": {}, "roll": {}}}, "velocity": [{}, {}, {}],
      "angular_velocity": [{}, {}, {}], "impulse_center": [{}, {}, {}]}})",
                       1300 + (i(g) + 999) / 2, 600, j01, j01, 2500, 2800, d(180), d(8), d(8), vx, d(6), d(1),
                       d(0.5), d(0.5), d(1), d(2), d(1), d(0.3));
  };
  return case_format::read_case(R"({"name": "seeded 3D", "units": "SI", "vehicles": [)" + vehicle(12) + ", " + vehicle(-12) +
                       R"(], "contact": {"normal_yaw_deg": )" + d(180) + R"(, "normal_pitch_deg": )" + d(10) +
                       R"(, "tangent_roll_deg": )" + d(30) + R"(}, "restitution": )" + restitution +
                       R"(, "strategy": )" + strategies + "}");
}

}  // namespace

// A final sliding that is the strategy's own constraint (a Full Impact's V_rf = -eps V_ri along t and z,
// eqs 10-12; Brach's critical ratio, eqs 25-27; Wach capped at its CIR, eq 19) is computed as a ball
// holding 0. Those questions are answered by the constraint rows (constraint_rows.hpp), "by
// construction", never left undecided; the answers are those of the 100-digit solve's rounding rule, an
// independent route, on seeded 3D cases at restitution 0 (where every such sliding stops) and above.
TEST_CASE("the zeros a strategy's constraint rows impose are decided by construction, as the 100-digit solve finds them",
          "[certified]") {
  std::mt19937_64 g(20261201);
  const std::string strategies = R"([{"name": "pc-crash", "mu": 50}, {"name": "brach", "mu_t": "critical", "mu_z": "critical"},
      {"name": "brach", "mu_t": "critical", "mu_z": 0.1}, {"name": "brach", "mu_t": 0.1, "mu_z": "critical"},
      {"name": "wach", "mu": 50, "limit": "cir"}])";
  namespace n = decision_names;
  int solutions = 0, by_rows = 0, cases = 0;
  while (cases < 12) {
    case_format::CaseSpec c;
    Analysis<mp::float100> a100;
    try {
      c = random_3d_case(g, cases % 3 == 0 ? "0" : "0.3", strategies);
      a100 = analyze(case_format::to_scene<mp::float100>(c), case_format::to_strategies<mp::float100>(c));
    } catch (const case_format::CaseError&) {
      continue;  // not approaching: drawn again
    }
    ++cases;
    const BallBits bits(256);
    const CertifiedAnalysis b = certified_analyze(case_format::to_scene<Ball>(c), case_format::to_strategies<Ball>(c));
    for (std::size_t k = 0; k < c.strategies.size(); ++k) {
      INFO("case " << cases << ", strategy " << k);
      const auto& sb = b.analysis.solutions[k];
      const auto& s100 = a100.solutions[k];
      REQUIRE(sb.impulse.regime == (k == 0 ? Regime::full : k == 4 ? Regime::capped : Regime::as_given));
      bool rows = false;
      for (const auto& d : b.decisions[k]) {
        INFO(d.name << ": " << d.detail);
        if (d.name == n::swerve || d.name == n::volume || d.name == n::z_sliding) CHECK(d.status != DecisionStatus::undecided);
        if (d.name == n::constraint_rows) {
          rows = true;
          CHECK(d.status == DecisionStatus::by_construction);
          CHECK(d.detail.find("by construction") != std::string::npos);
        }
      }
      CHECK(rows);
      by_rows += rows;
      CHECK(sb.t_change == s100.t_change);
      CHECK(sb.z_change == s100.z_change);
      CHECK(sb.volume == s100.volume);
      CHECK(sb.reversed == s100.reversed);
      CHECK(sb.swerve_deg.has_value() == s100.swerve_deg.has_value());
      if (sb.swerve_deg && s100.swerve_deg) CHECK(meets(*sb.swerve_deg, *s100.swerve_deg, mp::float100(1e-60)));
      ++solutions;
    }
  }
  CHECK(solutions == 12 * 5);
  CHECK(by_rows == 12 * 5);
}

TEST_CASE("doubling the bits narrows the enclosures by about the factor the bits promise", "[certified]") {
  std::mt19937_64 g(7);
  int compared = 0;
  for (int n = 0; n < 8; ++n) {
    const Scene<double> s = random_scene(g);
    const std::vector<Strategy<double>> st = {PcCrash<double>{0.4}, Wach<double>{0.4, WachLimit::cir}, Brach<double>{0.3, 0.05}};
    std::array<std::vector<double>, 2> log2_radius;
    for (int round = 0; round < 2; ++round) {
      const BallBits bits(round == 0 ? 128 : 256);
      const CertifiedAnalysis b = certified_analyze(widen<Ball>(s), widen<Ball>(st));
      for (const auto& sol : b.analysis.solutions)
        for (int i = 0; i < 3; ++i)
          log2_radius[round].push_back(mag_get_d_log2_approx(arb_radref(sol.impulse.P_C[i].get())));
    }
    for (std::size_t j = 0; j < log2_radius[0].size(); ++j) {
      // 128 more bits: each radius shrinks by 2^-128; the error propagation's own constants differ a
      // little between the two runs, so 2^-100 to 2^-156 is asked.
      const double shrink = log2_radius[1][j] - log2_radius[0][j];
      INFO("case " << n << " entry " << j << ": log2 shrink " << shrink);
      CHECK(shrink <= -100);
      CHECK(shrink >= -156);
      ++compared;
    }
  }
  CHECK(compared == 8 * 3 * 3);
}

// Balls with a radius (each entry times a third, rounded) are the same ball either side of the diagonal
// and are solved, though Ball's == holds only of exact balls; one entry's radius widened, its midpoint
// kept, makes a tensor that is not symmetric: refused, naming the body and entry (scene.hpp). A check
// by order alone (neither ball below the other) would take it.
TEST_CASE("certified_analyze takes an inertia tensor of the same balls either side of the diagonal, and no other",
          "[certified]") {
  std::mt19937_64 g(20261128);
  const BallBits bits(256);
  Scene<Ball> s = widen<Ball>(random_scene(g));
  const Ball third = Ball(1) / Ball(3);
  for (auto& b : s.body)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) b.J_B(i, j) = b.J_B(i, j) * third;
  REQUIRE_FALSE(s.body[0].J_B(0, 1).exact());
  const auto st = widen<Ball>(every_strategy(0.45));
  CHECK_NOTHROW(certified_analyze(s, st));
  Scene<Ball> bent = s;
  arb_add_error_2exp_si(bent.body[1].J_B(2, 0).get(), -200);
  REQUIRE_FALSE(EnclosureTraits<Ball>::identical(bent.body[1].J_B(2, 0), bent.body[1].J_B(0, 2)));
  CHECK_THROWS_WITH(certified_analyze(bent, st), Catch::Contains("body[1].J_B is not symmetric: entry (0, 2)"));
}

}  // namespace check_certified
