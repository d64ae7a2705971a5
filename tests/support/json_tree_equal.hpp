// Two JSON trees are the same document: types, keys in order, number texts, values to the bit.
#pragma once

#include <cstring>

#include "impact3d/case_format/json_tree.hpp"

namespace impact3d::case_format {

inline bool json_tree_equal(const JsonValue& a, const JsonValue& b) {
  if (a.type != b.type || a.flag != b.flag || a.text != b.text || a.keys != b.keys || a.items.size() != b.items.size())
    return false;
  if (std::memcmp(&a.number, &b.number, sizeof a.number) != 0) return false;
  for (std::size_t i = 0; i < a.items.size(); ++i)
    if (!json_tree_equal(a.items[i], b.items[i])) return false;
  return true;
}

}  // namespace impact3d::case_format
