#include "impact3d/cli/row_output.hpp"

#include <fcntl.h>
#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace impact3d::cli {

namespace {

// What direct writes need aligned (buffer, offset and length): a page covers the logical block sizes
// of common disks, 512 and 4096 bytes.
constexpr std::size_t kPage = 4096;
// Pages handed to the disk by one write.
constexpr std::size_t kStage = std::size_t{4} << 20;

}  // namespace

void RowOutput::Free::operator()(char* p) const { std::free(p); }

RowOutput::RowOutput(int fd, bool own, std::uint64_t direct_after) : fd_(fd), direct_after_(direct_after) {
  struct stat st {};
  const off_t at = own && ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) ? ::lseek(fd, 0, SEEK_CUR) : -1;
  void* stage = nullptr;
  may_direct_ = at >= 0 && ::posix_memalign(&stage, kPage, kStage) == 0;
  if (!may_direct_) return;
  stage_.reset(static_cast<char*>(stage));
  written_ = static_cast<std::uint64_t>(at);
  page_offset_ = written_ / kPage * kPage;
  staged_ = static_cast<std::size_t>(written_ - page_offset_);
  // Bytes before the first write (written by someone else) are not in the stage: such a start would
  // need them read back, so it is written through the cache.
  if (staged_ != 0) may_direct_ = false;
}

RowOutput::~RowOutput() = default;

// Kept where the call fails: a later call (a destructor's free) may set errno again.
bool RowOutput::failed(int error) {
  error_ = error;
  return false;
}

bool RowOutput::set_direct(bool on) {
  const int flags = ::fcntl(fd_, F_GETFL);
  return flags >= 0 && ::fcntl(fd_, F_SETFL, on ? flags | O_DIRECT : flags & ~O_DIRECT) == 0;
}

bool RowOutput::write(std::span<const iovec> pieces) {
  // After a failed write the bookkeeping is not the file's: nothing more is written.
  if (error_ != 0) return false;
  if (pieces.empty()) return true;
  if (!staging_ && may_direct_ && written_ >= direct_after_) {
    may_direct_ = false;  // tried once
    direct_ = set_direct(true);
    // From here on through the stage, at the program's offsets (the file position is left where it
    // was), whether the direct writes stay on or the file system refuses them.
    staging_ = direct_;
  }
  return staging_ ? write_staged(pieces) : write_cached(pieces);  // a failure sets error_ (failed())
}

// Through partial writes, IOV_MAX pieces at a time.
bool RowOutput::write_cached(std::span<const iovec> pieces) {
  std::vector<iovec> iov;
  for (std::size_t k = 0; k < pieces.size();) {
    const std::size_t n = std::min<std::size_t>(pieces.size() - k, IOV_MAX);
    iov.assign(pieces.begin() + k, pieces.begin() + k + n);
    k += n;
    for (std::size_t first = 0; first < iov.size();) {
      const ssize_t w = ::writev(fd_, iov.data() + first, static_cast<int>(iov.size() - first));
      if (w < 0 && errno == EINTR) continue;
      if (w < 0) return failed(errno);
      if (w == 0 && iov[first].iov_len > 0) return failed(EIO);  // no bytes taken, and no reason given
      auto left = static_cast<std::size_t>(w);
      written_ += left;
      while (first < iov.size() && left >= iov[first].iov_len) left -= iov[first++].iov_len;
      if (first < iov.size()) {
        iov[first].iov_base = static_cast<char*>(iov[first].iov_base) + left;
        iov[first].iov_len -= left;
      }
    }
  }
  if (may_direct_) keep_tail(pieces);
  return true;
}

// The stage follows the file through the cached writes, so that it holds the last page's bytes when
// the writes turn direct.
void RowOutput::keep_tail(std::span<const iovec> pieces) {
  std::size_t bytes = 0;
  for (const iovec& p : pieces) bytes += p.iov_len;
  const std::size_t keep = static_cast<std::size_t>(written_ % kPage);
  page_offset_ = written_ - keep;
  // The pieces' last `keep` bytes; or, where they all fall on the last page, all of them after that
  // page's earlier bytes, which the stage holds from the writes before.
  std::size_t skip = bytes >= keep ? bytes - keep : 0;
  staged_ = bytes >= keep ? 0 : keep - bytes;
  for (const iovec& p : pieces) {
    const std::size_t s = std::min(skip, p.iov_len);
    skip -= s;
    std::memcpy(stage_.get() + staged_, static_cast<const char*>(p.iov_base) + s, p.iov_len - s);
    staged_ += p.iov_len - s;
  }
}

// The stage's first `bytes` (whole pages, or the last page's rows) at the stage's offset; a direct
// write the file system refuses is made through the cache, as every later one.
bool RowOutput::flush_pages(std::size_t bytes) {
  const char* p = stage_.get();
  std::uint64_t at = page_offset_;
  while (bytes > 0) {
    const ssize_t w = ::pwrite(fd_, p, bytes, static_cast<off_t>(at));
    if (w < 0 && errno == EINTR) continue;
    if (w < 0 && (errno == EINVAL || errno == EOPNOTSUPP) && direct_) {
      if (!set_direct(false)) return failed(errno);
      direct_ = false;  // and for every later write
      continue;
    }
    if (w < 0) return failed(errno);
    if (w == 0) return failed(EIO);  // no bytes taken, and no reason given
    p += w, at += static_cast<std::uint64_t>(w), bytes -= static_cast<std::size_t>(w);
  }
  return true;
}

bool RowOutput::write_staged(std::span<const iovec> pieces) {
  for (const iovec& piece : pieces) {
    const char* p = static_cast<const char*>(piece.iov_base);
    for (std::size_t left = piece.iov_len; left > 0;) {
      const std::size_t n = std::min(left, kStage - staged_);
      std::memcpy(stage_.get() + staged_, p, n);
      staged_ += n, p += n, left -= n;
      if (staged_ < kStage) continue;
      if (!flush_pages(kStage)) return false;
      page_offset_ += kStage;
      staged_ = 0;
    }
  }
  const std::size_t pages = staged_ / kPage * kPage;
  if (pages > 0 && !flush_pages(pages)) return false;
  page_offset_ += pages;
  staged_ -= pages;
  std::memmove(stage_.get(), stage_.get() + pages, staged_);
  if (staged_ > 0) {
    // The last page's rows through the cache (its next direct write will take the page again, whole).
    const bool was_direct = direct_;
    if (was_direct && !set_direct(false)) return failed(errno);
    direct_ = false;
    if (!flush_pages(staged_)) return false;
    direct_ = was_direct && set_direct(true);
  }
  written_ = page_offset_ + staged_;
  return true;
}

}  // namespace impact3d::cli
