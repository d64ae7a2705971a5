// --precision certified[:BITS] (issue 14; contract: many-cases.md): the result document with every
// number the midpoint of a ball that encloses the exact result for the inputs as written, the enclosures
// as decimal strings rounded outward, and each result's decisions with the other branch of each that
// the balls could not decide. The text report prints only certified digits.
#include "render_certified.hpp"

#include <algorithm>
#include <charconv>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/number_literals.hpp"
#include "impact3d/case_format/read_case.hpp"
#include "impact3d/case_format/report_text.hpp"
#include "impact3d/case_format/result_json.hpp"
#include "impact3d/case_format/to_scene.hpp"
#include "impact3d/mechanics/certified.hpp"
#include "impact3d/mechanics/exact_analysis.hpp"

namespace impact3d::studies {
using namespace case_format;  // the studies are written in the case format's terms
namespace {

// The ball text of this thread for one scope.
class TextForm {
 public:
  explicit TextForm(BallText t) : previous_(ball_text) { ball_text = t; }
  ~TextForm() { ball_text = previous_; }
  TextForm(const TextForm&) = delete;
  TextForm& operator=(const TextForm&) = delete;

 private:
  BallText previous_;
};

// Undecided decisions that the exact solve shows to be ties become ties, and lose their alternative.
void recognize_ties(const CaseSpec& spec, Engine engine, CertifiedAnalysis& x) {
  if (!x.undecided()) return;
  std::optional<ExactAnalysis> exact;
  try {
    exact = exact_analyze(to_scene<rational>(spec), to_strategies<rational>(spec), engine);
  } catch (const std::exception&) {
    return;  // not rational, or not solvable exactly: the decisions stay undecided
  }
  const auto strategies = to_strategies<rational>(spec);
  for (std::size_t k = 0; k < x.decisions.size(); ++k) {
    const auto& r = exact->results[k];
    if (!r.solution) continue;
    for (const auto& name : exact_ties(x.decisions[k], strategies[k], *r.solution, x.analysis.solutions[k])) {
      const bool same = same_result_at_tie(name);
      for (auto& d : x.decisions[k])
        if (d.name == name) {
          d.status = DecisionStatus::tie;
          d.detail += same ? "; exact arithmetic: a tie (the compared quantities are equal), where both branches "
                             "give the same result"
                           : "; exact arithmetic: a tie (the compared quantity is exactly zero): the boundary case "
                             "holds; the result shows the branch taken (the zero branch where a quantity's ball holds "
                             "0, which is that boundary case; else the midpoints') and \"alternatives\" the other";
        }
      if (same) std::erase_if(x.alternatives[k], [&](const CertifiedAlternative& a) { return a.decision == name; });
    }
  }
}

void write_decisions(JsonWriter& w, const std::vector<Decision>& decisions) {
  w.key("decisions").begin_array();
  for (const auto& d : decisions) {
    w.begin_object();
    w.key("name").string(d.name);
    w.key("status").string(decision_status_name(d.status));
    w.key("detail").string(d.detail);
    w.end_object();
  }
  w.end_array();
}

std::string document(const CaseSpec& shown, const CertifiedAnalysis& x, const std::string& label, bool one_line,
                     const std::function<void(JsonWriter&)>& extra) {
  const Present<Ball> p(shown.units, std::numeric_limits<Ball>::max_digits10);
  const std::string split_rule = shown.energy_split ? shown.energy_split->rule : std::string("mass");
  return result_json<Ball>(shown, x.analysis, label, 0, false, extra, one_line, nullptr, [&](JsonWriter& w, std::size_t k) {
    write_decisions(w, x.decisions[k]);
    if (x.alternatives[k].empty()) return;
    w.key("alternatives").begin_array();
    for (const auto& a : x.alternatives[k]) {
      w.begin_object();
      w.key("decision").string(a.decision);
      if (a.solution) {
        w.key("result");
        write_solution(w, shown.strategies[k], shown.vehicles.data(), *a.solution, p, false, split_rule,
                       [&](JsonWriter& to) { write_decisions(to, a.decisions); });
      } else {
        w.key("failure").string(a.failure);
      }
      w.end_object();
    }
    w.end_array();
  });
}

// Each number of an own document with its literal (none for a null: a bound that is not finite).
std::vector<std::pair<std::string, std::optional<std::string>>> number_paths(const std::string& text) {
  std::vector<std::pair<std::string, std::optional<std::string>>> out;
  for (auto& n : number_literals(text))
    out.emplace_back(std::move(n.path), n.null ? std::nullopt : std::optional(text.substr(n.begin, n.end - n.begin)));
  return out;
}

std::string certified_json(const CaseSpec& shown, const CertifiedAnalysis& x, const std::string& label, bool one_line) {
  std::string texts[3];
  const BallText forms[3] = {BallText::midpoint, BallText::lower, BallText::upper};
  for (int i = 0; i < 3; ++i) {
    const TextForm form(forms[i]);
    texts[i] = document(shown, x, label, false, {});
  }
  const auto mid = number_paths(texts[0]), lo = number_paths(texts[1]), hi = number_paths(texts[2]);
  if (lo.size() != mid.size() || hi.size() != mid.size())
    throw std::logic_error("certified: the bounds' documents differ in shape");
  // A number whose ball reaches infinity has a null bound; a null (not a number) has no enclosure.
  std::vector<std::pair<std::string, std::pair<std::optional<std::string>, std::optional<std::string>>>> enclosures;
  for (std::size_t i = 0; i < mid.size(); ++i) {
    if (lo[i].first != mid[i].first || hi[i].first != mid[i].first)
      throw std::logic_error("certified: the bounds' documents differ in shape at " + mid[i].first);
    if (mid[i].second) enclosures.push_back({mid[i].first, {lo[i].second, hi[i].second}});
  }
  const TextForm form(BallText::midpoint);
  return document(shown, x, label, one_line, [&](JsonWriter& w) {
    w.key("enclosures").begin_object();
    for (const auto& [path, bounds] : enclosures) {
      w.key(path).begin_array();
      for (const auto& b : {bounds.first, bounds.second}) b ? w.string(*b) : w.null();
      w.end_array();
    }
    w.end_object();
  });
}

std::string decisions_text(const CaseSpec& c, const CertifiedAnalysis& x) {
  std::string out = wrap(fmt::format("\nDecisions (ball arithmetic at {} bits; a branch is decided only when the "
                                     "ball of the compared difference lies on one side of zero)",
                                     x.bits));
  for (std::size_t k = 0; k < x.decisions.size(); ++k) {
    out += wrap(strategy_label(c.strategies[k]) + ":", kTextWidth, "  ");
    for (const auto& d : x.decisions[k]) {
      const bool undecided = d.status == DecisionStatus::undecided;
      out += wrap(fmt::format("{}: {}; {}{}", undecided ? "UNDECIDED" : decision_status_name(d.status), d.name, d.detail,
                              undecided ? "; the other branch's result is in --format json's \"alternatives\"" : ""),
                  kTextWidth, "    ");
    }
  }
  return out;
}

bool wide(const CertifiedAnalysis& x) {
  for (const auto& s : x.analysis.solutions)
    if (!(to_double(s.rounding_bound) <= kCertifiedWidth)) return true;
  return false;
}

// Which strategy's which decisions are undecided.
std::vector<std::pair<std::size_t, std::string>> undecided_names(const CertifiedAnalysis& x) {
  std::vector<std::pair<std::size_t, std::string>> names;
  for (std::size_t k = 0; k < x.decisions.size(); ++k)
    for (const auto& d : x.decisions[k])
      if (d.status == DecisionStatus::undecided) names.emplace_back(k, d.name);
  return names;
}

}  // namespace

std::optional<long> certified_bits(std::string_view precision) {
  constexpr std::string_view stem = "certified";
  if (precision.substr(0, stem.size()) != stem) return std::nullopt;
  const std::string_view rest = precision.substr(stem.size());
  if (rest.empty()) return 0;
  long bits = 0;
  const char* begin = rest.data() + 1;
  const char* end = rest.data() + rest.size();
  const auto r = std::from_chars(begin, end, bits);
  if (rest[0] != ':' || begin == end || r.ec != std::errc() || r.ptr != end || bits < kMinCertifiedBits ||
      bits > kMaxCertifiedBits)
    throw CaseError("--precision", fmt::format("certified takes a number of bits from {} to {} (certified:BITS), not {}",
                                               kMinCertifiedBits, kMaxCertifiedBits, printable(precision)));
  return bits;
}

std::string render_certified(const CaseSpec& spec, long bits, const RenderOptions& o) {
  if (o.format == Format::html)
    throw CaseError("--precision", "the HTML report is written at a floating precision; certified results: impact3d solve "
                                   "--precision certified");
  CaseSpec storage;
  const CaseSpec* shown = &shown_in_units(spec, o, storage);
  const bool given = bits > 0;
  // The default mode doubles the bits while a decision is undecided or a result's ball is wide. When a
  // decision stays undecided to the last doubling, the extra bits bought nothing: the run reported is the
  // first that was not wide and left the same decisions undecided (its digits are as certified, and far
  // fewer than the last run's thousands).
  std::vector<CertifiedAnalysis> runs;
  for (long b = given ? bits : kDefaultCertifiedBits;; b *= 2) {
    const BallBits precision(b);
    try {
      runs.push_back(certified_analyze(to_scene<Ball>(spec), to_strategies<Ball>(spec), o.engine));
    } catch (const SolveError&) {
      // A closed form dividing by a ball that holds zero, or an undecided approach: more bits may decide.
      if (given || b * 2 > kMaxDefaultCertifiedBits) throw;
      continue;
    }
    CertifiedAnalysis& x = runs.back();
    recognize_ties(spec, o.engine, x);
    if (given || !(x.undecided() || wide(x)) || b * 2 > kMaxDefaultCertifiedBits) break;
  }
  CertifiedAnalysis* shown_run = &runs.back();
  if (!given && runs.back().undecided()) {
    for (auto& r : runs)
      if (!wide(r) && undecided_names(r) == undecided_names(runs.back())) {
        shown_run = &r;
        break;
      }
    for (std::size_t k = 0; k < shown_run->decisions.size(); ++k)
      for (auto& d : shown_run->decisions[k]) {
        if (d.status != DecisionStatus::undecided) continue;
        std::vector<long> at;
        for (const auto& r : runs) {
          const auto names = undecided_names(r);
          if (std::find(names.begin(), names.end(), std::pair{k, d.name}) != names.end()) at.push_back(r.bits);
        }
        if (at.size() > 1)
          d.detail += fmt::format("; undecided at {} bits, the difference's ball narrowing around 0: consistent with "
                                  "an exact tie, which ball arithmetic cannot prove (nor exact arithmetic, where the "
                                  "case or the quantity is not rational)",
                                  fmt::join(at, ", "));
      }
  }
  const CertifiedAnalysis& x = *shown_run;
  const BallBits precision(x.bits);  // the digits printed are those of the run shown
  const std::string label = "certified:" + std::to_string(x.bits);
  if (is_json(o.format)) return certified_json(*shown, x, label, o.format == Format::jsonl);
  const TextForm form(BallText::certified);
  return report_text(*shown, x.analysis, label + " (only certified digits are printed)",
                     o.digits > 0 ? o.digits : kCertifiedTextDigits) +
         decisions_text(spec, x);
}

}  // namespace impact3d::studies
