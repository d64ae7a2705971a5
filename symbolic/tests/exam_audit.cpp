// Exact answers of the derivation and the audit.
#include <catch2/catch.hpp>

#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "appendix_a.hpp"
#include "audit.hpp"
#include "closed_forms.hpp"
#include "model.hpp"

using namespace impact3d::symbolic;
using namespace GiNaC;

TEST_CASE("K of two equal spheres struck on their x axes is diag(1, 3, 3), exactly", "[exam]") {
  // m = 1000, J = 500 I, r = (+-1, 0, 0), T = I: by hand [r]x^T J^-1 [r]x = diag(0, 1, 1) / 500, m' = 500.
  const Derivation d = derive();
  exmap v{{sym("mp"), 500}};
  for (const Body& b : d.body) {
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) {
        v[b.Jinv(p, q)] = p == q ? numeric(1, 500) : numeric(0);
        v[b.T(p, q)] = p == q ? 1 : 0;
      }
    v[b.r(0, 0)] = b.index == 1 ? 1 : -1;
    v[b.r(1, 0)] = 0;
    v[b.r(2, 0)] = 0;
  }
  const int diag[3] = {1, 3, 3};
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) CHECK(normal(d.K(p, q).subs(v)) == (p == q ? diag[p] : 0));
}

namespace {

const std::vector<AuditEntry>& audit() {
  static const std::vector<AuditEntry> entries = [] {
    const Derivation d = derive();
    return run_audit(d, specialize(d), derive_closed_forms());
  }();
  return entries;
}

const AuditEntry& entry(const std::string& id) {
  for (const auto& e : audit())
    if (e.id == id) return e;
  throw std::runtime_error("no audit entry " + id);
}

std::set<std::string> with_status(const std::string& status) {
  std::set<std::string> out;
  for (const auto& e : audit())
    if (status_of(e) == status) out.insert(e.id);
  return out;
}

bool mentions(const std::vector<Check>& checks, const std::string& text) {
  for (const auto& c : checks)
    if (c.what().find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

// Which status each entry has, from the paper read line by line: the two errata (eq 4's r_1, Appendix A's
// sign of f_8 in c_3); eq 17's unprimed coefficients and eq 25's undefined r (inherited by eq 27); the
// Full Impact swerve of Figure 8, which eqs 10-12 exclude when V_rzi = 0.
TEST_CASE("the audit's statuses: two errata, three ambiguities, one contradicted claim", "[exam]") {
  CHECK(with_status("erratum") == std::set<std::string>{"eq4", "A.c3"});
  CHECK(with_status("ambiguous") == std::set<std::string>{"eq17", "eq25", "eq27"});
  CHECK(with_status("claim-contradicted") == std::set<std::string>{"fig8.full_swerve"});
  // Constraints that define a strategy (eqs 16, 22) have nothing to compare; their consequence, eq 18, does.
  CHECK(with_status("definition") ==
        std::set<std::string>{"eq1", "eq2", "eq3", "eq7", "eq13", "eq15", "eq16", "eq21", "eq22"});
  CHECK(with_status("claim-checked") ==
        std::set<std::string>{"fig8.full_t_sliding", "fig8.vertical_impulse", "fig8.same_ratio", "fig8.not_wach",
                              "fig8.sliding_swerve", "conclusion.full_impact_cil", "conclusion.full_impact_plane",
                              "conclusion.wach", "conclusion.brach_cil"});
  for (const char* id : {"eq5", "eq6", "eq8", "eq9", "eq10", "eq11", "eq12", "eq14", "eq18", "eq19", "eq20",
                         "eq23", "eq24", "eq26", "eq29", "A.T", "A.A", "A.B", "A.C", "A.f1", "A.f2", "A.f3",
                         "A.f4", "A.f5", "A.f6", "A.f7", "A.f8", "A.a1", "A.a2", "A.a3", "A.b1", "A.b2", "A.b3", "A.c1",
                         "A.c2"})
    CHECK(status_of(entry(id)) == "verified");
  CHECK(audit().size() == 9 + 2 + 3 + 35 + 10);  // no entry beyond these (eq 28 does not exist)
}

TEST_CASE("every line and component of a multi-line equation is a comparison of its own", "[exam]") {
  CHECK(entry("eq4").checks.size() == 12);  // 2 lines x (middle, right) x 3 components
  CHECK(entry("eq5").checks.size() == 6);   // 2 lines x 3 components
  for (const char* id : {"eq6", "eq8", "eq9", "eq23"}) CHECK(entry(id).checks.size() == 3);
  CHECK(entry("A.T").checks.size() == 9);
  // eq 17's third row (across the plane: the swerve) is compared under both readings.
  const AuditEntry& e17 = entry("eq17");
  REQUIRE(e17.readings.size() == 2);
  for (const auto& r : e17.readings) CHECK(mentions(r.checks, "row 3"));
  CHECK(e17.readings[0].used_by_implementation);
  CHECK(e17.readings[0].checks.size() == 6);
}

TEST_CASE("eq 22 is Wach's constraint, not verified by another equation; eq 25 states both readings of r", "[exam]") {
  // Once "verified" by comparing eq 18 on Wach's plane: the constraint itself has nothing to compare, and
  // its consequence is eq 18's comparison, made for every plane angle.
  CHECK(status_of(entry("eq22")) == "definition");
  CHECK(entry("eq22").checks.empty());
  CHECK(mentions(entry("eq18").checks, "solved in contact axes"));
  // eq 14 compares its printed ratio with eq 20 on the phi_FI plane (not constraints that hold by construction).
  REQUIRE(entry("eq14").checks.size() == 1);
  CHECK(mentions(entry("eq14").checks, "against eq 20 at phi_FI"));
  const AuditEntry& e25 = entry("eq25");
  REQUIRE(e25.readings.size() == 2);
  CHECK(e25.readings[0].used_by_implementation);
  CHECK(e25.readings[0].description.find("V_rti / V_rni") != std::string::npos);
  CHECK(e25.readings[0].checks[0].equal());
  CHECK_FALSE(e25.readings[1].checks[0].equal());  // eq 19's r does not give the critical ratio
}

TEST_CASE("a witness defines every symbol it uses and shows two different numbers", "[exam]") {
  int witnesses = 0;
  auto look = [&](const std::vector<Check>& checks) {
    for (const auto& c : checks) {
      if (!c.witness()) continue;
      ++witnesses;
      for (const auto& [name, value] : c.witness()->inputs) CHECK_NOTHROW(symbol_meaning(name));
      CHECK(c.witness()->left != c.witness()->right);
      CHECK(c.witness()->left_decimal != c.witness()->right_decimal);
    }
  };
  for (const auto& e : audit()) {
    look(e.checks);
    for (const auto& r : e.readings) look(r.checks);
  }
  // eq 4 (3 components), A.c3, eq 17 (3 rows), eq 25, eq 27 (2), and the four claims that something differs
  // and does (fig8.full_swerve differs from nothing: no witness).
  CHECK(witnesses == 3 + 1 + 3 + 1 + 2 + 4);
}

TEST_CASE("an entry whose status was not produced by a comparison is rejected", "[exam]") {
  AuditEntry forged;
  forged.id = "forged";
  forged.kind = EntryKind::formula;  // "verified" with nothing compared
  CHECK_THROWS_AS(status_of(forged), std::logic_error);
  forged.kind = EntryKind::claim;  // a claim decided by nothing
  forged.claim = "the paper says so";
  CHECK_THROWS_AS(status_of(forged), std::logic_error);
  forged.kind = EntryKind::definition;  // a definition that carries a comparison
  forged.checks = entry("eq6").checks;
  CHECK_THROWS_AS(status_of(forged), std::logic_error);
  AuditEntry no_correction = entry("eq4");  // an erratum without its checked correction
  no_correction.corrections.clear();
  CHECK_THROWS_AS(status_of(no_correction), std::logic_error);
  AuditEntry one_reading = entry("eq25");  // an ambiguity with one reading
  one_reading.readings.pop_back();
  CHECK_THROWS_AS(status_of(one_reading), std::logic_error);
  AuditEntry wrong_reading = entry("eq25");  // the implementation's reading does not agree
  std::swap(wrong_reading.readings[0].used_by_implementation, wrong_reading.readings[1].used_by_implementation);
  CHECK_THROWS_AS(status_of(wrong_reading), std::logic_error);
  AuditEntry agreeing = entry("eq25");  // two readings that both agree: nothing is ambiguous
  agreeing.readings[1] = agreeing.readings[0];
  agreeing.readings[1].used_by_implementation = false;
  CHECK_THROWS_AS(status_of(agreeing), std::logic_error);
}

// The committed generated/audit.json, read as a tool would: each status follows from the comparisons
// listed with it.
TEST_CASE("every status in generated/audit.json follows from its listed comparisons", "[exam]") {
  std::ifstream in(IMPACT3D_SOURCE_DIR "/generated/audit.json");
  REQUIRE(in);
  const auto j = nlohmann::json::parse(in);
  auto all = [](const nlohmann::json& comparisons, const char* field, const char* value) {
    for (const auto& c : comparisons)
      if (c.at(field) != value) return false;
    return true;
  };
  int items = 0;
  for (const auto& it : j.at("items")) {
    ++items;
    const std::string status = it.at("status");
    INFO(it.at("id").get<std::string>() << ": " << status);
    const auto none = nlohmann::json::array();
    const auto& cmp = it.contains("comparisons") ? it.at("comparisons") : none;
    if (status == "definition") {
      CHECK(cmp.empty());
      CHECK_FALSE(it.contains("readings"));
    } else if (status == "verified") {
      CHECK(!cmp.empty());
      CHECK(all(cmp, "result", "equal"));
    } else if (status == "erratum") {
      CHECK_FALSE(all(cmp, "result", "equal"));
      CHECK(all(it.at("correction_comparisons"), "result", "equal"));
      CHECK(it.contains("corrected"));
    } else if (status == "ambiguous") {
      REQUIRE(it.at("readings").size() >= 2);
      int implementation = 0, differing = 0;
      for (const auto& r : it.at("readings")) {
        CHECK(!r.at("comparisons").empty());
        if (r.at("used_by_implementation")) {
          ++implementation;
          CHECK(all(r.at("comparisons"), "result", "equal"));
        } else if (!all(r.at("comparisons"), "result", "equal")) {
          ++differing;
        }
      }
      CHECK(implementation == 1);
      CHECK(differing >= 1);
    } else if (status == "claim-checked" || status == "claim-contradicted") {
      CHECK(!cmp.empty());
      bool holds = true;
      for (const auto& c : cmp) holds = holds && c.at("result") == c.at("expected");
      CHECK(holds == (status == "claim-checked"));
    } else {
      FAIL("unknown status " << status);
    }
  }
  CHECK(items == static_cast<int>(audit().size()));
}

TEST_CASE("the c3 witness: the printed c3 falls below 1, the derived one does not", "[exam]") {
  // K = I + m' sum T [r]x^T J^-1 [r]x T^T is I plus a positive semidefinite matrix, so every diagonal
  // entry is at least 1; the witness makes the printed sign error visible.
  const AuditEntry& e = entry("A.c3");
  REQUIRE(e.checks.size() == 1);
  REQUIRE(e.checks[0].witness());
  CHECK(std::stod(e.checks[0].witness()->left_decimal) < 1.0);
  CHECK(std::stod(e.checks[0].witness()->right_decimal) >= 1.0);
}
