#include "impact3d/verification/reference_proof.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "impact3d/case_format/decimal.hpp"
#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/number_literals.hpp"
#include "impact3d/case_format/scalar_text.hpp"
#include "impact3d/scalar/exact.hpp"

namespace impact3d::verification {
namespace {

using json = nlohmann::json;

rational exact(std::string_view literal) { return case_format::scalar_from_text<rational>(std::string(literal)); }

// The rounding interval of `x` written at `digits` significant digits: the exact values that round to
// it. Below a power of ten the next digit down is a tenth as large.
std::pair<rational, rational> rounding_interval(std::string_view literal, int digits) {
  const case_format::Decimal d = case_format::parse_decimal(literal);
  const long lead = d.exponent + static_cast<long>(d.digits.size()) - 1;
  const auto half_unit = [&](long at) {
    const long e = at - (digits - 1);
    const rational power = exact(fmt::format("1e{}", e < 0 ? -e : e));
    return e < 0 ? rational(rational(1, 2) / power) : rational(rational(1, 2) * power);
  };
  const rational x = exact(literal), up = half_unit(lead);
  const rational down = d.digits == "1" ? half_unit(lead - 1) : up;  // toward zero
  return d.negative ? std::pair{x - up, x + down} : std::pair{x - down, x + up};
}

// What the arithmetic of the solve that wrote the reference says about itself, not a result.
bool about_the_arithmetic(const std::string& path) {
  const auto ends = [&](std::string_view tail) {
    return path.size() >= tail.size() && path.compare(path.size() - tail.size(), tail.size(), tail) == 0;
  };
  return ends("rounding_bound") || ends("residual_over_bound");
}

// results[k].rest -> (k, rest)
std::optional<std::pair<std::size_t, std::string>> in_result(const std::string& path) {
  constexpr std::string_view stem = "results[";
  if (path.compare(0, stem.size(), stem) != 0) return std::nullopt;
  const std::size_t close = path.find(']');
  return std::pair{static_cast<std::size_t>(std::stoul(path.substr(stem.size(), close - stem.size()))),
                   path.substr(close + 1)};
}

// Each scalar that is not a number under `node`, with its path spelled as number_literals spells it;
// objects' members named in `skip` are left out, at any depth.
template <typename F>
void for_each_other(const json& node, const std::string& path, std::initializer_list<std::string_view> skip, F&& f) {
  if (node.is_object()) {
    for (const auto& [key, value] : node.items())
      if (std::find(skip.begin(), skip.end(), key) == skip.end())
        for_each_other(value, path.empty() ? key : path + "." + key, skip, f);
  } else if (node.is_array()) {
    for (std::size_t i = 0; i < node.size(); ++i) for_each_other(node[i], fmt::format("{}[{}]", path, i), skip, f);
  } else if (!node.is_number()) {
    f(path, node);
  }
}

// A field of the reference: a number's literal, or another value (a string, a boolean, a null).
struct ReferenceField {
  std::string path;
  std::string literal;     // numbers
  const json* value = nullptr;  // the rest
};

// What a branch makes of a result's fields: proven, or the first field that is not.
struct BranchCheck {
  std::string failure;
  std::vector<std::string> noise;
  std::size_t proven = 0;
  double widest = 0, zero_reach = 0;
};

class Prover {
 public:
  Prover(const std::string& certified, int digits) : cert_(json::parse(certified)), digits_(digits) {
    for (const auto& [path, bounds] : cert_.at("enclosures").items()) enclosures_.emplace(path, bounds);
    for_each_other(cert_, "", {"enclosures"}, [&](const std::string& path, const json& v) { others_.emplace(path, &v); });
  }

  // The paths of the numbers that are rounding noise (to be written 0); failure() empty when the rest
  // is proven.
  std::vector<std::string> check(const std::string& text) {
    failure_.clear();
    proven_ = 0, other_branch_ = 0, widest_ = 0, zero_reach_ = 0;
    const json doc = json::parse(text);
    // Fields by scope: the top level (-1) and each result.
    std::map<long, std::vector<ReferenceField>> scopes;
    double largest = 0;
    for (const auto& n : case_format::number_literals(text)) {
      if (n.null || excluded(n.path)) continue;
      ReferenceField f{n.path, text.substr(n.begin, n.end - n.begin), nullptr};
      largest = std::max(largest, std::fabs(std::strtod(f.literal.c_str(), nullptr)));
      scopes[scope(n.path)].push_back(std::move(f));
    }
    for_each_other(doc, "", {"certified", "decisions", "warnings", "precision", "engine"},
                   [&](const std::string& path, const json& v) { scopes[scope(path)].push_back(ReferenceField{path, {}, &v}); });
    // The 100-digit solve's rounding noise: far below what its 100 digits resolve of the document's
    // largest number, and far above the noise itself (10^-98 of it at most).
    noise_bound_ = kNoiseFraction * largest;
    std::vector<std::string> noise;
    for (const auto& [k, fields] : scopes) {
      std::vector<std::string> branches = {k < 0 ? "" : fmt::format("results[{}]", k)};
      if (k >= 0) {
        const json& r = cert_.at("results").at(static_cast<std::size_t>(k));
        bool settled = true;
        for (const auto& d : r.value("decisions", json::array())) settled = settled && d.at("status") == "decided";
        if (!settled)
          for (std::size_t j = 0; j < r.value("alternatives", json::array()).size(); ++j)
            branches.push_back(fmt::format("results[{}].alternatives[{}].result", k, j));
      }
      std::optional<BranchCheck> passed;
      std::string first_failure;
      for (std::size_t b = 0; b < branches.size() && !passed; ++b) {
        BranchCheck c = on_branch(fields, k < 0 ? "" : fmt::format("results[{}]", k), branches[b]);
        if (c.failure.empty()) {
          passed = std::move(c);
          other_branch_ += b > 0;
        } else if (b == 0) {
          first_failure = c.failure;
        }
      }
      if (!passed) {
        failure_ = first_failure;
        return {};
      }
      proven_ += passed->proven;
      widest_ = std::max(widest_, passed->widest);
      zero_reach_ = std::max(zero_reach_, passed->zero_reach);
      noise.insert(noise.end(), passed->noise.begin(), passed->noise.end());
    }
    return noise;
  }

  const std::string& failure() const { return failure_; }

  void write_block(case_format::JsonWriter& w) const {
    w.key("certified").begin_object();
    w.key("by").string(fmt::format("impact3d solve --precision certified (ball arithmetic, {})", cert_.at("precision").get<std::string>()));
    w.key("numbers_proven").number([&](auto& out) { out += std::to_string(proven_); });
    w.key("statement").string(fmt::format(
        "Each number written is the exact result for the inputs as written, correctly rounded to {} significant "
        "digits; a number written 0 is within zero_reach of it. Strings, booleans and nulls are the certified "
        "result's. A result with a decision the balls leave undecided (see its \"decisions\") is proven on one "
        "branch throughout: {}. Not proven: rounding_bound and residual_over_bound, which describe the arithmetic "
        "of the 100-digit solve, and the warnings, prose about each computation.",
        digits_,
        other_branch_ == 0 ? std::string("the branch shown, where a quantity whose ball holds 0 is zero and other "
                                         "comparisons follow the balls' midpoints")
                           : fmt::format("the branch shown, or for {} of the results the other branch of one decision "
                                         "(the result's alternative)", other_branch_)));
    w.key("largest_relative_radius").string(fmt::format("{:.1e}", widest_));
    w.key("zero_reach").string(fmt::format("{:.1e}", zero_reach_));
    w.end_object();
  }

  void write_decisions(case_format::JsonWriter& w, std::size_t k) const {
    w.key("decisions").begin_array();
    for (const auto& d : cert_.at("results").at(k).value("decisions", json::array())) {
      w.begin_object();
      w.key("name").string(d.at("name").get<std::string>());
      w.key("status").string(d.at("status").get<std::string>());
      w.key("detail").string(d.at("detail").get<std::string>());
      w.end_object();
    }
    w.end_array();
  }

 private:
  // 10^-90: ten digits above the 100-digit solve's unit roundoff.
  static constexpr double kNoiseFraction = 1e-90;

  json cert_;
  int digits_;
  std::map<std::string, json> enclosures_;
  std::map<std::string, const json*> others_;  // the certified document's strings, booleans and nulls
  std::string failure_;
  std::size_t proven_ = 0, other_branch_ = 0;
  double widest_ = 0, zero_reach_ = 0, noise_bound_ = 0;

  static bool excluded(const std::string& path) {
    return about_the_arithmetic(path) || path.rfind("certified.", 0) == 0 || path.find(".decisions[") != std::string::npos;
  }

  static long scope(const std::string& path) {
    const auto r = in_result(path);
    return r ? static_cast<long>(r->first) : -1;
  }

  // Every field of one scope against the branch at `branch` (the scope's own path, or an alternative's).
  BranchCheck on_branch(const std::vector<ReferenceField>& fields, const std::string& own, const std::string& branch) const {
    BranchCheck c;
    for (const auto& f : fields) {
      const std::string there = branch + f.path.substr(own.size());
      if (f.value) {
        const auto it = others_.find(there);
        const json* v = it == others_.end() ? nullptr : it->second;
        if (!v || *v != *f.value) {
          c.failure = fmt::format("{}: {} where the certified result has {}", f.path, case_format::printable(f.value->dump()),
                                  v ? case_format::printable(v->dump()) : std::string("nothing"));
          return c;
        }
        continue;
      }
      if (!number(f, there, c)) {
        const auto it = enclosures_.find(there);
        c.failure = fmt::format("{}: {} is not proven by its certified enclosure {}", f.path, f.literal,
                                it == enclosures_.end() ? std::string("(none)") : it->second.dump());
        return c;
      }
    }
    return c;
  }

  bool number(const ReferenceField& f, const std::string& there, BranchCheck& c) const {
    const auto it = enclosures_.find(there);
    if (it == enclosures_.end() || !it->second[0].is_string() || !it->second[1].is_string()) return false;
    const rational lo = exact(it->second[0].get<std::string>()), hi = exact(it->second[1].get<std::string>());
    const rational x = exact(f.literal);
    if (lo <= 0 && 0 <= hi) {
      // The exact value may be 0: a 0 written is within the ball's reach of it, and so is the noise
      // of the 100-digit solve, written 0. Anything larger the ball cannot prove.
      if (x != 0 && abs(x) > rational(noise_bound_)) return false;
      if (x != 0) c.noise.push_back(f.path);
      c.zero_reach = std::max(c.zero_reach, rational(std::max(-lo, hi)).convert_to<double>());
      ++c.proven;
      return true;
    }
    if (x == 0) return false;
    const auto [down, up] = rounding_interval(f.literal, digits_);
    if (!(down < lo && hi < up)) return false;
    c.widest = std::max(c.widest, rational((hi - lo) / (2 * abs(x))).convert_to<double>());
    ++c.proven;
    return true;
  }
};

// The literal at each of `paths` in `text` replaced by 0.
std::string zeroed(const std::string& text, const std::vector<std::string>& paths) {
  std::string out;
  out.reserve(text.size());
  std::size_t from = 0;
  for (const auto& n : case_format::number_literals(text))
    if (std::find(paths.begin(), paths.end(), n.path) != paths.end()) {
      out.append(text, from, n.begin - from);
      out += '0';
      from = n.end;
    }
  out.append(text, from, std::string::npos);
  return out;
}

}  // namespace

ReferenceProof prove_reference(const RenderReference& render, const std::string& certified, int digits) {
  Prover prover(certified, digits);
  const auto noise = prover.check(render({}, {}));
  if (!prover.failure().empty()) return {{}, prover.failure()};
  std::string document = zeroed(render([&](case_format::JsonWriter& w) { prover.write_block(w); },
                                       [&](case_format::JsonWriter& w, std::size_t k) { prover.write_decisions(w, k); }),
                                noise);
  // The document as written, proven again: nothing left that is noise or unproven.
  if (!prover.check(document).empty() || !prover.failure().empty())
    return {{}, prover.failure().empty() ? "the noise written 0 is not proven" : prover.failure()};
  return {std::move(document), {}};
}

}  // namespace impact3d::verification
