// The batch entry points: the widest lane kernel this CPU runs, then the scalar path (solve_lean) for the
// tail of the range and for every row the lanes left to it, with the same strategy.
#include "impact3d/mechanics/batch/columns.hpp"

#include <atomic>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "impact3d/mechanics/lean.hpp"
#include "lanes_entry.hpp"

namespace impact3d::batch {

namespace {

struct Kernel {
  const char* name;
  std::size_t width;
  std::size_t (*pc_crash)(const CollisionColumns&, const ImpulseColumns&, std::size_t, std::size_t);
  std::size_t (*wach)(const CollisionColumns&, bool, const ImpulseColumns&, std::size_t, std::size_t);
  std::size_t (*brach)(const CollisionColumns&, const double*, const double*, const ImpulseColumns&, std::size_t, std::size_t);
  std::size_t (*sin_cos)(const double*, double*, double*, std::size_t);
};

// Widest first.
#define IMPACT3D_KERNEL_(name, text, width) \
  {text, width, lanes::pc_crash_##name, lanes::wach_##name, lanes::brach_##name, lanes::sin_cos_##name}
const Kernel kKernels[] = {IMPACT3D_KERNEL_(avx512f, "avx512f", 8), IMPACT3D_KERNEL_(avx2_fma, "avx2+fma", 4),
                           IMPACT3D_KERNEL_(sse2, "sse2", 2)};
#undef IMPACT3D_KERNEL_

// GCC's CPU test, which also asks the OS (XGETBV) whether it saves the wide registers: a CPU that has
// AVX-512 under a kernel or hypervisor that leaves it off must not run the wide kernel. (xsimd 8's own
// test reads CPUID alone.)
bool runs_here(const Kernel& k) {
  const std::string name = k.name;
  if (name == "avx512f") return __builtin_cpu_supports("avx512f");
  if (name == "avx2+fma") return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return true;  // SSE2 is x86-64's baseline
}

std::atomic<const Kernel*>& chosen() {
  static std::atomic<const Kernel*> k = [] {
    for (const Kernel& k : kKernels)
      if (runs_here(k)) return &k;
    return &kKernels[std::size(kKernels) - 1];
  }();
  return k;
}

const Kernel& kernel() { return *chosen().load(); }

void solve_row(const CollisionColumns& in, const ImpulseColumns& out, std::size_t i, const Strategy<double>& strategy) {
  const Scene<double> s = scene_of(row_of(in, i));
  const LeanSolution<double> r = solve_lean(s, strategy);
  const bool solved = r.status == Status::solved;
  for (int k = 0; k < 3; ++k) out.P_C[k][i] = solved ? r.impulse.P_C(k) : std::numeric_limits<double>::quiet_NaN();
  out.status[i] = static_cast<std::uint8_t>(r.status);
  out.regime[i] = static_cast<std::uint8_t>(r.impulse.regime);
  out.warnings[i] = r.warnings;
}

}  // namespace

const char* simd_name() { return kernel().name; }

std::vector<std::string> simd_available() {
  std::vector<std::string> names;
  for (const Kernel& k : kKernels)
    if (runs_here(k)) names.push_back(k.name);
  return names;
}

bool use_simd(const std::string& name) {
  for (const Kernel& k : kKernels)
    if (k.name == name && runs_here(k)) {
      chosen().store(&k);
      return true;
    }
  return false;
}
std::size_t simd_width() { return kernel().width; }

RawCollision<double> row_of(const CollisionColumns& in, std::size_t i) {
  RawCollision<double> c;
  for (int b = 0; b < 2; ++b) {
    const VehicleColumns& v = in.vehicle[b];
    RawVehicle<double>& r = c.vehicle[b];
    r.mass = v.mass[i];
    const int entry[3][3] = {{xx, xy, xz}, {xy, yy, yz}, {xz, yz, zz}};
    for (int p = 0; p < 3; ++p) {
      for (int q = 0; q < 3; ++q) r.J_B(p, q) = v.J_B[entry[p][q]][i];
      r.v_W(p) = v.v_W[p][i];
      r.w_B(p) = v.w_B[p][i];
      r.p_CgIc_B(p) = v.p_CgIc_B[p][i];
    }
    r.yaw_deg = v.yaw_deg[i], r.pitch_deg = v.pitch_deg[i], r.roll_deg = v.roll_deg[i];
  }
  c.normal_yaw_deg = in.normal_yaw_deg[i], c.normal_pitch_deg = in.normal_pitch_deg[i];
  c.tangent_roll_deg = in.tangent_roll_deg[i], c.restitution = in.restitution[i];
  return c;
}

namespace {

// The rows the lanes did not decide (from lanes_end to end, and those marked kDeferred before it) on
// the scalar path, with each row's strategy; how many.
std::size_t finish(const CollisionColumns& in, const ColumnStrategy& strategy, const ImpulseColumns& out,
                   std::size_t begin, std::size_t lanes_end, std::size_t end) {
  std::size_t scalar = end - lanes_end;
  for (std::size_t i = begin; i < lanes_end; ++i)
    if (out.status[i] == lanes::kDeferred) solve_row(in, out, i, strategy.row(in, i)), ++scalar;
  for (std::size_t i = lanes_end; i < end; ++i) solve_row(in, out, i, strategy.row(in, i));
  return scalar;
}

}  // namespace

namespace {

static_assert([] {
  bool fits = true;
  for_each_strategy([&](auto, auto spec) { fits = fits && decltype(spec)::type::parameters.size() <= ColumnStrategy::kParameters; });
  return fits;
}());

// A row's parameter values as a strategy's make reads them.
struct RowValues {
  const ColumnStrategy& strategy;
  std::span<const Parameter> parameters;
  const CollisionColumns& in;
  std::size_t i;
  std::size_t place(std::string_view key) const {
    std::size_t k = 0;
    while (k < parameters.size() && parameters[k].key != key) ++k;
    return k;
  }
  std::optional<double> number(std::string_view key) const {
    const std::size_t k = place(key);
    if (parameters[k].type == ParameterType::non_negative) return in.mu[i];
    const double* column = strategy.ratio[k];
    return column ? std::optional<double>(column[i]) : std::nullopt;
  }
  std::size_t choice_index(std::string_view key) const { return strategy.choice[place(key)]; }
};

}  // namespace

Strategy<double> ColumnStrategy::row(const CollisionColumns& in, std::size_t i) const {
  return with_strategy_index(kind, [&]<std::size_t I>(std::integral_constant<std::size_t, I>) {
    using Spec = std::variant_alternative_t<I, Strategy<double>>;
    return Strategy<double>(Spec::make(RowValues{*this, Spec::parameters, in, i}));
  });
}

std::size_t solve_columns(const CollisionColumns& in, const ColumnStrategy& strategy, const ImpulseColumns& out,
                          std::size_t begin, std::size_t end) {
  const Kernel& k = kernel();
  std::size_t lanes_end = begin;  // the strategies with a kernel on lanes
  if (strategy.is<PcCrash<double>>()) lanes_end = k.pc_crash(in, out, begin, end);
  else if (strategy.is<Wach<double>>())
    lanes_end = k.wach(in, static_cast<WachLimit>(strategy.choice[1]) == WachLimit::cir, out, begin, end);  // its limit, 2nd
  else if (strategy.is<Brach<double>>()) lanes_end = k.brach(in, strategy.ratio[0], strategy.ratio[1], out, begin, end);
  return finish(in, strategy, out, begin, lanes_end, end);
}

std::size_t pc_crash_columns(const CollisionColumns& in, const ImpulseColumns& out, std::size_t begin, std::size_t end) {
  return solve_columns(in, {strategy_index<PcCrash<double>>}, out, begin, end);
}

std::size_t wach_columns(const CollisionColumns& in, WachLimit limit, const ImpulseColumns& out, std::size_t begin,
                         std::size_t end) {
  return solve_columns(in, {strategy_index<Wach<double>>, {}, {0, static_cast<std::size_t>(limit)}}, out, begin, end);
}

std::size_t brach_columns(const CollisionColumns& in, const double* mu_t, const double* mu_z, const ImpulseColumns& out,
                          std::size_t begin, std::size_t end) {
  return solve_columns(in, {strategy_index<Brach<double>>, {mu_t, mu_z}}, out, begin, end);
}

void sin_cos_deg_columns(const double* deg, double* s, double* c, std::size_t n) {
  for (std::size_t i = kernel().sin_cos(deg, s, c, n); i < n; ++i) {
    const SinCos<double> r = sin_cos_deg(deg[i]);
    s[i] = r.s, c[i] = r.c;
  }
}

// ---- Tables -------------------------------------------------------------------------------------------

void CollisionTable::resize(std::size_t rows) {
  rows_ = rows;
  for (auto& column : data_) column.resize(rows);
}

// Column order: per vehicle mass, J (6), yaw, pitch, roll, v (3), w (3), r (3); then the contact angles,
// the restitution and mu.
void CollisionTable::set(std::size_t i, const RawCollision<double>& c, double mu) {
  int k = 0;
  for (const RawVehicle<double>& v : c.vehicle) {
    data_[k++][i] = v.mass;
    for (auto [p, q] : {std::pair{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}}) data_[k++][i] = v.J_B(p, q);
    data_[k++][i] = v.yaw_deg, data_[k++][i] = v.pitch_deg, data_[k++][i] = v.roll_deg;
    for (const Vec3<double>* x : {&v.v_W, &v.w_B, &v.p_CgIc_B})
      for (int p = 0; p < 3; ++p) data_[k++][i] = (*x)(p);
  }
  for (double x : {c.normal_yaw_deg, c.normal_pitch_deg, c.tangent_roll_deg, c.restitution, mu}) data_[k++][i] = x;
}

CollisionColumns CollisionTable::columns() const {
  CollisionColumns c;
  c.rows = rows_;
  int k = 0;
  for (VehicleColumns& v : c.vehicle) {
    v.mass = data_[k++].data();
    for (auto& j : v.J_B) j = data_[k++].data();
    v.yaw_deg = data_[k++].data(), v.pitch_deg = data_[k++].data(), v.roll_deg = data_[k++].data();
    for (auto* x : {&v.v_W, &v.w_B, &v.p_CgIc_B})
      for (auto& p : *x) p = data_[k++].data();
  }
  c.normal_yaw_deg = data_[k++].data(), c.normal_pitch_deg = data_[k++].data(), c.tangent_roll_deg = data_[k++].data();
  c.restitution = data_[k++].data(), c.mu = data_[k++].data();
  return c;
}

void ImpulseTable::resize(std::size_t rows) {
  for (auto& p : P_C) p.resize(rows);
  status.resize(rows), regime.resize(rows), warnings.resize(rows);
}

ImpulseColumns ImpulseTable::columns() {
  return {{P_C[0].data(), P_C[1].data(), P_C[2].data()}, status.data(), regime.data(), warnings.data()};
}

}  // namespace impact3d::batch
