// impact3d compare on named inputs: it passes what matches, names what does not, reads the documented
// CSV, never passes on what it did not compare, and answers hostile input with one error line.
//
// Where the expected answers come from: the reference results in verification/reference (32 cases, so
// "N of 32 cases pass"), compared with themselves (a pass) or with copies altered here in one named field
// (a failure naming that field); the rules are docs/verification-and-compare.md's (compare's pass rule,
// what --subset and a CSV must hold, a comparison of nothing fails), the wording of the report lines
// (`FAIL case: field`, `N of M cases pass`, `subset: ...`) is compare's own output, pinned here; the exit
// policy is docs/limits-and-exit-status.md's ("Exit status": 1 with one `impact3d: error:` line and nothing on stdout for bad input, 1
// with the report on stdout and nothing on stderr for a failed comparison).
#include <catch2/catch.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"

namespace exam_compare {

namespace fs = std::filesystem;
using namespace impact3d::test;

namespace {

const fs::path kWork = fresh_directory("impact3d-compare");
const std::string kReferenceDir = IMPACT3D_REFERENCE_DIR;
const std::string kReference = kReferenceDir + "/fig8_side_impact.json";

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

// A directory of result files holding fig8 only.
std::string one_case_dir() {
  fs::create_directories(kWork / "one");
  fs::copy_file(kReference, kWork / "one" / "fig8_side_impact.json", fs::copy_options::overwrite_existing);
  return (kWork / "one").string();
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Bad input: exit 1, nothing on stdout, exactly one line on stderr, which names `names`.
void check_one_error(const Run& r, const std::string& names) {
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  CHECK(r.status == 1);
  CHECK(r.out.empty());
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(r.err.rfind("impact3d: error: ", 0) == 0);
  CHECK(has(r.err, names));
}

// A failing comparison (not an error): exit 1, the report on stdout, nothing on stderr.
void check_fails(const Run& r) {
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  CHECK(r.status == 1);
  CHECK(r.err.empty());
}

// The table row of `name`.
std::string row_of(const std::string& out, const std::string& name) {
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(name + " ", 0) == 0) return line;
  return "";
}

// A result's scalars by dotted path, written as a tool would write them in a CSV.
void flatten(const nlohmann::json& v, const std::string& path, std::map<std::string, std::string>& out) {
  if (v.is_object())
    for (const auto& [k, x] : v.items()) flatten(x, path.empty() ? k : path + "." + k, out);
  else if (v.is_array())
    for (std::size_t i = 0; i < v.size(); ++i) flatten(v[i], path + "." + std::to_string(i), out);
  else if (v.is_string()) out[path] = v.get<std::string>();
  else if (v.is_number_float()) out[path] = fmt::format("{:.17g}", v.get<double>());
  else if (!v.is_null()) out[path] = v.dump();
}

// A CSV of the contract's fields for some results of some reference cases (files in kReferenceDir).
std::string contract_csv(const std::vector<std::pair<std::string, std::vector<int>>>& cases) {
  const std::vector<std::string> contract = {"regime", "impulse_ratio", "limits", "impulse", "relative_velocity",
                                             "energy"};
  std::vector<std::pair<std::string, std::map<std::string, std::string>>> rows;
  std::vector<std::string> columns;
  for (const auto& [name, results] : cases) {
    std::ifstream in(kReferenceDir + "/" + name + ".json");
    const auto doc = nlohmann::json::parse(in);
    for (int i : results) {
      std::map<std::string, std::string> cells;
      flatten(doc["coefficients"]["m_prime"], "coefficients.m_prime", cells);
      flatten(doc["coefficients"]["K"], "coefficients.K", cells);
      const auto& r = doc["results"][i];
      for (const auto& key : contract) flatten(r[key], key, cells);
      for (const char* v : {"0", "1"})
        for (const char* q : {"velocity", "angular_velocity", "delta_v"})
          flatten(r["vehicles"][std::stoi(v)][q], fmt::format("vehicles.{}.{}", v, q), cells);
      for (const auto& [c, _] : cells)
        if (std::find(columns.begin(), columns.end(), c) == columns.end()) columns.push_back(c);
      rows.push_back({fmt::format("{},{}", name, i), std::move(cells)});
    }
  }
  std::string csv = "case,result";
  for (const auto& c : columns) csv += "," + c;
  csv += "\n";
  for (const auto& [key, cells] : rows) {
    csv += key;
    for (const auto& c : columns) csv += "," + (cells.count(c) ? cells.at(c) : "");
    csv += "\n";
  }
  return csv;
}

}  // namespace

TEST_CASE("the reference against itself passes", "[compare]") {
  const Run r = run_cli(fmt::format("compare '{}' '{}'", kReference, kReference));
  CHECK(r.status == 0);
  CHECK((r.out + r.err).find("1 of 1 cases pass") != std::string::npos);
}

TEST_CASE("a tolerance that is not a finite number from 0 is a usage error", "[compare]") {
  // CLI11's range lets a NaN through: each text is checked before it is converted.
  for (const std::string bad : {"--rtol nan", "--atol nan", "--rtol -nan", "--rtol inf", "--atol -1", "--rtol 1e301", "--rtol x"}) {
    const Run r = run_cli(fmt::format("compare '{}' '{}' {}", kReference, kReference, bad));
    INFO(bad << ": " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find("must be a finite number from 0 to 1e300") != std::string::npos);
  }
  CHECK(run_cli(fmt::format("compare '{}' '{}' --rtol 0 --atol 1e-12", kReference, kReference)).status == 0);
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

TEST_CASE("a failing case's row names its failure even when no number is off", "[compare]") {
  auto doc = reference();
  doc["results"][2]["regime"] = "full";
  const Run r = run_cli(fmt::format("compare '{}' '{}'", kReference, write("regime.json", doc.dump())));
  check_fails(r);
  CHECK(has(row_of(r.out, "fig8_side_impact"), "results.2.regime: reference \"sliding\", other \"full\""));
}

TEST_CASE("CSV with case, result and path columns", "[compare]") {
  const auto doc = reference();
  const auto& r0 = doc["results"][0];
  std::string csv = "case,result,regime,impulse.contact.0,impulse.contact.1,energy.loss\n";
  csv += fmt::format("fig8_side_impact,0,{},{:.17g},{:.17g},{:.17g}\n", r0["regime"].get<std::string>(),
                     r0["impulse"]["contact"][0].get<double>(), r0["impulse"]["contact"][1].get<double>(),
                     r0["energy"]["loss"].get<double>());
  // A few columns of one result: a subset, and said to be one.
  const Run ok = run_cli(fmt::format("compare '{}' '{}' --subset", kReference, write("tool.csv", csv)));
  CHECK(ok.status == 0);
  CHECK(has(ok.out, "fig8_side_impact"));
  CHECK(has(ok.out, "subset: 4 of "));
  // A wrong regime fails, and the case's row names it although no number is off.
  std::string bad = csv;
  bad.replace(bad.find(",full,"), 6, ",sliding,");
  const Run r = run_cli(fmt::format("compare '{}' '{}' --subset", kReference, write("bad.csv", bad)));
  check_fails(r);
  CHECK(has(r.out, "FAIL fig8_side_impact: results.0.regime: reference \"full\", other \"sliding\""));
  CHECK(has(row_of(r.out, "fig8_side_impact"), "results.0.regime: reference \"full\", other \"sliding\""));
}

TEST_CASE("a complete CSV passes without --subset", "[compare]") {
  const Run r = run_cli(fmt::format("compare '{}' '{}'", kReference,
                                    write("complete.csv", contract_csv({{"fig8_side_impact", {0, 1, 2, 3}}}))));
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  CHECK(has(r.out, "1 of 1 cases pass"));
  CHECK(!has(r.out, "subset"));
}

TEST_CASE("a reference nested 100000 deep is one error line, not a crash", "[compare]") {
  const std::string deep = "{\"results\": [" + std::string(100000, '[') + std::string(100000, ']') + "]}";
  const std::string file = write("deep.json", deep);
  check_one_error(run_cli(fmt::format("compare '{}' '{}'", file, kReference)), "deep.json: $.results[0]");
  // The other side nested as deep: the same.
  check_one_error(run_cli(fmt::format("compare '{}' '{}'", kReference, file)), "deep.json: $.results[0]");
  // Below a key compared beyond the contract, against itself (once a stack overflow).
  const std::string field = write("deep_field.json", "{\"results\": [{\"sliding\": " + std::string(100000, '[') +
                                                           std::string(100000, ']') + "}]}");
  check_one_error(run_cli(fmt::format("compare '{}' '{}'", field, field)), "deep_field.json: $.results[0].sliding");
}

TEST_CASE("a result cell that is not an index of the case's results is a row and column error", "[compare]") {
  for (const std::string cell : {"100000000", "-1", "abc", "4"}) {
    const std::string file = write("index.csv", "case,result,regime\nfig8_side_impact,0,full\nfig8_side_impact," + cell + ",full\n");
    const auto start = std::chrono::steady_clock::now();
    const Run r = run_cli(fmt::format("compare '{}' '{}'", kReference, file));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    INFO(cell);
    check_one_error(r, fmt::format("index.csv: row 3, column result: expected a result index from 0 to 3, got \"{}\"", cell));
    CHECK(seconds < 10);
  }
}

TEST_CASE("a column with a huge array index is an error naming it, not an allocation", "[compare]") {
  const std::string file = write("huge.csv", "case,result,regime,coefficients.K.99999999999.0\nfig8_side_impact,0,full,1\n");
  check_one_error(run_cli(fmt::format("compare '{}' '{}'", kReference, file)),
                  "huge.csv: column \"coefficients.K.99999999999.0\"");
}

TEST_CASE("a misspelt column is an error naming it, never a pass", "[compare]") {
  const auto loss = reference()["results"][0]["energy"]["loss"].get<double>();
  const std::string file = write("misspelt.csv", fmt::format("case,result,energy.los\nfig8_side_impact,0,{:.17g}\n", loss));
  check_one_error(run_cli(fmt::format("compare '{}' '{}' --subset", kReference, file)), "misspelt.csv: column \"energy.los\"");
  check_one_error(run_cli(fmt::format("compare '{}' '{}'", kReference, file)), "misspelt.csv: column \"energy.los\"");
}

TEST_CASE("without --subset every case, result and contract field must be there", "[compare]") {
  // Two of fig8's four results and no other case.
  const std::string csv = write("partial.csv", contract_csv({{"fig8_side_impact", {0, 1}}}));
  const Run r = run_cli(fmt::format("compare '{}' '{}'", kReferenceDir, csv));
  check_fails(r);
  CHECK(has(row_of(r.out, "general_1"), "case missing"));
  CHECK(has(r.out, "FAIL general_1: case missing"));
  CHECK(has(r.out, "FAIL fig8_side_impact: results.2: missing"));
  CHECK(has(r.out, "FAIL fig8_side_impact: results.3: missing"));
  CHECK(has(r.out, "0 of 32 cases pass"));
  // A directory of result files with one case: the others are missing.
  const Run d = run_cli(fmt::format("compare '{}' '{}'", kReferenceDir, one_case_dir()));
  check_fails(d);
  CHECK(has(d.out, "FAIL general_1: case missing"));
  CHECK(has(d.out, "1 of 32 cases pass"));
  // The coverage line counts what was given: 1 of 32 cases, 2 of its 4 results.
  CHECK(has(r.out, "coverage: 1 of 32 reference cases, 2 of "));
  // A CSV row for one result of four: the other three are missing, each by name.
  const Run f = run_cli(fmt::format("compare '{}' '{}'", kReference,
                                    write("one_row.csv", "case,result,regime\nfig8_side_impact,0,full\n")));
  check_fails(f);
  for (int i : {1, 2, 3}) CHECK(has(f.out, fmt::format("FAIL fig8_side_impact: results.{}: missing (no row)", i)));
  CHECK(has(f.out, "coverage: 1 of 1 reference cases, 1 of 4 results given"));
}

TEST_CASE("a CSV is compared on the columns it has, and the report names them with their counts", "[compare]") {
  // One component of one vector, for every result: passes, compares 4 values and says which.
  const auto doc = reference();
  std::string csv = "case,result,relative_velocity.after.1\n";
  for (int i = 0; i < 4; ++i)
    csv += fmt::format("fig8_side_impact,{},{:.17g}\n", i, doc["results"][i]["relative_velocity"]["after"][1].get<double>());
  const Run r = run_cli(fmt::format("compare '{}' '{}'", kReference, write("one_column.csv", csv)));
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  CHECK(!has(r.out, "FAIL"));
  CHECK(has(r.out, "fields compared: 4 values in the CSV's 1 column (only these;"));
  CHECK(has(r.out, "relative_velocity.after.1 x4"));
  // An empty cell in that column is a missing value of a field the CSV claims.
  std::string holed = csv;
  holed.replace(holed.find("fig8_side_impact,2,"), holed.find('\n', holed.find("fig8_side_impact,2,")) - holed.find("fig8_side_impact,2,"),
                "fig8_side_impact,2,");
  const Run h = run_cli(fmt::format("compare '{}' '{}'", kReference, write("holed.csv", holed)));
  check_fails(h);
  CHECK(has(h.out, "FAIL fig8_side_impact: results.2.relative_velocity.after.1: missing (an empty cell"));
}

namespace {

// The reference fig8 file with `change` applied to every number below the paths given, in every result.
std::string altered(const std::vector<std::string>& keys, const std::function<void(nlohmann::json&, const std::string&)>& change) {
  auto doc = reference();
  for (auto& r : doc["results"])
    for (const auto& k : keys) change(r, k);
  return write("altered.json", doc.dump());
}

void scale_numbers(nlohmann::json& v, double f) {
  if (v.is_number_float() || v.is_number_integer()) v = v.get<double>() * f;
  else if (v.is_object() || v.is_array())
    for (auto& x : v) scale_numbers(x, f);
}

}  // namespace

TEST_CASE("compare diagnoses an opposite sign convention, exchanged vehicles and a unit factor", "[compare]") {
  // Opposite convention: the impulse, the relative velocities and the vehicles' changes negated.
  const Run neg = run_cli(fmt::format("compare '{}' '{}'", kReference,
                                      altered({"impulse", "relative_velocity"}, [](nlohmann::json& r, const std::string& k) {
                                        scale_numbers(r[k], -1);
                                      })));
  check_fails(neg);
  CHECK(has(neg.out, "diagnosis: "));
  CHECK(has(neg.out, "failing numbers are the reference negated"));
  CHECK(has(neg.out, "the normal n points into vehicle 1"));
  // Vehicles numbered the other way: their fields exchanged, the impulse on vehicle 1 and the relative
  // velocity negated.
  const Run swapped = run_cli(fmt::format("compare '{}' '{}'", kReference,
                                          altered({"vehicles", "impulse", "relative_velocity"},
                                                  [](nlohmann::json& r, const std::string& k) {
                                                    if (k == "vehicles") std::swap(r[k][0], r[k][1]);
                                                    else scale_numbers(r[k], -1);
                                                  })));
  check_fails(swapped);
  CHECK(has(swapped.out, "failing numbers are what numbering the vehicles the other way gives"));
  // Another tool prints 6 significant digits: its negated numbers fail at rtol 1e-9 and are still seen
  // as negated.
  const Run six = run_cli(fmt::format("compare '{}' '{}'", kReference,
                                      altered({"impulse", "relative_velocity"}, [](nlohmann::json& r, const std::string& k) {
                                        scale_numbers(r[k], -(1 + 2e-7));
                                      })));
  check_fails(six);
  CHECK(has(six.out, "failing numbers are the reference negated"));
  // Velocities written in mph against an SI reference: x 1/0.44704.
  const Run mph = run_cli(fmt::format("compare '{}' '{}'", kReference,
                                      altered({"relative_velocity"}, [](nlohmann::json& r, const std::string& k) {
                                        scale_numbers(r[k], 1 / 0.44704);
                                      })));
  check_fails(mph);
  CHECK(has(mph.out, "differ from the reference by a unit factor (x 2.23694, m/s -> mph"));
  // A failure with no pattern gets no diagnosis.
  auto doc = reference();
  doc["results"][1]["impulse"]["contact"][0] = doc["results"][1]["impulse"]["contact"][0].get<double>() * 1.01;
  const Run plain = run_cli(fmt::format("compare '{}' '{}'", kReference, write("fig8_side_impact.json", doc.dump())));
  check_fails(plain);
  CHECK(!has(plain.out, "diagnosis"));
}

TEST_CASE("the summary names the worst failure whatever kind of field it is", "[compare]") {
  auto doc = reference();
  doc["results"][2]["regime"] = "full";
  doc["results"][1]["impulse"]["contact"][0] = doc["results"][1]["impulse"]["contact"][0].get<double>() * (1 + 1e-3);
  const Run r = run_cli(fmt::format("compare '{}' '{}'", kReference, write("regime_and_number.json", doc.dump())));
  check_fails(r);
  // A wrong regime outranks a number off by 1e-3: the row and the summary name it.
  CHECK(has(row_of(r.out, "fig8_side_impact"), "mismatch  results.2.regime: reference \"sliding\", other \"full\""));
  CHECK(has(r.out, "worst failure mismatch at fig8_side_impact: results.2.regime (reference \"sliding\", other \"full\")"));
  CHECK(!has(r.out, "worst relative error 0.000e+00 at -"));
  // A number alone: its relative error and field.
  auto num = reference();
  num["results"][1]["impulse"]["contact"][0] = num["results"][1]["impulse"]["contact"][0].get<double>() * (1 + 1e-3);
  const Run n = run_cli(fmt::format("compare '{}' '{}'", kReference, write("number.json", num.dump())));
  check_fails(n);
  CHECK(has(n.out, "worst failure 1.000e-03 at fig8_side_impact: results.1.impulse.contact.0"));
}

TEST_CASE("with --subset only what is given is compared, and the summary says so", "[compare]") {
  const std::string csv = write("partial.csv", contract_csv({{"fig8_side_impact", {0, 1}}}));
  const Run r = run_cli(fmt::format("compare '{}' '{}' --subset", kReferenceDir, csv));
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  CHECK(has(r.out, "1 of 1 cases pass"));
  CHECK(has(r.out, "; subset: "));
  CHECK(has(r.out, " reference fields compared"));
  CHECK(!has(r.out, "general_1"));
  const Run d = run_cli(fmt::format("compare '{}' '{}' --subset", kReferenceDir, one_case_dir()));
  CHECK(d.status == 0);
  CHECK(has(d.out, "1 of 1 cases pass"));
  CHECK(has(d.out, "; subset: "));
}

TEST_CASE("a comparison of nothing fails, even with --subset", "[compare]") {
  const std::string csv = write("empty_cells.csv", "case,result,regime,energy.loss\nfig8_side_impact,0,,\n");
  const Run r = run_cli(fmt::format("compare '{}' '{}' --subset", kReference, csv));
  check_fails(r);
  CHECK(has(r.out, "nothing was compared"));
  CHECK(has(r.out, "subset: 0 of "));
  const Run j = run_cli(fmt::format("compare '{}' '{}' --subset", kReference, write("empty.json", "{}")));
  check_fails(j);
  CHECK(has(j.out, "nothing was compared"));
}

TEST_CASE("invalid JSON in the other file is one error line naming the file", "[compare]") {
  check_one_error(run_cli(fmt::format("compare '{}' '{}'", kReference, write("broken.json", "{\"results\": [1,"))),
                  "broken.json: $");
}

TEST_CASE("a reference that is not an object with a results array is an error naming $.results", "[compare]") {
  for (const std::string text : {"{}", "[1, 2]", "{\"results\": 3}"}) {
    INFO(text);
    const Run r = run_cli(fmt::format("compare '{}' '{}'", write("not_reference.json", text), kReference));
    check_one_error(r, "not_reference.json: $.results");
    CHECK(!has(r.err, "json.exception"));
  }
}

TEST_CASE("a result of the wrong shape fails by field, not with a library message", "[compare]") {
  auto doc = reference();
  doc["results"][0]["impulse"] = nlohmann::json::array({1, 2});
  doc["results"][1] = "no result";
  const Run r = run_cli(fmt::format("compare '{}' '{}'", kReference, write("shape.json", doc.dump())));
  check_fails(r);
  CHECK(has(r.out, "FAIL fig8_side_impact: results.0.impulse.contact.0: missing"));
  CHECK(has(r.out, "FAIL fig8_side_impact: results.1: not an object"));
}

TEST_CASE("CSV rows: duplicates and ragged rows are errors, a non-finite number fails", "[compare]") {
  check_one_error(run_cli(fmt::format("compare '{}' '{}'", kReference,
                                      write("dup.csv", "case,result,regime\nfig8_side_impact,0,full\nfig8_side_impact,0,full\n"))),
                  "dup.csv: row 3: case \"fig8_side_impact\" result 0 is also in row 2");
  check_one_error(run_cli(fmt::format("compare '{}' '{}'", kReference,
                                      write("ragged.csv", "case,result,regime\nfig8_side_impact,0,full,1\n"))),
                  "ragged.csv: row 2 has 4 cells, the header 3");
  check_one_error(run_cli(fmt::format("compare '{}' '{}'", kReference,
                                      write("case.csv", "case,result,regime\nfig9,0,full\n"))),
                  "case.csv: row 2, column case: \"fig9\" is not a case of the reference");
  const Run r = run_cli(fmt::format("compare '{}' '{}' --subset", kReference,
                                    write("inf.csv", "case,result,energy.loss\nfig8_side_impact,0,inf\n")));
  check_fails(r);
  CHECK(has(r.out, "results.0.energy.loss: reference "));
  CHECK(has(r.out, ", other \"inf\": not a finite number"));
}

TEST_CASE("a value where the reference has none fails; a NUL inside a cell is not a number", "[compare]") {
  // Result 3 of fig8 is Brach with both ratios critical (eq 27): no sliding after, so the reference's swerve
  // angle is null (undefined). A tool that prints an angle there has sliding where there is none.
  const auto doc = reference();
  REQUIRE(doc["results"][3]["sliding"]["swerve_angle_deg"].is_null());
  auto other = doc;
  other["results"][3]["sliding"]["swerve_angle_deg"] = 12.5;
  const Run r = run_cli(fmt::format("compare '{}' '{}'", kReference, write("angle.json", other.dump())));
  check_fails(r);
  CHECK(has(r.out, "FAIL fig8_side_impact: results.3.sliding.swerve_angle_deg: reference null (undefined here), other 12.5"));
  // In a CSV, an empty cell or "null" agrees with a null, a number does not.
  for (const std::string cell : {"", "null"})
    CHECK(run_cli(fmt::format("compare '{}' '{}' --subset", kReference,
                              write("null.csv", "case,result,sliding.swerve_angle_deg,regime\nfig8_side_impact,3," + cell +
                                                    "," + doc["results"][3]["regime"].get<std::string>() + "\n")))
              .status == 0);
  const Run c = run_cli(fmt::format("compare '{}' '{}' --subset", kReference,
                                    write("angle.csv", "case,result,sliding.swerve_angle_deg\nfig8_side_impact,3,12.5\n")));
  check_fails(c);
  CHECK(has(c.out, "results.3.sliding.swerve_angle_deg: reference null (undefined here), other \"12.5\""));
  // "1\0junk": strtod would stop at the NUL and read 1.
  const double loss = doc["results"][0]["energy"]["loss"].get<double>();
  std::string nul = fmt::format("case,result,energy.loss\nfig8_side_impact,0,{:.17g}", loss);
  nul += std::string(1, '\0') + "junk\n";
  const Run n = run_cli(fmt::format("compare '{}' '{}' --subset", kReference, write("nul.csv", nul)));
  check_fails(n);
  CHECK(has(n.out, ": not a number"));
}

TEST_CASE("a CSV with the option --all is refused: --all asks for every field of a result file", "[compare]") {
  check_one_error(run_cli(fmt::format("compare '{}' '{}' --all", kReference,
                                      write("all.csv", "case,result,regime\nfig8_side_impact,0,full\n"))),
                  "all.csv: --all requires every field of a result file");
}

}  // namespace exam_compare
