// Nothing lost (cli/library/include/impact3d/cli/output_file.hpp): every writer of the program on a full disk (a 16 KiB tmpfs,
// mounted here when run as root, as CI runs) leaves the old file whole and no partial file, with one
// line and a non-zero exit; a character device and a FIFO (made here with mknod and mkfifo in a scratch
// directory, never under /dev) are written as streams and stay what they are; a directory, a socket, a
// FIFO that nothing reads and a link to nothing are refused with one line; a link to a file replaces
// the file and keeps the link; an old file's permissions are kept.
#include <fcntl.h>
#include <sys/mount.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"

namespace check_output_files {

namespace {

namespace fs = std::filesystem;
using impact3d::test::Run;
using impact3d::test::run_argv;
using impact3d::test::run_program;
using impact3d::test::slurp;

const std::string kCase = IMPACT3D_EXAMPLES_DIR "/fig8_side_impact.json";
const std::string kUncertainty = IMPACT3D_EXAMPLES_DIR "/uncertainty/fig8_side_impact.json";

int lines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

fs::path scratch(const std::string& what) {
  static int calls = 0;
  const fs::path p = fs::temp_directory_path() / fmt::format("impact3d-out-{}-{}-{}", what, ::getpid(), calls++);
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

// A 16 KiB tmpfs over a fresh directory, unmounted when done. Empty path when it cannot be mounted.
class FullDisk {
 public:
  FullDisk() : dir_(scratch("tmpfs")) {
    if (::geteuid() != 0 || ::mount("tmpfs", dir_.c_str(), "tmpfs", 0, "size=16k") != 0) mounted_ = false;
  }
  ~FullDisk() {
    if (mounted_) ::umount(dir_.c_str());
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  bool mounted() const { return mounted_; }
  const fs::path& dir() const { return dir_; }

 private:
  fs::path dir_;
  bool mounted_ = true;
};

// 9 000 bytes of an earlier run: three of the disk's four pages, so that no new output fits beside it.
std::string old_text() {
  std::string s;
  for (int i = 0; s.size() < 9000; ++i) s += fmt::format("an earlier run's line {}\n", i);
  return s;
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// Every name in a directory, the hidden ones (a temporary) included.
std::vector<std::string> names(const fs::path& dir) {
  std::vector<std::string> v;
  for (const auto& e : fs::directory_iterator(dir)) v.push_back(e.path().filename().string());
  std::sort(v.begin(), v.end());
  return v;
}

// The case on one line, `n` times: a batch input.
fs::path batch_input(int n) {
  const fs::path p = scratch("batch") / "cases.jsonl";
  const std::string line = nlohmann::json::parse(slurp(kCase)).dump() + "\n";
  std::string all;
  for (int i = 0; i < n; ++i) all += line;
  write(p, all);
  return p;
}

}  // namespace

TEST_CASE("on a full disk every writer leaves the old file whole, no partial file, one line, a non-zero exit") {
  if (::geteuid() != 0) {
    WARN("not root: no tmpfs can be mounted; CI runs this as root");
    return;
  }
  const fs::path cases = batch_input(40);
  struct Writer {
    std::string name;
    std::vector<std::string> args;  // OUT stands for the target
    std::string target;             // the file, or in a directory the file planted there
    int status;
  };
  const std::vector<Writer> writers = {
      {"report -o", {"report", kCase, "-o", "OUT", "--no-figures"}, "r.html", 3},
      {"batch -o", {"batch", cases.string(), "-o", "OUT"}, "b.jsonl", 3},
      {"batch -o --format csv", {"batch", cases.string(), "--format", "csv", "-o", "OUT"}, "b.csv", 3},
      {"montecarlo --samples-out", {"montecarlo", kCase, "--uncertainty", kUncertainty, "--samples", "300", "--samples-out", "OUT"}, "s.csv", 3},
      {"plot -o DIR", {"plot", kCase, "-o", "OUT"}, "figures/contact_plane.svg", 3},
      {"montecarlo --plot DIR", {"montecarlo", kCase, "--uncertainty", kUncertainty, "--samples", "300", "--plot", "OUT"}, "figures/mc0_hist_vehicles_0_delta_v_magnitude.svg", 3},
      {"sensitivity --plot DIR", {"sensitivity", kCase, "--plot", "OUT"}, "figures/sens0_tornado_dv0.svg", 3},
  };
  int checked = 0;
  for (const Writer& w : writers) {
    const FullDisk disk;
    REQUIRE(disk.mounted());
    const fs::path target = disk.dir() / w.target;
    fs::create_directories(target.parent_path());
    const std::string old = old_text();
    write(target, old);
    const auto before = names(target.parent_path());
    std::vector<std::string> args = w.args;
    const fs::path named = target.parent_path() == disk.dir() ? target : target.parent_path();
    std::replace(args.begin(), args.end(), std::string("OUT"), named.string());
    const Run r = run_argv(args);
    INFO(w.name << ": exit " << r.status << ", stderr: " << r.err);
    CHECK(r.status == w.status);
    CHECK(r.out.empty());
    CHECK(lines(r.err) == 1);
    CHECK(r.err.find(std::strerror(ENOSPC)) != std::string::npos);
    CHECK(slurp(target) == old);
    // No temporary left; in a directory, only whole files the run finished may have been added.
    for (const std::string& n : names(target.parent_path())) CHECK(n[0] != '.');
    if (target.parent_path() == disk.dir()) CHECK(names(disk.dir()) == before);
    ++checked;
  }
  CHECK(checked == 7);
}

TEST_CASE("a character device and a FIFO are written as streams and never replaced") {
  if (::geteuid() != 0) {
    WARN("not root: no device node can be made; CI runs this as root");
    return;
  }
  const fs::path dir = scratch("devices");
  const fs::path null = dir / "null", full = dir / "full", fifo = dir / "fifo";
  REQUIRE(::mknod(null.c_str(), S_IFCHR | 0666, ::makedev(1, 3)) == 0);  // what /dev/null is
  REQUIRE(::mknod(full.c_str(), S_IFCHR | 0666, ::makedev(1, 7)) == 0);  // /dev/full: every write ENOSPC
  REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
  const auto still = [](const fs::path& p, mode_t type) {
    struct stat st {};
    return ::lstat(p.c_str(), &st) == 0 && (st.st_mode & S_IFMT) == type;
  };
  const fs::path cases = batch_input(3);

  const Run to_null = run_argv({"report", kCase, "-o", null.string(), "--no-figures"});
  CHECK(to_null.status == 0);
  CHECK(to_null.out == null.string() + "\n");
  CHECK(still(null, S_IFCHR));

  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"report", kCase, "-o", full.string(), "--no-figures"},
        std::vector<std::string>{"montecarlo", kCase, "--uncertainty", kUncertainty, "--samples", "50", "--samples-out", full.string()}}) {
    const Run r = run_argv(args);
    INFO(args[0] << ": " << r.err);
    CHECK(r.status == 3);
    CHECK(r.out.empty());
    CHECK(lines(r.err) == 1);
    CHECK(r.err.find(std::strerror(ENOSPC)) != std::string::npos);
    CHECK(still(full, S_IFCHR));
  }
  const Run batch_full = run_argv({"batch", cases.string(), "-o", full.string()});
  CHECK(batch_full.status == 3);
  CHECK(lines(batch_full.err) == 1);
  CHECK(still(full, S_IFCHR));

  // A FIFO that nothing reads is refused at once, rather than waited on.
  const Run unread = run_argv({"report", kCase, "-o", fifo.string(), "--no-figures"});
  CHECK(unread.status == 1);
  CHECK(unread.err == "impact3d: error: " + fifo.string() + ": cannot write the file (a FIFO that nothing reads)\n");
  CHECK(still(fifo, S_IFIFO));

  // With a reader, the FIFO carries what a file would have held.
  for (const std::vector<std::string>& args : {std::vector<std::string>{"report", kCase, "-o", "OUT", "--no-figures"},
                                               std::vector<std::string>{"batch", cases.string(), "-o", "OUT"}}) {
    const fs::path file = dir / "as_file";
    std::vector<std::string> to_file = args, to_fifo = args;
    std::replace(to_file.begin(), to_file.end(), std::string("OUT"), file.string());
    std::replace(to_fifo.begin(), to_fifo.end(), std::string("OUT"), fifo.string());
    REQUIRE(run_argv(to_file).status == 0);
    const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);  // not the program's too
    REQUIRE(reader >= 0);
    std::string got;
    const auto drain = [&] {
      char buf[1 << 16];
      for (ssize_t n; (n = ::read(reader, buf, sizeof buf)) > 0;) got.append(buf, static_cast<std::size_t>(n));
      return false;
    };
    const Run r = run_program(IMPACT3D_CLI, to_fifo, "", "", 20, 2048, drain);
    drain();
    ::close(reader);
    INFO(args[0] << ": " << r.err);
    CHECK(r.status == 0);
    CHECK(got == slurp(file));
    CHECK(still(fifo, S_IFIFO));
  }
  fs::remove_all(dir);
}

TEST_CASE("a directory, a socket and a link to nothing are refused; a link is followed; permissions are kept") {
  const fs::path dir = scratch("kinds");
  const auto report_to = [&](const fs::path& p) { return run_argv({"report", kCase, "-o", p.string(), "--no-figures"}); };

  fs::create_directories(dir / "a_dir");
  const Run to_dir = report_to(dir / "a_dir");
  CHECK(to_dir.status == 1);
  CHECK(to_dir.err == "impact3d: error: " + (dir / "a_dir").string() +
                          ": cannot write the file (a directory: only a file, a FIFO or a character device is written)\n");

  const int s = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  const std::string sock = (dir / "sock").string();
  REQUIRE(sock.size() < sizeof addr.sun_path);
  std::strcpy(addr.sun_path, sock.c_str());
  REQUIRE(::bind(s, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) == 0);
  const Run to_socket = report_to(sock);
  ::close(s);
  CHECK(to_socket.status == 1);
  CHECK(to_socket.err.find("(a socket: only a file") != std::string::npos);
  CHECK(fs::is_socket(sock));

  fs::create_symlink(dir / "nowhere", dir / "dangling");
  const Run dangling = report_to(dir / "dangling");
  CHECK(dangling.status == 1);
  CHECK(dangling.err == "impact3d: error: " + (dir / "dangling").string() + ": cannot write the file (a link to nothing)\n");
  CHECK(!fs::exists(dir / "nowhere"));

  // A link to a file: the file is replaced, the link stays a link; the file's permissions are kept.
  write(dir / "real.html", "old");
  fs::permissions(dir / "real.html", fs::perms::owner_read | fs::perms::owner_write);
  fs::create_symlink("real.html", dir / "link.html");
  const Run linked = report_to(dir / "link.html");
  CHECK(linked.status == 0);
  CHECK(fs::is_symlink(dir / "link.html"));
  CHECK(slurp(dir / "real.html").rfind("<!DOCTYPE html>", 0) == 0);
  CHECK(fs::status(dir / "real.html").permissions() == (fs::perms::owner_read | fs::perms::owner_write));
  for (const std::string& n : names(dir)) CHECK(n[0] != '.');

  // A batch may write over its own input: the input is read whole from the file it opened.
  const fs::path cases = batch_input(2);
  const Run over = run_argv({"batch", cases.string(), "-o", cases.string()});
  CHECK(over.status == 0);
  CHECK(lines(slurp(cases)) == 2);
  CHECK(slurp(cases).find("\"results\"") != std::string::npos);

  // In a figures' directory, an entry of a figure's name that is not a file is refused, not replaced.
  fs::create_directories(dir / "figs");
  REQUIRE(::mkfifo((dir / "figs" / "contact_plane.svg").c_str(), 0644) == 0);
  const Run planted = run_argv({"plot", kCase, "-o", (dir / "figs").string()});
  CHECK(planted.status == 1);
  CHECK(planted.err == "impact3d: error: " + (dir / "figs").string() + "/contact_plane.svg: cannot replace (not a regular file)\n");
  CHECK(fs::is_fifo(dir / "figs" / "contact_plane.svg"));
  fs::remove_all(dir);
}

TEST_CASE("a run ended by a signal leaves no temporary; a FIFO whose reader quits is one line, exit 3") {
  const fs::path dir = scratch("signal");
  const fs::path samples = dir / "s.csv";
  write(samples, "old");
  // Terminated while it samples: the temporary, made before the run, is removed by the handler.
  bool started = false;
  const Run r = run_program(IMPACT3D_CLI, {"montecarlo", kCase, "--uncertainty", kUncertainty, "--samples", "200000", "--jobs", "1",
                                           "--samples-out", samples.string()},
                            "", "", 60, 2048, [&] {
                              for (const std::string& n : names(dir)) started = started || n[0] == '.';
                              return started;
                            });
  CHECK(started);
  CHECK(r.status == -1);  // killed by SIGTERM, its default action
  CHECK(names(dir) == std::vector<std::string>{"s.csv"});
  CHECK(slurp(samples) == "old");

  // A reader that takes ten bytes and goes: EPIPE, not a silent death by SIGPIPE.
  const fs::path fifo = dir / "fifo";
  REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);  // not the program's too
  REQUIRE(reader >= 0);
  bool closed = false;
  // Samples of some megabytes, past what the FIFO holds, so that writes come after the reader has gone.
  const Run quit = run_program(IMPACT3D_CLI, {"montecarlo", kCase, "--uncertainty", kUncertainty, "--samples", "3000",
                                              "--samples-out", fifo.string()}, "", "", 20, 2048, [&] {
    char buf[10];
    if (!closed && ::read(reader, buf, sizeof buf) > 0) ::close(reader), closed = true;
    return false;
  });
  if (!closed) ::close(reader);
  CHECK(closed);
  CHECK(quit.status == 3);
  CHECK(quit.out.empty());
  CHECK(quit.err == "impact3d: error: --samples-out: " + fifo.string() + ": cannot write the file (" + std::strerror(EPIPE) + ")\n");
  fs::remove_all(dir);
}

}  // namespace check_output_files
