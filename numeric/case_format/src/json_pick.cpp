#include "impact3d/case_format/json_pick.hpp"

#include <stdexcept>

#include "impact3d/case_format/json_tree.hpp"

namespace impact3d::case_format {

JsonPick::JsonPick(const std::vector<JsonPath>& paths, bool only_picked) : nodes_(1), only_picked_(only_picked) {
  for (std::size_t c = 0; c < paths.size(); ++c) {
    std::size_t node = 0;
    for (const PathStep& s : paths[c]) {
      int next = kNone;
      const Node& n = nodes_[node];
      if (s.kind == PathStep::Kind::any) next = n.any;
      else if (s.kind == PathStep::Kind::key) {
        for (const auto& [k, id] : n.members)
          if (k == s.key) next = id;
      } else {
        for (const auto& [i, id] : n.elements)
          if (i == s.index) next = id;
      }
      if (next == kNone) {
        next = static_cast<int>(nodes_.size());
        Node& parent = nodes_[node];
        if (s.kind == PathStep::Kind::any) parent.any = next;
        else if (s.kind == PathStep::Kind::key) parent.members.emplace_back(s.key, next);
        else parent.elements.emplace_back(s.index, next);
        nodes_.emplace_back();  // last: it may move every node
      }
      node = static_cast<std::size_t>(next);
    }
    if (nodes_[node].column != kNone) throw std::invalid_argument("JsonPick: a path given twice");
    nodes_[node].column = static_cast<int>(c);
  }
}

int JsonPick::member(int node, std::string_view key) const {
  if (node == kNone) return kNone;
  for (const auto& [k, id] : nodes_[static_cast<std::size_t>(node)].members)
    if (same_key(k, key)) return id;
  return kNone;
}

int JsonPick::element(int node, std::size_t index, std::size_t& group) const {
  if (node == kNone) return kNone;
  const Node& n = nodes_[static_cast<std::size_t>(node)];
  for (const auto& [i, id] : n.elements)
    if (i == index) return id;
  if (n.any != kNone) group = index;
  return n.any;
}

}  // namespace impact3d::case_format
