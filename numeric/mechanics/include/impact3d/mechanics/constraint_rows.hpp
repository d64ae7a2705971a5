// The questions about the post-impact relative velocity V_rf that the strategy's own constraint rows
// answer (ConstraintRows, strategy.hpp): a final sliding that is the strategy's constraint is zero by
// construction, not by a ball that happens to hold 0. Only an enclosure asks here, and only where its
// ball holds 0 without being 0: everywhere else (a ball that decides, an exact zero, every other
// scalar, whose rounding rule gives the same answer) the question is the comparison's own. An answer
// from the rows is recorded in the decision log with the equation that gives it.
#pragma once

#include <optional>
#include <string>

#include "impact3d/mechanics/decisions.hpp"
#include "impact3d/mechanics/rounding.hpp"
#include "impact3d/mechanics/strategy.hpp"
#include "impact3d/scalar/types.hpp"

namespace impact3d {

// What the rows say of one zero question: nothing, or whether the quantity is zero, and why.
struct RowsAnswer {
  std::optional<bool> zero;
  std::string why;
};

struct ZeroAnswer {
  bool zero;
  bool by_rows;  // the rows answered, the balls having left it open
};

// Whether x is zero: the balls' answer (rounding::within_rounding), or the rows' (`rows()`, a
// RowsAnswer, asked only of an enclosure whose ball holds 0 without being 0).
template <typename Scalar, typename Rows>
ZeroAnswer zero_or_by_rows(const Scalar& x, const Scalar& tol, Rows&& rows) {
  if constexpr (is_enclosure_v<Scalar>) {
    if (x.contains_zero() && !x.exactly_zero()) {
      const RowsAnswer r = rows();
      if (r.zero) {
        if (DecisionLog* log = DecisionLog::current)
          log->by_construction(r.why + (*r.zero ? ": zero by construction" : ": not zero by construction"));
        return {*r.zero, true};
      }
    }
  }
  return {rounding::within_rounding(x, tol), false};
}

// Whether eps is zero, for the rows that scale by it: exactly 0, or a ball excluding 0 (a decimal
// restitution is one or the other); nothing where neither.
template <typename Scalar>
bool exactly_zero(const Scalar& x) {
  if constexpr (is_enclosure_v<Scalar>) return x.exactly_zero();
  else return false;  // not asked: only an enclosure takes the rows' answers
}

template <typename Scalar>
std::optional<bool> restitution_zero(const Scalar& eps) {
  if constexpr (is_enclosure_v<Scalar>) {
    if (eps.exactly_zero()) return true;
    if (!eps.contains_zero()) return false;
  }
  return std::nullopt;
}

// V_rnf = -eps V_rni, every strategy's restitution row (V_rni > 0: the bodies approach).
inline RowsAnswer normal_after(std::optional<bool> eps_zero) {
  return {eps_zero, "V_rn after = -eps V_rn before (the restitution row, eq 9)"};
}

// V_rf along t (axis 1) or z (axis 2), given whether V_ri along it was taken as zero and whether V_ri
// along the other axis is exactly zero (a ball of radius 0: then the initial sliding, and with it Wach's
// plane axis, lies along this axis exactly).
inline RowsAnswer axis_after(const ConstraintRows& r, int axis, bool was_zero, std::optional<bool> eps_zero,
                             bool other_before_exactly_zero) {
  const char* name = axis == 1 ? "V_rt" : "V_rz";
  if (axis == 1 ? r.t_zero : r.z_zero)
    return {true, std::string(name) + " after = 0 (" + r.zero_rows + ")"};
  if (r.along_plane_zero && other_before_exactly_zero)
    return {true, std::string(name) + " after = 0 (" + r.zero_rows + ", the plane along the initial sliding, which is along " +
                      (axis == 1 ? "t" : "z") + " alone)"};
  if (r.full) {
    const std::string why = std::string(name) + " after = -eps " + name + " before (the Full Impact's rows, eqs 10-12)";
    if (was_zero) return {true, why + ", given " + name + " before zero"};
    return {eps_zero, why};
  }
  return {};
}

// Which contact-plane components are zero before and after, exactly: by a row, or by a ball of
// radius 0 (a planar case's vertical components), for the sliding and swerve questions below.
struct PlaneZeros {
  bool ri_t, ri_z, rf_t, rf_z;
};

template <typename Scalar>
PlaneZeros plane_zeros(const ConstraintRows& r, const Vec3<Scalar>& V_ri, const Vec3<Scalar>& V_rf) {
  const bool ri_t = exactly_zero(V_ri.y()), ri_z = exactly_zero(V_ri.z());
  return {ri_t, ri_z, r.t_zero || exactly_zero(V_rf.y()) || (r.along_plane_zero && ri_z),
          r.z_zero || exactly_zero(V_rf.z()) || (r.along_plane_zero && ri_t)};
}

// The final sliding |(V_rt, V_rz)| after, where the initial sliding is not zero.
inline RowsAnswer sliding_after(const ConstraintRows& r, const PlaneZeros& z, std::optional<bool> eps_zero) {
  if (z.rf_t && z.rf_z)
    return {true, std::string("sliding after = 0 (") + (r.t_zero || r.z_zero || r.along_plane_zero ? r.zero_rows : "") +
                      ", each of V_rt and V_rz after zero by its row or exactly)"};
  if (r.full) return {eps_zero, "sliding after = -eps times the sliding before (the Full Impact's rows, eqs 10-12)"};
  return {};
}

// The final sliding across the initial one's line (the swerve, V_rt V_rz' - V_rz V_rt'), where both
// are not zero.
inline RowsAnswer swerve_across(const ConstraintRows& r, const PlaneZeros& z) {
  if (r.full) return {true, "no swerve: the sliding after is -eps times the sliding before (the Full Impact's rows, eqs 10-12)"};
  if ((z.ri_t || z.rf_z) && (z.ri_z || z.rf_t))
    return {true, std::string("no swerve: each product of V_rt V_rz' - V_rz V_rt' has a zero factor (") + r.zero_rows + ")"};
  return {};
}

// The final sliding along the initial one's direction (V_rt V_rt' + V_rz V_rz'), where both are not zero.
inline RowsAnswer swerve_along(const ConstraintRows& r, const PlaneZeros& z, std::optional<bool> eps_zero) {
  if (r.along_plane_zero)
    return {true, std::string("no sliding along the initial sliding's direction after (") + r.zero_rows + ")"};
  if (r.full) return {eps_zero, "sliding along the initial direction after = -eps |sliding before| (the Full Impact's rows, eqs 10-12)"};
  if ((z.ri_t || z.rf_t) && (z.ri_z || z.rf_z))
    return {true, std::string("no sliding along the initial direction after: each product of V_rt V_rt' + V_rz V_rz' has a zero factor (") +
                      r.zero_rows + ")"};
  return {};
}

}  // namespace impact3d
