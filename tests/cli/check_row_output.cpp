// Where `batch` writes its rows (cli/library/include/impact3d/cli/row_output.hpp): through the page cache, then, past a number
// of bytes, straight to the disk from a stage of whole pages with the last page through the cache.
// Checked against the bytes given: after every write the file holds exactly what was written so far
// (so it ends at a whole row), whatever the pieces' sizes, their number (beyond IOV_MAX) and where the
// switch falls.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "impact3d/cli/row_output.hpp"

namespace check_row_output {

namespace {

namespace fs = std::filesystem;
using impact3d::cli::RowOutput;

std::string file_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A directory beside the build (the temporary directory may be a tmpfs), removed however the test ends.
struct Scratch {
  fs::path dir = fs::current_path() / fmt::format("impact3d-row-output-{}", ::getpid());
  Scratch() { fs::create_directories(dir); }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

// Whether this directory's file system takes a direct write of one aligned page (tmpfs before Linux 6.6
// does not, nor some FUSE file systems).
bool takes_direct(const fs::path& dir) {
  const fs::path probe = dir / "probe";
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_DIRECT | O_CLOEXEC, 0644);
  bool taken = false;
  if (fd >= 0) {
    void* page = nullptr;
    if (::posix_memalign(&page, 4096, 4096) == 0) {
      std::memset(page, 'x', 4096);
      taken = ::pwrite(fd, page, 4096, 0) == 4096;
      std::free(page);
    }
    ::close(fd);
  }
  fs::remove(probe);
  return taken;
}

// A file opened as batch opens it, written through a RowOutput, held to the bytes given after every
// write: its size always, its whole text every fourth write and at the end.
class Written {
 public:
  Written(const fs::path& file, std::uint64_t direct_after)
      : file_(file), fd_(::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644)), out_(fd_, true, direct_after) {}
  ~Written() { ::close(fd_); }
  Written(const Written&) = delete;
  Written& operator=(const Written&) = delete;

  // Rows of the given sizes; each byte depends on where it lands in the file, so that a page written
  // at another offset, twice or not at all shows.
  void rows(const std::vector<std::size_t>& sizes, std::mt19937_64* split = nullptr) {
    std::vector<std::string> texts;
    std::size_t at = expected_.size();
    for (std::size_t size : sizes) {
      std::string row(size, '\n');
      for (std::size_t i = 0; i + 1 < size; ++i) row[i] = char('a' + ((at + i) * 131 + texts.size()) % 26);
      at += size;
      if (split && (*split)() % 4 == 0 && size > 1) {
        const std::size_t cut = (*split)() % (size - 1) + 1;
        texts.push_back(row.substr(0, cut));
        texts.push_back(row.substr(cut));
      } else {
        texts.push_back(std::move(row));
      }
    }
    std::vector<iovec> pieces;
    std::size_t bytes = 0;
    for (auto& t : texts) {
      pieces.push_back({t.data(), t.size()});
      bytes += t.size();
      expected_ += t;
    }
    const bool was_direct = out_.direct();
    REQUIRE(out_.write(pieces));
    ++writes;
    if (!was_direct && pieces.size() > 1024) ++many_pieces_cached;
    if (was_direct && bytes > (std::size_t{4} << 20)) ++over_a_stage_direct;
    direct = direct || out_.direct();
    struct stat st {};
    REQUIRE(::fstat(fd_, &st) == 0);
    REQUIRE(static_cast<std::size_t>(st.st_size) == expected_.size());
    if (writes % 4 == 0) check();
  }
  void check() {
    REQUIRE(file_text(file_) == expected_);
    ++checked;
  }
  std::size_t size() const { return expected_.size(); }
  RowOutput& out() { return out_; }

  int writes = 0, checked = 0, many_pieces_cached = 0, over_a_stage_direct = 0;
  bool direct = false;

 private:
  fs::path file_;
  int fd_;
  RowOutput out_;
  std::string expected_;
};

}  // namespace

TEST_CASE("rows written through the cache and then directly are the bytes given, whole after every write", "[batch]") {
  const Scratch scratch;
  const bool direct_here = takes_direct(scratch.dir);
  INFO("direct writes taken by this file system: " << direct_here);
  // From the start; from a byte inside a page; never. 12 MiB each: several stages of 4 MiB.
  const std::uint64_t never = std::uint64_t{1} << 40;
  int writes = 0, many_pieces = 0, over_a_stage = 0;
  for (std::uint64_t seed = 1; seed <= 2; ++seed) {
    for (const std::uint64_t after : {std::uint64_t{0}, std::uint64_t{100'003}, never}) {
      std::mt19937_64 draw(seed * 7 + after);
      Written w(scratch.dir / "rows", after);
      // Writes of 0 to 40 rows, one in twenty of 3 000; half the rows under 64 bytes, half up to 12 KiB.
      while (w.size() < (std::size_t{12} << 20)) {
        std::vector<std::size_t> sizes(draw() % 20 == 0 ? 3000 : draw() % 41);
        for (auto& size : sizes) size = draw() % 2 ? draw() % 64 + 1 : draw() % (12 << 10) + 1;
        w.rows(sizes, &draw);
      }
      w.check();
      CHECK(w.writes >= 5);
      CHECK(w.direct == (direct_here && after != never));
      writes += w.writes;
      many_pieces += w.many_pieces_cached;
      over_a_stage += w.over_a_stage_direct;
    }
  }
  CHECK(writes >= 30);
  CHECK(many_pieces > 0);                     // more pieces than one writev takes
  CHECK((over_a_stage > 0 || !direct_here));  // a stage filled and written within one write
}

TEST_CASE("the switch to direct writes after writes within one page, and writes of no rows", "[batch]") {
  const Scratch scratch;
  const bool direct_here = takes_direct(scratch.dir);
  INFO("direct writes taken by this file system: " << direct_here);
  Written w(scratch.dir / "rows", 10'000);
  w.rows({9000});             // into the third page
  for (int i = 0; i < 3; ++i) w.rows({100});  // each within that page
  REQUIRE(w.out().write({}));
  w.rows({800});              // 10 100 bytes: the switch is due at the next write with rows
  CHECK_FALSE(w.out().direct());
  REQUIRE(w.out().write({}));
  CHECK_FALSE(w.out().direct());
  w.rows({5000, 1});          // the first write through the stage rewrites the third page whole
  CHECK(w.out().direct() == direct_here);
  REQUIRE(w.out().write({}));
  w.rows({50});
  w.rows({4096 * 3});
  w.check();
  CHECK(w.writes == 8);
}

TEST_CASE("rows to a pipe are written through it, never directly", "[batch]") {
  int p[2];
  REQUIRE(::pipe(p) == 0);
  std::string expected;
  {
    RowOutput out(p[1], true, 0);
    std::vector<std::string> texts;
    for (int r = 0; r < 2000; ++r) texts.push_back(fmt::format("{{\"line\": {}}}\n", r + 1));  // under the pipe's 64 KiB
    std::vector<iovec> pieces;
    for (auto& t : texts) {
      pieces.push_back({t.data(), t.size()});
      expected += t;
    }
    REQUIRE(expected.size() < 60000);
    REQUIRE(out.write(pieces));
    CHECK_FALSE(out.direct());
  }
  ::close(p[1]);
  std::string got(expected.size() + 1, '\0');
  std::size_t n = 0;
  for (ssize_t r; (r = ::read(p[0], got.data() + n, got.size() - n)) > 0;) n += static_cast<std::size_t>(r);
  ::close(p[0]);
  got.resize(n);
  CHECK(got == expected);
}

TEST_CASE("a write that fails says why, and nothing is written after it", "[batch]") {
  std::string row = "{\"line\": 1}\n";  // 12 bytes
  const iovec piece{row.data(), row.size()};
  SECTION("a full disk: /dev/full refuses every write with ENOSPC") {
    const int fd = ::open("/dev/full", O_WRONLY | O_CLOEXEC);
    REQUIRE(fd >= 0);
    RowOutput out(fd, true, 0);
    CHECK(out.error() == 0);
    CHECK_FALSE(out.write({&piece, 1}));
    CHECK(out.error() == ENOSPC);
    ::close(fd);
  }
  SECTION("a reader gone away: EPIPE") {
    int p[2];
    REQUIRE(::pipe(p) == 0);
    ::close(p[0]);
    const auto previous = std::signal(SIGPIPE, SIG_IGN);
    RowOutput out(p[1], false);
    CHECK_FALSE(out.write({&piece, 1}));
    std::signal(SIGPIPE, previous);
    CHECK(out.error() == EPIPE);
    ::close(p[1]);
  }
  SECTION("a file over its size limit (EFBIG), then under it again: nothing more is written") {
    const Scratch scratch;
    const fs::path file = scratch.dir / "rows";
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    REQUIRE(fd >= 0);
    RowOutput out(fd, true, 0);
    rlimit saved{};
    REQUIRE(::getrlimit(RLIMIT_FSIZE, &saved) == 0);
    const auto previous = std::signal(SIGXFSZ, SIG_IGN);
    const rlimit small{20, saved.rlim_max};
    REQUIRE(::setrlimit(RLIMIT_FSIZE, &small) == 0);
    const bool first = out.write({&piece, 1});    // 12 bytes: within the limit
    const bool second = out.write({&piece, 1});   // 8 more taken, then EFBIG
    ::setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, previous);
    CHECK(first);
    CHECK_FALSE(second);
    CHECK(out.error() == EFBIG);
    CHECK_FALSE(out.write({&piece, 1}));  // the limit lifted, but the file is not what the rows were
    CHECK(fs::file_size(file) == 20);
    ::close(fd);
  }
}

}  // namespace check_row_output
