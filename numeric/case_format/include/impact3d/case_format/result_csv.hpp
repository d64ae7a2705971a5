// The result as CSV (docs/batch.md, "Results as CSV"): a fixed set of columns, one row per strategy of each
// case, every cell the text the result document (result_json.hpp) has at the column's path, written
// straight from the analysis (result_csv_rows; tests/studies/check_result_csv.cpp holds it to the document). The
// columns are listed once, the document's in result_csv_document_cells and each result's in
// result_csv_cells, for the header and the cells.
#pragma once

#include <algorithm>
#include <charconv>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/csv_text.hpp"
#include "impact3d/case_format/json_text.hpp"
#include "impact3d/case_format/present.hpp"
#include "impact3d/case_format/scalar_text.hpp"
#include "impact3d/mechanics/analysis.hpp"

namespace impact3d::case_format {

// The result document's own columns, the same in every row of a case, in order; a sink as
// result_csv_cells' takes each as text(name, text).
template <typename Sink>
void result_csv_document_cells(Sink& c, const CaseSpec& spec, std::string_view precision, Engine engine) {
  c.text("name", spec.name);
  c.text("units", units_name(spec.units));
  c.text("precision", precision);
  c.text("engine", engine_name(engine));
}

// The columns of one result, in order, each named by its path in the result document. A sink takes
// each as number(name, value[, factor]), number(name, optional[, factor]), vec(name, v, factor), count(name, optional
// int), text(name, text) and bound(name, value) (the rounding bound's 3 digits); an absent value is an
// empty cell. The names do not depend on the solution: the header is the same sink over any.
template <typename Scalar, typename Sink>
void result_csv_cells(Sink& c, const Solution<Scalar>& s, const Present<Scalar>& p) {
  const auto& f = p.f;
  const auto& imp = s.impulse;
  c.number("impulse_ratio.mu", imp.mu);
  c.number("impulse_ratio.mu_t", imp.mu_t);
  c.number("impulse_ratio.mu_z", imp.mu_z);
  c.number("limits.gir", imp.gir);
  c.number("limits.cir", imp.cir);
  c.number("limits.mu_t_critical", imp.mu_t_critical);
  c.number("limits.mu_z_critical", imp.mu_z_critical);
  c.number("plane_angle_deg", imp.plane_angle_deg);
  c.vec("impulse.contact", imp.P_C, f.impulse);
  c.vec("impulse.world", s.P_W, f.impulse);
  c.vec("relative_velocity.before", s.V_ri, f.velocity);
  c.vec("relative_velocity.after", s.V_rf, f.velocity);
  c.number("sliding.before", s.sliding_before, f.velocity);
  c.number("sliding.after", s.sliding_after, f.velocity);
  c.number("sliding.swerve_angle_deg", s.swerve_deg);
  c.number("sliding.swerve_speed", s.swerve_speed, f.velocity);
  c.number("impulse_space.restitution_effective", s.restitution_effective);
  c.text("impulse_space.t_sliding", axis_change_name(s.t_change));
  c.text("impulse_space.z_sliding", axis_change_name(s.z_change));
  c.text("impulse_space.volume", s.volume);
  static constexpr const char* kVehicle[2][6] = {
      {"vehicles[0].velocity", "vehicles[0].angular_velocity", "vehicles[0].delta_v", "vehicles[0].delta_v_magnitude",
       "vehicles[0].pdof_deg", "vehicles[0].pdof_clock"},
      {"vehicles[1].velocity", "vehicles[1].angular_velocity", "vehicles[1].delta_v", "vehicles[1].delta_v_magnitude",
       "vehicles[1].pdof_deg", "vehicles[1].pdof_clock"}};
  for (int i = 0; i < 2; ++i) {
    const auto& change = s.change[i];
    c.vec(kVehicle[i][0], s.after[i].v_W, f.velocity);
    c.vec(kVehicle[i][1], s.after[i].w_B, f.angular_velocity);
    c.vec(kVehicle[i][2], change.dv_W, f.velocity);
    c.number(kVehicle[i][3], change.dv, f.velocity);
    c.number(kVehicle[i][4], change.pdof_deg);
    c.count(kVehicle[i][5], change.clock);
  }
  c.number("energy.before", s.energy_before, f.energy);
  c.number("energy.after", s.energy_after, f.energy);
  c.number("energy.loss", s.energy_loss, f.energy);
  // An integrated impulse's course (stronge), empty cells for the others; its events only in JSON.
  const stronge::History<Scalar>* h = imp.history ? &*imp.history : nullptr;
  const auto of = [h](Scalar stronge::History<Scalar>::*field) { return h ? std::optional<Scalar>(h->*field) : std::nullopt; };
  const auto count_of = [h](int stronge::History<Scalar>::*field) { return h ? std::optional<int>(h->*field) : std::nullopt; };
  c.number("swerve_deg", of(&stronge::History<Scalar>::swerve_deg));
  c.number("final_direction_deg", h ? h->final_direction_deg : std::nullopt);
  c.number("normal_work.compression", of(&stronge::History<Scalar>::work_compression), f.energy);
  c.number("normal_work.restitution", of(&stronge::History<Scalar>::work_restitution), f.energy);
  c.count("integration.steps", count_of(&stronge::History<Scalar>::steps));
  c.bound("integration.error_bound", of(&stronge::History<Scalar>::error_bound));
  c.count("integration.diverging_directions", count_of(&stronge::History<Scalar>::diverging_directions));
  c.bound("rounding_bound", s.rounding_bound);
}

// The names of result_csv_cells' columns, a vector's as three ("impulse.contact[0]", ...).
const std::vector<std::string>& result_csv_column_names();

// "line,result,error", the document's columns (name, units, precision, engine), "strategy,regime",
// result_csv_cells' columns, "warnings"; and a newline.
std::string result_csv_header();
// The row of a case that was rejected: its line and the problem, every other cell empty.
std::string result_csv_error(long line, const std::string& problem);
// A strategy's cell: as --strategy writes it, name:key=value,...
std::string strategy_cell_text(const StrategySpec& s);

namespace detail {

// Cells appended straight from the solution, as the result document writes each value (a value that
// is not finite is null there, an empty cell here).
template <typename Scalar>
struct CsvCells {
  JsonText& out;
  const Present<Scalar>& p;

  void finite_or_empty(std::size_t at) {
    const std::string_view t = out.view().substr(at);
    const std::size_t i = !t.empty() && (t.front() == '-' || t.front() == '+');
    if (t.size() > i && (t[i] == 'i' || t[i] == 'n')) out.resize(at);
  }
  void scalar(const Scalar& x, int digits) {
    out += ',';
    const std::size_t at = out.size();
    append_scalar(out, x, digits);
    finite_or_empty(at);
  }
  void number(const char*, const Scalar& x) { scalar(x, p.digits); }
  void number(const char*, const Scalar& x, const Scalar& factor) { scalar(Scalar(x / factor), p.digits); }
  void number(const char*, const std::optional<Scalar>& x) {
    if (x) scalar(*x, p.digits);
    else out += ',';
  }
  void number(const char*, const std::optional<Scalar>& x, const Scalar& factor) {
    if (x) scalar(Scalar(*x / factor), p.digits);
    else out += ',';
  }
  void vec(const char*, const Vec3<Scalar>& v, const Scalar& factor) {
    for (int i = 0; i < 3; ++i) scalar(Scalar(v[i] / factor), p.digits);
  }
  void count(const char*, const std::optional<int>& n) {
    out += ',';
    if (!n) return;
    char* q = out.room(16);
    out.commit(std::to_chars(q, q + 16, *n).ptr);
  }
  void text(const char*, std::string_view s) {
    out += ',';
    put_csv_text(out, s);
  }
  void bound(const char*, const Scalar& x) { scalar(x, 3); }
  void bound(const char*, const std::optional<Scalar>& x) {
    if (x) scalar(*x, 3);
    else out += ',';
  }
};

}  // namespace detail

// The rows of one case straight from its analysis, `line` first: the cells the document
// result_json(c, a, precision, 0, false, {}, true) writes, byte for byte.
template <typename Scalar>
std::string result_csv_rows(const CaseSpec& c, const Analysis<Scalar>& a, const std::string& precision, long line) {
  const Present<Scalar> p(c.units, std::numeric_limits<Scalar>::max_digits10);
  JsonText out;
  out.reserve(1024 * std::max<std::size_t>(a.solutions.size(), 1));
  // The document's cells, the same in every row.
  JsonText head;
  detail::CsvCells<Scalar> head_cells{head, p};
  result_csv_document_cells(head_cells, c, precision, a.engine);
  head += ',';
  detail::CsvCells<Scalar> cells{out, p};
  for (std::size_t k = 0; k < a.solutions.size(); ++k) {
    const Solution<Scalar>& s = a.solutions[k];
    constexpr std::size_t kDigits = 24;  // a long or a size_t in decimal, with room to spare
    char* q = out.room(2 * kDigits + 2);
    q = std::to_chars(q, q + kDigits, line).ptr;
    *q++ = ',';
    q = std::to_chars(q, q + kDigits, k).ptr;
    *q++ = ',';
    out.commit(q);
    out += head.view();
    put_csv_text(out, strategy_cell_text(c.strategies[k]));
    out += ',';
    put_csv_text(out, regime_name(s.impulse.regime));
    result_csv_cells(cells, s, p);
    out += ',';
    if (!s.warnings.empty()) {
      std::string joined;
      for (const auto& w : s.warnings) joined += (joined.empty() ? "" : " | ") + w.text;
      put_csv_text(out, joined);
    }
    out += '\n';
  }
  return std::move(out).take();
}

// Compiled once per scalar of the list, in case_format/src/instantiate.cpp (with render), not in every
// object that writes at one of them.
#define IMPACT3D_EXTERN_RESULT_CSV_(type, name, u) \
  extern template std::string result_csv_rows<type>(const CaseSpec&, const Analysis<type>&, const std::string&, long);
IMPACT3D_SCALARS(IMPACT3D_EXTERN_RESULT_CSV_)
#undef IMPACT3D_EXTERN_RESULT_CSV_

}  // namespace impact3d::case_format
