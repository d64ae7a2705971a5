// A parsed JSON document that keeps every number as it is written, so that each precision converts the
// decimal of the file and never a rounded double (case_spec.hpp). The case reader walks this tree.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace impact3d::case_format {

// Key equality for the lookups readers and writers make by the dozen per document: lengths first, then
// a key of up to 16 bytes by two overlapping loads from each (no call into memcmp).
inline bool same_key(std::string_view a, std::string_view b) {
  const std::size_t n = a.size();
  if (n != b.size()) return false;
  auto same = [&]<std::size_t W>() {
    std::uint64_t x[2] = {}, y[2] = {};
    std::memcpy(&x[0], a.data(), W);
    std::memcpy(&y[0], b.data(), W);
    std::memcpy(&x[1], a.data() + n - W, W);
    std::memcpy(&y[1], b.data() + n - W, W);
    return x[0] == y[0] && x[1] == y[1];
  };
  if (n >= 8) return n <= 16 ? same.template operator()<8>() : a == b;
  if (n >= 4) return same.template operator()<4>();
  for (std::size_t i = 0; i < n; ++i)
    if (a[i] != b[i]) return false;
  return true;
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

}  // namespace impact3d::case_format
