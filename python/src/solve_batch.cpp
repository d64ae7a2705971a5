#include "solve_batch.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "case.hpp"
#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/limits.hpp"
#include "impact3d/mechanics/batch/columns.hpp"
#include "impact3d/mechanics/lean.hpp"
#include "impact3d/scalar/parallel_chunks.hpp"

namespace py = pybind11;

namespace impact3d::python {
namespace {

using Column = py::array_t<double, py::array::c_style | py::array::forcecast>;

// A row's status beyond lean.hpp's: its inputs are not a collision (an impact3d.CaseError for a case).
constexpr std::uint8_t kInvalid = 3;
// The regime of a row that was not solved: none (REGIMES has no such index).
constexpr std::uint8_t kNoRegime = 255;

constexpr std::size_t kBlock = 4096;  // rows a thread takes at a time

const char* const kVehicleColumns[] = {"mass", "J00", "J01", "J02", "J10", "J11", "J12", "J20", "J21", "J22", "yaw",
                                       "pitch", "roll", "v0",  "v1",  "v2",  "w0",  "w1",  "w2",  "r0",  "r1",  "r2"};
const char* const kContactColumns[] = {"normal_yaw", "normal_pitch", "tangent_roll", "restitution"};

// The strategies (strategies/list.hpp) by name, and the columns of their numbers.
struct StrategyChoice {
  batch::ColumnStrategy lanes;  // the ratio columns once the columns are read
  std::string_view name;
  std::span<const Parameter> parameters;
};

StrategyChoice kind_at(std::size_t kind) {
  return with_strategy_index(kind, [&]<std::size_t I>(std::integral_constant<std::size_t, I>) {
    using Spec = std::variant_alternative_t<I, Strategy<double>>;
    return StrategyChoice{{I}, Spec::name, Spec::parameters};
  });
}

StrategyChoice strategy_of(const std::string& name, const std::optional<std::string>& limit) {
  std::optional<StrategyChoice> found;
  std::vector<std::string> names;
  for (std::size_t k = 0; k < Strategies::size; ++k) {
    const StrategyChoice c = kind_at(k);
    names.push_back(fmt::format("\"{}\"", c.name));
    if (c.name == name) found = c;
  }
  if (!found)
    throw py::value_error(fmt::format("solve_batch: strategy {} is not one of {}", case_format::quoted(name), fmt::join(names, ", ")));
  StrategyChoice c = *found;
  if (limit) {
    // The choice named `limit`: Wach's cap.
    std::optional<std::size_t> place;
    for (std::size_t p = 0; p < c.parameters.size(); ++p)
      if (c.parameters[p].type == ParameterType::choice && c.parameters[p].key == "limit") place = p;
    if (!place) {
      std::string_view owner;
      for (std::size_t k = 0; k < Strategies::size && owner.empty(); ++k) {
        const StrategyChoice other = kind_at(k);
        for (const Parameter& p : other.parameters)
          if (p.type == ParameterType::choice && p.key == "limit") owner = other.name;
      }
      throw py::value_error(fmt::format("solve_batch: limit is {}'s, not {}'s", owner, c.name));
    }
    const auto& choices = c.parameters[*place].choices;
    const auto at = std::find(choices.begin(), choices.end(), *limit);
    if (at == choices.end())
      throw py::value_error(fmt::format("solve_batch: limit {} is not \"{}\"", case_format::quoted(*limit),
                                        fmt::join(choices, "\" or \"")));
    c.lanes.choice[*place] = static_cast<std::size_t>(at - choices.begin());
  }
  return c;
}

// The columns of a strategy's numbers, by their keys; a choice has none.
std::vector<const char*> ratio_columns(const StrategyChoice& c) {
  std::vector<const char*> out;
  for (const Parameter& p : c.parameters)
    if (p.type != ParameterType::choice) out.push_back(p.key.data());  // a literal's view: terminated
  return out;
}

bool required(const std::string& name) {
  for (const char* r : {"mass_", "J00_", "J11_", "J22_", "yaw_", "v0_", "v1_", "r0_", "r1_"})
    if (name.rfind(r, 0) == 0) return true;
  return name == "normal_yaw" || name == "restitution" || name == "mu";
}

// Every column by name: the caller's arrays as they are (no copy when they are contiguous doubles), a
// number repeated on every row, or 0.
class Columns {
 public:
  Columns(const py::dict& given, const StrategyChoice& strategy) {
    std::vector<std::string> names;
    for (int i = 1; i <= 2; ++i)
      for (const char* c : kVehicleColumns) names.push_back(fmt::format("{}_{}", c, i));
    for (const char* c : kContactColumns) names.emplace_back(c);
    for (const char* c : ratio_columns(strategy)) names.emplace_back(c);
    for (const auto& [key, value] : given) {
      const std::string name = py::str(key);
      if (std::find(names.begin(), names.end(), name) == names.end()) {
        for (std::size_t other = 0; other < Strategies::size; ++other)
          for (const char* ratio : ratio_columns(kind_at(other)))
            if (name == ratio)
              throw py::type_error(fmt::format("solve_batch: {} is not a column of {} (its ratios: {})", name,
                                               strategy.name, fmt::join(ratio_columns(strategy), ", ")));
        throw py::type_error(fmt::format("solve_batch: no column {} (the columns are those of "
                                         "impact3d.BATCH_COLUMNS)", case_format::quoted(name)));
      }
      // Numbers only: NumPy would also cast strings, complex numbers, dates, None, and a masked array's
      // hidden values.
      const py::array raw = py::array::ensure(value);
      if (!raw || std::string("biuf").find(raw.dtype().kind()) == std::string::npos ||
          py::isinstance(value, py::module_::import("numpy.ma").attr("MaskedArray")))
        throw py::type_error(fmt::format("solve_batch: {} is not real numbers (a number, or an array of integers, "
                                         "floats or booleans)", name));
      Column a = Column::ensure(raw);
      if (a.ndim() > 1) throw py::value_error(fmt::format("solve_batch: {} has {} dimensions; a column has one", name, a.ndim()));
      if (a.ndim() == 1) {
        if (rows_ && *rows_ != static_cast<std::size_t>(a.shape(0)))
          throw py::value_error(fmt::format("solve_batch: {} has {} rows, another column {}", name, a.shape(0), *rows_));
        rows_ = static_cast<std::size_t>(a.shape(0));
      }
      given_[name] = std::move(a);
    }
    for (const auto& name : names)
      if (required(name) && !given_.count(name))
        throw py::type_error(fmt::format("solve_batch: the column {} is required", name));
    const std::size_t n = rows();
    for (const auto& name : names) {
      const auto it = given_.find(name);
      if (it != given_.end() && it->second.ndim() == 1) {
        data_[name] = it->second.data();
      } else if (it == given_.end()) {
        if (zeros_.size() != n) zeros_.assign(n, 0.0);  // one column of zeros for every absent one
        data_[name] = zeros_.data();
      } else {
        filled_.emplace_back(n, *it->second.data());
        data_[name] = filled_.back().data();
      }
    }
  }

  std::size_t rows() const { return rows_.value_or(1); }
  const double* operator[](const std::string& name) const { return data_.at(name); }
  bool given(const std::string& name) const { return given_.count(name) > 0; }

 private:
  std::optional<std::size_t> rows_;
  std::map<std::string, Column> given_;
  std::vector<std::vector<double>> filled_;
  std::vector<double> zeros_;
  std::map<std::string, const double*> data_;
};

// Why row i is not a collision, worded as the case reader words it of a case; empty when it is one.
struct RowCheck {
  const batch::CollisionColumns& in;
  std::vector<std::pair<std::string, const double*>> named;  // every column read, by name
  const double* lower[2][3];  // J10, J20, J21 of each vehicle, when given (else nullptr)

  std::string operator()(std::size_t i) const {
    static const double kMax = std::strtod(case_format::limits::kMaxMagnitude, nullptr);
    static const double kMin = std::strtod(case_format::limits::kMinMagnitude, nullptr);
    for (const auto& [name, column] : named) {
      const double x = column[i];
      if (!std::isfinite(x)) return name + ": not a finite number";
      if (std::fabs(x) > kMax) return fmt::format("{}: out of range: magnitude {} exceeds {:g}", name, x, kMax);
      if (x != 0 && std::fabs(x) < kMin)
        return fmt::format("{}: out of range: {} is not zero but below {:g} in magnitude", name, x, kMin);
    }
    for (int b = 0; b < 2; ++b) {
      const batch::VehicleColumns& v = in.vehicle[b];
      const double J[6] = {v.J_B[0][i], v.J_B[1][i], v.J_B[2][i], v.J_B[3][i], v.J_B[4][i], v.J_B[5][i]};
      if (!(v.mass[i] > 0)) return fmt::format("mass_{}: not positive", b + 1);
      const double upper[3] = {J[batch::xy], J[batch::xz], J[batch::yz]};
      for (int k = 0; k < 3; ++k)
        if (lower[b][k] && lower[b][k][i] != upper[k]) return fmt::format("J_{}: not symmetric", b + 1);
      // Sylvester's criterion on the leading minors.
      const double m1 = J[batch::xx], m2 = J[batch::xx] * J[batch::yy] - J[batch::xy] * J[batch::xy];
      const double m3 = J[batch::xx] * (J[batch::yy] * J[batch::zz] - J[batch::yz] * J[batch::yz]) -
                        J[batch::xy] * (J[batch::xy] * J[batch::zz] - J[batch::yz] * J[batch::xz]) +
                        J[batch::xz] * (J[batch::xy] * J[batch::yz] - J[batch::yy] * J[batch::xz]);
      if (!(m1 > 0 && m2 > 0 && m3 > 0)) return fmt::format("J_{}: not positive definite", b + 1);
    }
    if (!(in.restitution[i] >= 0 && in.restitution[i] <= 1)) return "restitution: outside [0, 1]";
    if (in.mu && !(in.mu[i] >= 0)) return "mu: negative";  // a ratio is signed
    return {};
  }
};

template <typename T>
py::array_t<T> column_out(std::size_t rows) {
  return py::array_t<T>(static_cast<py::ssize_t>(rows));
}

py::array_t<double> rows_by_3(std::size_t rows) {
  return py::array_t<double>({static_cast<py::ssize_t>(rows), py::ssize_t{3}});
}

}  // namespace

py::dict solve_batch(const py::dict& given, unsigned jobs, bool velocities, const std::string& strategy_name,
                     const std::optional<std::string>& limit) {
  if (jobs > kMaxJobs) throw py::value_error(fmt::format("solve_batch: jobs at most {}, not {}", kMaxJobs, jobs));
  StrategyChoice strategy = strategy_of(strategy_name, limit);
  const Columns c(given, strategy);
  const std::size_t n = c.rows();
  batch::CollisionColumns in;
  in.rows = n;
  for (int b = 0; b < 2; ++b) {
    const auto col = [&](const char* name) { return c[fmt::format("{}_{}", name, b + 1)]; };
    batch::VehicleColumns& v = in.vehicle[b];
    v.mass = col("mass");
    const char* entries[6] = {"J00", "J01", "J02", "J11", "J12", "J22"};  // by InertiaEntry
    for (int k = 0; k < 6; ++k) v.J_B[k] = col(entries[k]);
    v.yaw_deg = col("yaw"), v.pitch_deg = col("pitch"), v.roll_deg = col("roll");
    for (int k = 0; k < 3; ++k) {
      v.v_W[k] = col(fmt::format("v{}", k).c_str());
      v.w_B[k] = col(fmt::format("w{}", k).c_str());
      v.p_CgIc_B[k] = col(fmt::format("r{}", k).c_str());
    }
  }
  in.normal_yaw_deg = c["normal_yaw"], in.normal_pitch_deg = c["normal_pitch"], in.tangent_roll_deg = c["tangent_roll"];
  in.restitution = c["restitution"];
  // A non-negative number (mu) is the one column in.mu; a ratio's column as given, an absent one critical
  // on every row (Brach's).
  in.mu = nullptr;
  for (std::size_t p = 0; p < strategy.parameters.size(); ++p) {
    const Parameter& param = strategy.parameters[p];
    const std::string key(param.key);
    if (param.type == ParameterType::non_negative) in.mu = c[key];
    else if (param.type == ParameterType::ratio_or_critical && c.given(key)) strategy.lanes.ratio[p] = c[key];
  }
  RowCheck check{in, {}, {}};
  for (int b = 1; b <= 2; ++b)
    for (const char* name : kVehicleColumns) check.named.emplace_back(fmt::format("{}_{}", name, b), nullptr);
  for (const char* name : kContactColumns) check.named.emplace_back(name, nullptr);
  for (const char* name : ratio_columns(strategy)) check.named.emplace_back(name, nullptr);
  for (auto& [name, column] : check.named) column = c[name];
  for (int b = 0; b < 2; ++b) {
    const char* lower[3] = {"J10", "J20", "J21"};
    for (int k = 0; k < 3; ++k) {
      const std::string name = fmt::format("{}_{}", lower[k], b + 1);
      check.lower[b][k] = c.given(name) ? c[name] : nullptr;
    }
  }

  // P_C as a (3, n) block, handed out as its (n, 3) transpose: each component a contiguous column.
  py::array_t<double> P_C({py::ssize_t{3}, static_cast<py::ssize_t>(n)});
  auto status = column_out<std::uint8_t>(n), regime = column_out<std::uint8_t>(n);
  auto warnings = column_out<WarningSet>(n);
  std::vector<py::array_t<double>> states;  // P_W, v_1, w_1, v_2, w_2: (n, 3)
  if (velocities)
    for (int k = 0; k < 5; ++k) states.push_back(rows_by_3(n));
  batch::ImpulseColumns out;
  double* const P_C_data = P_C.mutable_data();
  for (int k = 0; k < 3; ++k) out.P_C[k] = P_C_data + static_cast<std::size_t>(k) * n;
  out.status = status.mutable_data();
  out.regime = regime.mutable_data();
  out.warnings = warnings.mutable_data();
  std::vector<double*> state_data;
  for (auto& s : states) state_data.push_back(s.mutable_data());
  std::vector<std::pair<std::size_t, std::string>> problems;

  {
    py::gil_scoped_release released;
    ParallelChunks pool(jobs);
    std::vector<std::vector<std::pair<std::size_t, std::string>>> found(pool.jobs());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    pool.run(n, kBlock, [&](unsigned t, std::size_t begin, std::size_t end) {
      if (velocities) {
        for (std::size_t i = begin; i < end; ++i) {
          const LeanSolution<double> r = solve_lean(scene_of(batch::row_of(in, i)), strategy.lanes.row(in, i),
                                                      Want::velocities);
          const bool solved = r.status == Status::solved;
          const Vec3<double>* vectors[5] = {&r.P_W, &r.v_W[0], &r.w_B[0], &r.v_W[1], &r.w_B[1]};
          for (int k = 0; k < 3; ++k) {
            out.P_C[k][i] = solved ? r.impulse.P_C(k) : nan;
            for (int s = 0; s < 5; ++s) state_data[s][3 * i + k] = solved ? (*vectors[s])(k) : nan;
          }
          out.status[i] = static_cast<std::uint8_t>(r.status);
          out.regime[i] = static_cast<std::uint8_t>(r.impulse.regime);
          out.warnings[i] = r.warnings;
        }
      } else {
        batch::solve_columns(in, strategy.lanes, out, begin, end);
      }
      for (std::size_t i = begin; i < end; ++i) {
        // A row that is not a collision is flagged, whatever the arithmetic made of it.
        if (std::string problem = check(i); !problem.empty()) {
          found[t].emplace_back(i, std::move(problem));
          for (int k = 0; k < 3; ++k) out.P_C[k][i] = nan;
          for (auto* s : state_data)
            for (int k = 0; k < 3; ++k) s[3 * i + k] = nan;
          out.status[i] = kInvalid;
          out.warnings[i] = 0;
        }
        if (out.status[i] != static_cast<std::uint8_t>(Status::solved)) out.regime[i] = kNoRegime;
      }
    });
    for (auto& f : found) std::move(f.begin(), f.end(), std::back_inserter(problems));
    std::sort(problems.begin(), problems.end());
  }

  py::dict result;
  result["P_C"] = P_C.attr("T");
  result["status"] = status;
  result["regime"] = regime;
  result["warnings"] = warnings;
  if (velocities) {
    const char* names[5] = {"P_W", "v_1", "w_1", "v_2", "w_2"};
    for (int s = 0; s < 5; ++s) result[names[s]] = states[static_cast<std::size_t>(s)];
  }
  py::dict flagged;
  for (const auto& [row, problem] : problems) flagged[py::int_(row)] = py::str(case_format::printable(problem));
  result["problems"] = flagged;
  return result;
}

void add_solve_batch(py::module_& m) {
  m.def("_solve_batch", &solve_batch, py::arg("columns"), py::arg("jobs") = 0u, py::arg("velocities") = false,
        py::arg("strategy") = "pc-crash", py::arg("limit") = std::nullopt);
  py::list names;
  for (int i = 1; i <= 2; ++i)
    for (const char* c : kVehicleColumns) names.append(fmt::format("{}_{}", c, i));
  for (const char* c : kContactColumns) names.append(c);
  for (const char* c : {"mu", "mu_t", "mu_z"}) names.append(c);
  m.attr("BATCH_COLUMNS") = py::tuple(names);
  m.attr("BATCH_SIMD") = batch::simd_name();
}

}  // namespace impact3d::python
