// The report as one self-contained HTML page: the case, every warning first, the reconstruction summary
// with the strategies side by side, then the figures given (SVG documents, inlined as data so that the
// page needs no network and no script), printable to PDF. The numbers are the text report's
// (report_summary.hpp); all the case author's text is escaped.
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/report_figure.hpp"
#include "impact3d/case_format/report_summary.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/mechanics/analysis.hpp"

namespace impact3d::case_format {

// `text` for HTML element content and attribute values; control characters escaped first (printable()).
std::string html_escaped(std::string_view text);
// Standard base64 of `bytes`, for a data URI.
std::string base64(std::string_view bytes);

// The page's style: tables that read at a glance and print on A4 landscape without clipping.
std::string_view report_css();

template <typename Scalar>
std::string report_html(const CaseSpec& c, const Analysis<Scalar>& a, const std::string& precision, int digits,
                        const std::vector<ReportFigure>& figures, const std::string& figures_note) {
  const Present<Scalar> p(c.units, digits);
  const auto h = [](std::string_view t) { return html_escaped(t); };
  const std::string title = c.name.empty() ? "unnamed case" : c.name;
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  out += fmt::format("<title>impact3d: {}</title>\n<style>\n{}</style>\n</head>\n<body>\n", h(title), report_css());
  out += fmt::format("<h1>{}</h1>\n", h(title));
  if (!c.description.empty()) out += fmt::format("<p class=\"description\">{}</p>\n", h(c.description));
  out += fmt::format("<p class=\"meta\">units {}, precision {}, {} engine, restitution &epsilon; = {}</p>\n<ul class=\"vehicles\">\n",
                     units_name(c.units), h(precision), engine_name(a.engine), h(c.restitution.text));
  for (int i = 0; i < 2; ++i) out += fmt::format("<li>vehicle {}: {}</li>\n", i + 1, h(c.vehicles[i].name.empty() ? "unnamed" : c.vehicles[i].name));
  out += "</ul>\n";

  std::vector<std::string> head;
  for (const auto& s : c.strategies) head.push_back(strategy_label(s));
  // Every warning first: a result with one is not to be read as if fine.
  std::string warnings;
  for (std::size_t k = 0; k < a.solutions.size(); ++k)
    for (const auto& w : a.solutions[k].warnings) warnings += fmt::format("<li><b>{}</b>: {}</li>\n", h(head[k]), h(w.text));
  out += warnings.empty() ? "<p class=\"ok\" id=\"warnings\">No warnings.</p>\n"
                          : "<div class=\"warnings\" id=\"warnings\"><h2>Warnings</h2>\n<ul>\n" + warnings + "</ul></div>\n";

  // The summary, one pair of columns per strategy; a row a strategy lacks left blank.
  std::vector<std::vector<SummaryRow>> rows;
  for (const auto& s : a.solutions) rows.push_back(summary_rows(c, s, p));
  std::vector<std::string> labels;  // each new one after the row that precedes it in its strategy
  for (const auto& r : rows) {
    std::size_t at = 0;
    for (const auto& row : r) {
      if (row.label.empty()) continue;
      const auto it = std::find(labels.begin(), labels.end(), row.label);
      if (it != labels.end()) {
        at = static_cast<std::size_t>(it - labels.begin()) + 1;
        continue;
      }
      labels.insert(labels.begin() + static_cast<std::ptrdiff_t>(at), row.label);
      ++at;
    }
  }
  const auto& share = a.solutions.empty() ? std::array<Scalar, 2>{} : a.solutions[0].deformation.share;
  const std::string rule = c.energy_split ? c.energy_split->rule : "mass";
  out += fmt::format("<h2>Summary</h2>\n<p class=\"note\">Yaw rates in deg/s. EES from the energy lost, split {}: vehicle 1 {}, "
                     "vehicle 2 {}.</p>\n",
                     rule == "share" ? "as given" : rule == "stiffness" ? "in inverse ratio of stiffness" : "in inverse ratio of mass",
                     p.num(share[0]), p.num(share[1]));
  out += "<table class=\"summary\" id=\"summary\">\n<thead>\n<tr><th></th>";
  for (const auto& name : head) out += fmt::format("<th colspan=\"2\">{}</th>", h(name));
  out += "</tr>\n<tr><th></th>";
  for (std::size_t k = 0; k < head.size(); ++k) out += "<th>vehicle 1</th><th>vehicle 2</th>";
  out += "</tr>\n</thead>\n<tbody>\n";
  for (const auto& label : labels) {
    const bool component = label.rfind("  ", 0) == 0;
    out += fmt::format("<tr><th class=\"{}\">{}</th>", component ? "component" : "quantity", h(component ? label.substr(2) : label));
    for (const auto& r : rows) {
      const auto it = std::find_if(r.begin(), r.end(), [&](const SummaryRow& x) { return x.label == label; });
      if (it == r.end()) {
        out += "<td colspan=\"2\"></td>";
      } else if (it->per_vehicle) {
        out += fmt::format("<td>{}</td><td>{}</td>", h(it->cells.at(0)), h(it->cells.at(1)));
      } else {
        std::string joined;
        for (const auto& cell : it->cells) joined += (joined.empty() ? "" : ", ") + cell;
        out += fmt::format("<td colspan=\"2\">{}</td>", h(joined));
      }
    }
    out += "</tr>\n";
  }
  out += "<tr><th class=\"quantity\">warnings</th>";
  for (const auto& s : a.solutions) out += fmt::format("<td colspan=\"2\">{}</td>", s.warnings.empty() ? "none" : fmt::format("{}", s.warnings.size()));
  out += "</tr>\n</tbody>\n</table>\n";

  out += "<h2>Figures</h2>\n";
  if (!figures_note.empty()) out += fmt::format("<p class=\"note\">{}</p>\n", h(figures_note));
  for (const auto& f : figures)
    out += fmt::format("<figure><img alt=\"{0}\" src=\"data:image/svg+xml;base64,{1}\"><figcaption>{0}</figcaption></figure>\n",
                       h(f.caption), base64(f.svg));
  out += "<p class=\"footer\">Written by impact3d from the case file; the equation-by-equation detail is in "
         "<code>impact3d solve CASE</code>.</p>\n</body>\n</html>\n";
  return out;
}

// Compiled once per scalar of the list, in case_format/src/instantiate.cpp (with render), not in every
// object that writes at one of them.
#define IMPACT3D_EXTERN_REPORT_HTML_(type, name, u) \
  extern template std::string report_html<type>(const CaseSpec&, const Analysis<type>&, const std::string&, int, \
                                                 const std::vector<ReportFigure>&, const std::string&);
IMPACT3D_SCALARS(IMPACT3D_EXTERN_REPORT_HTML_)
#undef IMPACT3D_EXTERN_REPORT_HTML_

}  // namespace impact3d::case_format
