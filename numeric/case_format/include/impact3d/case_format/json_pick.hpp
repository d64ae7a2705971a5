// Values of a document taken by their paths as JsonWriter writes it, instead of reading the document
// back: `montecarlo` takes its outputs so, and `batch --format csv` its cells at exact precision
// (case_format/result_csv.hpp). A path is a chain of steps (a key, an index, or any index); a value under an
// any-index step belongs to the group of that index ("results[].regime" of the third result is in
// group 2). A string value is also kept as the writer was given it, so that no reader has to undo the
// writer's escapes.
#pragma once

#include <cassert>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "impact3d/case_format/json_path.hpp"

namespace impact3d::case_format {

class JsonPick {
 public:
  // Where a picked value stands in the document's text: [begin, end), a number's or a literal's text,
  // a string with its quotes, or a whole object or array; a string's own text is strings()[string].
  static constexpr std::size_t kNoString = ~std::size_t{0};
  struct Span {
    std::size_t column, group, begin, end, string = kNoString;
  };

  // Path c is column c. `only_picked`: the writer writes the picked values and nothing else, so that
  // its text is no longer a JSON document but every span reads as it would in the whole document.
  explicit JsonPick(const std::vector<JsonPath>& paths, bool only_picked = false);
  bool only_picked() const { return only_picked_; }

  const std::vector<Span>& spans() const { return spans_; }
  std::string_view string(const Span& s) const {
    assert(s.string < used_);  // only a string's span has one
    return strings_[s.string];
  }
  void clear() {
    spans_.clear();
    used_ = 0;
  }

  // What JsonWriter asks, from the root node 0; kNone is nothing picked below.
  static constexpr int kNone = -1;
  int member(int node, std::string_view key) const;
  int element(int node, std::size_t index, std::size_t& group) const;
  int column(int node) const { return node == kNone ? kNone : nodes_[static_cast<std::size_t>(node)].column; }
  void add(int column, std::size_t group, std::size_t begin, std::size_t end) {
    spans_.push_back({static_cast<std::size_t>(column), group, begin, end});
  }
  void add_string(int column, std::size_t group, std::size_t begin, std::size_t end, std::string_view text) {
    if (used_ == strings_.size()) strings_.emplace_back();
    strings_[used_].assign(text);  // the slots keep their capacity from document to document
    spans_.push_back({static_cast<std::size_t>(column), group, begin, end, used_++});
  }

 private:
  struct Node {
    std::vector<std::pair<std::string, int>> members;
    std::vector<std::pair<std::size_t, int>> elements;
    int any = kNone;
    int column = kNone;
  };
  std::vector<Node> nodes_;
  bool only_picked_;
  std::vector<Span> spans_;
  std::vector<std::string> strings_;
  std::size_t used_ = 0;
};

}  // namespace impact3d::case_format
