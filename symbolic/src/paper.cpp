#include "paper.hpp"

#include <functional>

namespace impact3d::symbolic::paper {

using namespace GiNaC;

namespace {
ex S(const char* name) { return sym(name); }
}  // namespace

matrix eq4_middle(const Derivation& d, int body, int lever_body) {
  const Body& b = d.body[body];
  const matrix& Pi = body == 0 ? d.P1 : d.P2;
  const matrix dw = b.Jinv.mul(cross(b.r, Pi));  // eq 2
  return Pi.mul_scalar(1 / b.m).add(cross(dw, d.body[lever_body].r));
}

matrix eq4_right(const Derivation& d, int body) {
  const Body& b = d.body[body];
  const matrix& Pi = body == 0 ? d.P1 : d.P2;
  return Pi.mul_scalar(1 / b.m).add(cross(b.Jinv.mul(cross(b.r, Pi)), b.r));
}

matrix eq5(const Derivation& d, int body) {
  const Body& b = d.body[body];
  const matrix& Pi = body == 0 ? d.P1 : d.P2;
  return b.T.mul(Pi).mul_scalar(1 / b.m).add(b.T.mul(cross(b.Jinv.mul(cross(b.r, Pi)), b.r)));
}

matrix eq6(const Derivation& d) {
  const Body &b1 = d.body[0], &b2 = d.body[1];
  const matrix t2 = b2.T.mul(d.P2).mul_scalar(1 / b2.m), t1 = b1.T.mul(d.P1).mul_scalar(1 / b1.m);
  const matrix r2 = b2.T.mul(cross(b2.Jinv.mul(cross(b2.r, d.P2)), b2.r));
  const matrix r1 = b1.T.mul(cross(b1.Jinv.mul(cross(b1.r, d.P1)), b1.r));
  return t2.sub(t1).add(r2).sub(r1);
}

matrix eq8(const Derivation& d) {
  const Body &b1 = d.body[0], &b2 = d.body[1];
  matrix sum = d.P.mul_scalar(1 / b1.m + 1 / b2.m);
  sum = sum.add(b1.T.mul(cross(b1.Jinv.mul(cross(b1.r, b1.T.transpose().mul(d.P))), b1.r)));
  sum = sum.add(b2.T.mul(cross(b2.Jinv.mul(cross(b2.r, b2.T.transpose().mul(d.P))), b2.r)));
  return sum.mul_scalar(-1);
}

namespace {
// A column of the three rows i = 1, 2, 3 of a printed equation, given row i's right-hand side in terms of
// the names a_i, b_i, c_i.
matrix rows(const std::function<ex(const ex& a, const ex& b, const ex& c)>& row) {
  matrix out(3, 1);
  for (int i = 1; i <= 3; ++i) {
    const std::string n = std::to_string(i);
    out(i - 1, 0) = row(sym("a" + n), sym("b" + n), sym("c" + n));
  }
  return out;
}
}  // namespace

matrix eq9() {
  return rows([](const ex& a, const ex& b, const ex& c) { return -(a * S("Pn") + b * S("Pt") + c * S("Pz")); });
}

matrix eq17_middle() {
  return rows([](const ex& a, const ex& b, const ex&) { return -(a * S("Pn") + b * S("Pcp")); });
}

matrix eq17_right() {
  return rows([](const ex& a, const ex& b, const ex&) { return -(a + S("mu") * b) * S("Pn"); });
}

matrix eq23() {
  return rows([](const ex& a, const ex& b, const ex& c) { return -(a + b * S("mut") + c * S("muz")) * S("Pn"); });
}

matrix eqs10_12() {
  const ex &a1 = S("a1"), &a2 = S("a2"), &a3 = S("a3"), &b1 = S("b1"), &b2 = S("b2"), &b3 = S("b3"), &c1 = S("c1"),
           &c2 = S("c2"), &c3 = S("c3"), &Vn = S("Vn"), &Vt = S("Vt"), &Vz = S("Vz");
  const ex f = S("mp") * (1 + S("eps"));
  const ex D = a1 * (b2 * c3 - b3 * c2) + b1 * (a3 * c2 - a2 * c3) + c1 * (a2 * b3 - a3 * b2);
  return column(f * (Vn * (b2 * c3 - b3 * c2) + Vt * (b3 * c1 - b1 * c3) + Vz * (b1 * c2 - b2 * c1)) / D,
                f * (Vn * (a3 * c2 - a2 * c3) + Vt * (a1 * c3 - a3 * c1) + Vz * (a2 * c1 - a1 * c2)) / D,
                f * (Vn * (a2 * b3 - a3 * b2) + Vt * (a3 * b1 - a1 * b3) + Vz * (a1 * b2 - a2 * b1)) / D);
}

PlaneCoefficients plane_coefficients() {
  const ex &cp = S("cp"), &sp = S("sp");
  return {S("a1"), cp * S("a2") + sp * S("a3"), cp * S("b1") + sp * S("c1"),
          cp * cp * S("b2") + cp * sp * (S("b3") + S("c2")) + sp * sp * S("c3"), (S("Vt") * cp + S("Vz") * sp) / S("Vn")};
}

ex eq18() {
  const PlaneCoefficients k = plane_coefficients();
  return S("mp") * (1 + S("eps")) * S("Vn") / (k.a1 + S("mu") * k.b1);
}

ex eq19() {
  const PlaneCoefficients k = plane_coefficients();
  const ex e = S("eps");
  return (k.r * k.a1 - (1 + e) * k.a2) / ((1 + e) * k.b2 - k.r * k.b1);
}

ex eq20() {
  const PlaneCoefficients k = plane_coefficients();
  return (k.r * k.a1 - k.a2) / (k.b2 - k.r * k.b1);
}

ex eq24() {
  return S("mp") * (1 + S("eps")) * S("Vn") / (S("a1") + S("mut") * S("b1") + S("muz") * S("c1"));
}

namespace {
struct Eta {
  ex eta_t, mu_tc0, eta_z, mu_zc0;
};
Eta eta(const ex& r) {
  const ex e = S("eps"), rz = S("Vz") / S("Vn");
  const ex dt = (1 + e) * S("b2") - r * S("b1"), dz = (1 + e) * S("c3") - rz * S("c1");
  return {(r * S("c1") - (1 + e) * S("c2")) / dt, (r * S("a1") - (1 + e) * S("a2")) / dt,
          (rz * S("b1") - (1 + e) * S("b3")) / dz, (rz * S("a1") - (1 + e) * S("a3")) / dz};
}
}  // namespace

ex eq25(const ex& r) {
  const Eta h = eta(r);
  return h.eta_t * S("muz") + h.mu_tc0;
}
ex eq26() {
  const Eta h = eta(S("Vt") / S("Vn"));  // eta_z and mu_zC0 do not contain r
  return h.eta_z * S("mut") + h.mu_zc0;
}
ex eq27_t(const ex& r) {
  const Eta h = eta(r);
  return (h.eta_t * h.mu_zc0 + h.mu_tc0) / (1 - h.eta_t * h.eta_z);
}
ex eq27_z(const ex& r) {
  const Eta h = eta(r);
  return (h.eta_z * h.mu_tc0 + h.mu_zc0) / (1 - h.eta_t * h.eta_z);
}

ex eq29() {
  return (S("snz") / S("cnz")) / (S("sni") * S("cpo") - S("cni") * S("spo"));
}

matrix appendix_T(const ex& cg, const ex& sg, const ex& ct, const ex& st, const ex& cp, const ex& sp) {
  return matrix(3, 3, lst{cg * ct, sg * ct, -st,                                      //
                          -sg * cp + cg * st * sp, cg * cp + sg * st * sp, ct * sp,  //
                          sg * sp + cg * st * cp, -cg * sp + sg * st * cp, ct * cp});
}

std::map<std::string, ex> appendix_definitions() {
  const ex mp = S("mp");
  auto per = [](int i, const char* n) { return sym(std::string(n) + std::to_string(i)); };
  auto sum2 = [&](auto term) { return term(1) + term(2); };
  auto Ix = [&](int i) { return per(i, "Ix"); };
  auto Iy = [&](int i) { return per(i, "Iy"); };
  auto Iz = [&](int i) { return per(i, "Iz"); };
  auto x = [&](int i) { return per(i, "x"); };
  auto y = [&](int i) { return per(i, "y"); };
  auto z = [&](int i) { return per(i, "z"); };
  auto cg = [&](int i) { return per(i, "cg"); };
  auto sg = [&](int i) { return per(i, "sg"); };

  std::map<std::string, ex> m;
  m["A"] = 1 + mp * sum2([&](int i) { return pow(-x(i) * sg(i) + y(i) * cg(i), 2) / Iz(i); });
  m["B"] = mp * sum2([&](int i) { return (x(i) * cg(i) + y(i) * sg(i)) * (-x(i) * sg(i) + y(i) * cg(i)) / Iz(i); });
  m["C"] = mp * sum2([&](int i) { return pow(x(i) * cg(i) + y(i) * sg(i), 2) / Iz(i); });
  m["f1"] = sum2([&](int i) { return pow(z(i), 2) * (pow(sg(i), 2) / Ix(i) + pow(cg(i), 2) / Iy(i)); });
  m["f2"] = sum2([&](int i) { return pow(z(i), 2) * sg(i) * cg(i) * (1 / Ix(i) - 1 / Iy(i)); });
  m["f3"] = -sum2([&](int i) { return z(i) * (x(i) * cg(i) / Iy(i) + y(i) * sg(i) / Ix(i)); });
  m["f4"] = sum2([&](int i) { return pow(z(i), 2) * (pow(cg(i), 2) / Ix(i) + pow(sg(i), 2) / Iy(i)); });
  m["f5"] = sum2([&](int i) { return z(i) * (x(i) * sg(i) / Iy(i) - y(i) * cg(i) / Ix(i)); });
  m["f6"] = sum2([&](int i) { return pow(y(i), 2) / Ix(i) + pow(x(i), 2) / Iy(i); });
  m["f7"] = sum2([&](int i) {
    return ((pow(y(i), 2) - pow(x(i), 2)) * sg(i) * cg(i) + x(i) * y(i) * (pow(cg(i), 2) - pow(sg(i), 2))) / Iz(i);
  });
  m["f8"] = -sum2([&](int i) { return pow(x(i) * cg(i) + y(i) * sg(i), 2) / Iz(i); });
  return m;
}

GiNaC::exmap appendix_definitions_map() {
  GiNaC::exmap out;
  for (const auto& [name, e] : appendix_definitions()) out[sym(name)] = e;
  return out;
}

std::map<std::string, ex> appendix_coefficients() {
  const ex mp = S("mp"), cp = S("cp"), sp = S("sp");
  const ex A = S("A"), B = S("B"), C = S("C"), f1 = S("f1"), f2 = S("f2"), f3 = S("f3"), f4 = S("f4"), f5 = S("f5"),
           f6 = S("f6"), f7 = S("f7"), f8 = S("f8");
  std::map<std::string, ex> m;
  m["a1"] = A + mp * f1;
  m["a2"] = -B * cp + mp * (f2 * cp + f3 * sp);
  m["a3"] = mp * f3 * cp + mp * (f7 - f2) * sp;
  m["b1"] = m["a2"];
  m["b2"] = (1 + C * pow(cp, 2)) + mp * (f4 * pow(cp, 2) + 2 * f5 * sp * cp + f6 * pow(sp, 2));
  m["b3"] = mp * (f5 * (pow(cp, 2) - pow(sp, 2)) + (f8 - f4 + f6) * sp * cp);
  m["c1"] = m["a3"];
  m["c2"] = m["b3"];
  m["c3"] = 1 + mp * (f6 * pow(cp, 2) + (f4 + f8) * pow(sp, 2) - 2 * f5 * sp * cp);
  return m;
}

std::map<std::string, ex> appendix_coefficients_corrected() {
  auto m = appendix_coefficients();
  const ex mp = S("mp"), cp = S("cp"), sp = S("sp");
  // The yaw-inertia term f8 enters c3 with the sign opposite to its entry in b3.
  m["c3"] = 1 + mp * (S("f6") * pow(cp, 2) + (S("f4") - S("f8")) * pow(sp, 2) - 2 * S("f5") * sp * cp);
  return m;
}

}  // namespace impact3d::symbolic::paper
