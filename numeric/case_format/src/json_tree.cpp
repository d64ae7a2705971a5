// The fast reader accepts only what it can vouch for: simdjson's On Demand reader validates the strings as
// UTF-8 (the SIMD kernels the whole text, the fallback kernel the strings, a byte outside them being a token
// the walk refuses) and the structure as it is walked, the walk visits every value (so each literal is
// validated) and nothing may follow the root; a limit reached, a duplicate key, a string that is not valid
// UTF-8 or anything simdjson refuses is left to the checking parser, whose messages name the path. So the
// fast reader never decides what a message says, only that none is needed. (A strict dom parse before the
// walk validated the text a second time: a tenth of a batch row's instructions.)
#include "impact3d/case_format/json_tree.hpp"

#include <charconv>
#include <cstring>
#include <string>

#include <simdjson.h>

#include "impact3d/case_format/decimal.hpp"
#include "impact3d/case_format/limits.hpp"

namespace impact3d::case_format {
namespace {

namespace od = simdjson::ondemand;

constexpr std::size_t kScannedKeys = 64;

struct Walk {
  bool as_written = false;
  // The reader's first stage has validated the strings as UTF-8, so a string needs checking again only
  // when a \u escape may have made a lone surrogate of it.
  bool escapes = true;
  std::size_t values = 0;

  bool valid(std::string_view s) const { return !escapes || simdjson::validate_utf8(s.data(), s.size()); }

  // Below the checker's limits with a margin, so that the checker alone judges every text near one.
  bool within(std::size_t depth) const { return values < limits::kValues && depth + 1 < static_cast<std::size_t>(limits::kDepth); }

  // Whether the first n keys of `o` hold `key`.
  static bool written(const JsonValue& o, std::size_t n, std::string_view key) {
    for (std::size_t i = 0; i < n; ++i)
      if (same_key(o.keys[i], key)) return true;
    return false;
  }

  // `out` may hold a node of an earlier document: every field is written again, and its vectors are cut
  // to this one's sizes, keeping their storage (a batch reads row after row into one tree).
  bool value(od::value v, JsonValue& out, std::size_t depth) {
    ++values;
    if (!within(depth)) return false;
    od::json_type type;
    if (v.type().get(type)) return false;
    out.flag = false;
    out.number = 0;
    out.text.clear();
    if (type != od::json_type::array && type != od::json_type::object) {
      out.items.clear();
      out.keys.clear();
    }
    switch (type) {
      case od::json_type::null: {
        bool null = false;
        if (v.is_null().get(null) || !null) return false;
        out.type = JsonValue::Type::null;
        return true;
      }
      case od::json_type::boolean:
        out.type = JsonValue::Type::boolean;
        return !v.get_bool().get(out.flag);
      case od::json_type::number: return number(v, out);
      case od::json_type::string: {
        std::string_view s;
        if (v.get_string().get(s) || !valid(s)) return false;
        out.type = JsonValue::Type::string;
        out.text.assign(s);
        return true;
      }
      case od::json_type::array: {
        od::array a;
        if (v.get_array().get(a)) return false;
        out.type = JsonValue::Type::array;
        out.keys.clear();
        std::size_t n = 0;
        for (auto element : a) {
          od::value e;
          if (element.get(e)) return false;
          if (n == out.items.size()) out.items.emplace_back();
          if (!value(e, out.items[n], depth + 1)) return false;
          ++n;
        }
        out.items.resize(n);
        return true;
      }
      case od::json_type::object: {
        od::object o;
        if (v.get_object().get(o)) return false;
        out.type = JsonValue::Type::object;
        std::size_t n = 0;
        for (auto field : o) {
          std::string_view key;
          if (field.unescaped_key().get(key)) return false;
          // The duplicate check is a scan: objects with more keys than a case has go to the checker.
          if (n >= kScannedKeys || key.size() > limits::kKeyChars || !valid(key) || written(out, n, key)) return false;
          if (n == out.keys.size()) out.keys.emplace_back(key);
          else out.keys[n].assign(key);
          if (n == out.items.size()) out.items.emplace_back();
          if (!value(field.value(), out.items[n], depth + 1)) return false;
          ++n;
        }
        out.keys.resize(n);
        out.items.resize(n);
        return true;
      }
    }
    return false;
  }

  // The literal as nlohmann reports it, so that both readers agree: an integer as std::to_string prints
  // it (which differs from the text only for "-0").
  bool number(od::value v, JsonValue& out) const {
    std::string_view raw = v.raw_json_token();
    while (!raw.empty() && (raw.back() == ' ' || raw.back() == '\t' || raw.back() == '\n' || raw.back() == '\r')) raw.remove_suffix(1);
    if (raw.size() > limits::kLiteralChars) return false;
    const long e = written_exponent(raw);
    if (e > limits::kExponent || e < -limits::kExponent) return false;
    // simdjson validates the literal; its value is taken from the text as the checker takes it
    // (correctly rounded), since simdjson 3.0's value is wrong for some long literals below one
    // (upstream issue 2093: "0." and 20 or more digits).
    double x;
    if (v.get_double().get(x)) return false;
    const auto r = std::from_chars(raw.data(), raw.data() + raw.size(), x);
    if (r.ec != std::errc() || r.ptr != raw.data() + raw.size()) return false;  // e.g. underflow: the checker decides
    out.type = JsonValue::Type::number;
    if (raw == "-0" && !as_written) raw = "0", x = 0;
    out.text.assign(raw);
    out.number = x;
    return true;
  }
};

}  // namespace

bool parse_json_tree_fast(std::string_view text, JsonValue& out, bool as_written) {
  if (text.size() > limits::kCaseFileBytes) return false;
  thread_local od::parser reader;
  // The text with simdjson's padding after it, in storage the thread keeps from one document to the next.
  thread_local std::string storage;
  if (storage.size() < text.size() + simdjson::SIMDJSON_PADDING) storage.resize(text.size() + simdjson::SIMDJSON_PADDING);
  std::memcpy(storage.data(), text.data(), text.size());
  std::memset(storage.data() + text.size(), 0, simdjson::SIMDJSON_PADDING);
  const simdjson::padded_string_view padded(storage.data(), text.size(), storage.size());
  od::document doc;
  if (reader.iterate(padded).get(doc)) return false;
  od::value root;
  if (doc.get_value().get(root)) return false;
  Walk walk{as_written, text.find("\\u") != std::string_view::npos};
  if (!walk.value(root, out, 0)) return false;
  // Nothing after the root: the reader's position is past its last token (3.0 has no document::at_end).
  const char* after = nullptr;
  return doc.current_location().get(after) == simdjson::OUT_OF_BOUNDS;
}

void parse_json_tree_into(std::string_view text, JsonValue& out, const std::string& root) {
  if (!parse_json_tree_fast(text, out)) out = parse_json_tree_checked(text, root);
}

JsonValue parse_json_tree(std::string_view text, const std::string& root) {
  JsonValue tree;
  parse_json_tree_into(text, tree, root);
  return tree;
}

}  // namespace impact3d::case_format
