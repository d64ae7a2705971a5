#include "case.hpp"

#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/read_case.hpp"

namespace impact3d::python {

std::string cli_line(const std::string& source, const std::string& line) {
  // An option's problem ("--strategy[0].mu: ...") is not the file's.
  const bool named = source.empty() || line.rfind(source + ":", 0) == 0 || line.rfind("--", 0) == 0;
  return case_format::printable(named ? line : source + ": " + line);
}

Case read_case_file(const std::string& path) {
  return guarded(path, [&] {
    Case c;
    c.text = case_format::read_text_file(path);
    c.spec = case_format::read_case(c.text);
    c.source = path;
    return c;
  });
}

Case read_case_text(const std::string& text, const std::string& source) {
  return guarded(source, [&] {
    Case c;
    c.spec = case_format::read_case(text);
    c.text = text;
    c.source = source;
    return c;
  });
}

}  // namespace impact3d::python
