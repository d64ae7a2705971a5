#include "impact3d/case/json_literals.hpp"

#include <set>
#include <vector>

#include "impact3d/case/case_spec.hpp"

namespace impact3d::io {
namespace {

using json = nlohmann::json;

std::string escape_token(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

std::string strip_exception_prefix(const std::string& what) {
  const auto close = what.find("] ");
  return close == std::string::npos ? what : what.substr(close + 2);
}

// Walks the same text as json::parse and records where each number stands and how it was written.
class LiteralCollector : public nlohmann::json_sax<json> {
 public:
  std::map<std::string, std::string> literal;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t v) override { return number(std::to_string(v)); }
  bool number_unsigned(number_unsigned_t v) override { return number(std::to_string(v)); }
  bool number_float(number_float_t, const string_t& s) override { return number(s); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    value();
    frames_.push_back({true, -1, "", {}});
    return true;
  }
  bool key(string_t& k) override {
    auto& f = frames_.back();
    f.key = k;
    if (!f.keys.insert(k).second) throw CaseError(display_path(location()), "duplicate key");
    return true;
  }
  bool end_object() override {
    frames_.pop_back();
    return true;
  }
  bool start_array(std::size_t) override {
    value();
    frames_.push_back({false, -1, "", {}});
    return true;
  }
  bool end_array() override {
    frames_.pop_back();
    return true;
  }
  bool parse_error(std::size_t, const std::string& token, const nlohmann::detail::exception& e) override {
    // 406: a number literal beyond the range of double, e.g. 1e400.
    if (e.id == 406) throw CaseError(display_path(location()), "not a finite number (" + token + ")");
    throw CaseError(display_path(location()), "invalid JSON: " + strip_exception_prefix(e.what()));
  }

 private:
  struct Frame {
    bool object;
    long index;
    std::string key;
    std::set<std::string> keys;
  };
  std::vector<Frame> frames_;
  std::string current_;

  bool value() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
    current_ = path();
    return true;
  }
  bool number(const std::string& text) {
    value();
    literal[current_] = text;
    return true;
  }
  std::string path() const {
    std::string p;
    for (const auto& f : frames_) p += "/" + (f.object ? escape_token(f.key) : std::to_string(f.index));
    return p;
  }
  // Where the value being read stands: the last key of the innermost object, or the next array index.
  std::string location() const {
    std::string p;
    for (std::size_t i = 0; i < frames_.size(); ++i) {
      const auto& f = frames_[i];
      const long index = i + 1 == frames_.size() ? f.index + 1 : f.index;
      p += "/" + (f.object ? escape_token(f.key) : std::to_string(index));
    }
    return p;
  }
};

}  // namespace

std::string display_path(const std::string& pointer) {
  std::string out = "$";
  std::size_t pos = 0;
  while (pos < pointer.size()) {
    const std::size_t next = pointer.find('/', pos + 1);
    std::string token = pointer.substr(pos + 1, next == std::string::npos ? std::string::npos : next - pos - 1);
    for (std::size_t i; (i = token.find("~1")) != std::string::npos;) token.replace(i, 2, "/");
    for (std::size_t i; (i = token.find("~0")) != std::string::npos;) token.replace(i, 2, "~");
    const bool index = !token.empty() && token.find_first_not_of("0123456789") == std::string::npos;
    out += index ? "[" + token + "]" : "." + token;
    pos = next == std::string::npos ? pointer.size() : next;
  }
  return out;
}

ParsedJson parse_json_with_literals(const std::string& text) {
  // The collector reads first: it reports syntax errors with the path where they stand.
  ParsedJson out;
  LiteralCollector collector;
  json::sax_parse(text, &collector);
  out.literal = std::move(collector.literal);
  out.doc = json::parse(text);
  return out;
}

}  // namespace impact3d::io
