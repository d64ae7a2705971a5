#include "impact3d/verification/reference_proof.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "impact3d/io/decimal.hpp"
#include "impact3d/io/escape.hpp"
#include "impact3d/io/number_literals.hpp"
#include "impact3d/io/scalar_text.hpp"
#include "impact3d/numeric/exact.hpp"

namespace impact3d::verification {
namespace {

using json = nlohmann::json;

rational exact(std::string_view literal) { return io::scalar_from_text<rational>(std::string(literal)); }

// The rounding interval of `x` written at `digits` significant digits: the exact values that round to
// it. Below a power of ten the next digit down is a tenth as large.
std::pair<rational, rational> rounding_interval(std::string_view literal, int digits) {
  const io::Decimal d = io::parse_decimal(literal);
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

// A JSON path of the dotted kind as a JSON pointer into the certified document.
const json* at_path(const json& doc, const std::string& path) {
  const json* node = &doc;
  std::size_t i = 0;
  while (i < path.size()) {
    if (path[i] == '.') ++i;
    if (path[i] == '[') {
      const std::size_t close = path.find(']', i);
      const std::size_t index = std::stoul(path.substr(i + 1, close - i - 1));
      if (!node->is_array() || index >= node->size()) return nullptr;
      node = &(*node)[index];
      i = close + 1;
    } else {
      const std::size_t end = std::min(path.find('.', i), path.find('[', i));
      const std::string key = path.substr(i, end == std::string::npos ? std::string::npos : end - i);
      const auto it = node->find(key);
      if (!node->is_object() || it == node->end()) return nullptr;
      node = &*it;
      i = end == std::string::npos ? path.size() : end;
    }
  }
  return node;
}

class Prover {
 public:
  Prover(const std::string& certified, int digits) : cert_(json::parse(certified)), digits_(digits) {
    for (const auto& [path, bounds] : cert_.at("enclosures").items()) enclosures_.emplace(path, bounds);
    for (const auto& r : cert_.at("results")) {
      int undecided = 0;
      for (const auto& d : r.value("decisions", json::array())) undecided += d.at("status") != "decided";
      undecided_.push_back(undecided);
    }
  }

  // The paths of the numbers that are rounding noise (written 0 instead); empty `failure` when the rest
  // is proven.
  std::vector<std::string> check(const std::string& text) {
    std::vector<std::string> noise;
    proven_ = 0, on_other_branch_ = 0, widest_ = 0, zero_reach_ = 0;
    for (const auto& n : io::number_literals(text)) {
      if (!failure_.empty()) break;
      if (n.null || about_the_arithmetic(n.path) || n.path.rfind("certified.", 0) == 0) continue;
      const std::string_view literal(text.data() + n.begin, n.end - n.begin);
      switch (number(n.path, literal)) {
        case Verdict::proven: ++proven_; break;
        case Verdict::noise: noise.push_back(n.path); break;
        case Verdict::other_branch: ++on_other_branch_; break;
        case Verdict::unproven: failure_ = fmt::format("{}: {} is not within its certified enclosure {}", n.path, literal, enclosure_text(n.path)); break;
      }
    }
    if (failure_.empty()) others(json::parse(text), "");
    return noise;
  }

  const std::string& failure() const { return failure_; }

  void write_block(io::JsonWriter& w) const {
    w.key("certified").begin_object();
    w.key("by").string(fmt::format("impact3d solve --precision certified (ball arithmetic, {})", cert_.at("precision").get<std::string>()));
    w.key("numbers_proven").number([&](std::string& out) { out += std::to_string(proven_); });
    w.key("statement").string(fmt::format(
        "Each number written is the exact result for the inputs as written, correctly rounded to {} significant "
        "digits; a number written 0 is within zero_reach of it. rounding_bound and residual_over_bound describe "
        "the arithmetic of the 100-digit solve, not the result, and are not proven. A result with an undecided "
        "decision (its \"decisions\") is proven on the branch it shows{}.",
        digits_, on_other_branch_ ? fmt::format(" ({} of its fields on the other branch than the balls' midpoints)", on_other_branch_) : ""));
    w.key("largest_relative_radius").string(fmt::format("{:.1e}", widest_));
    w.key("zero_reach").string(fmt::format("{:.1e}", zero_reach_));
    w.end_object();
  }

  void write_decisions(io::JsonWriter& w, std::size_t k) const {
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
  enum class Verdict { proven, noise, other_branch, unproven };

  json cert_;
  int digits_;
  std::map<std::string, json> enclosures_;
  std::vector<int> undecided_;
  std::string failure_;
  std::size_t proven_ = 0, on_other_branch_ = 0;
  double widest_ = 0, zero_reach_ = 0;

  std::string enclosure_text(const std::string& path) const {
    const auto it = enclosures_.find(path);
    return it == enclosures_.end() ? std::string("(none)") : it->second.dump();
  }

  // The same field in each alternative of its result, where the result has an undecided decision.
  std::vector<std::string> alternative_paths(const std::string& path) const {
    std::vector<std::string> out;
    const auto r = in_result(path);
    if (!r || r->first >= undecided_.size() || undecided_[r->first] == 0) return out;
    const json* alternatives = at_path(cert_, fmt::format("results[{}].alternatives", r->first));
    for (std::size_t j = 0; alternatives && j < alternatives->size(); ++j)
      out.push_back(fmt::format("results[{}].alternatives[{}].result{}", r->first, j, r->second));
    return out;
  }

  std::optional<std::pair<rational, rational>> bounds(const std::string& path) const {
    const auto it = enclosures_.find(path);
    if (it == enclosures_.end() || !it->second[0].is_string() || !it->second[1].is_string()) return std::nullopt;
    return std::pair{exact(it->second[0].get<std::string>()), exact(it->second[1].get<std::string>())};
  }

  Verdict on(const std::string& path, std::string_view literal) {
    const auto b = bounds(path);
    if (!b) return Verdict::unproven;
    const auto& [lo, hi] = *b;
    const rational x = exact(literal);
    if (lo <= 0 && 0 <= hi && abs(x) <= std::max(-lo, hi)) {
      zero_reach_ = std::max(zero_reach_, rational(std::max(-lo, hi)).convert_to<double>());
      return x == 0 ? Verdict::proven : Verdict::noise;
    }
    if (x == 0) return Verdict::unproven;
    const auto [down, up] = rounding_interval(literal, digits_);
    if (!(down < lo && hi < up)) return Verdict::unproven;
    widest_ = std::max(widest_, rational((hi - lo) / (2 * abs(x))).convert_to<double>());
    return Verdict::proven;
  }

  Verdict number(const std::string& path, std::string_view literal) {
    const Verdict v = on(path, literal);
    if (v != Verdict::unproven) return v;
    for (const auto& other : alternative_paths(path))
      if (const Verdict w = on(other, literal); w != Verdict::unproven) return w == Verdict::proven ? Verdict::other_branch : w;
    return Verdict::unproven;
  }

  // Strings, booleans and nulls: the certified result's, or an undecided decision's other branch's.
  void others(const json& node, const std::string& path) {
    if (!failure_.empty()) return;
    if (node.is_object()) {
      for (const auto& [key, value] : node.items())
        if (key != "certified" && key != "decisions" && key != "warnings" && key != "precision" && key != "engine")
          others(value, path.empty() ? key : path + "." + key);
    } else if (node.is_array()) {
      for (std::size_t i = 0; i < node.size(); ++i) others(node[i], fmt::format("{}[{}]", path, i));
    } else if (!node.is_number()) {
      const auto same = [&](const std::string& p) {
        const json* c = at_path(cert_, p);
        return c && *c == node;
      };
      if (same(path)) return;
      for (const auto& other : alternative_paths(path))
        if (same(other)) {
          ++on_other_branch_;
          return;
        }
      const json* c = at_path(cert_, path);
      failure_ = fmt::format("{}: {} where the certified result has {}", path, io::printable(node.dump()),
                             c ? io::printable(c->dump()) : std::string("nothing"));
    }
  }
};

// The literal at each of `paths` in `text` replaced by 0.
std::string zeroed(const std::string& text, const std::vector<std::string>& paths) {
  std::string out;
  out.reserve(text.size());
  std::size_t from = 0;
  for (const auto& n : io::number_literals(text))
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
  std::string document = zeroed(render([&](io::JsonWriter& w) { prover.write_block(w); },
                                       [&](io::JsonWriter& w, std::size_t k) { prover.write_decisions(w, k); }),
                                noise);
  // The document as written, proven again: nothing left that is noise or unproven.
  if (!prover.check(document).empty() || !prover.failure().empty())
    return {{}, prover.failure().empty() ? "the noise written 0 is not proven" : prover.failure()};
  return {std::move(document), {}};
}

}  // namespace impact3d::verification
