// A case as Python holds it, and the errors Python sees: the CLI's one-line messages.
#pragma once

#include <stdexcept>
#include <string>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/mechanics/strategy.hpp"

namespace impact3d::python {

// The most threads a call may ask for, as the CLI's --jobs.
inline constexpr unsigned kMaxJobs = 1024;

struct Case {
  case_format::CaseSpec spec;   // read and checked
  std::string text;    // as read: montecarlo and sensitivity read it again
  std::string source;  // the file it came from, named first in messages; empty for a dict
};

// Bad input, as the CLI words it: "FILE: $.path: problem" (Python: impact3d.CaseError, a ValueError).
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The CLI's line for a problem `line` of the input `source` (named first unless the line names it, or
// is about an option).
std::string cli_line(const std::string& source, const std::string& line);

// Runs `body`, with the library's bad-input exceptions (CaseError, SolveError) as InputError about
// `source`, worded as the CLI words them.
template <typename F>
auto guarded(const std::string& source, F&& body) -> decltype(body()) {
  try {
    return body();
  } catch (const case_format::CaseError& e) {
    throw InputError(cli_line(source, e.line()));
  } catch (const SolveError& e) {
    throw InputError(cli_line(source, std::string("no solution: ") + e.what()));
  }
}

Case read_case_file(const std::string& path);
// `text`: a case as JSON; `source`: what messages call it (empty: nothing).
Case read_case_text(const std::string& text, const std::string& source);

}  // namespace impact3d::python
