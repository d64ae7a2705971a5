// Values of a document taken by their paths as JsonWriter writes it, instead of reading the document
// back: `batch --format csv` fills its cells so. A path is a chain of steps (a key, an index, or any
// index); a value under an any-index step belongs to the group of that index ("results[].regime" of
// the third result is in group 2).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace impact3d::io {

class JsonPick {
 public:
  struct Step {
    enum class Kind { key, index, any } kind = Kind::key;
    std::string key;
    std::size_t index = 0;
  };
  // Where a picked value stands in the document's text: [begin, end), a number's or a literal's text,
  // a string with its quotes, or a whole object or array.
  struct Span {
    std::size_t column, group, begin, end;
  };

  // Path c is column c.
  explicit JsonPick(const std::vector<std::vector<Step>>& paths);

  const std::vector<Span>& spans() const { return spans_; }
  void clear() { spans_.clear(); }

  // What JsonWriter asks, from the root node 0; kNone is nothing picked below.
  static constexpr int kNone = -1;
  int member(int node, std::string_view key) const;
  int element(int node, std::size_t index, std::size_t& group) const;
  int column(int node) const { return node == kNone ? kNone : nodes_[static_cast<std::size_t>(node)].column; }
  void add(int column, std::size_t group, std::size_t begin, std::size_t end) {
    spans_.push_back({static_cast<std::size_t>(column), group, begin, end});
  }

 private:
  struct Node {
    std::vector<std::pair<std::string, int>> members;
    std::vector<std::pair<std::size_t, int>> elements;
    int any = kNone;
    int column = kNone;
  };
  std::vector<Node> nodes_;
  std::vector<Span> spans_;
};

}  // namespace impact3d::io
