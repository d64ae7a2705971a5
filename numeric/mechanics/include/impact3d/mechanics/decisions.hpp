// The names of the branch decisions the mechanics take (beside the two the log itself files under,
// impact3d/scalar/decision_log.hpp, which records them).
#pragma once

#include "impact3d/scalar/decision_log.hpp"

namespace impact3d {

// As results list them.
namespace decision_names {
inline constexpr char approach[] = "approach: V_rn > 0";
inline constexpr char pc_crash_regime[] = "regime: mu >= GIR (eq 14)";
inline constexpr char wach_cap_cir[] = "cap: mu >= CIR (eq 19)";
inline constexpr char wach_cap_gir[] = "cap: mu >= GIR (eq 20)";
inline constexpr char plane_direction[] = "solution plane: direction lost in rounding";
inline constexpr char fallback_direction[] = "solution plane: the fallback axis's direction, the cap's sign";
inline constexpr char ratio_sign[] = "sign of the impulse ratio used";
inline constexpr char normal_impulse_sign[] = "sign of P_n";
inline constexpr char volume[] = "volume (Figure 2): the sign of V_rn after and the change of sliding along t";
inline constexpr char z_sliding[] = "sliding along z: none, started, continued, stopped or reversed";
inline constexpr char energy_loss_sign[] = "energy: sign of the loss";
inline constexpr char pdof[] = "PDOF: Delta-V has a horizontal part in vehicle axes, and its angle's quadrant";
inline constexpr char swerve[] = "sliding and swerve: which of the initial and final sliding are zero, and the swerve's side";
inline constexpr char heading_after[] = "heading after: horizontal speed > 0";
inline constexpr char cil_direction[] = "critical impulse line: the sign of its direction's P_n component";
}  // namespace decision_names

}  // namespace impact3d
