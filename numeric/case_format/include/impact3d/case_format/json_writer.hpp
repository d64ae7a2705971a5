// A small JSON emitter for results: numbers go out as text the caller formats (every digit of the
// precision), which a generic JSON library would re-round. A non-finite number is written as null:
// JSON has no NaN, and the solution's warnings say which result is not finite (precision_warnings.hpp).
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "impact3d/case_format/json_pick.hpp"
#include "impact3d/case_format/json_text.hpp"

namespace impact3d::case_format {

class JsonWriter {
 public:
  // Indented (a file a person reads), or one line (JSON Lines: `batch`), with ", " and ": " between items.
  // `pick`, when given, records where the values it names are written (json_pick.hpp).
  explicit JsonWriter(bool one_line = false, JsonPick* pick = nullptr)
      : one_line_(one_line), pick_(pick), only_picked_(pick && pick->only_picked()) {
    out_.reserve(reserve_hint());
  }
  void begin_object() { open('{'); }
  void end_object() { close('}'); }
  void begin_array() { open('['); }
  void end_array() { close(']'); }
  JsonWriter& key(std::string_view k) {
    key_begin_ = out_.size();
    if (pick_) next_ = pick_->member(frames_.empty() ? JsonPick::kNone : frames_.back().node, k);
    if (only_picked_ && whole_ == 0) {
      // Outside a picked container no key is read back: a span starts at its value.
      pending_key_ = true;
      return *this;
    }
    if (one_line_ && !pending_key_ && !has_items_.empty() && k.size() <= kShortKey && plain(k)) {
      // The keys the program writes, with the separator before them: stored in place, no escaping.
      char* p = out_.room(k.size() + 6);
      if (has_items_.back()) *p++ = ',', *p++ = ' ';
      has_items_.back() = true;
      *p++ = '"';
      JsonText::copy(p, k.data(), k.size());
      p += k.size();
      *p++ = '"', *p++ = ':', *p++ = ' ';
      out_.commit(p);
    } else {
      item();
      append_quoted(out_, k);
      out_ += ": ";
    }
    pending_key_ = true;
    return *this;
  }
  // After key(): true when the writer writes only picked values and nothing under this key is picked.
  // The key is then taken back, and the caller writes no value for it (a section it need not compute).
  bool unpicked() {
    if (!only_picked_ || whole_ > 0 || next_ != JsonPick::kNone) return false;
    out_.resize(key_begin_);
    pending_key_ = false;
    return true;
  }
  void raw(std::string_view number_text) { value(finite(number_text)); }
  // A number whose text `format(JsonText&)` appends in place, so that no string is made per number.
  template <typename Format>
  void number(Format&& format) {
    if (!pick_) {  // the common case, without a pick's bookkeeping
      item();
      pending_key_ = false;
      append_number(format);
      return;
    }
    const std::size_t from = start();
    item();
    pending_key_ = false;
    const Mark m = mark();
    if (skipped(m, from)) return;
    append_number(format);
    picked(m);
  }
  // A short array of `n` numbers on one line, element i appended by `format(JsonText&, i)`.
  template <typename Format>
  void number_row(int n, Format&& format) {
    if (!pick_) {
      item();
      pending_key_ = false;
      out_ += '[';
      for (int i = 0; i < n; ++i) {
        if (i) out_.append(", ", 2);
        append_number([&](JsonText& out) { format(out, i); });
      }
      out_ += ']';
      return;
    }
    const std::size_t from = start();
    item();
    pending_key_ = false;
    const Mark row = mark();
    if (row.node == JsonPick::kNone && skipped(row, from)) return;  // no element of the row is picked either
    if (only_picked_ && whole_ == 0 && pick_->column(row.node) == JsonPick::kNone) {
      out_.resize(from);  // some elements are picked: they are written alone
      for (int i = 0; i < n; ++i) {
        Mark m{JsonPick::kNone, row.group, out_.size()};
        m.node = pick_->element(row.node, static_cast<std::size_t>(i), m.group);
        if (pick_->column(m.node) == JsonPick::kNone) continue;
        append_number([&](JsonText& out) { format(out, i); });
        picked(m);
      }
      return;
    }
    out_ += '[';
    for (int i = 0; i < n; ++i) {
      if (i) out_ += ", ";
      Mark m{JsonPick::kNone, row.group, out_.size()};
      if (pick_) m.node = pick_->element(row.node, static_cast<std::size_t>(i), m.group);
      append_number([&](JsonText& out) { format(out, i); });
      picked(m);
    }
    out_ += ']';
    picked(row);
  }
  void string(std::string_view s) {
    const std::size_t from = start();
    item();
    pending_key_ = false;
    const Mark m = mark();
    if (skipped(m, from)) return;
    append_quoted(out_, s);
    if (pick_)
      if (const int column = pick_->column(m.node); column != JsonPick::kNone) pick_->add_string(column, m.group, m.begin, out_.size(), s);
  }
  void boolean(bool b) { value(b ? "true" : "false"); }
  void null() { value("null"); }
  // A short array of numbers on one line.
  void number_array(const std::vector<std::string>& items) {
    number_row(static_cast<int>(items.size()), [&](JsonText& out, int i) { out += items[i]; });
  }
  std::string str() && {
    out_ += '\n';
    // The next document of this thread (a batch's next row) is likely as long as this one: room for
    // it, with a little to spare.
    reserve_hint() = std::min<std::size_t>(out_.size() + 64, kMaxReserve);
    return std::move(out_).take();
  }
  std::string str() const& { return std::string(out_.view()) + "\n"; }

  static std::string quote(std::string_view s) {
    std::string q;
    append_quoted(q, s);
    return q;
  }

  template <typename Out>  // std::string or JsonText
  static void append_quoted(Out& q, std::string_view s) {
    q += '"';
    // Runs of characters that need no escape are copied whole.
    std::size_t run = 0;
    for (std::size_t i = next_special(s, 0); i < s.size(); i = next_special(s, run)) {
      q.append(s.substr(run, i - run));
      run = i + 1;
      const unsigned char c = static_cast<unsigned char>(s[i]);
      if (c == '"') q += "\\\"";
      else if (c == '\\') q += "\\\\";
      else if (c == '\n') q += "\\n";
      else {
        static const char* hex = "0123456789abcdef";
        q += "\\u00";
        q += hex[c >> 4];
        q += hex[c & 15];
      }
    }
    q.append(s.substr(run));
    q += '"';
  }

  // The first byte at or after `i` that a JSON string must escape (a control byte, '"' or '\\'), or
  // s.size(). Eight bytes at a time: a byte below 0x20, or equal to 0x22 or 0x5c, sets its high bit in
  // `hit` (the borrow of the subtraction may also set higher bytes' bits, never a lower one's, so the
  // lowest bit set is the first such byte); bytes of 0x80 and above are not control bytes.
  static std::size_t next_special(std::string_view s, std::size_t i) {
    constexpr bool little = std::endian::native == std::endian::little;  // the first byte is the lowest
    for (; little && i + 8 <= s.size(); i += 8) {
      if (const std::uint64_t hit = special_bytes(load<std::uint64_t>(s.data() + i)))
        return i + static_cast<std::size_t>(std::countr_zero(hit)) / 8;
    }
    for (; i < s.size(); ++i) {
      const unsigned char c = static_cast<unsigned char>(s[i]);
      if (c < 0x20 || c == '"' || c == '\\') return i;
    }
    return s.size();
  }

 private:
  JsonText out_;
  std::vector<char> has_items_;  // bytes, not vector<bool>: its bit arithmetic was a quarter of a key
  bool pending_key_ = false;
  bool one_line_;
  // Picking: the pick node of each open container, the node the last key named, and where a value began.
  struct Frame {
    int node;
    std::size_t count, begin, group;
    bool object, whole;  // whole: the container is picked, or is inside one that is
  };
  struct Mark {
    int node = JsonPick::kNone;
    std::size_t group = 0, begin = 0;
  };
  JsonPick* pick_;
  std::vector<Frame> frames_;
  int next_ = JsonPick::kNone;
  // Writing only the picked values: how many open containers are written whole, and where the last key
  // began (a value that is not written takes its key back).
  bool only_picked_;
  int whole_ = 0;
  std::size_t key_begin_ = 0;

  std::size_t start() const { return pending_key_ ? key_begin_ : out_.size(); }
  // Whether the value at `m` is left out; then the text written for it since `from` is taken back.
  bool skipped(const Mark& m, std::size_t from) {
    if (!only_picked_ || whole_ > 0 || pick_->column(m.node) != JsonPick::kNone) return false;
    out_.resize(from);
    return true;
  }

  // The pick node of the value about to be written (after its separator) and its group.
  Mark mark() {
    Mark m;
    if (!pick_) return m;
    m.begin = out_.size();
    if (frames_.empty()) {
      m.node = 0;  // the root
      return m;
    }
    Frame& f = frames_.back();
    m.group = f.group;
    m.node = f.object ? next_ : pick_->element(f.node, f.count++, m.group);
    return m;
  }
  void picked(const Mark& m) {
    if (!pick_) return;
    if (const int column = pick_->column(m.node); column != JsonPick::kNone) pick_->add(column, m.group, m.begin, out_.size());
  }

  // Every scalar's text of an infinity or a NaN starts with "inf" or "nan", signed or not (std::to_chars,
  // format_g17, the multiprecision types' streams, a ball's text); no finite one has a letter there.
  static bool non_finite(std::string_view number_text) {
    if (!number_text.empty() && (number_text.front() == '-' || number_text.front() == '+')) number_text.remove_prefix(1);
    return !number_text.empty() && (number_text.front() == 'i' || number_text.front() == 'n');
  }
  static std::string_view finite(std::string_view number_text) { return non_finite(number_text) ? "null" : number_text; }
  template <typename Format>
  void append_number(Format&& format) {
    const std::size_t at = out_.size();
    format(out_);
    if (non_finite(out_.view().substr(at))) {
      out_.resize(at);
      out_ += "null";
    }
  }
  // The high bit of each byte of x that a JSON string must escape, and perhaps of bytes above one (a
  // borrow); none when no byte must be escaped, whatever the byte order.
  static std::uint64_t special_bytes(std::uint64_t x) {
    constexpr std::uint64_t ones = 0x0101010101010101ULL, highs = 0x8080808080808080ULL;
    const std::uint64_t quote = x ^ (ones * '"'), backslash = x ^ (ones * '\\');
    return (((x - ones * 0x20) & ~x) | ((quote - ones) & ~quote) | ((backslash - ones) & ~backslash)) & highs;
  }
  template <typename T>
  static T load(const char* p) {
    T x;
    std::memcpy(&x, p, sizeof x);
    return x;
  }
  // No byte to escape: every byte is tested by whole words, overlapping where the length is not a
  // multiple of eight, and a string under eight bytes by one word filled from it (two overlapping loads,
  // repeated across the word below four bytes). A key took a branch and a dozen instructions a byte in
  // next_special's tail.
  static bool plain(std::string_view s) {
    const char* p = s.data();
    const std::size_t n = s.size();
    std::uint64_t x;
    if (n >= 8) {
      std::uint64_t any = 0;
      for (std::size_t i = 0; i + 8 <= n; i += 8) any |= special_bytes(load<std::uint64_t>(p + i));
      return (any | special_bytes(load<std::uint64_t>(p + n - 8))) == 0;
    }
    if (n >= 4) {
      x = load<std::uint32_t>(p) | std::uint64_t{load<std::uint32_t>(p + n - 4)} << 32;
    } else if (n >= 2) {
      x = (load<std::uint16_t>(p) | std::uint64_t{load<std::uint16_t>(p + n - 2)} << 16) * 0x0000000100000001ULL;
    } else {
      if (n == 0) return true;
      x = static_cast<unsigned char>(*p) * 0x0101010101010101ULL;
    }
    return special_bytes(x) == 0;
  }
  static constexpr std::size_t kShortKey = 48;
  static constexpr std::size_t kMaxReserve = std::size_t{1} << 20;
  static std::size_t& reserve_hint() {
    thread_local std::size_t bytes = 4096;
    return bytes;
  }
  void item() {
    if (pending_key_) return;
    if (!has_items_.empty()) {
      if (has_items_.back()) {
        if (one_line_) out_.append(", ", 2);
        else out_ += ',';
      }
      has_items_.back() = true;
      newline(has_items_.size());
    }
  }
  void newline(std::size_t depth) {
    if (one_line_) return;
    out_ += '\n';
    out_.append(2 * depth, ' ');
  }
  void value(std::string_view text) {
    const std::size_t from = start();
    item();
    pending_key_ = false;
    const Mark m = mark();
    if (skipped(m, from)) return;
    out_ += text;
    picked(m);
  }
  void open(char c) {
    const std::size_t from = start();
    item();
    pending_key_ = false;
    has_items_.push_back(false);
    if (!pick_) {
      out_ += c;
      return;
    }
    const Mark m = mark();
    const bool whole = whole_ > 0 || pick_->column(m.node) != JsonPick::kNone;
    frames_.push_back({m.node, 0, m.begin, m.group, c == '{', whole});
    whole_ += whole;
    if (only_picked_ && !whole) out_.resize(from);  // its picked members, if any, are written alone
    else out_ += c;
  }
  void close(char c) {
    const bool had = has_items_.back();
    has_items_.pop_back();
    if (!pick_) {
      if (had) newline(has_items_.size());
      out_ += c;
      return;
    }
    const Frame f = frames_.back();
    frames_.pop_back();
    whole_ -= f.whole;
    if (only_picked_ && !f.whole) return;
    if (had) newline(has_items_.size());
    out_ += c;
    picked({f.node, f.group, f.begin});
  }
};

}  // namespace impact3d::case_format
