// A small JSON emitter for results: numbers go out as text the caller formats (every digit of the
// precision), which a generic JSON library would re-round. A non-finite number is written as null:
// JSON has no NaN, and the solution's warnings say which result is not finite (precision_warnings.hpp).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace impact3d::io {

class JsonWriter {
 public:
  // Indented (a file a person reads), or one line (JSON Lines: `batch`), with ", " and ": " between items.
  explicit JsonWriter(bool one_line = false) : one_line_(one_line) { out_.reserve(4096); }
  void begin_object() { open('{'); }
  void end_object() { close('}'); }
  void begin_array() { open('['); }
  void end_array() { close(']'); }
  JsonWriter& key(const std::string& k) {
    item();
    append_quoted(out_, k);
    out_ += ": ";
    pending_key_ = true;
    return *this;
  }
  void raw(const std::string& number_text) { value(finite(number_text)); }
  void string(const std::string& s) {
    item();
    pending_key_ = false;
    append_quoted(out_, s);
  }
  void boolean(bool b) { value(b ? "true" : "false"); }
  void null() { value("null"); }
  // A short array of numbers on one line.
  void number_array(const std::vector<std::string>& items) {
    std::string line = "[";
    for (std::size_t i = 0; i < items.size(); ++i) {
      line += (i ? ", " : "") + finite(items[i]);
    }
    value(line + "]");
  }
  std::string str() const { return out_ + "\n"; }

  static std::string quote(const std::string& s) {
    std::string q;
    append_quoted(q, s);
    return q;
  }

  static void append_quoted(std::string& q, const std::string& s) {
    q += '"';
    for (unsigned char c : s) {
      if (c == '"') q += "\\\"";
      else if (c == '\\') q += "\\\\";
      else if (c == '\n') q += "\\n";
      else if (c < 0x20) {
        static const char* hex = "0123456789abcdef";
        q += "\\u00";
        q += hex[c >> 4];
        q += hex[c & 15];
      } else q += static_cast<char>(c);
    }
    q += '"';
  }

 private:
  std::string out_;
  std::vector<bool> has_items_;
  bool pending_key_ = false;
  bool one_line_;

  static std::string finite(const std::string& number_text) {
    if (number_text.find_first_of("ni") != std::string::npos) return "null";  // inf, nan
    return number_text;
  }
  void item() {
    if (pending_key_) return;
    if (!has_items_.empty()) {
      if (has_items_.back()) out_ += one_line_ ? ", " : ",";
      has_items_.back() = true;
      newline(has_items_.size());
    }
  }
  void newline(std::size_t depth) {
    if (one_line_) return;
    out_ += '\n';
    out_.append(2 * depth, ' ');
  }
  void value(const std::string& text) {
    item();
    pending_key_ = false;
    out_ += text;
  }
  void open(char c) {
    item();
    pending_key_ = false;
    out_ += c;
    has_items_.push_back(false);
  }
  void close(char c) {
    const bool had = has_items_.back();
    has_items_.pop_back();
    if (had) newline(has_items_.size());
    out_ += c;
  }
};

}  // namespace impact3d::io
