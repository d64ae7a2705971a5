// Where `batch` writes its rows: whole rows at each call, to a pipe, a terminal or a file. A file the
// program opened itself goes past its first `direct_after` bytes straight to the disk (O_DIRECT), not
// through the page cache: a batch writes gigabytes that nobody reads back at once, and copying them into
// the cache cost one to two and a half seconds of system time a gigabyte, on cores the solvers need, on
// the machine BENCHMARKS.md measures. Direct writes take whole pages from a buffer of whole pages; the
// last page's rows go through the cache, so that after every call the file ends at a whole row.
// A file system that refuses direct writes (tmpfs before Linux 6.6, some FUSE file systems) is written
// through the cache throughout.
#pragma once

#include <sys/uio.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

namespace impact3d::cli {

class RowOutput {
 public:
  static constexpr std::uint64_t kDirectAfter = 64 << 20;
  // `fd` is written from its current position. `own` says the program opened it (not O_APPEND, no
  // other writer), which direct writes need, since they write at offsets the program keeps.
  RowOutput(int fd, bool own, std::uint64_t direct_after = kDirectAfter);
  ~RowOutput();
  RowOutput(const RowOutput&) = delete;
  RowOutput& operator=(const RowOutput&) = delete;

  // The pieces in order, together whole rows; false when the output is gone (a closed pipe, a full
  // disk), and for every write after.
  bool write(std::span<const iovec> pieces);
  // The errno of the write that failed (EPIPE: the reader went away), or 0.
  int error() const { return error_; }
  // Whether whole pages now go to the disk directly.
  bool direct() const { return direct_; }

 private:
  bool write_cached(std::span<const iovec> pieces);
  bool write_staged(std::span<const iovec> pieces);
  bool flush_pages(std::size_t bytes);
  void keep_tail(std::span<const iovec> pieces);
  bool set_direct(bool on);
  bool failed(int error);

  int fd_;
  bool may_direct_;
  std::uint64_t direct_after_;
  int error_ = 0;  // set once, by the first failure: every write after it fails
  bool staging_ = false;  // writes go through the stage
  bool direct_ = false;   // and from it to the disk directly
  std::uint64_t written_ = 0;  // bytes in the file
  // Whole pages: the bytes from page_offset_ (a page boundary) to the end of the file are its first
  // staged_ bytes, fewer than a page between calls (the last page, already written through the cache).
  struct Free {
    void operator()(char* p) const;
  };
  std::unique_ptr<char, Free> stage_;
  std::size_t staged_ = 0;
  std::uint64_t page_offset_ = 0;
};

}  // namespace impact3d::cli
