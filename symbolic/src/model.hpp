// The impulse-momentum form of the Newton-Euler equations for two rigid bodies (paper eqs 1-9), with
// full symmetric inertia tensors, general impulse-centre vectors and general contact rotations T_i.
#pragma once

#include <array>
#include <string>

#include <ginac/ginac.h>

namespace impact3d::symbolic {

using GiNaC::ex;
using GiNaC::matrix;
using GiNaC::symbol;

// A symbol by name: one object per name for the whole program, so that expressions built in different
// places refer to the same symbol.
const symbol& sym(const std::string& name);

matrix column(const ex& a, const ex& b, const ex& c);
matrix cross(const matrix& a, const matrix& b);
matrix skew(const matrix& r);

struct Body {
  int index;       // 1 or 2
  ex m;            // mass
  matrix J;        // inertia tensor, body axes: Jxx, Jxy, ... (symmetric)
  matrix Jinv;     // its inverse, as symbols jixx, ... (symmetric)
  matrix r;        // impulse centre relative to the CG, body axes
  matrix T;        // vehicle -> contact coordinates (a rotation), entries T11 ... T33
};

Body make_body(int i);

struct Derivation {
  std::array<Body, 2> body;
  matrix P;            // impulse on vehicle 1, contact axes
  matrix P1, P2;       // body impulses, body axes (symbols, before eq 7)
  ex m_prime;          // symbol mp
  matrix dV_ic[2];     // eq 4: change of impulse-centre velocity of each body, body axes, in P_i
  matrix dV_rel_body;  // eq 6: T2 dV_IC2 - T1 dV_IC1 in P1, P2
  matrix dV_rel;       // eq 8: the same after eq 7 (P1 = T1^T P, P2 = -T2^T P), in P
  matrix K;            // eq 9: K = -m' d(dV_rel)/dP, masses through m' only
  matrix K_factored;   // I + m' sum_i T_i [r_i]x^T J_i^-1 [r_i]x T_i^T, the form the kernel evaluates
};

// Builds every step from eqs 2, 4, 6 and 7; throws if the masses do not combine into m'.
Derivation derive();

// Weierstrass substitutions: c -> (1-u^2)/(1+u^2), s -> 2u/(1+u^2) for each (c, s) pair given, so that
// an identity in sines and cosines becomes an identity of rational functions, decided by normal().
GiNaC::exmap weierstrass(const std::vector<std::pair<std::string, std::string>>& cos_sin_names);

bool identical(const ex& a, const ex& b, const GiNaC::exmap& substitutions = {});

}  // namespace impact3d::symbolic
