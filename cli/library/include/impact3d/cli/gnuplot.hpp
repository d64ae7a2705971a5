// gnuplot run without a shell: an argument vector, the output directory as its working directory, and
// its output files created exclusively, so that no text from a case or the command line is ever read as
// a command and no planted link is followed.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "impact3d/cli/output_file.hpp"

namespace impact3d::cli {

// An open output directory; every file is created in it by name (a plain file name, no '/'), through a
// temporary file renamed over the name when complete (output_file.hpp).
class OutputDir {
 public:
  explicit OutputDir(const std::string& path);  // creates it when missing; throws UserError
  ~OutputDir();
  OutputDir(const OutputDir&) = delete;
  OutputDir& operator=(const OutputDir&) = delete;

  // Replaces a file or a link of that name (never followed) with a new file holding `text`; refuses to
  // replace anything else (a directory, a device, a FIFO).
  void write(const std::string& name, std::string_view text) const;
  // The same, for a file another program writes through the replacement's descriptor.
  std::unique_ptr<Replacement> replace(const std::string& name) const;
  int fd() const { return fd_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_;
};

// A gnuplot single-quoted string holding `text` as data: control characters escaped (printable()),
// quotes doubled. gnuplot substitutes neither backquotes nor macros inside single quotes.
std::string gnuplot_string(std::string_view text);

// Runs `gnuplot SCRIPT` in `dir`, its standard output into the new file `image`. Returns gnuplot's
// messages (empty when it had none). Throws UserError when gnuplot is missing or fails, with its first
// message line escaped.
std::string run_gnuplot(const OutputDir& dir, const std::string& script, const std::string& image);

// The `set terminal` line of every figure: cairo's antialiased PNG (dash styles kept), or SVG.
std::string gnuplot_terminal(bool png, int width, int height);

// Writes NAME.gp holding `script` and runs it into NAME.png or NAME.svg; returns that image's name and a
// line end. gnuplot's messages, if any, are added to `warnings` as one line naming the script.
std::string draw_figure(const OutputDir& dir, const std::string& name, const std::string& script, bool png,
                        std::string& warnings);

// Throws UserError when no gnuplot can be started.
void require_gnuplot();

}  // namespace impact3d::cli
