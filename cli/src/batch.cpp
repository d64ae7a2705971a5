// `impact3d batch`: the input is read in blocks of lines, each block solved by --jobs threads and written
// in input order while the next is solved, so memory stays flat in the number of rows and output appears
// as it is done. Each row is the document `solve --format json` prints for its case, on one line, with
// "line" first; a row that cannot be read or solved becomes {"line": i, "error": "..."} and the run
// goes on. Output is written in whole rows only (row_output.hpp). SIGINT or SIGTERM stop the run: the rows
// in hand are finished and written up to the first not started, every row written is whole, and the
// summary counts them; a second signal ends the program at once.
#include "batch.hpp"

#include <fcntl.h>
#include <malloc.h>
#include <poll.h>
#include <pthread.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/json_tree.hpp"
#include "impact3d/case_format/json_writer.hpp"
#include "impact3d/case_format/limits.hpp"
#include "impact3d/case_format/read_case.hpp"
#include "impact3d/studies/precision.hpp"
#include "impact3d/case_format/result_csv.hpp"
#include "impact3d/case_format/strategy_option.hpp"
#include "impact3d/cli/batch_csv.hpp"
#include "impact3d/scalar/helper_thread.hpp"
#include "impact3d/scalar/parallel_chunks.hpp"
#include "impact3d/cli/output_file.hpp"
#include "impact3d/cli/row_output.hpp"
#include "impact3d/cli/user_error.hpp"

namespace impact3d::cli {

namespace {

// Lock-free, so the handler may set it and the workers read it.
std::atomic<int> stop_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_stop(int signal) { stop_signal = signal; }

// Threads started inside this scope block SIGINT and SIGTERM, so that a signal reaches the main thread
// and interrupts its read of the input.
class SignalsToMain {
 public:
  SignalsToMain() {
    sigset_t stop;
    sigemptyset(&stop);
    sigaddset(&stop, SIGINT);
    sigaddset(&stop, SIGTERM);
    ::pthread_sigmask(SIG_BLOCK, &stop, &saved_);
  }
  ~SignalsToMain() { ::pthread_sigmask(SIG_SETMASK, &saved_, nullptr); }
  SignalsToMain(const SignalsToMain&) = delete;
  SignalsToMain& operator=(const SignalsToMain&) = delete;

 private:
  sigset_t saved_;
};

// Rows solved between two writes: enough to keep every thread busy, few enough to bound memory (a
// block also ends at kBlockBytes of case text, since a row may be as long as a case file).
constexpr std::size_t kBlockRows = 2048;
constexpr std::size_t kBlockBytes = 32 << 20;

struct Row {
  long line;         // 1-based line number in the input
  std::string text;  // the case, or empty when too long
  bool too_long = false;
};

// Lines of a file descriptor, at most limits::kCaseFileBytes each: a longer line is skipped to its end
// and reported, not held.
class LineReader {
 public:
  explicit LineReader(int fd) : fd_(fd) {
    struct stat st {};
    regular_ = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
  }

  // The next non-blank line; false at the end of the input.
  bool next(Row& row) {
    for (;;) {
      std::string text;
      bool too_long = false, any = false;
      for (;;) {
        if (pos_ == len_ && !fill()) break;
        any = true;
        const char* start = buf_ + pos_;
        const void* nl = std::memchr(start, '\n', len_ - pos_);
        const std::size_t n = nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - start) : len_ - pos_;
        if (!too_long && text.size() + n > case_format::limits::kCaseFileBytes) too_long = true, text.clear(), text.shrink_to_fit();
        if (!too_long) text.append(start, n);
        pos_ += n;
        if (nl) {
          ++pos_;
          break;
        }
      }
      if (!any || stopped_) return false;  // at the end, or stopped inside a line: no partial row
      ++line_;
      if (!too_long && text.find_first_not_of(" \t\r") == std::string::npos) continue;  // blank: not a case
      row = {line_, std::move(text), too_long};
      return true;
    }
  }
  long lines() const { return line_; }
  // True when the next line is whole in hand, or the input is a regular file: reading it cannot wait
  // for a writer in the middle of a line.
  bool line_ready() const { return regular_ || std::memchr(buf_ + pos_, '\n', len_ - pos_) != nullptr; }
  // True when reading would not wait for a writer: bytes in hand, or the descriptor has some or is at
  // its end (a regular file always is).
  bool ready() const {
    if (pos_ < len_) return true;
    pollfd p{fd_, POLLIN, 0};
    return ::poll(&p, 1, 0) != 0;
  }
  std::uint64_t bytes() const { return consumed_; }

 private:
  bool fill() {
    for (;;) {
      const ssize_t n = ::read(fd_, buf_, sizeof buf_);
      if (n < 0 && errno == EINTR) {
        if (stop_signal) return !(stopped_ = true);
        continue;
      }
      if (n < 0) throw UserError(fmt::format("batch: cannot read the input ({})", std::strerror(errno)));
      pos_ = 0;
      len_ = static_cast<std::size_t>(n);
      consumed_ += len_;
      return n > 0;
    }
  }
  int fd_;
  char buf_[1 << 16];
  std::size_t pos_ = 0, len_ = 0;
  long line_ = 0;
  std::uint64_t consumed_ = 0;
  bool stopped_ = false;
  bool regular_ = false;
};

std::string error_record(long line, const std::string& problem) {
  return fmt::format("{{\"line\": {}, \"error\": {}}}\n", line, case_format::JsonWriter::quote(case_format::printable(problem)));
}

// A row's output: `head`, then `text` from byte `from`. A JSON Lines result is its document with
// "line" first: the key goes out in front of the document's text, which then starts after its '{', so
// that the 4 KB of text are not moved to make room for it.
struct Solved {
  std::string text;
  bool ok = false;
  bool internal = false;  // a defect of impact3d, not of the row: the run's status is 3
  std::array<char, 32> head{};
  std::size_t head_size = 0, from = 0;
};

Solved with_line(std::string doc, long line) {
  if (doc.empty() || doc.front() != '{') throw std::logic_error("the result document is not an object");
  Solved s{std::move(doc), true};
  const auto written = fmt::format_to_n(s.head.data(), s.head.size(), "{{\"line\": {}, ", line);
  s.head_size = written.size;
  s.from = 1;
  return s;
}

// How rows are read and written: the CSV header's columns when the input is CSV, and the output format.
struct Formats {
  const csv::CaseColumns* columns = nullptr;  // null: JSON Lines in
  bool csv_out = false;
  studies::PrecisionChoice precision;  // --precision, parsed once
};

std::string rejected_row(long line, const std::string& problem, const Formats& f) {
  return f.csv_out ? case_format::result_csv_error(line, problem) : error_record(line, problem);
}

// The result document as the output wants it: one JSON line with "line" first, or CSV rows.
Solved answer(const case_format::CaseSpec& spec, const BatchOptions& o, long line, const Formats& f) {
  case_format::RenderOptions ro;
  ro.format = case_format::Format::jsonl;
  ro.engine = o.engine;
  if (!f.csv_out) return with_line(studies::render(spec, f.precision, ro), line);
  ro.format = case_format::Format::csv;
  ro.line = line;
  return {studies::render(spec, f.precision, ro), true};
}

Solved solve_row(const Row& row, const BatchOptions& o, const std::vector<case_format::StrategySpec>& strategies, const Formats& f) {
  if (row.too_long)
    return {rejected_row(row.line, fmt::format("$: larger than {} bytes, the limit for this input", case_format::limits::kCaseFileBytes), f),
            false};
  try {
    case_format::CaseSpec spec = f.columns ? f.columns->case_spec(row.text) : case_format::read_case(row.text);
    if (!strategies.empty()) spec.strategies = strategies;
    try {
      return answer(spec, o, row.line, f);
    } catch (const SolveError& e) {
      throw case_format::no_solution(spec, e);
    }
  } catch (const case_format::CaseError& e) {
    return {rejected_row(row.line, e.line(), f), false};
  } catch (const Irrational& e) {
    return {rejected_row(row.line, std::string("$: ") + e.what(), f), false};
  } catch (const std::exception& e) {
    return {rejected_row(row.line, std::string("$: internal error: ") + e.what(), f), false, true};
  }
}

bool csv_input(const BatchOptions& o) {
  if (o.input_format != "auto") return o.input_format == "csv";
  return o.input.size() > 4 && o.input.compare(o.input.size() - 4, 4, ".csv") == 0;
}

int open_input(const std::string& path) {
  if (path == "-") return STDIN_FILENO;
  // No blocking on a FIFO without a writer: opened non-blocking, then made blocking to read.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd < 0) throw UserError(fmt::format("{}: cannot read the file ({})", path, std::strerror(errno)));
  struct stat st {};
  if (::fstat(fd, &st) != 0 || S_ISDIR(st.st_mode)) {
    ::close(fd);
    throw UserError(fmt::format("{}: cannot read the file (a directory)", path));
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  return fd;
}

// The first `n` rows' texts in order (their head and document pieces, not copied here).
bool write_rows(RowOutput& output, const std::vector<Solved>& rows, std::size_t n) {
  std::vector<iovec> iov;
  iov.reserve(2 * n);
  for (std::size_t j = 0; j < n; ++j) {
    const Solved& r = rows[j];
    if (r.head_size) iov.push_back({const_cast<char*>(r.head.data()), r.head_size});
    iov.push_back({const_cast<char*>(r.text.data()) + r.from, r.text.size() - r.from});
  }
  return output.write(iov);
}

class Progress {
 public:
  Progress(bool shown, std::uint64_t total_bytes) : shown_(shown), total_(total_bytes) {}
  void update(long rows, std::uint64_t bytes) {
    if (!shown_) return;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double rate = seconds > 0 ? rows / seconds : 0;
    std::string left;
    if (total_ > 0 && bytes > 0 && bytes <= total_)
      left = fmt::format(", {:.0f} s left", seconds * static_cast<double>(total_ - bytes) / static_cast<double>(bytes));
    std::fprintf(stderr, "\rimpact3d: batch: %ld rows, %.0f rows/s%s   ", rows, rate, left.c_str());
  }
  void finish() {
    if (shown_) std::fputs("\r\033[K", stderr);
  }

 private:
  bool shown_;
  std::uint64_t total_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace

int batch(const BatchOptions& o) {
  std::vector<case_format::StrategySpec> strategies;
  if (o.strategies.size() > case_format::limits::kStrategies)
    throw case_format::CaseError("--strategy", fmt::format("more than {} strategies", case_format::limits::kStrategies));
  for (std::size_t i = 0; i < o.strategies.size(); ++i)
    strategies.push_back(case_format::read_strategy_option(o.strategies[i], static_cast<int>(i)));
  const unsigned jobs = o.jobs ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  // Every block allocates and frees the same few megabytes: kept by the allocator rather than handed
  // back to the system and faulted in again.
  ::mallopt(M_TRIM_THRESHOLD, 256 << 20);
  ::mallopt(M_MMAP_THRESHOLD, 64 << 20);

  const int in = open_input(o.input);
  struct stat st {};
  const std::uint64_t total = ::fstat(in, &st) == 0 && S_ISREG(st.st_mode) ? static_cast<std::uint64_t>(st.st_size) : 0;
  // A file is written beside its name and renamed over it when the run ends well or is interrupted (the
  // rows written are whole); a run whose output failed leaves the old file (output_file.hpp).
  std::optional<OutputFile> file;
  if (!o.output.empty() && o.output != "-") file.emplace(o.output);
  const int out = file ? file->fd() : STDOUT_FILENO;
  struct sigaction sa {};
  sa.sa_handler = on_stop;
  sa.sa_flags = SA_RESETHAND;  // a second signal ends the program at once
  sigemptyset(&sa.sa_mask);
  ::sigaction(SIGINT, &sa, nullptr);
  ::sigaction(SIGTERM, &sa, nullptr);
  std::signal(SIGPIPE, SIG_IGN);

  LineReader reader(in);
  bool output_lost = false, internal = false;
  Formats formats;
  formats.csv_out = o.format == "csv";
  formats.precision = studies::parse_precision(o.precision);
  std::optional<csv::CaseColumns> columns;
  if (csv_input(o)) {  // the first line that is not blank is the header
    Row header;
    if (reader.next(header)) {
      const std::string name = o.input == "-" ? "standard input" : o.input;
      if (header.too_long) throw UserError(fmt::format("{}: the header is longer than {} bytes", name, case_format::limits::kCaseFileBytes));
      try {
        columns.emplace(header.text);
      } catch (const case_format::CaseError& e) {
        throw case_format::CaseError(name + ": line " + std::to_string(header.line) + ": " + e.path, e.what());
      }
      formats.columns = &*columns;
    }
  }
  RowOutput output(out, file && file->replaces());
  if (formats.csv_out) {
    const std::string header = case_format::result_csv_header();
    const iovec piece{const_cast<char*>(header.data()), header.size()};
    if (!output.write({&piece, 1})) output_lost = true;
  }
  // Not over rows being written to the same terminal.
  Progress progress(::isatty(STDERR_FILENO) == 1 && ::isatty(out) != 1, total);
  long read = 0, solved = 0, rejected = 0;
  std::vector<Row> rows;
  std::vector<char> done;
  // A block's rows are written by another thread (row_output.hpp), while the next block
  // is solved.
  std::vector<Solved> results, writing;
  std::size_t to_write = 0;
  bool wrote = true;  // the last write all went out
  // The next block is read by this thread while the others solve the current one (with --jobs 2 or
  // more), as far as whole lines are in hand: the current block's answers never wait for a slow
  // producer. A read error there is kept until the current block is written. Rows read ahead when a
  // stop comes were not started, and are not counted, as the rows of a block not yet reached.
  std::vector<Row> ahead;
  std::exception_ptr ahead_error;
  auto read_block = [&](std::vector<Row>& into, bool wait) {
    into.clear();
    std::size_t bytes = 0;
    Row row;
    // A block also ends when the input would keep it waiting, so that a slow producer (cases piped one
    // at a time) gets each answer as soon as it is solved.
    auto more = [&] { return wait ? into.empty() || reader.ready() : reader.line_ready(); };
    while (into.size() < kBlockRows && bytes < kBlockBytes && !stop_signal && more() && reader.next(row)) {
      bytes += row.text.size();
      into.push_back(std::move(row));
    }
  };
  fill_shared_before_threads();  // before the first thread starts (thread_caches.hpp)
  // Declared after everything their tasks read, so that leaving early finishes the tasks first; the
  // writer made at once, the solvers as blocks first need them, all with the signals left to this
  // thread.
  const std::unique_ptr<HelperThread> writer_thread = [] {
    const SignalsToMain mask;
    return std::make_unique<HelperThread>();
  }();
  ParallelChunks solvers(jobs, [](const std::function<void()>& make) {
    const SignalsToMain mask;
    make();
  });
  auto wait_write = [&] {
    writer_thread->wait();
    if (!wrote) output_lost = true;
  };
  while (!stop_signal && !output_lost) {
    if (ahead_error) std::rethrow_exception(ahead_error);
    if (ahead.empty()) read_block(rows, true);
    else std::swap(rows, ahead), ahead.clear();
    if (rows.empty()) break;
    results.assign(rows.size(), {});
    done.assign(rows.size(), 0);
    // The rows of the block go to whichever thread asks next; a stop leaves those not yet started.
    ParallelChunks::Caller reader_ahead;
    reader_ahead.first = [&](unsigned helpers) {
      if (helpers == 0) return;
      try {
        read_block(ahead, false);
      } catch (...) {
        ahead_error = std::current_exception();
      }
    };
    solvers.run(rows.size(), 1, [&](unsigned, std::size_t i, std::size_t) {
      if (stop_signal) return;
      results[i] = solve_row(rows[i], o, strategies, formats);
      done[i] = 1;
    }, reader_ahead);
    std::size_t written = 0;
    for (; written < rows.size() && done[written]; ++written) {  // the finished rows before the first not
      ++(results[written].ok ? solved : rejected);
      internal = internal || results[written].internal;
    }
    read += static_cast<long>(written);
    wait_write();
    if (output_lost) break;
    std::swap(results, writing);
    to_write = written;
    writer_thread->start([&] { wrote = write_rows(output, writing, to_write); });
    progress.update(read, reader.bytes());
  }
  wait_write();
  progress.finish();
  if (in != STDIN_FILENO) ::close(in);
  int lost_errno = output.error();
  std::string why;
  if (file && !output_lost) {
    try {
      file->commit();
    } catch (const UserError& e) {
      output_lost = true;
      lost_errno = 0;
      why = fmt::format(" (the output could not be written: {})", e.what());
    }
  }
  if (stop_signal) why = " (interrupted: the rows written are whole)";
  else if (output_lost && lost_errno == EPIPE) why = " (the output was closed)";
  else if (output_lost && lost_errno) why = fmt::format(" (the output could not be written: {}{})", std::strerror(lost_errno),
                                                         file && file->replaces() ? "; nothing was replaced" : "");
  std::fprintf(stderr, "impact3d: batch: %ld rows read, %ld solved, %ld rejected%s\n", read, solved, rejected, why.c_str());
  if (stop_signal) return 128 + stop_signal;
  if (output_lost || internal) return 3;
  return rejected ? 1 : 0;
}

}  // namespace impact3d::cli
