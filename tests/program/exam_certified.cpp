// impact3d solve --precision certified[:BITS] (issue 14) on named cases. Where the known answers come from:
//  - Figure 8's GIR (eq 14) from the 100-digit solve (MPFR, another arithmetic): mu = GIR + 1e-20 is a
//    Full Impact and GIR - 1e-20 a Sliding Impact by eq 14's rule, a difference 64 bits (19 digits)
//    cannot resolve and 256 bits (77 digits) can;
//  - a hand derivation: with both impulse centres at the centres of mass, K = I (eq 9), so the Full
//    Impact (V_rf = -e V_ri, eqs 10-12) is P = m' (1 + e) V_ri and GIR = |V_rt| / V_rn (eq 14), while
//    sliding stops on the plane of the sliding with P_t = m' V_rt, P_n = m' (1 + e) V_rn, so Wach's CIR
//    (eq 19) is |V_rt| / ((1 + e) V_rn). At V_rn = 4, |V_rt| = 3, e = 0.5: GIR = 3/4, CIR = 1/2 exactly,
//    and mu = 0.75 for pc-crash, 0.5 for Wach, are exact ties;
//  - the contract (many-cases.md): every number of the document has an enclosure [lo, hi] holding it.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "cli_process.hpp"
#include "impact3d/case_format/json_tree.hpp"
#include "impact3d/case_format/scalar_text.hpp"
#include "impact3d/scalar/ball.hpp"
#include "impact3d/mechanics/decisions.hpp"
#include "impact3d/scalar/exact.hpp"

namespace exam_certified {

using namespace impact3d;
using namespace impact3d::test;
namespace fs = std::filesystem;

namespace {

const std::string kFig8 = std::string(IMPACT3D_EXAMPLES_DIR) + "/fig8_side_impact.json";

case_format::JsonValue solve_json(const std::vector<std::string>& args) {
  std::vector<std::string> all = {"solve"};
  all.insert(all.end(), args.begin(), args.end());
  all.insert(all.end(), {"--format", "json"});
  const Run r = run_argv(all);
  INFO(r.err);
  REQUIRE(r.status == 0);
  return case_format::parse_json_tree(r.out);
}

const case_format::JsonValue& at(const case_format::JsonValue& v, const std::string& key) {
  const case_format::JsonValue* x = v.find(key);
  INFO(key);
  REQUIRE(x);
  return *x;
}

const case_format::JsonValue* decision(const case_format::JsonValue& result, const std::string& prefix) {
  for (const auto& d : at(result, "decisions").items)
    if (at(d, "name").text.rfind(prefix, 0) == 0) return &d;
  return nullptr;
}

// q as a decimal with `places` digits after the point (q * 10^places must be an integer).
std::string decimal_text(const rational& q, int places) {
  using boost::multiprecision::cpp_int;
  cpp_int scale = boost::multiprecision::pow(cpp_int(10), static_cast<unsigned>(places));
  const rational n = q * rational(scale);
  REQUIRE(boost::multiprecision::denominator(n) == 1);
  std::string digits = boost::multiprecision::numerator(n).str();
  const bool negative = digits[0] == '-';
  if (negative) digits.erase(0, 1);
  if (static_cast<int>(digits.size()) <= places) digits.insert(0, static_cast<std::size_t>(places + 1 - digits.size()), '0');
  digits.insert(digits.size() - static_cast<std::size_t>(places), ".");
  return (negative ? "-" : "") + digits;
}

const char* kIdentityK = R"({
  "name": "K = I: both impulse centres at the centres of mass",
  "units": "SI",
  "vehicles": [
    { "name": "A", "mass": 1000, "inertia": { "Ixx": 400, "Iyy": 1500, "Izz": 1700 },
      "orientation_deg": { "yaw": 0, "pitch": 0, "roll": 0 }, "velocity": [-4, 3, 0],
      "impulse_center": [0, 0, 0], "angular_velocity": [0, 0, 0] },
    { "name": "B", "mass": 1500, "inertia": { "Ixx": 500, "Iyy": 2000, "Izz": 2200 },
      "orientation_deg": { "yaw": 0, "pitch": 0, "roll": 0 }, "velocity": [0, 0, 0],
      "impulse_center": [0, 0, 0], "angular_velocity": [0, 0, 0] }
  ],
  "contact": { "normal_yaw_deg": 0 },
  "restitution": 0.5,
  "strategy": [ { "name": "pc-crash", "mu": 0.75 }, { "name": "wach", "mu": 0.5, "limit": "cir" },
                { "name": "pc-crash", "mu": 0.4 } ]
})";

}  // namespace

TEST_CASE("mu within 1e-20 of the GIR is undecided at 64 bits and decided correctly at 256", "[certified]") {
  const case_format::JsonValue ref = solve_json({kFig8, "--precision", "100", "--strategy", "pc-crash:mu=0.4"});
  const std::string gir100 = at(at(at(ref, "results").items.at(0), "limits"), "gir").text;
  // GIR to 40 places (its 100-digit value is good to far more), then 1e-20 either side.
  const rational gir = case_format::scalar_from_text<rational>(gir100.substr(0, 42));
  const rational step = rational(1) / rational(boost::multiprecision::pow(boost::multiprecision::cpp_int(10), 20));
  int checked = 0;
  for (const int side : {+1, -1}) {
    const std::string mu = decimal_text(gir + rational(side) * step, 40);
    INFO("mu = " << mu);
    const case_format::JsonValue at64 = solve_json({kFig8, "--precision", "certified:64", "--strategy", "pc-crash:mu=" + mu});
    const case_format::JsonValue& r64 = at(at64, "results").items.at(0);
    const case_format::JsonValue* d64 = decision(r64, "regime");
    REQUIRE(d64);
    CHECK(at(*d64, "status").text == "undecided");
    // The other branch is there, with the other regime.
    const case_format::JsonValue& alternatives = at(r64, "alternatives");
    bool other = false;
    for (const auto& a : alternatives.items)
      if (at(a, "decision").text.rfind("regime", 0) == 0)
        other = at(at(a, "result"), "regime").text != at(r64, "regime").text;
    CHECK(other);

    const case_format::JsonValue at256 = solve_json({kFig8, "--precision", "certified:256", "--strategy", "pc-crash:mu=" + mu});
    const case_format::JsonValue& r256 = at(at256, "results").items.at(0);
    const case_format::JsonValue* d256 = decision(r256, "regime");
    REQUIRE(d256);
    CHECK(at(*d256, "status").text == "decided");
    CHECK(at(r256, "regime").text == (side > 0 ? "full" : "sliding"));
    CHECK(at(at256, "precision").text == "certified:256");
    ++checked;
  }
  CHECK(checked == 2);
}

TEST_CASE("an exact rational tie is reported as a tie", "[certified]") {
  const fs::path dir = fresh_directory("impact3d-certified");
  const std::string path = (dir / "identity.json").string();
  std::ofstream(path) << kIdentityK;
  // The hand derivation, by exact arithmetic first.
  const Run exact = run_argv({"solve", path, "--precision", "exact", "--format", "json"});
  REQUIRE(exact.status == 0);
  const case_format::JsonValue x = case_format::parse_json_tree(exact.out);
  CHECK(at(at(at(at(x, "exact"), "results").items.at(0), "limits"), "gir").text == "3/4");
  CHECK(at(at(at(at(x, "exact"), "results").items.at(1), "limits"), "cir").text == "1/2");

  for (const std::string precision : {"certified", "certified:64"}) {
    INFO(precision);
    const case_format::JsonValue doc = solve_json({path, "--precision", precision});
    const auto& results = at(doc, "results").items;
    const char* names[] = {"regime", "cap"};
    for (int k = 0; k < 2; ++k) {
      const case_format::JsonValue* d = decision(results.at(static_cast<std::size_t>(k)), names[k]);
      REQUIRE(d);
      CHECK(at(*d, "status").text == "tie");
      const case_format::JsonValue* alternatives = results.at(static_cast<std::size_t>(k)).find("alternatives");
      if (alternatives)
        for (const auto& a : alternatives->items) CHECK(at(a, "decision").text.rfind(names[k], 0) != 0);
    }
    // mu = 0.4 < 3/4 by a margin any precision decides.
    const case_format::JsonValue* d = decision(results.at(2), "regime");
    REQUIRE(d);
    CHECK(at(*d, "status").text == "decided");
    CHECK(at(results.at(2), "regime").text == "sliding");
  }
  fs::remove_all(dir);
}

TEST_CASE("every number of a certified document has an enclosure that holds it", "[certified]") {
  const case_format::JsonValue doc = solve_json({kFig8, "--precision", "certified:128"});
  const case_format::JsonValue& enclosures = at(doc, "enclosures");
  int numbers = 0;
  std::function<void(const case_format::JsonValue&, const std::string&)> walk = [&](const case_format::JsonValue& v, const std::string& path) {
    if (v.is(case_format::JsonValue::Type::number)) {
      ++numbers;
      const case_format::JsonValue* e = enclosures.find(path);
      INFO(path);
      REQUIRE(e);
      REQUIRE(e->size() == 2);
      const rational lo = case_format::scalar_from_text<rational>(e->items[0].text), hi = case_format::scalar_from_text<rational>(e->items[1].text);
      const rational mid = case_format::scalar_from_text<rational>(v.text);
      CHECK(lo <= mid);
      CHECK(mid <= hi);
      return;
    }
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (v.is(case_format::JsonValue::Type::object) && path.empty() && v.keys[i] == "enclosures") continue;
      walk(v.items[i], v.is(case_format::JsonValue::Type::object) ? (path.empty() ? "" : path + ".") + v.keys[i]
                                                         : path + "[" + std::to_string(i) + "]");
    }
  };
  walk(doc, "");
  CHECK(numbers > 400);  // Figure 8's four results (413 numbers), with no alternative: every decision is decided
  CHECK(static_cast<int>(enclosures.size()) == numbers);
}

TEST_CASE("certified precision names are checked, and the text prints only certified digits", "[certified]") {
  for (const std::string bad : {"certified:8", "certified:9000", "certified:", "certified:12x", "certified64"}) {
    INFO(bad);
    const Run r = run_argv({"solve", kFig8, "--precision", bad});
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find("--precision") != std::string::npos);
  }
  const Run text = run_argv({"solve", kFig8, "--precision", "certified:256", "--strategy", "pc-crash:mu=0.4"});
  REQUIRE(text.status == 0);
  CHECK(text.out.find("precision certified:256") != std::string::npos);
  CHECK(text.out.find("Decisions (ball arithmetic at 256 bits") != std::string::npos);
  // Figure 8's K is well conditioned: at 256 bits P_n has the 17 digits asked for, which are the
  // 100-digit solve's rounded to 17.
  const case_format::JsonValue ref = solve_json({kFig8, "--precision", "100", "--strategy", "pc-crash:mu=0.4"});
  const rational P_n = case_format::scalar_from_text<rational>(at(at(at(ref, "results").items.at(0), "impulse"), "contact").items.at(0).text);
  using boost::multiprecision::cpp_int;
  const cpp_int scale = boost::multiprecision::pow(cpp_int(10), 12);  // P_n is 12519.3...: 5 + 12 digits
  const rational rounded = rational(floor_of(rational(P_n * rational(scale) + rational(1, 2)))) / rational(scale);
  const std::string expected = decimal_text(rounded, 12);
  INFO(expected);
  CHECK(expected.size() == 18);
  CHECK(text.out.find(expected) != std::string::npos);
}

// Known answers of the text form, by the definition of decimal rounding: a ball holding 11.17 exactly
// rounds to 11.170000000000000 at 17 digits; a ball of 1 +- 10^-6 (its radius rounded up by Arb) reaches
// below 0.999999, which rounds to 0.999999 at 6 digits and 1.0000 at 5, where 1.000001 does too: it
// prints 1.0000 with the distance to its bounds; a ball of 0 +- 10^-30 shares no digit and prints its
// bounds.
TEST_CASE("a ball's text holds only digits every point of it shares", "[certified]") {
  const BallBits bits(128);
  auto text = [](const Ball& x, int digits) {
    const BallText previous = ball_text;
    ball_text = BallText::certified;
    std::string out;
    x.append_text(out, digits);
    ball_text = previous;
    return out;
  };
  CHECK(text(Ball(std::string("11.17")), 17) == "11.170000000000000");
  CHECK(text(Ball(std::string("-0.0625")), 5) == "-0.062500");
  CHECK(text(Ball(0), 17) == "0");
  const std::string near_one = text(Ball(std::string("1 +/- 1e-6")), 17);
  INFO(near_one);
  CHECK(near_one.rfind("1.0000(+-", 0) == 0);
  CHECK(text(Ball(std::string("0 +/- 1e-30")), 17).front() == '[');
  // 1.5e+30 at 2 digits: no padded zeros that would read as certified.
  CHECK(text(Ball(std::string("1.5e30")), 2) == "1.5e30");
}

// The default precision doubles the bits up to 4096 while a decision stays undecided. Its JSON was once
// read back under the case files' 256-character literal limit, and failed on every such case.
nlohmann::json solve_certified(const std::string& file, const std::string& precision) {
  const Run r = run_argv({"solve", file, "--precision", precision, "--format", "json"});
  INFO(file << ": " << r.err);
  REQUIRE(r.status == 0);
  return nlohmann::json::parse(r.out);
}

TEST_CASE("the default certified JSON of every bundled case is written at the fewest bits that decide as much", "[certified]") {
  int cases = 0, undecided = 0;
  for (const auto& dir : {std::string(IMPACT3D_EXAMPLES_DIR), std::string(IMPACT3D_SOURCE_DIR) + "/verification/cases"})
    for (const auto& f : fs::directory_iterator(dir)) {
      if (f.path().extension() != ".json") continue;
      const nlohmann::json doc = solve_certified(f.path().string(), "certified");
      const std::string bits = doc.at("precision").get<std::string>().substr(10);
      INFO(f.path().string() << " at " << bits << " bits");
      // Every bundled case is narrow at 256 bits; what stays undecided there stays so at every doubling.
      CHECK(bits == "256");
      for (const auto& r : doc.at("results"))
        for (const auto& d : r.at("decisions"))
          if (d.at("status") == "undecided") {
            ++undecided;
            CHECK(d.at("detail").get<std::string>().find("undecided at 256, 512, 1024, 2048, 4096 bits") != std::string::npos);
          }
      ++cases;
    }
  CHECK(cases == 32);
  CHECK(undecided > 0);  // irrational exact zeros: planar z components, restitution 1's energy loss
}

TEST_CASE("certified JSON at 4096 bits has literals longer than a case's and still an enclosure for each", "[certified]") {
  const nlohmann::json doc = solve_certified(kFig8, "certified:4096");
  const std::string lo = doc.at("enclosures").at("coefficients.K[0][0]")[0].get<std::string>();
  CHECK(lo.size() > 1000);  // 4096 bits: 1233 digits
  CHECK(doc.at("enclosures").size() > 400);
}

// Restitution 1 without sliding loses no energy exactly; the balls cannot tell 0 from a tiny loss or
// gain. The zero branch is taken, as the floating solve's rounding rule takes it: no gain warning and an
// EES of exactly 0, the decision undecided, and its alternative on the other side.
TEST_CASE("a quantity whose ball holds zero takes the zero branch, undecided, with the other as its alternative", "[certified]") {
  const nlohmann::json doc =
      solve_certified(std::string(IMPACT3D_SOURCE_DIR) + "/verification/cases/restitution_one.json", "certified:256");
  const nlohmann::json& r = doc.at("results")[0];
  CHECK(r.at("warnings").dump().find("energy gained") == std::string::npos);
  CHECK(r.at("vehicles")[0].at("ees") == 0);
  CHECK(doc.at("enclosures").at("results[0].vehicles[0].ees") == nlohmann::json::array({"0", "0"}));
  bool undecided = false, alternative = false;
  for (const auto& d : r.at("decisions"))
    undecided = undecided || (d.at("name") == decision_names::energy_loss_sign && d.at("status") == "undecided");
  for (const auto& a : r.at("alternatives"))
    if (a.at("decision") == decision_names::energy_loss_sign)
      alternative = a.at("result").at("vehicles")[0].at("ees") != 0;
  CHECK(undecided);
  CHECK(alternative);
}

}  // namespace exam_certified
