// Structural validation of a case file: every rejection names the JSON path and the problem. Limits on
// numbers are checked on the exact decimal as written, the value every precision computes with.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <set>

#include <fmt/format.h>

#include "impact3d/io/case_spec.hpp"
#include "impact3d/io/decimal.hpp"
#include "impact3d/io/escape.hpp"
#include "impact3d/io/json_literals.hpp"
#include "impact3d/io/limits.hpp"
#include "impact3d/io/scalar_text.hpp"
#include "impact3d/io/strategy_kinds.hpp"
#include "impact3d/io/strategy_option.hpp"
#include "impact3d/numeric/exact.hpp"

namespace impact3d::io {
namespace {

using json = nlohmann::json;

// Larger magnitudes are no vehicle collision and would overflow energies and products of inertia;
// smaller non-zero ones would underflow double, so that precisions would disagree on the input itself.
const Decimal kMax = parse_decimal(limits::kMaxMagnitude), kMin = parse_decimal(limits::kMinMagnitude);
const Decimal kZero{}, kOne = parse_decimal("1");

Decimal decimal(const Number& n) { return parse_decimal(n.text); }

const char* type_name(const json& v) {
  switch (v.type()) {
    case json::value_t::null: return "null";
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: return "a string";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return "a number";
    default: return "an unsupported value";
  }
}

class Reader {
 public:
  explicit Reader(const ParsedJson& p) : parsed_(p) {}

  [[noreturn]] void fail(const std::string& ptr, const std::string& msg) const {
    throw CaseError(ptr, msg);
  }

  const json& object(const json& v, const std::string& ptr, std::set<std::string> allowed) const {
    if (!v.is_object()) fail(ptr, fmt::format("expected an object, got {}", type_name(v)));
    for (const auto& [k, _] : v.items()) {
      if (!k.empty() && k[0] == '_') continue;  // comments and private extensions
      if (!allowed.count(k)) fail(member_path(ptr, k), "unknown key (keys starting with '_' are ignored)");
    }
    return v;
  }

  const json* optional(const json& obj, const std::string& key) const {
    auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
  }

  const json& required(const json& obj, const std::string& ptr, const std::string& key) const {
    auto* v = optional(obj, key);
    if (!v) fail(member_path(ptr, key), "missing");
    return *v;
  }

  Number number(const json& v, const std::string& ptr) const {
    if (!v.is_number()) fail(ptr, fmt::format("expected a number, got {}", type_name(v)));
    const auto lit = parsed_.literal.find(ptr);
    Number n{lit == parsed_.literal.end() ? v.dump() : lit->second, v.get<double>(), ptr};
    if (!std::isfinite(n.value)) fail(ptr, fmt::format("not a finite number ({})", n.text));
    const Decimal d = decimal(n);
    if (compare_magnitude(d, kMax) > 0)
      fail(ptr, fmt::format("out of range: magnitude {} exceeds {:g}", n.text, std::stod(limits::kMaxMagnitude)));
    if (!d.zero() && compare_magnitude(d, kMin) < 0)
      fail(ptr, fmt::format("out of range: {} is not zero but below {:g} in magnitude", n.text, std::stod(limits::kMinMagnitude)));
    return n;
  }

  Number number_or(const json& obj, const std::string& ptr, const std::string& key) const {
    if (auto* v = optional(obj, key)) return number(*v, member_path(ptr, key));
    return Number{"0", 0.0, member_path(ptr, key)};
  }

  Number positive(const json& v, const std::string& ptr) const {
    Number n = number(v, ptr);
    if (compare(decimal(n), kZero) <= 0) fail(ptr, fmt::format("must be > 0 (got {})", n.text));
    return n;
  }

  Vector3 vector3(const json& v, const std::string& ptr) const {
    if (!v.is_array()) fail(ptr, fmt::format("expected an array of 3 numbers, got {}", type_name(v)));
    if (v.size() != 3) fail(ptr, fmt::format("expected 3 numbers, got {}", v.size()));
    return {number(v[0], element_path(ptr, 0)), number(v[1], element_path(ptr, 1)), number(v[2], element_path(ptr, 2))};
  }

  Vector3 vector3_or_zero(const json& obj, const std::string& ptr, const std::string& key) const {
    if (auto* v = optional(obj, key)) return vector3(*v, member_path(ptr, key));
    const std::string p = member_path(ptr, key);
    return {Number{"0", 0.0, p}, Number{"0", 0.0, p}, Number{"0", 0.0, p}};
  }

  std::string string(const json& v, const std::string& ptr) const {
    if (!v.is_string()) fail(ptr, fmt::format("expected a string, got {}", type_name(v)));
    return v.get<std::string>();
  }

  void inertia(VehicleSpec& veh, const json& v, const std::string& ptr) const {
    veh.inertia_path = ptr;
    const std::string zero_path = ptr;
    if (v.is_object()) {
      object(v, ptr, {"Ixx", "Iyy", "Izz"});
      const char* keys[3] = {"Ixx", "Iyy", "Izz"};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          veh.inertia[i][j] = i == j ? positive(required(v, ptr, keys[i]), member_path(ptr, keys[i]))
                                     : Number{"0", 0.0, zero_path};
      return;
    }
    if (!v.is_array() || v.size() != 3)
      fail(ptr, "expected a 3x3 tensor [[Ixx, Ixy, Ixz], ...] or {\"Ixx\", \"Iyy\", \"Izz\"}");
    for (int i = 0; i < 3; ++i) veh.inertia[i] = vector3(v[i], element_path(ptr, i));
    for (int i = 0; i < 3; ++i) {
      if (compare(decimal(veh.inertia[i][i]), kZero) <= 0)
        fail(ptr, fmt::format("not positive definite: diagonal entry [{}][{}] = {}", i, i, veh.inertia[i][i].text));
      for (int j = i + 1; j < 3; ++j)
        if (!(decimal(veh.inertia[i][j]) == decimal(veh.inertia[j][i])))
          fail(ptr, fmt::format("not symmetric: [{}][{}] = {} but [{}][{}] = {}", i, j, veh.inertia[i][j].text, j, i,
                                veh.inertia[j][i].text));
    }
    // Positive definite as written (Sylvester: the leading minors), so that every precision computes with
    // the same admissible tensor; a precision that rounds it to an indefinite one flags its results.
    rational J[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) J[i][j] = scalar_from_text<rational>(veh.inertia[i][j].text);
    const rational minor2 = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    const rational det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
    if (!(minor2 > 0) || !(det > 0)) fail(ptr, "not positive definite");
  }

  VehicleSpec vehicle(const json& v, const std::string& ptr) const {
    object(v, ptr, {"name", "mass", "inertia", "orientation_deg", "orientation_matrix", "velocity", "angular_velocity",
                    "impulse_center"});
    VehicleSpec veh;
    if (auto* n = optional(v, "name")) veh.name = string(*n, member_path(ptr, "name"));
    veh.mass = positive(required(v, ptr, "mass"), member_path(ptr, "mass"));
    inertia(veh, required(v, ptr, "inertia"), member_path(ptr, "inertia"));
    static const json empty = json::object();
    const json* o = optional(v, "orientation_deg");
    if (const json* m = optional(v, "orientation_matrix")) {
      const std::string mptr = member_path(ptr, "orientation_matrix");
      if (o) fail(mptr, "give either orientation_deg or orientation_matrix, not both");
      if (!m->is_array() || m->size() != 3) fail(mptr, "expected a 3x3 rotation matrix (rows of R_WB)");
      std::array<Vector3, 3> rows;
      for (int i = 0; i < 3; ++i) rows[i] = vector3((*m)[i], element_path(mptr, i));
      veh.orientation_matrix = rows;
      veh.orientation_path = mptr;
    }
    const std::string optr = member_path(ptr, "orientation_deg");
    if (o) object(*o, optr, {"yaw", "pitch", "roll"});
    const json& orient = o ? *o : empty;
    veh.yaw = number_or(orient, optr, "yaw");
    veh.pitch = number_or(orient, optr, "pitch");
    veh.roll = number_or(orient, optr, "roll");
    veh.velocity = vector3(required(v, ptr, "velocity"), member_path(ptr, "velocity"));
    veh.angular_velocity = vector3_or_zero(v, ptr, "angular_velocity");
    veh.impulse_center = vector3(required(v, ptr, "impulse_center"), member_path(ptr, "impulse_center"));
    return veh;
  }

  ContactSpec contact(const json& v, const std::string& ptr) const {
    object(v, ptr, {"normal_yaw_deg", "normal_pitch_deg", "tangent_roll_deg", "normal", "tangent"});
    ContactSpec c;
    c.path = ptr;
    const bool angles = optional(v, "normal_yaw_deg") || optional(v, "normal_pitch_deg") || optional(v, "tangent_roll_deg");
    const bool vectors = optional(v, "normal") || optional(v, "tangent");
    if (angles && vectors) fail(ptr, "give either the angles (normal_yaw_deg, ...) or the vectors (normal, tangent), not both");
    if (!angles && !vectors) fail(member_path(ptr, "normal_yaw_deg"), "missing (or give \"normal\" and \"tangent\" vectors)");
    c.by_vectors = vectors;
    if (vectors) {
      c.normal = vector3(required(v, ptr, "normal"), member_path(ptr, "normal"));
      c.tangent = vector3(required(v, ptr, "tangent"), member_path(ptr, "tangent"));
    } else {
      c.normal_yaw = number(required(v, ptr, "normal_yaw_deg"), member_path(ptr, "normal_yaw_deg"));
      c.normal_pitch = number_or(v, ptr, "normal_pitch_deg");
      c.tangent_roll = number_or(v, ptr, "tangent_roll_deg");
    }
    return c;
  }

  Number non_negative(const json& obj, const std::string& ptr, const std::string& key) const {
    Number n = number(required(obj, ptr, key), member_path(ptr, key));
    if (compare(decimal(n), kZero) < 0) fail(member_path(ptr, key), fmt::format("must be >= 0 (got {})", n.text));
    return n;
  }

  std::optional<Number> ratio_or_critical(const json& obj, const std::string& ptr, const std::string& key) const {
    const json& v = required(obj, ptr, key);
    const std::string path = member_path(ptr, key);
    if (v.is_string()) {
      if (v.get<std::string>() == "critical") return std::nullopt;
      fail(path, fmt::format("expected a number or \"critical\", got {}", io::quoted(v.get<std::string>())));
    }
    if (!v.is_number()) fail(path, fmt::format("expected a number or \"critical\", got {}", type_name(v)));
    return number(v, path);
  }

  StrategySpec strategy(const json& v, const std::string& ptr) const {
    if (!v.is_object()) fail(ptr, fmt::format("expected an object, got {}", type_name(v)));
    const std::string name = string(required(v, ptr, "name"), member_path(ptr, "name"));
    const auto kind = find_strategy_kind(name);
    if (!kind) fail(member_path(ptr, "name"), fmt::format("unknown strategy {} (expected {})", io::quoted(name), strategy_kind_names()));
    const KindRow row = strategy_kind(*kind);
    std::set<std::string> keys{"name"};
    for (const auto& p : row.parameters) keys.emplace(p.key);
    object(v, ptr, keys);
    StrategySpec s;
    s.kind = *kind;
    s.path = ptr;
    for (const auto& p : row.parameters) {
      const std::string key(p.key), path = member_path(ptr, key);
      switch (p.type) {
        case ParameterType::non_negative: s.numbers[key] = non_negative(v, ptr, key); break;
        case ParameterType::ratio_or_critical: s.numbers[key] = ratio_or_critical(v, ptr, key); break;
        case ParameterType::choice: {
          std::string value(p.choices[0]);
          if (auto* given = optional(v, key)) value = string(*given, path);
          if (value != p.choices[0] && value != p.choices[1])
            fail(path, fmt::format("expected \"{}\" or \"{}\", got {}", p.choices[0], p.choices[1], io::quoted(value)));
          s.choices[key] = value;
          break;
        }
      }
    }
    return s;
  }

  CaseSpec read() const {
    const json& root = parsed_.doc;
    object(root, "$", {"name", "description", "units", "vehicles", "contact", "restitution", "strategy"});
    CaseSpec c;
    if (auto* n = optional(root, "name")) c.name = string(*n, "$.name");
    if (auto* d = optional(root, "description")) c.description = string(*d, "$.description");
    if (auto* u = optional(root, "units")) {
      const std::string units = string(*u, "$.units");
      if (units == "US") c.units = Units::US;
      else if (units != "SI") fail("$.units", fmt::format("unknown unit system {} (expected \"SI\" or \"US\")", io::quoted(units)));
    }
    const json& vs = required(root, "$", "vehicles");
    if (!vs.is_array()) fail("$.vehicles", fmt::format("expected an array of 2 vehicles, got {}", type_name(vs)));
    if (vs.size() != 2) fail("$.vehicles", fmt::format("expected 2 vehicles, got {}", vs.size()));
    for (int i = 0; i < 2; ++i) c.vehicles[i] = vehicle(vs[i], element_path("$.vehicles", i));
    c.contact = contact(required(root, "$", "contact"), "$.contact");
    c.restitution = number(required(root, "$", "restitution"), "$.restitution");
    const Decimal e = decimal(c.restitution);
    if (compare(e, kZero) < 0 || compare(e, kOne) > 0)
      fail("$.restitution", fmt::format("must be in [0, 1] (got {})", c.restitution.text));
    const json& st = required(root, "$", "strategy");
    if (st.is_array()) {
      if (st.empty()) fail("$.strategy", "empty array: give at least one strategy");
      if (st.size() > limits::kStrategies) fail("$.strategy", fmt::format("more than {} strategies", limits::kStrategies));
      c.strategy_is_array = true;
      for (std::size_t i = 0; i < st.size(); ++i) c.strategies.push_back(strategy(st[i], element_path("$.strategy", i)));
    } else {
      c.strategies.push_back(strategy(st, "$.strategy"));
    }
    return c;
  }

 private:
  const ParsedJson& parsed_;
};

}  // namespace

StrategySpec read_strategy_option(const std::string& text, int index) {
  const std::string label = "--strategy[" + std::to_string(index) + "]";
  if (!valid_utf8(text)) throw CaseError(label, "not valid UTF-8");
  if (text.size() > limits::kCaseFileBytes) throw CaseError(label, "longer than a case file may be");
  std::string doc = text;
  if (text.empty() || text.front() != '{') {
    // name[:key=value,...] -> {"name": "...", "key": value}; values that are not JSON numbers are strings.
    const auto colon = text.find(':');
    doc = "{\"name\": " + nlohmann::json(text.substr(0, colon)).dump();
    std::string rest = colon == std::string::npos ? "" : text.substr(colon + 1);
    std::size_t pos = 0;
    while (pos < rest.size()) {
      const auto comma = rest.find(',', pos);
      const std::string item = rest.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
      const auto eq = item.find('=');
      const std::string key = item.substr(0, eq), value = eq == std::string::npos ? "" : item.substr(eq + 1);
      const bool is_number = !value.empty() && (value[0] == '-' || std::isdigit(static_cast<unsigned char>(value[0]))) &&
                             json::accept(value) && json::parse(value).is_number();
      doc += ", " + nlohmann::json(key).dump() + ": " + (is_number ? value : nlohmann::json(value).dump());
      pos = comma == std::string::npos ? rest.size() : comma + 1;
    }
    doc += "}";
  }
  const ParsedJson parsed = parse_json_with_literals(doc, label);
  return Reader(parsed).strategy(parsed.doc, label);
}

std::string read_text_file(const std::string& path, std::size_t max_bytes) {
  // No blocking on a FIFO without a writer, no endless read of a device: the size is capped as read.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd < 0) throw CaseError(path, fmt::format("cannot read the file ({})", std::strerror(errno)));
  struct stat st {};
  if (::fstat(fd, &st) != 0 || S_ISDIR(st.st_mode)) {
    ::close(fd);
    throw CaseError(path, "cannot read the file (a directory)");
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  std::string text;
  char buf[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      throw CaseError(path, fmt::format("cannot read the file ({})", std::strerror(err)));
    }
    if (n == 0) break;
    if (text.size() + static_cast<std::size_t>(n) > max_bytes) {
      ::close(fd);
      throw CaseError(path, fmt::format("larger than {} bytes, the limit for this input", max_bytes));
    }
    text.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return text;
}

CaseError no_solution(const CaseSpec& spec, const SolveError& e) {
  const std::string where = e.strategy && *e.strategy < spec.strategies.size() ? spec.strategies[*e.strategy].path : "$";
  return CaseError(where, std::string("no solution: ") + e.what());
}

CaseSpec read_case(const std::string& json_text) {
  const ParsedJson parsed = parse_json_with_literals(json_text);
  return Reader(parsed).read();
}

}  // namespace impact3d::io
