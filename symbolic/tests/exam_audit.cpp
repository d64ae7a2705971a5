// Exact answers of the derivation and the audit.
#include <catch2/catch.hpp>

#include <set>

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

TEST_CASE("the audit finds exactly the two errata, and verifies every printed closed form", "[exam]") {
  const Derivation d = derive();
  const auto entries = run_audit(d, specialize(d), derive_closed_forms());
  std::set<std::string> errata, verified;
  for (const auto& e : entries) {
    if (e.status == "erratum") errata.insert(e.id);
    if (e.status == "verified") verified.insert(e.id);
  }
  CHECK(errata == std::set<std::string>{"eq4", "A.c3"});
  for (const char* id : {"eq6", "eq8", "eq9", "eq10", "eq11", "eq12", "eq14", "eq18", "eq19", "eq20", "eq22", "eq24",
                         "eq25", "eq26", "eq27", "A.T", "A.A", "A.B", "A.C", "A.f1", "A.f2", "A.f3", "A.f4", "A.f5",
                         "A.f6", "A.f7", "A.f8", "A.a1", "A.a2", "A.a3", "A.b1", "A.b2", "A.b3", "A.c1", "A.c2"})
    CHECK(verified.count(id) == 1);
}

TEST_CASE("the c3 witness: the printed c3 falls below 1, the derived one does not", "[exam]") {
  // K = I + m' sum T [r]x^T J^-1 [r]x T^T is I plus a positive semidefinite matrix, so every diagonal
  // entry is at least 1; the witness makes the printed sign error visible.
  const Derivation d = derive();
  for (const auto& e : run_audit(d, specialize(d), derive_closed_forms())) {
    if (e.id != "A.c3") continue;
    REQUIRE(e.witness);
    CHECK(std::stod(e.witness->printed_decimal) < 1.0);
    CHECK(std::stod(e.witness->derived_decimal) >= 1.0);
    return;
  }
  FAIL("no A.c3 entry");
}
