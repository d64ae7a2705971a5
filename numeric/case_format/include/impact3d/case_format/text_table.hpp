// Text laid out for a terminal of a given width: aligned rows of a label and cells, and words wrapped.
// Widths count bytes, never fewer than the columns a UTF-8 text takes.
#pragma once

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

namespace impact3d::case_format {

inline constexpr std::size_t kTextWidth = 80;

// `text` broken at spaces into lines of at most `width` bytes, each after `indent`; a word longer than a
// line is cut.
inline std::string wrap(std::string_view text, std::size_t width = kTextWidth, std::string_view indent = "") {
  std::string out, line(indent);
  const std::size_t room = width > indent.size() + 8 ? width - indent.size() : 8;
  auto flush = [&] {
    while (line.size() > indent.size() && line.back() == ' ') line.pop_back();
    out += line + "\n";
    line = indent;
  };
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && text[i] == ' ') ++i;
    std::size_t j = text.find(' ', i);
    if (j == std::string_view::npos) j = text.size();
    std::string_view word = text.substr(i, j - i);
    i = j;
    if (word.empty()) break;
    while (word.size() > room) {  // no break point: cut
      if (line.size() > indent.size()) flush();
      line += word.substr(0, room);
      word.remove_prefix(room);
      flush();
    }
    if (word.empty()) continue;
    const std::size_t used = line.size() - indent.size();
    if (used > 0 && used + 1 + word.size() > room) flush();
    if (line.size() > indent.size()) line += ' ';
    line += word;
  }
  if (line.size() > indent.size() || out.empty()) flush();
  return out;
}

// Rows of a label and cells, the cells right-aligned in columns of one width. A row that does not fit
// the width on one line (a label longer than `kLabelMax`, or more cells than the rest) has its label
// on a line of its own and its cells below, right-aligned with the other rows' last column and wrapped
// as needed.
class Table {
 public:
  static constexpr std::size_t kLabelMax = 34;

  void row(std::string label, std::vector<std::string> cells) { rows_.push_back({std::move(label), std::move(cells), false, {}}); }
  void heading(std::string text) { rows_.push_back({std::move(text), {}, true, {}}); }
  // A line of prose after a lead such as "WARNING: ", wrapped under its own first word so that no
  // continuation reads as a row's label.
  void note(std::string lead, std::string text) {
    rows_.push_back({std::move(text), {}, false, std::move(lead)});
  }

  std::string str(std::size_t width = kTextWidth) const {
    std::size_t label_w = 0, cell_w = 0;
    for (const auto& r : rows_) {
      if (r.heading || !r.lead.empty()) continue;
      if (r.label.size() <= kLabelMax) label_w = std::max(label_w, r.label.size());
      for (const auto& c : r.cells) cell_w = std::max(cell_w, c.size());
    }
    const std::size_t lead = 2 + label_w, column = 2 + cell_w;
    const auto fits = [&](const Row& r) { return r.label.size() <= label_w && lead + r.cells.size() * column <= width; };
    std::size_t right = lead + column;  // the right edge of the rows on one line
    for (const auto& r : rows_)
      if (!r.heading && r.lead.empty() && fits(r)) right = std::max(right, lead + r.cells.size() * column);
    const std::size_t per_line = std::max<std::size_t>(1, (right > 2 ? right - 2 : 0) / column);
    std::string out;
    for (const auto& r : rows_) {
      if (r.heading) {
        out += "\n" + wrap(r.label, width);
        continue;
      }
      if (!r.lead.empty()) {
        const std::string hang(2 + r.lead.size(), ' ');
        const std::string body = wrap(r.label, width, hang);
        out += "  " + r.lead + body.substr(hang.size());
        continue;
      }
      if (fits(r)) {
        std::string line = "  " + r.label;
        line.resize(lead, ' ');
        for (const auto& c : r.cells) line += fmt::format("  {:>{}}", c, cell_w);
        out += trimmed(line) + "\n";
        continue;
      }
      out += wrap(r.label, width, "  ");
      for (std::size_t k = 0; k < r.cells.size(); k += per_line) {
        const std::size_t n = std::min(per_line, r.cells.size() - k);
        std::string line(right > n * column ? right - n * column : 0, ' ');
        for (std::size_t j = k; j < k + n; ++j) line += fmt::format("  {:>{}}", r.cells[j], cell_w);
        out += line + "\n";
      }
    }
    return out;
  }

 private:
  static std::string trimmed(std::string s) {
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
  }
  struct Row {
    std::string label;
    std::vector<std::string> cells;
    bool heading = false;
    std::string lead;  // a note's
  };
  std::vector<Row> rows_;
};

}  // namespace impact3d::case_format
