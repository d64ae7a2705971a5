// Where the program's files go, so that nothing is lost. A regular file, or a name not yet taken, is
// written into a temporary file beside it and renamed over it only when complete and on the disk
// (commit): a run that fails, a full disk included, leaves the old file whole and no partial one. A
// character device or a FIFO is written as a stream, never replaced. A directory, a block device, a
// socket, a FIFO no one reads and a link to nothing are refused with one line.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "impact3d/cli/user_error.hpp"

namespace impact3d::cli {

// An output that was opened but could not be written whole (a full disk, a reader gone away): exit
// status 3, as batch's, where a name that cannot be written at all is bad input (UserError, 1).
struct OutputLost : UserError {
  using UserError::UserError;
};

// A file being written in place of `name` in the directory `dir_fd`: the temporary is removed unless
// commit() renamed it over the name, also when SIGINT, SIGTERM or SIGHUP ends the program (where their
// handling is the default one when the first temporary is made; batch's own handler commits instead).
class Replacement {
 public:
  // Throws UserError naming `shown` (the target as the user would name it).
  Replacement(int dir_fd, std::string name, std::string shown, int mode_of_old = -1);
  ~Replacement();
  Replacement(const Replacement&) = delete;
  Replacement& operator=(const Replacement&) = delete;

  int fd() const { return fd_; }
  // Flushes the file to the disk, closes it and renames it over the name; throws UserError with the
  // system's reason, the temporary then removed and the old file untouched.
  void commit();

 private:
  [[noreturn]] void fail(const char* doing, int error);
  int dir_fd_;
  int slot_ = -1;  // in the table the signal handler removes temporaries from
  std::string name_, temp_, shown_;
  int fd_ = -1;
};

// The named output of a command (report -o, batch -o, montecarlo --samples-out).
class OutputFile {
 public:
  // Throws UserError, one line naming `path`, when it cannot be written.
  explicit OutputFile(const std::string& path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  int fd() const;
  // False for a stream (a character device, a FIFO): written from the start, no offsets of its own.
  bool replaces() const { return replacement_ != nullptr; }
  // Writes all of `text`; throws UserError with the system's reason.
  void write(std::string_view text);
  // Completes the output (the rename, or the stream's close); throws UserError.
  void commit();

 private:
  std::string path_;
  int dir_fd_ = -1, stream_fd_ = -1;
  std::unique_ptr<Replacement> replacement_;
};

// `fd`, or a copy above 2 (the original closed; -1 where none can be made): descriptors 0-2 may be closed
// when impact3d starts, and a file opened then must never be taken for a standard stream, nor be
// replaced by redirecting gnuplot's.
int above_std(int fd);

// Writes all of `text` to `fd`; returns 0 or the errno of the failure (ENOSPC for a write that took
// nothing, EPIPE for a reader gone away: SIGPIPE is held off while it writes, so that a FIFO whose
// reader quits is an error line, not a silent death).
int write_all(int fd, std::string_view text);

}  // namespace impact3d::cli
