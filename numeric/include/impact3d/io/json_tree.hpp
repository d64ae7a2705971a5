// A parsed JSON document that keeps every number as it is written, so that each precision converts the
// decimal of the file and never a rounded double (case_spec.hpp). The case reader walks this tree.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace impact3d::io {

// Key equality for the lookups readers and writers make by the dozen per document: lengths, then the
// first and last bytes settle most pairs before any memcmp.
inline bool same_key(std::string_view a, std::string_view b) {
  return a.size() == b.size() && (a.empty() || (a.front() == b.front() && a.back() == b.back())) && a == b;
}

struct JsonValue {
  enum class Type : unsigned char { null, boolean, number, string, array, object };
  Type type = Type::null;
  bool flag = false;              // booleans
  double number = 0;              // numbers: the value, for validation and messages
  std::string text;               // numbers: the literal; strings: the value (unescaped UTF-8)
  std::vector<JsonValue> items;   // arrays: the elements; objects: the members' values
  std::vector<std::string> keys;  // objects: the members' keys, in the order written (no duplicates)

  bool is(Type t) const { return type == t; }
  std::size_t size() const { return items.size(); }
  const JsonValue* find(std::string_view key) const {
    for (std::size_t i = 0; i < keys.size(); ++i)
      if (same_key(keys[i], key)) return &items[i];
    return nullptr;
  }
};

// Parses `text` within the input limits (limits.hpp). simdjson reads it when it is valid JSON within
// every limit; anything else is read again by the checking parser (json_literals.hpp), whose message
// names the JSON path where the problem stands (`root` is the root's name: "$", or "--strategy[0]").
// Both readers give the same tree for every document they accept (check_json_tree). Throws CaseError.
JsonValue parse_json_tree(std::string_view text, const std::string& root = "$");

// The same, into `out`, whose storage the fast reader writes over (read_case keeps one tree per thread).
void parse_json_tree_into(std::string_view text, JsonValue& out, const std::string& root = "$");

// The checking parser alone (what parse_json_tree falls back to).
JsonValue parse_json_tree_checked(std::string_view text, const std::string& root = "$");

// simdjson alone: false when it refuses the text or the text reaches a limit, a duplicate key, an
// object of more than 64 keys or a string that is not valid UTF-8 (left for the checking parser to
// name). `as_written` keeps the integer -0 as "-0" (the checker, like nlohmann, reads it as 0): for
// reading back impact3d's own documents, whose -0 is a printed negative zero. `out` may hold an earlier
// tree, whose storage is reused (read_case keeps one per thread); after a refusal its content is unspecified.
bool parse_json_tree_fast(std::string_view text, JsonValue& out, bool as_written = false);

}  // namespace impact3d::io
