#include "impact3d/case_format/read_uncertainty.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string_view>

#include <fmt/format.h>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/json_fields.hpp"
#include "impact3d/case_format/json_tree.hpp"
#include "impact3d/case_format/limits.hpp"
#include "impact3d/uncertainty/moments.hpp"

namespace impact3d::case_format {
namespace {

using Type = JsonValue::Type;
using uncertainty::Distribution;
using Kind = Distribution::Kind;

using fields::fail;
using fields::member;
using fields::need;
using fields::only_keys;
using fields::parameter;
using fields::positive;
using fields::within_magnitude;

Distribution distribution(const JsonValue& v, const std::string& at) {
  const JsonValue& name = need(v, at, "distribution", Type::string, "a string");
  Distribution d;
  if (!uncertainty::kind_of(name.text, d.kind))
    fail(member(at, "distribution"), fmt::format("unknown distribution {} (normal, truncated-normal, uniform, triangular, lognormal, discrete)", case_format::quoted(name.text)));
  auto ordered = [&](std::string_view lo, double a, std::string_view hi, double b, bool strict) {
    if (strict ? !(a < b) : !(a <= b)) fail(member(at, hi), fmt::format("must be {} \"{}\"", strict ? "above" : "at least", lo));
  };
  switch (d.kind) {
    case Kind::normal:
      only_keys(v, at, {"path", "distribution", "mean", "sd"});
      d.mean = parameter(v, at, "mean"), d.sd = positive(v, at, "sd");
      break;
    case Kind::truncated_normal:
      only_keys(v, at, {"path", "distribution", "mean", "sd", "min", "max"});
      d.mean = parameter(v, at, "mean"), d.sd = positive(v, at, "sd");
      d.min = parameter(v, at, "min"), d.max = parameter(v, at, "max");
      ordered("min", d.min, "max", d.max, true);
      if (const std::string problem = uncertainty::truncated_sampling_problem(d); !problem.empty()) fail(at, problem);
      break;
    case Kind::uniform:
      only_keys(v, at, {"path", "distribution", "min", "max"});
      d.min = parameter(v, at, "min"), d.max = parameter(v, at, "max");
      ordered("min", d.min, "max", d.max, true);
      break;
    case Kind::triangular:
      only_keys(v, at, {"path", "distribution", "min", "mode", "max"});
      d.min = parameter(v, at, "min"), d.mode = parameter(v, at, "mode"), d.max = parameter(v, at, "max");
      ordered("min", d.min, "max", d.max, true);
      ordered("min", d.min, "mode", d.mode, false);
      ordered("mode", d.mode, "max", d.max, false);
      break;
    case Kind::lognormal:
      only_keys(v, at, {"path", "distribution", "median", "sigma"});
      d.median = positive(v, at, "median"), d.sigma = positive(v, at, "sigma");
      if (d.sigma > 10) fail(member(at, "sigma"), "must be at most 10 (a factor of e^10 per standard deviation)");
      break;
    case Kind::discrete: {
      only_keys(v, at, {"path", "distribution", "values", "weights"});
      const JsonValue& values = need(v, at, "values", Type::array, "an array of numbers");
      const std::string vat = member(at, "values");
      if (values.size() == 0 || values.size() > kMaxDiscreteValues)
        fail(vat, fmt::format("must hold 1 to {} numbers", kMaxDiscreteValues));
      for (std::size_t i = 0; i < values.size(); ++i) {
        const JsonValue& x = values.items[i];
        const std::string xat = fmt::format("{}[{}]", vat, i);
        if (!within_magnitude(x)) fail(xat, fmt::format("must be a finite number of magnitude at most {}", limits::kMaxMagnitude));
        d.values.push_back(x.number);
      }
      std::vector<double> weights(values.size(), 1.0);
      if (const JsonValue* w = v.find("weights")) {
        const std::string wat = member(at, "weights");
        if (!w->is(Type::array) || w->size() != values.size()) fail(wat, fmt::format("must be an array of {} numbers, one per value", values.size()));
        double total = 0;
        for (std::size_t i = 0; i < w->size(); ++i) {
          const JsonValue& x = w->items[i];
          if (!within_magnitude(x) || x.number < 0)
            fail(fmt::format("{}[{}]", wat, i), fmt::format("must be a number from 0 to {}", limits::kMaxMagnitude));
          total += weights[i] = x.number;
        }
        if (!(total > 0)) fail(wat, "must not all be 0");
      }
      d.cumulative = uncertainty::cumulative_weights(weights);
      break;
    }
  }
  return d;
}

}  // namespace

UncertaintySpec read_uncertainty(const std::string& json_text) {
  if (json_text.size() > limits::kCaseFileBytes) fail("$", fmt::format("larger than {} bytes", limits::kCaseFileBytes));
  const JsonValue root = parse_json_tree(json_text);
  if (!root.is(Type::object)) fail("$", "must be an object");
  only_keys(root, "$", {"samples", "seed", "inputs", "correlations"});
  UncertaintySpec spec;
  if (const JsonValue* s = root.find("samples")) spec.samples = fields::count(*s, "$.samples", 1, kMaxSamples);
  if (const JsonValue* s = root.find("seed")) spec.seed = fields::count(*s, "$.seed", 0, UINT64_MAX);
  const JsonValue& inputs = need(root, "$", "inputs", Type::array, "an array of inputs");
  if (inputs.size() == 0 || inputs.size() > kMaxUncertainInputs) fail("$.inputs", fmt::format("must hold 1 to {} inputs", kMaxUncertainInputs));
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const std::string at = fmt::format("$.inputs[{}]", i);
    const JsonValue& v = inputs.items[i];
    if (!v.is(Type::object)) fail(at, "must be an object");
    UncertainInput in;
    in.path_text = need(v, at, "path", Type::string, "a string").text;
    in.path = parse_json_path(in.path_text, member(at, "path"));
    for (const UncertainInput& earlier : spec.inputs)
      if (earlier.path_text == in.path_text) fail(member(at, "path"), fmt::format("{} is given twice", case_format::quoted(in.path_text)));
    in.distribution = distribution(v, at);
    spec.inputs.push_back(std::move(in));
  }
  if (const JsonValue* cs = root.find("correlations")) {
    if (!cs->is(Type::array)) fail("$.correlations", "must be an array");
    // Each pair at most once, so that no more than the inputs' pairs are read: an element past them
    // names an input that is none, or a pair given before, and is refused by its path.
    std::vector<char> paired(spec.inputs.size() * spec.inputs.size(), 0);
    for (std::size_t k = 0; k < cs->size(); ++k) {
      const std::string at = fmt::format("$.correlations[{}]", k);
      const JsonValue& c = cs->items[k];
      if (!c.is(Type::object)) fail(at, "must be an object");
      only_keys(c, at, {"paths", "rho"});
      const JsonValue& paths = need(c, at, "paths", Type::array, "an array of two input paths");
      if (paths.size() != 2) fail(member(at, "paths"), "must name two inputs");
      std::size_t pair[2];
      for (int j = 0; j < 2; ++j) {
        const JsonValue& p = paths.items[static_cast<std::size_t>(j)];
        const std::string pat = fmt::format("{}.paths[{}]", at, j);
        if (!p.is(Type::string)) fail(pat, "must be a string");
        std::size_t found = spec.inputs.size();
        for (std::size_t i = 0; i < spec.inputs.size(); ++i)
          if (spec.inputs[i].path_text == p.text) found = i;
        if (found == spec.inputs.size()) fail(pat, fmt::format("{} is not one of the inputs", case_format::quoted(p.text)));
        pair[j] = found;
      }
      if (pair[0] == pair[1]) fail(member(at, "paths"), "must name two different inputs");
      char& seen = paired[std::min(pair[0], pair[1]) * spec.inputs.size() + std::max(pair[0], pair[1])];
      if (seen) fail(member(at, "paths"), "this pair is correlated twice");
      seen = 1;
      const double rho = need(c, at, "rho", Type::number, "a number").number;
      if (!(rho > -1 && rho < 1)) fail(member(at, "rho"), fmt::format("must be strictly between -1 and 1 (got {})", printable(c.find("rho")->text)));
      spec.correlations.push_back({pair[0], pair[1], rho});
    }
    (void)make_sampler(spec);  // positive definite, or the error naming the inputs
  }
  return spec;
}

uncertainty::Sampler make_sampler(const UncertaintySpec& spec) {
  std::vector<Distribution> ds;
  for (const UncertainInput& in : spec.inputs) ds.push_back(in.distribution);
  try {
    return uncertainty::Sampler(std::move(ds), spec.correlations, spec.seed);
  } catch (const uncertainty::NotPositiveDefinite& e) {
    std::string with;
    for (const auto& c : spec.correlations)
      if (c.a == e.input || c.b == e.input) {
        const std::size_t other = c.a == e.input ? c.b : c.a;
        if (other < e.input) with += (with.empty() ? "" : ", ") + case_format::quoted(spec.inputs[other].path_text);
      }
    fail("$.correlations", fmt::format("not positive definite: the correlations of {} with {} cannot all hold with the others",
                                       case_format::quoted(spec.inputs[e.input].path_text), with.empty() ? "the inputs before it" : with));
  }
}

}  // namespace impact3d::case_format
