// Many collisions at once, as columns (structure of arrays): the layout SIMD lanes load from, and that
// NumPy arrays hand over without copying. Each row is a RawCollision (raw_collision.hpp) and a friction
// coefficient mu; each result row is what solve_lean gives for Want::impulse: P_C, the status, the regime
// and the warning codes.
//
// solve_columns (and pc_crash_columns, wach_columns, brach_columns) computes rows on SIMD lanes through
// the generated kernels (the widest instruction set the CPU offers among AVX-512, AVX2 with FMA and SSE2),
// with the regime as a lane mask. A row whose decision is not clear on the lane is solved by solve_lean
// instead, so every row gets the scalar path's status, regime and warnings: the bodies do not approach; a
// value is not finite; eps is outside [0, 1] or m' not positive; a solution plane, the regime, the sign of
// Wach's cap or of the normal impulse, a denominator of a ratio decided on or reported (solve_lean goes
// singular where a reported ratio is not finite), or the rounding warning falls within thrice the cheap
// rounding bound, widened for a ratio by what its denominator amplifies; or the row carries a warning
// other than the two the lanes give themselves, a tensile normal impulse and Wach's negative ratio. The
// impulses of the rows solved on lanes differ from solve_lean's only by the rounding of the vectorized
// sine and cosine and of fused multiply-adds (tests/mechanics/check_batch.cpp states and checks the bound).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "impact3d/mechanics/batch/sin_cos.hpp"
#include "impact3d/mechanics/raw_collision.hpp"
#include "impact3d/mechanics/strategies/list.hpp"

namespace impact3d::batch {

// Inertia tensor entries, upper triangle.
enum InertiaEntry { xx, xy, xz, yy, yz, zz };

struct VehicleColumns {
  const double* mass;
  const double* J_B[6];  // by InertiaEntry
  const double *yaw_deg, *pitch_deg, *roll_deg;
  const double* v_W[3];
  const double* w_B[3];
  const double* p_CgIc_B[3];
};

struct CollisionColumns {
  std::size_t rows = 0;
  VehicleColumns vehicle[2];
  const double *normal_yaw_deg, *normal_pitch_deg, *tangent_roll_deg, *restitution, *mu;
};

struct ImpulseColumns {
  double* P_C[3];           // on vehicle 1, contact axes (n, t, z); NaN unless solved
  std::uint8_t* status;     // Status (lean.hpp)
  std::uint8_t* regime;     // Regime (strategy.hpp), when solved
  WarningSet* warnings;     // warning_bit(WarningCode) set
};

// Which instruction set solve_columns uses on this CPU: "avx512f", "avx2+fma" or "sse2".
const char* simd_name();
// Doubles per lane group on that instruction set.
std::size_t simd_width();
// The instruction sets this CPU runs, widest first; use_simd chooses one of them for every later call
// (false, and no change, for one it does not run). For tests and benchmarks.
std::vector<std::string> simd_available();
bool use_simd(const std::string& name);

// One strategy for every row, `kind` its index in strategies/list.hpp, its parameters by their place in
// the strategy's list of them: a non-negative one (pc-crash's and Wach's mu) from in.mu, a ratio
// (Brach's) from its column or, where the column is null, critical (eqs 25-27) on every row, a choice
// (Wach's cap) the same for every row. A strategy with no kernel on lanes is solved on the scalar path.
struct ColumnStrategy {
  static constexpr std::size_t kParameters = 2;  // the most any strategy has (checked in columns.cpp)
  std::size_t kind = 0;
  std::array<const double*, kParameters> ratio{};
  std::array<std::size_t, kParameters> choice{};
  // Row i's, for the scalar path.
  Strategy<double> row(const CollisionColumns& in, std::size_t i) const;
  template <typename Spec>
  bool is() const {
    return kind == strategy_index<Spec>;
  }
};

// Rows [begin, end) of `in` into the same rows of `out`; returns how many of them the scalar path
// solved (the tail shorter than a lane group and the rows the lanes left to it). Safe to call on
// disjoint ranges from several threads.
std::size_t solve_columns(const CollisionColumns& in, const ColumnStrategy& strategy, const ImpulseColumns& out,
                          std::size_t begin, std::size_t end);
// The same, for each strategy.
std::size_t pc_crash_columns(const CollisionColumns& in, const ImpulseColumns& out, std::size_t begin, std::size_t end);
std::size_t wach_columns(const CollisionColumns& in, WachLimit limit, const ImpulseColumns& out, std::size_t begin,
                         std::size_t end);
std::size_t brach_columns(const CollisionColumns& in, const double* mu_t, const double* mu_z, const ImpulseColumns& out,
                          std::size_t begin, std::size_t end);

// Row i as a RawCollision, for the scalar path.
RawCollision<double> row_of(const CollisionColumns& in, std::size_t i);

// Columns that own their storage: filled row by row, viewed as CollisionColumns / ImpulseColumns.
class CollisionTable {
 public:
  explicit CollisionTable(std::size_t rows = 0) { resize(rows); }
  void resize(std::size_t rows);
  std::size_t rows() const { return rows_; }
  void set(std::size_t i, const RawCollision<double>& c, double mu);
  CollisionColumns columns() const;

 private:
  static constexpr int kColumns = 2 * 19 + 5;
  std::size_t rows_ = 0;
  std::vector<double> data_[kColumns];
};

class ImpulseTable {
 public:
  explicit ImpulseTable(std::size_t rows = 0) { resize(rows); }
  void resize(std::size_t rows);
  ImpulseColumns columns();
  std::vector<double> P_C[3];
  std::vector<std::uint8_t> status, regime;
  std::vector<WarningSet> warnings;
};

}  // namespace impact3d::batch
