#include "impact3d/case_format/read_evidence.hpp"

#include <fmt/format.h>

#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/json_fields.hpp"
#include "impact3d/case_format/json_tree.hpp"
#include "impact3d/case_format/limits.hpp"
#include "impact3d/case_format/result_outputs.hpp"

namespace impact3d::case_format {
namespace {

using Type = JsonValue::Type;
using fields::fail;
using fields::member;
using fields::need;
using fields::only_keys;

int vehicle_index(const JsonValue& v, const std::string& at) { return static_cast<int>(fields::count(v, at, 0, 1)); }

// The standard deviation of a value: > 0, and not so small that its inverse overflows.
double sd_value(const JsonValue& x, const std::string& at) {
  const double s = fields::number(x, at);
  if (!(s >= 1e-12)) fail(at, fmt::format("must be at least 1e-12 (got {})", printable(x.text)));
  return s;
}

Unknown unknown(const JsonValue& v, const std::string& at) {
  if (!v.is(Type::object)) fail(at, "must be an object");
  only_keys(v, at, {"speed", "heading", "path", "start"});
  Unknown u;
  const JsonValue* speed = v.find("speed");
  const JsonValue* heading = v.find("heading");
  const JsonValue* path = v.find("path");
  if ((speed != nullptr) + (heading != nullptr) + (path != nullptr) != 1)
    fail(at, "must name exactly one of \"speed\" (a vehicle), \"heading\" (a vehicle) or \"path\" (an input of the case)");
  if (speed) {
    u.kind = Unknown::Kind::speed;
    u.vehicle = vehicle_index(*speed, member(at, "speed"));
  } else if (heading) {
    u.kind = Unknown::Kind::heading;
    u.vehicle = vehicle_index(*heading, member(at, "heading"));
  } else {
    if (!path->is(Type::string)) fail(member(at, "path"), "must be a string");
    u.path = parse_json_path(path->text, member(at, "path"));
    u.path_text = path_text(u.path);
  }
  if (const JsonValue* s = v.find("start")) u.start = fields::number(*s, member(at, "start"));
  return u;
}

// The outputs a name stands for: itself, or the components of a vector.
std::vector<std::size_t> outputs_named(const std::string& name, const std::string& at) {
  const JsonPath p = parse_json_path(name, at);
  const std::string text = path_text(p);
  const auto& all = monte_carlo_outputs();
  std::vector<std::size_t> found;
  for (std::size_t c = 0; c < all.size(); ++c)
    if (path_text(all[c].path) == text) return {c};
  for (std::size_t c = 0; c < all.size(); ++c) {
    const std::string o = path_text(all[c].path);
    if (o.size() > text.size() && o.compare(0, text.size(), text) == 0 && o[text.size()] == '[' &&
        o.find('.', text.size()) == std::string::npos)
      found.push_back(c);
  }
  if (found.empty())
    fail(at, fmt::format("{} is not an output of a result (the Monte Carlo outputs: docs/montecarlo-and-sensitivity.md)", case_format::quoted(name)));
  return found;
}

std::vector<double> per_component(const JsonValue& v, const std::string& at, std::size_t n, bool sd) {
  std::vector<double> out;
  if (v.is(Type::array)) {
    if (v.size() != n) fail(at, fmt::format("must be {} numbers, one per component", n));
    for (std::size_t k = 0; k < n; ++k) {
      const std::string kat = fmt::format("{}[{}]", at, k);
      out.push_back(sd ? sd_value(v.items[k], kat) : fields::number(v.items[k], kat));
    }
  } else {
    if (n > 1 && !sd) fail(at, fmt::format("must be an array of {} numbers, one per component", n));
    out.assign(n, sd ? sd_value(v, at) : fields::number(v, at));
  }
  return out;
}

EvidenceItem evidence_item(const JsonValue& v, const std::string& at) {
  if (!v.is(Type::object)) fail(at, "must be an object");
  only_keys(v, at, {"output", "speed", "value", "sd"});
  EvidenceItem e;
  const JsonValue* output = v.find("output");
  const JsonValue* speed = v.find("speed");
  if ((output != nullptr) == (speed != nullptr))
    fail(at, "must name exactly one of \"output\" (of the result) or \"speed\" (a vehicle's pre-impact speed)");
  if (output) {
    if (!output->is(Type::string)) fail(member(at, "output"), "must be a string");
    e.outputs = outputs_named(output->text, member(at, "output"));
    e.output = output->text;
  } else {
    e.kind = EvidenceItem::Kind::speed;
    e.vehicle = vehicle_index(*speed, member(at, "speed"));
    e.output = fmt::format("speed[{}]", e.vehicle);
  }
  const std::size_t n = e.kind == EvidenceItem::Kind::speed ? 1 : e.outputs.size();
  if (!v.find("value")) fail(at, "missing \"value\"");
  if (!v.find("sd")) fail(at, "missing \"sd\"");
  e.value = per_component(*v.find("value"), member(at, "value"), n, false);
  e.sd = per_component(*v.find("sd"), member(at, "sd"), n, true);
  return e;
}

bool same_unknown(const Unknown& a, const Unknown& b) {
  return a.kind == b.kind && (a.kind == Unknown::Kind::path ? a.path_text == b.path_text : a.vehicle == b.vehicle);
}

}  // namespace

std::string Unknown::label() const {
  switch (kind) {
    case Kind::speed: return fmt::format("speed[{}]", vehicle);
    case Kind::heading: return fmt::format("heading[{}]", vehicle);
    case Kind::path: break;
  }
  return path_text;
}

std::size_t EvidenceSpec::components() const {
  std::size_t n = 0;
  for (const auto& e : evidence) n += e.value.size();
  return n;
}

EvidenceSpec read_evidence(const std::string& json_text) {
  if (json_text.size() > limits::kCaseFileBytes) fail("$", fmt::format("larger than {} bytes", limits::kCaseFileBytes));
  const JsonValue root = parse_json_tree(json_text);
  if (!root.is(Type::object)) fail("$", "must be an object");
  only_keys(root, "$", {"unknowns", "evidence"});
  EvidenceSpec spec;
  const JsonValue& unknowns = need(root, "$", "unknowns", Type::array, "an array of unknowns");
  if (unknowns.size() == 0) fail("$.unknowns", "must name at least one unknown");
  std::size_t paths = 0;
  for (std::size_t i = 0; i < unknowns.size(); ++i) {
    const std::string at = fmt::format("$.unknowns[{}]", i);
    if (i == 4 + kMaxPathUnknowns) fail(at, fmt::format("more than {} unknowns", 4 + kMaxPathUnknowns));
    Unknown u = unknown(unknowns.items[i], at);
    for (const Unknown& earlier : spec.unknowns)
      if (same_unknown(earlier, u)) fail(at, fmt::format("{} is an unknown twice", case_format::quoted(u.label())));
    if (u.kind == Unknown::Kind::path && ++paths > kMaxPathUnknowns)
      fail(member(at, "path"), fmt::format("more than {} unknowns given by path", kMaxPathUnknowns));
    spec.unknowns.push_back(std::move(u));
  }
  const JsonValue& evidence = need(root, "$", "evidence", Type::array, "an array of evidence items");
  if (evidence.size() == 0) fail("$.evidence", "must hold at least one item");
  if (evidence.size() > kMaxEvidence) fail("$.evidence", fmt::format("must hold at most {} items", kMaxEvidence));
  for (std::size_t i = 0; i < evidence.size(); ++i)
    spec.evidence.push_back(evidence_item(evidence.items[i], fmt::format("$.evidence[{}]", i)));
  return spec;
}

}  // namespace impact3d::case_format
