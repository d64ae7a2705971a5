#include "appendix_a.hpp"

#include "paper.hpp"

namespace impact3d::symbolic {

using namespace GiNaC;

namespace {

// The coefficients are linear in the inverse principal moments; these symbols stand for them while
// the parts are separated.
const char* kInverse[3] = {"iX", "iY", "iZ"};

ex inverse(int axis, int body) { return sym(kInverse[axis] + std::to_string(body)); }

ex with_moments(const ex& e) {
  exmap m;
  const char* moment[3] = {"Ix", "Iy", "Iz"};
  for (int b = 1; b <= 2; ++b)
    for (int a = 0; a < 3; ++a) m[inverse(a, b)] = 1 / sym(moment[a] + std::to_string(b));
  return e.subs(m);
}

ex zero_inverse(const ex& e, bool xy, bool z) {
  exmap m;
  for (int b = 1; b <= 2; ++b) {
    if (xy) m[inverse(0, b)] = m[inverse(1, b)] = 0;
    if (z) m[inverse(2, b)] = 0;
  }
  return expand(e).subs(m);
}

// The part of a coefficient that comes from yaw inertia (1/Iz) and from roll/pitch inertia (1/Ix, 1/Iy).
ex z_part(const ex& e) { return zero_inverse(e, true, false) - zero_inverse(e, true, true); }
ex xy_part(const ex& e) { return zero_inverse(e, false, true) - zero_inverse(e, true, true); }

ex at(const ex& e, const ex& c, const ex& s) { return expand(e.subs(lst{sym("cp") == c, sym("sp") == s})); }

}  // namespace

AppendixA specialize(const Derivation& d) {
  AppendixA out;
  exmap m;
  const char* ax = "xyz";
  for (int b = 0; b < 2; ++b) {
    const std::string n = std::to_string(b + 1);
    for (int p = 0; p < 3; ++p)
      for (int q = p; q < 3; ++q)
        m[sym(std::string("ji") + n + "_" + ax[p] + ax[q])] = p == q ? inverse(p, b + 1) : ex(0);
    const matrix T = paper::appendix_T(sym("cg" + n), sym("sg" + n), 1, 0, sym("cp"), sym("sp"));
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) m[d.body[b].T(p, q)] = T(p, q);
  }
  matrix K(3, 3);
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) K(p, q) = expand(d.K(p, q).subs(m));

  const ex& mp = sym("mp");
  auto& D = out.derived;
  D["A"] = with_moments(zero_inverse(K(0, 0), true, true) + z_part(K(0, 0)));
  D["f1"] = with_moments(xy_part(K(0, 0)) / mp);
  D["B"] = with_moments(-at(z_part(K(1, 0)), 1, 0));
  D["f2"] = with_moments(at(xy_part(K(1, 0)), 1, 0) / mp);
  D["f3"] = with_moments(at(xy_part(K(1, 0)), 0, 1) / mp);
  D["f7"] = with_moments(at(z_part(K(2, 0)), 0, 1) / mp);
  D["C"] = with_moments(at(z_part(K(1, 1)), 1, 0));
  D["f4"] = with_moments(at(xy_part(K(1, 1)), 1, 0) / mp);
  D["f6"] = with_moments(at(xy_part(K(1, 1)), 0, 1) / mp);
  D["f5"] = with_moments((at(xy_part(K(1, 1)), 1, 1) / mp - D["f4"] - D["f6"]) / 2);
  // f8 as it first enters, through b3 (row z, column t) with weight sin(phi) cos(phi).
  D["f8"] = with_moments(at(z_part(K(2, 1)), 1, 1) / mp);
  const char* names[3][3] = {{"a1", "b1", "c1"}, {"a2", "b2", "c2"}, {"a3", "b3", "c3"}};
  out.K = matrix(3, 3);
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) {
      out.K(p, q) = with_moments(K(p, q));
      D[names[p][q]] = out.K(p, q);
    }
  out.angles = weierstrass({{"cg1", "sg1"}, {"cg2", "sg2"}, {"cp", "sp"}});
  return out;
}

}  // namespace impact3d::symbolic
