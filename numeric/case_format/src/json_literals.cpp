#include "impact3d/case_format/json_literals.hpp"
#include "impact3d/case_format/json_tree.hpp"

#include <cctype>
#include <charconv>
#include <set>
#include <vector>

#include <fmt/format.h>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/decimal.hpp"
#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/limits.hpp"

namespace impact3d::case_format {
namespace {

using json = nlohmann::json;

std::string strip_exception_prefix(const std::string& what) {
  const auto close = what.find("] ");
  return close == std::string::npos ? what : what.substr(close + 2);
}

bool identifier(std::string_view key) {
  if (key.empty() || !(std::isalpha(static_cast<unsigned char>(key[0])) || key[0] == '_')) return false;
  for (char c : key)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

// Walks the text as json::parse does, enforcing the limits with messages that name the path where the
// problem stands, and when given a tree, building it with every number as written. The current
// container's path is kept in one string that grows and shrinks with the nesting, so the cost stays
// linear in the input.
class LimitChecker : public nlohmann::json_sax<json> {
 public:
  LimitChecker(const std::string& root, int depth, JsonValue* tree) : root_(root), depth_(depth), path_(root), tree_(tree) {}

  bool null() override { return scalar(JsonValue::Type::null); }
  bool boolean(bool b) override {
    if (JsonValue* v = add(JsonValue::Type::boolean)) v->flag = b;
    return scalar();
  }
  bool number_integer(number_integer_t v) override { return number(std::to_string(v), static_cast<double>(v)); }
  bool number_unsigned(number_unsigned_t v) override { return number(std::to_string(v), static_cast<double>(v)); }
  bool number_float(number_float_t v, const string_t& s) override { return number(s, v); }
  bool string(string_t& s) override {
    if (JsonValue* v = add(JsonValue::Type::string)) v->text = s;
    return scalar();
  }
  bool binary(binary_t&) override { return scalar(JsonValue::Type::null); }
  bool start_object(std::size_t) override { return open(true); }
  bool start_array(std::size_t) override { return open(false); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool key(string_t& k) override {
    auto& f = frames_.back();
    if (k.size() > limits::kKeyChars)
      throw CaseError(path_, fmt::format("a key longer than {} characters ({}...)", limits::kKeyChars,
                                         case_format::quoted(std::string_view(k).substr(0, 20))));
    f.key = k;
    if (!f.keys.insert(k).second) throw CaseError(member_path(path_, k), "duplicate key");
    return true;
  }
  bool parse_error(std::size_t, const std::string& token, const nlohmann::detail::exception& e) override {
    // 406: a number literal beyond the range of double, e.g. 1e400.
    if (e.id == 406) throw CaseError(child(), "not a finite number (" + printable(token) + ")");
    throw CaseError(child(), "invalid JSON: " + printable(strip_exception_prefix(e.what())));
  }

 private:
  struct Frame {
    bool object;
    std::size_t index = 0;   // arrays: the index of the next element
    std::size_t path_length;  // path_ without this container
    std::string key;         // objects: the key being read
    std::set<std::string> keys;
  };
  std::string root_;
  int depth_;
  std::vector<Frame> frames_;
  std::string path_;  // the innermost open container (the root's name outside every container)
  std::size_t values_ = 0;
  JsonValue* tree_;                // the root, or null when no tree is built
  std::vector<JsonValue*> open_;   // the tree's open containers

  // The tree's node for the value being read: the root, or a new element or member of the innermost
  // container. Nodes of open containers stay put: a container grows only while it is the innermost.
  JsonValue* add(JsonValue::Type type) {
    if (!tree_) return nullptr;
    JsonValue* v = tree_;
    if (!open_.empty()) {
      JsonValue& parent = *open_.back();
      if (parent.is(JsonValue::Type::object)) parent.keys.push_back(frames_.back().key);
      v = &parent.items.emplace_back();
    }
    v->type = type;
    return v;
  }
  std::string child() const {
    if (frames_.empty()) return root_;
    const Frame& f = frames_.back();
    return f.object ? member_path(path_, f.key) : element_path(path_, f.index);
  }
  void count() {
    if (++values_ > limits::kValues)
      throw CaseError(child(), fmt::format("more than {} values in one document", limits::kValues));
  }
  bool scalar(JsonValue::Type type) {
    count();
    add(type);
    return advance();
  }
  bool scalar() {
    count();
    return advance();
  }
  bool advance() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
    return true;
  }
  bool number(const std::string& text, double value) {
    count();
    if (text.size() > limits::kLiteralChars)
      throw CaseError(child(), fmt::format("a number literal longer than {} characters", limits::kLiteralChars));
    const long e = written_exponent(text);
    if (e > limits::kExponent || e < -limits::kExponent)
      throw CaseError(child(), fmt::format("the exponent of {} is beyond +-{}", printable(text.substr(0, 40)), limits::kExponent));
    if (JsonValue* v = add(JsonValue::Type::number)) v->text = text, v->number = value;
    return advance();
  }
  bool open(bool object) {
    count();
    if (frames_.size() >= static_cast<std::size_t>(depth_))
      throw CaseError(child(), fmt::format("nested deeper than {} levels", depth_));
    if (JsonValue* v = add(object ? JsonValue::Type::object : JsonValue::Type::array)) open_.push_back(v);
    const std::size_t length = path_.size();
    path_ = child();
    frames_.push_back({object, 0, length, "", {}});
    return true;
  }
  bool close() {
    path_.resize(frames_.back().path_length);
    frames_.pop_back();
    if (tree_) open_.pop_back();
    return advance();
  }
};

void check(std::string_view text, const std::string& root, int depth, JsonValue* tree) {
  if (const auto nul = text.find('\0'); nul != std::string_view::npos)
    throw CaseError(root, fmt::format("invalid JSON: a NUL byte at offset {}", nul));
  LimitChecker checker(root, depth, tree);
  json::sax_parse(text.begin(), text.end(), &checker);
}

}  // namespace

// Each path is built in one allocation: the case reader makes one per number it reads.
std::string member_path(const std::string& parent, std::string_view key) {
  if (!identifier(key)) return parent + "[" + case_format::quoted(key) + "]";
  std::string path;
  path.reserve(parent.size() + 1 + key.size());
  path.append(parent).append(1, '.').append(key);
  return path;
}

std::string element_path(const std::string& parent, std::size_t index) {
  char digits[24];
  const auto end = std::to_chars(digits, digits + sizeof digits, index).ptr;
  std::string path;
  path.reserve(parent.size() + 2 + static_cast<std::size_t>(end - digits));
  path.append(parent).append(1, '[').append(digits, end).append(1, ']');
  return path;
}

JsonValue parse_json_tree_checked(std::string_view text, const std::string& root) {
  JsonValue tree;
  check(text, root, limits::kDepth, &tree);
  return tree;
}

// The checker reads first: it enforces the limits and reports errors with the path where they stand.
nlohmann::json parse_json_bounded(std::string_view text, const std::string& root, int depth) {
  check(text, root, depth, nullptr);
  return json::parse(text.begin(), text.end());
}

}  // namespace impact3d::case_format
