#include "impact3d/cli/output_file.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iterator>

#include <fmt/format.h>


namespace impact3d::cli {
namespace {

namespace fs = std::filesystem;

// Hidden, beside the target, named for it (cut so that the name stays within NAME_MAX).
std::string temporary_name(const std::string& name, int attempt) {
  static std::atomic<unsigned> counter{0};
  const auto now = static_cast<unsigned long long>(std::chrono::steady_clock::now().time_since_epoch().count());
  return fmt::format(".{}.{:x}-{:x}-{:x}.tmp", name.substr(0, 160), static_cast<unsigned>(::getpid()), counter++,
                     (now >> 4) + static_cast<unsigned long long>(attempt));
}

// The temporaries not yet renamed, for the signal handler to remove: written before they are
// published (dir, release), read by the handler (acquire). A fixed table: no allocation in the handler.
struct Pending {
  std::atomic<int> dir{-1};
  char name[NAME_MAX + 1];
};
Pending pending[16];

extern "C" void remove_pending(int sig) {
  for (Pending& p : pending)
    if (const int dir = p.dir.load(std::memory_order_acquire); dir >= 0) ::unlinkat(dir, p.name, 0);
  ::raise(sig);  // the default action, SA_RESETHAND having restored it, once this handler returns
}

void handle_signals_once() {
  static const bool installed = [] {
    for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction old {};
      if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL || (old.sa_flags & SA_SIGINFO)) continue;
      struct sigaction sa {};
      sa.sa_handler = remove_pending;
      sa.sa_flags = SA_RESETHAND;
      sigemptyset(&sa.sa_mask);
      ::sigaction(sig, &sa, nullptr);
    }
    return true;
  }();
  (void)installed;
}

int publish(int dir, const std::string& name) {
  if (name.size() > NAME_MAX) return -1;
  for (int i = 0; i < static_cast<int>(std::size(pending)); ++i) {
    int expected = -1;
    // A slot is taken by storing -2, filled, then given its directory.
    if (pending[i].dir.compare_exchange_strong(expected, -2, std::memory_order_acq_rel)) {
      std::memcpy(pending[i].name, name.c_str(), name.size() + 1);
      pending[i].dir.store(dir, std::memory_order_release);
      return i;
    }
  }
  return -1;  // more pending files than slots: the extra ones are not removed on a signal
}

void withdraw(int slot) {
  if (slot >= 0) pending[slot].dir.store(-1, std::memory_order_release);
}

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  return "not a regular file";
}

}  // namespace

int above_std(int fd) {
  if (fd < 0 || fd > 2) return fd;
  const int moved = ::fcntl(fd, F_DUPFD_CLOEXEC, 3);
  ::close(fd);
  return moved;
}

int write_all(int fd, std::string_view text) {
  sigset_t pipe, before;
  sigemptyset(&pipe);
  sigaddset(&pipe, SIGPIPE);
  ::pthread_sigmask(SIG_BLOCK, &pipe, &before);
  int error = 0;
  for (std::size_t done = 0; done < text.size() && !error;) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) error = errno;
    else if (n == 0) error = ENOSPC;
    else done += static_cast<std::size_t>(n);
  }
  if (error == EPIPE && !sigismember(&before, SIGPIPE)) {  // the SIGPIPE this write raised, taken back
    const timespec now{0, 0};
    while (::sigtimedwait(&pipe, nullptr, &now) < 0 && errno == EINTR) {
    }
  }
  ::pthread_sigmask(SIG_SETMASK, &before, nullptr);
  return error;
}

Replacement::Replacement(int dir_fd, std::string name, std::string shown, int mode_of_old)
    : dir_fd_(dir_fd), name_(std::move(name)), shown_(std::move(shown)) {
  // The kernel applies the umask to a new file's 0666; an old file's permissions are kept, and the
  // temporary never allows more than they do.
  handle_signals_once();
  const mode_t mode = mode_of_old >= 0 ? static_cast<mode_t>(mode_of_old) & 0777 : 0666;
  for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
    temp_ = temporary_name(name_, attempt);
    fd_ = ::openat(dir_fd_, temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC | O_NOCTTY, mode);
    if (fd_ < 0 && errno != EEXIST) break;
  }
  if (fd_ >= 0) slot_ = publish(dir_fd_, temp_);
  if (fd_ < 0) {
    const int err = errno;
    throw UserError(fmt::format("{}: cannot write the file: no temporary file can be made beside it ({})", shown_, std::strerror(err)));
  }
  if ((fd_ = above_std(fd_)) < 0) fail("cannot write the file", errno);
  if (mode_of_old >= 0 && ::fchmod(fd_, static_cast<mode_t>(mode_of_old) & 07777) != 0) fail("cannot write the file", errno);
}

Replacement::~Replacement() {
  if (fd_ >= 0) ::close(fd_);
  if (!temp_.empty()) ::unlinkat(dir_fd_, temp_.c_str(), 0);
  withdraw(slot_);
}

void Replacement::fail(const char* doing, int error) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  ::unlinkat(dir_fd_, temp_.c_str(), 0);
  temp_.clear();
  withdraw(slot_);
  slot_ = -1;
  throw OutputLost(fmt::format("{}: {} ({}); nothing was replaced", shown_, doing, std::strerror(error)));
}

void Replacement::commit() {
  if (::fsync(fd_) != 0) fail("cannot write the file", errno);
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail("cannot write the file", errno);
  if (::renameat(dir_fd_, temp_.c_str(), dir_fd_, name_.c_str()) != 0) fail("cannot replace the file", errno);
  temp_.clear();
  withdraw(slot_);
  slot_ = -1;
  ::fsync(dir_fd_);  // the rename itself on the disk; a file system that cannot says nothing worse
}

OutputFile::OutputFile(const std::string& path) : path_(path) {
  if (path.empty()) throw UserError("an output file name is empty");
  struct stat st {};
  std::string target = path;
  int old_mode = -1;
  uid_t replaced_owner = ::geteuid();
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISREG(st.st_mode)) {
      old_mode = static_cast<int>(st.st_mode);
      replaced_owner = st.st_uid;
      // A link is followed: the file it names is the one replaced, the link kept.
      struct stat lst {};
      if (::lstat(path.c_str(), &lst) == 0 && S_ISLNK(lst.st_mode)) {
        char* real = ::realpath(path.c_str(), nullptr);
        if (!real) throw UserError(fmt::format("{}: cannot write the file ({})", path, std::strerror(errno)));
        target = real;
        std::free(real);
      }
    } else if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) {
      // A FIFO no one reads would keep the program waiting: opened without blocking, refused then.
      stream_fd_ = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
      if (stream_fd_ < 0) {
        const int err = errno;
        if (err == ENXIO) throw UserError(fmt::format("{}: cannot write the file (a FIFO that nothing reads)", path));
        throw UserError(fmt::format("{}: cannot write the file ({})", path, std::strerror(err)));
      }
      ::fcntl(stream_fd_, F_SETFL, ::fcntl(stream_fd_, F_GETFL) & ~O_NONBLOCK);
      if ((stream_fd_ = above_std(stream_fd_)) < 0)
        throw UserError(fmt::format("{}: cannot write the file ({})", path, std::strerror(errno)));
      return;
    } else {
      throw UserError(fmt::format("{}: cannot write the file ({}: only a file, a FIFO or a character device is written)", path,
                                  kind_of(st.st_mode)));
    }
  } else if (errno != ENOENT) {
    throw UserError(fmt::format("{}: cannot write the file ({})", path, std::strerror(errno)));
  } else if (struct stat lst {}; ::lstat(path.c_str(), &lst) == 0) {
    throw UserError(fmt::format("{}: cannot write the file (a link to nothing)", path));
  }
  const fs::path p(target);
  const std::string name = p.filename().string();
  if (name.empty() || name == "." || name == "..") throw UserError(fmt::format("{}: cannot write the file (not a file name)", path));
  const std::string dir = p.has_parent_path() ? p.parent_path().string() : ".";
  dir_fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd_ < 0) throw UserError(fmt::format("{}: cannot write the file: its directory cannot be opened ({})", path, std::strerror(errno)));
  // In a sticky directory (/tmp) another user's file cannot be renamed over: said now, not after the run.
  struct stat dst {};
  if (replaced_owner != ::geteuid() && ::geteuid() != 0 && ::fstat(dir_fd_, &dst) == 0 && (dst.st_mode & S_ISVTX) &&
      dst.st_uid != ::geteuid()) {
    ::close(dir_fd_);
    dir_fd_ = -1;
    throw UserError(fmt::format("{}: cannot write the file (another user's file in a sticky directory cannot be replaced)", path));
  }
  try {
    replacement_ = std::make_unique<Replacement>(dir_fd_, name, path, old_mode);
  } catch (...) {
    ::close(dir_fd_);
    throw;
  }
}

OutputFile::~OutputFile() {
  replacement_.reset();
  if (dir_fd_ >= 0) ::close(dir_fd_);
  if (stream_fd_ >= 0) ::close(stream_fd_);
}

int OutputFile::fd() const { return replacement_ ? replacement_->fd() : stream_fd_; }

void OutputFile::write(std::string_view text) {
  if (const int err = write_all(fd(), text); err != 0) {
    if (replacement_) {
      replacement_.reset();
      throw OutputLost(fmt::format("{}: cannot write the file ({}); nothing was replaced", path_, std::strerror(err)));
    }
    throw OutputLost(fmt::format("{}: cannot write the file ({})", path_, std::strerror(err)));
  }
}

void OutputFile::commit() {
  if (replacement_) {
    replacement_->commit();
    return;
  }
  const int fd = stream_fd_;
  stream_fd_ = -1;
  if (::close(fd) != 0) throw OutputLost(fmt::format("{}: cannot write the file ({})", path_, std::strerror(errno)));
}

}  // namespace impact3d::cli
