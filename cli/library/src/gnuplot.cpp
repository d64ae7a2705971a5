#include "impact3d/cli/gnuplot.hpp"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

#include <fmt/format.h>

#include "impact3d/case_format/escape.hpp"
#include "impact3d/cli/user_error.hpp"

extern char** environ;

namespace impact3d::cli {
namespace {

constexpr std::size_t kMessageBytes = 1 << 16;  // gnuplot's messages kept; the rest is read and dropped

// The line of gnuplot's messages that says what went wrong: gnuplot echoes the script line and a caret
// before `"NAME.gp" line N: ...`, so the last line naming a script line, else the last non-blank one.
std::string summary_line(const std::string& text) {
  std::vector<std::string> lines;
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    std::string line = text.substr(pos, end - pos);
    if (line.find_first_not_of(" \r\t^") != std::string::npos) lines.push_back(line);
    pos = end + 1;
  }
  if (lines.empty()) return "";
  std::string pick = lines.back();
  for (const auto& l : lines)
    if (l.find(" line ") != std::string::npos && l.find(": ") != std::string::npos) pick = l;
  const auto begin = pick.find_first_not_of(" \t");
  pick = pick.substr(begin);
  if (pick.size() > 200) pick = pick.substr(0, 200) + "...";
  return case_format::printable(pick);
}

// gnuplot's absolute path from PATH, skipping empty and relative entries: those name the working
// directory, which for gnuplot is the output directory, where anyone may have left a `gnuplot`.
std::string gnuplot_path() {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/local/bin:/usr/bin:/bin";
  for (std::size_t pos = 0; pos <= dirs.size();) {
    const std::size_t end = std::min(dirs.find(':', pos), dirs.size());
    const std::string dir = dirs.substr(pos, end - pos);
    pos = end + 1;
    if (dir.empty() || dir[0] != '/') continue;
    const std::string candidate = dir + "/gnuplot";
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

// Starts gnuplot with `args`, stdout to `out_fd`, stderr to `err_fd`, in `dir_fd` when >= 0. Returns
// the pid, or -1 with errno set when gnuplot cannot be started.
pid_t spawn(const std::vector<std::string>& args, int out_fd, int err_fd, int dir_fd) {
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&fa, out_fd, 1);
  posix_spawn_file_actions_adddup2(&fa, err_fd, 2);
  if (dir_fd >= 0) posix_spawn_file_actions_addfchdir_np(&fa, dir_fd);
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = -1;
  const std::string program = gnuplot_path();
  if (program.empty()) {
    posix_spawn_file_actions_destroy(&fa);
    errno = ENOENT;
    return -1;
  }
  const int rc = posix_spawn(&pid, program.c_str(), &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) {
    errno = rc;
    return -1;
  }
  return pid;
}

int wait_for(pid_t pid) {
  int status = 0;
  for (;;) {
    if (::waitpid(pid, &status, 0) >= 0) break;
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

[[noreturn]] void not_found() {
  throw UserError("gnuplot not found: install it (Debian: apt-get install gnuplot-nox) or put it on PATH");
}

}  // namespace

OutputDir::OutputDir(const std::string& path) : path_(path) {
  std::error_code ec;
  std::filesystem::create_directories(path, ec);
  fd_ = above_std(::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (fd_ < 0) throw UserError(fmt::format("{}: cannot use as the output directory ({})", path, std::strerror(errno)));
}

OutputDir::~OutputDir() { ::close(fd_); }

std::unique_ptr<Replacement> OutputDir::replace(const std::string& name) const {
  const std::string shown = path_ + "/" + name;
  struct stat st {};
  int mode = -1;
  if (::fstatat(fd_, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0) {
    if (S_ISREG(st.st_mode)) mode = static_cast<int>(st.st_mode);
    else if (!S_ISLNK(st.st_mode))  // a planted link is replaced, never followed
      throw UserError(fmt::format("{}: cannot replace (not a regular file)", shown));
  } else if (errno != ENOENT) {
    throw UserError(fmt::format("{}: cannot replace ({})", shown, std::strerror(errno)));
  }
  return std::make_unique<Replacement>(fd_, name, shown, mode);
}

void OutputDir::write(const std::string& name, std::string_view text) const {
  const auto file = replace(name);
  if (const int err = write_all(file->fd(), text); err != 0)
    throw OutputLost(fmt::format("{}/{}: cannot write ({}); nothing was replaced", path_, name, std::strerror(err)));
  file->commit();
}

std::string gnuplot_string(std::string_view text) {
  std::string out = "'";
  for (char c : case_format::printable(text)) {
    if (c == '\'') out += '\'';
    out += c;
  }
  return out + "'";
}

std::string gnuplot_terminal(bool png, int width, int height) {
  return fmt::format("set terminal {} size {},{}\n", png ? "pngcairo enhanced font 'sans,10'" : "svg enhanced font 'sans,12'",
                     width, height);
}

std::string draw_figure(const OutputDir& dir, const std::string& name, const std::string& script, bool png,
                        std::string& warnings) {
  dir.write(name + ".gp", script);
  const std::string image = name + (png ? ".png" : ".svg");
  const std::string messages = run_gnuplot(dir, name + ".gp", image);
  if (!messages.empty()) warnings += fmt::format("impact3d: warning: gnuplot on {}.gp: {}\n", name, messages);
  return image + "\n";
}

void require_gnuplot() {
  const int null = above_std(::open("/dev/null", O_WRONLY | O_CLOEXEC));
  const pid_t pid = spawn({"gnuplot", "--version"}, null, null, -1);
  ::close(null);
  if (pid < 0 || wait_for(pid) != 0) not_found();
}

std::string run_gnuplot(const OutputDir& dir, const std::string& script, const std::string& image) {
  // gnuplot's image comes through a pipe and is written here, so that a write that fails (a full disk)
  // is seen: gnuplot may end well having written half an image.
  const auto file = dir.replace(image);
  int out[2], err[2];
  if (::pipe2(out, O_CLOEXEC) != 0) throw UserError(fmt::format("cannot run gnuplot ({})", std::strerror(errno)));
  if (::pipe2(err, O_CLOEXEC) != 0) {
    const int e = errno;
    ::close(out[0]), ::close(out[1]);
    throw UserError(fmt::format("cannot run gnuplot ({})", std::strerror(e)));
  }
  for (int* fd : {&out[0], &out[1], &err[0], &err[1]}) *fd = above_std(*fd);
  const pid_t pid = spawn({"gnuplot", script}, out[1], err[1], dir.fd());
  const int spawn_errno = errno;
  ::close(out[1]);
  ::close(err[1]);
  if (pid < 0) {
    ::close(out[0]), ::close(err[0]);
    if (spawn_errno == ENOENT) not_found();
    throw UserError(fmt::format("cannot run gnuplot ({})", std::strerror(spawn_errno)));
  }
  std::string messages;
  int write_error = 0;
  char buf[1 << 16];
  pollfd fds[2] = {{out[0], POLLIN, 0}, {err[0], POLLIN, 0}};
  for (int open = 2; open > 0;) {
    if (::poll(fds, 2, -1) < 0) {
      if (errno == EINTR) continue;
      break;
    }
    for (pollfd& p : fds) {
      if (p.fd < 0 || !(p.revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t n = ::read(p.fd, buf, sizeof buf);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        ::close(p.fd);
        p.fd = -1;
        --open;
        continue;
      }
      const std::string_view got(buf, static_cast<std::size_t>(n));
      if (p.fd == out[0]) {
        if (!write_error) write_error = write_all(file->fd(), got);  // the rest is read and dropped
      } else if (messages.size() < kMessageBytes) {
        messages.append(got);
      }
    }
  }
  for (const pollfd& p : fds)
    if (p.fd >= 0) ::close(p.fd);
  const int status = wait_for(pid);
  if (status != 0)
    throw UserError(fmt::format("gnuplot failed on {} (exit status {}): {}", script, status, summary_line(messages)));
  if (write_error)
    throw OutputLost(fmt::format("{}/{}: cannot write ({}); nothing was replaced", dir.path(), image, std::strerror(write_error)));
  file->commit();
  return summary_line(messages);
}

}  // namespace impact3d::cli
