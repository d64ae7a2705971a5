// impact3d.solve_batch: pc-crash, Wach or Brach on many collisions held as NumPy columns (structure of
// arrays), on every core with the GIL released, through the SIMD lanes of batch/columns.hpp (or, for
// post-impact velocities, the scalar lean path row by row).
#pragma once

#include <optional>
#include <string>

#include <pybind11/pybind11.h>

namespace impact3d::python {

// Column names are those of bench/naive/pc_crash.py (the NumPy peer): per vehicle i = 1, 2, mass_i,
// Jpq_i (the inertia tensor's entries, body axes), yaw_i, pitch_i, roll_i (degrees), v0_i..v2_i (CG
// velocity, world), w0_i..w2_i (angular velocity, body), r0_i..r2_i (impulse centre, body); then
// normal_yaw, normal_pitch, tangent_roll (degrees), restitution; and the strategy's ratios: mu (pc-crash,
// Wach), or mu_t and mu_z (Brach; an absent one is critical on every row). SI units. Each a 1-D array of
// one length, or a number for every row; the ones not required default to 0. `strategy` is "pc-crash",
// "wach" or "brach"; `limit` Wach's cap, "cir" (the default) or "gir".
pybind11::dict solve_batch(const pybind11::dict& columns, unsigned jobs, bool velocities, const std::string& strategy,
                           const std::optional<std::string>& limit);

void add_solve_batch(pybind11::module_& m);

}  // namespace impact3d::python
