// impact3d compare: it passes what matches, names what does not, and reads the documented CSV.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"

namespace fs = std::filesystem;
using namespace impact3d::test;

namespace {

const fs::path kWork = fs::temp_directory_path() / fmt::format("impact3d-compare-{}", ::getpid());
const std::string kReference = std::string(IMPACT3D_REFERENCE_DIR) + "/fig8_side_impact.json";

nlohmann::json reference() {
  std::ifstream in(kReference);
  return nlohmann::json::parse(in);
}

std::string write(const std::string& name, const std::string& text) {
  fs::create_directories(kWork);
  const auto p = kWork / name;
  std::ofstream(p) << text;
  return p.string();
}

}  // namespace

TEST_CASE("the reference against itself passes", "[compare]") {
  const Run r = run_cli(fmt::format("compare '{}' '{}'", kReference, kReference));
  CHECK(r.status == 0);
  CHECK((r.out + r.err).find("1 of 1 cases pass") != std::string::npos);
}

TEST_CASE("a perturbed field fails and is named", "[compare]") {
  auto doc = reference();
  const double pn = doc["results"][1]["impulse"]["contact"][0].get<double>();
  doc["results"][1]["impulse"]["contact"][0] = pn * (1 + 1e-6);
  const Run r = run_cli(fmt::format("compare '{}' '{}' --rtol 1e-9", kReference, write("fig8_side_impact.json", doc.dump())));
  CHECK(r.status == 1);
  CHECK((r.out + r.err).find("FAIL fig8_side_impact: results.1.impulse.contact.0") != std::string::npos);
  // The same file passes when the tolerance admits the change.
  CHECK(run_cli(fmt::format("compare '{}' '{}' --rtol 1e-5", kReference, (kWork / "fig8_side_impact.json").string())).status == 0);
}

TEST_CASE("a field the contract requires is missing: fail", "[compare]") {
  auto doc = reference();
  doc["results"][0]["energy"].erase("loss");
  const Run r = run_cli(fmt::format("compare '{}' '{}'", kReference, write("missing.json", doc.dump())));
  CHECK(r.status == 1);
  CHECK((r.out + r.err).find("results.0.energy.loss: missing") != std::string::npos);
}

TEST_CASE("CSV with case, result and path columns", "[compare]") {
  const auto doc = reference();
  const auto& r0 = doc["results"][0];
  std::string csv = "case,result,regime,impulse.contact.0,impulse.contact.1,energy.loss\n";
  csv += fmt::format("fig8_side_impact,0,{},{:.17g},{:.17g},{:.17g}\n", r0["regime"].get<std::string>(),
                     r0["impulse"]["contact"][0].get<double>(), r0["impulse"]["contact"][1].get<double>(),
                     r0["energy"]["loss"].get<double>());
  const Run ok = run_cli(fmt::format("compare '{}' '{}'", kReference, write("tool.csv", csv)));
  CHECK(ok.status == 0);
  CHECK((ok.out + ok.err).find("fig8_side_impact") != std::string::npos);
  // A wrong regime fails.
  std::string bad = csv;
  bad.replace(bad.find(",full,"), 6, ",sliding,");
  const Run r = run_cli(fmt::format("compare '{}' '{}'", kReference, write("bad.csv", bad)));
  CHECK(r.status == 1);
  CHECK((r.out + r.err).find("results.0.regime") != std::string::npos);
}
