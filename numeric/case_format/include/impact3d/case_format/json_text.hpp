// The text a JsonWriter builds. A result row of `impact3d batch` is some 600 short pieces (keys,
// separators, numbers); appended to a std::string each is a call into the library and one into memcpy,
// which took a tenth of the row's time. Here the storage is a std::string kept at its full capacity, of
// which the first size() characters are the text: a short piece is copied by a few fixed-width moves,
// and a number is formatted straight into the storage (room()).
#pragma once

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <cstring>
#include <string>
#include <string_view>

namespace impact3d::case_format {

class JsonText {
 public:
  std::size_t size() const { return size_; }
  std::string_view view() const { return {buf_.data(), size_}; }
  void reserve(std::size_t n) {
    if (n > buf_.size()) grow(n);
  }
  // Only shorter: the text written since `n` is taken back.
  void resize(std::size_t n) {
    assert(n <= size_);
    size_ = n;
  }

  void append(const char* p, std::size_t n) {
    if (n > buf_.size() - size_) grow(size_ + n);
    copy(buf_.data() + size_, p, n);
    size_ += n;
  }
  void append(std::string_view s) { append(s.data(), s.size()); }
  void append(std::size_t n, char c) {
    if (n > buf_.size() - size_) grow(size_ + n);
    std::memset(buf_.data() + size_, c, n);
    size_ += n;
  }
  JsonText& operator+=(char c) {
    if (size_ == buf_.size()) grow(size_ + 1);
    buf_[size_++] = c;
    return *this;
  }
  JsonText& operator+=(std::string_view s) {
    append(s);
    return *this;
  }

  // Room for `n` characters after the text, to be written at the pointer and kept by commit(end).
  char* room(std::size_t n) {
    if (n > buf_.size() - size_) grow(size_ + n);
    return buf_.data() + size_;
  }
  void commit(const char* end) {
    size_ = static_cast<std::size_t>(end - buf_.data());
    assert(size_ <= buf_.size());
  }

  // The text, its storage given away (no copy).
  std::string take() && {
    buf_.resize(size_);
    size_ = 0;
    return std::move(buf_);
  }

  // n bytes by at most two overlapping moves of a fixed width, read and written within [s, s + n) and
  // [d, d + n).
  static void copy(char* d, const char* s, std::size_t n) {
    auto two = [&]<std::size_t W>() {
      char a[W], b[W];
      std::memcpy(a, s, W);
      std::memcpy(b, s + n - W, W);
      std::memcpy(d, a, W);
      std::memcpy(d + n - W, b, W);
    };
    if (n >= 16) {
      if (n <= 32) two.template operator()<16>();
      else std::memcpy(d, s, n);
    } else if (n >= 8) {
      two.template operator()<8>();
    } else if (n >= 4) {
      two.template operator()<4>();
    } else if (n >= 2) {
      two.template operator()<2>();
    } else if (n == 1) {
      *d = *s;
    }
  }

 private:
  std::string buf_;  // size() is the capacity in use; [size_, buf_.size()) is room
  std::size_t size_ = 0;

  void grow(std::size_t n) { buf_.resize(std::max({n, 2 * buf_.size(), std::size_t{256}})); }
};

}  // namespace impact3d::case_format
