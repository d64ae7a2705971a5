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
    if (!f.keys.insert(k).second) throw CaseError(display_path(path() + "/" + escape_token(k)), "duplicate key");
    f.key = k;
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
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

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
};

std::string strip_exception_prefix(const std::string& what) {
  const auto close = what.find("] ");
  return close == std::string::npos ? what : what.substr(close + 2);
}

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
  ParsedJson out;
  try {
    out.doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw CaseError("$", "invalid JSON: " + strip_exception_prefix(e.what()));
  }
  LiteralCollector collector;
  json::sax_parse(text, &collector);
  out.literal = std::move(collector.literal);
  return out;
}

}  // namespace impact3d::io
