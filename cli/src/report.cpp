#include "report.hpp"

#include <stdlib.h>

#include <filesystem>
#include <vector>

#include <fmt/format.h>

#include "impact3d/cli/gnuplot.hpp"
#include "impact3d/cli/output_file.hpp"
#include "impact3d/case_format/read_case.hpp"
#include "impact3d/studies/precision.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/cli/plot.hpp"
#include "impact3d/cli/user_error.hpp"

namespace impact3d::cli {
namespace {

namespace fs = std::filesystem;

// A private directory for the figures, removed with everything in it when done.
class ScratchDir {
 public:
  ScratchDir() {
    std::string pattern = (fs::temp_directory_path() / "impact3d-report-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw UserError("cannot create a temporary directory for the figures");
    path_ = pattern;
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

std::string read_file(const fs::path& p) { return case_format::read_text_file(p.string()); }

// The figures in reading order: the collision, the paper's views, Stronge's impact as it happens, then
// the sweeps.
std::vector<case_format::ReportFigure> figures_of(const case_format::CaseSpec& spec, const fs::path& dir) {
  std::vector<case_format::ReportFigure> out;
  const auto add = [&](const std::string& name, const std::string& caption) {
    const fs::path f = dir / (name + ".svg");
    if (fs::exists(f)) out.push_back({caption, read_file(f)});
  };
  const std::size_t n = spec.strategies.size();
  std::vector<std::string> label(n);
  for (std::size_t k = 0; k < n; ++k) label[k] = case_format::strategy_label(spec.strategies[k]);
  for (std::size_t k = 0; k < n; ++k) add(fmt::format("collision_{}", k + 1), "The collision under " + label[k] + " (Figures 1 and 5)");
  add("contact_plane", "Contact-plane view on the restitution plane (Figures 3-4, right)");
  add("impulse_space", "Impulse space (Figures 2-3, left)");
  for (std::size_t k = 0; k < n; ++k) add(fmt::format("solution_plane_{}", k + 1), "Solution plane of " + label[k] + " (Figures 4 right and 7)");
  for (std::size_t k = 0; k < n; ++k) {
    add(fmt::format("stronge_hodograph_{}", k + 1), "Hodograph of the sliding velocity through the impact, " + label[k]);
    add(fmt::format("stronge_normal_{}", k + 1), "Normal velocity and normal work against the normal impulse, " + label[k]);
    add(fmt::format("stronge_impulse_path_{}", k + 1), "Impulse path through the impact beside every strategy's impulse, " + label[k]);
  }
  for (std::size_t k = 0; k < n; ++k) add(fmt::format("sweep_mu_{}", k + 1), "Sweep over the friction ratio from " + label[k]);
  for (std::size_t k = 0; k < n; ++k) add(fmt::format("sweep_eps_{}", k + 1), "Sweep over restitution, " + label[k]);
  return out;
}

}  // namespace

std::string report(const ReportOptions& o) {
  const case_format::CaseSpec spec = case_format::read_case(case_format::read_text_file(o.case_path));
  // Opened before the work, so that none is lost to a path that cannot be written.
  OutputFile out(o.out_file);
  std::vector<case_format::ReportFigure> figures;
  std::string note;
  if (!o.figures) {
    note = "Figures left out (--no-figures).";
  } else {
    bool gnuplot = true;
    try {
      require_gnuplot();
    } catch (const UserError& e) {
      gnuplot = false;
      note = std::string("Figures left out: ") + e.what();
    }
    if (gnuplot) {
      const ScratchDir scratch;
      PlotOptions p;
      p.out_dir = scratch.path();
      p.engine = o.engine;
      p.units = o.units;
      (void)plot(spec, p);
      figures = figures_of(spec, scratch.path());
    }
  }
  case_format::RenderOptions r;
  r.format = case_format::Format::html;
  r.digits = o.digits == 0 && o.precision == "double" ? 10 : o.digits;
  r.engine = o.engine;
  r.units = o.units;
  r.figures = &figures;
  r.figures_note = note;
  const std::string page = studies::render(spec, studies::parse_precision(o.precision), r);
  out.write(page);
  out.commit();
  return o.out_file + "\n";
}

}  // namespace impact3d::cli
