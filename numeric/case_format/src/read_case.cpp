// Structural validation of a case file: every rejection names the JSON path and the problem. Limits on
// numbers are checked on the exact decimal as written, the value every precision computes with.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <optional>
#include <span>

#include <fmt/format.h>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/decimal.hpp"
#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/json_literals.hpp"
#include "impact3d/case_format/json_tree.hpp"
#include "impact3d/case_format/limits.hpp"
#include "impact3d/case_format/nearest_key.hpp"
#include "impact3d/case_format/scalar_text.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/case_format/strategy_option.hpp"
#include "impact3d/scalar/exact.hpp"

namespace impact3d::case_format {
namespace {

using json = nlohmann::json;
using Type = JsonValue::Type;

// Larger magnitudes are no vehicle collision and would overflow energies and products of inertia;
// smaller non-zero ones would underflow double, so that precisions would disagree on the input itself.
const Decimal kMax = parse_decimal(limits::kMaxMagnitude), kMin = parse_decimal(limits::kMinMagnitude);
const Decimal kZero{}, kOne = parse_decimal("1");

Decimal decimal(const Number& n) { return parse_decimal(n.text); }

const char* type_name(const JsonValue& v) {
  switch (v.type) {
    case Type::null: return "null";
    case Type::object: return "an object";
    case Type::array: return "an array";
    case Type::string: return "a string";
    case Type::boolean: return "a boolean";
    case Type::number: return "a number";
  }
  return "an unsupported value";
}

// The signs of the leading minors (Sylvester) from the doubles of the literals, when rounding cannot
// change them: each literal is within u = 2^-53 relative of its decimal (correctly rounded, in the
// normal range by the magnitude limits, so that no product of three under- or overflows), and a sum of
// k products of m factors computed in double is within about (m + k) u of the sum of their magnitudes
// (Higham, Accuracy and Stability, ch. 3). 32 u covers the 2x2 minor and the determinant with room to
// spare; within that band the exact rational decides.
std::optional<bool> positive_definite_by_double(const std::array<Vector3, 3>& J) {
  double a[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[i][j] = J[i][j].value;
  const double u = std::ldexp(1.0, -53), band = 32 * u;
  const double minor2 = a[0][0] * a[1][1] - a[0][1] * a[1][0];
  const double minor2_size = std::abs(a[0][0] * a[1][1]) + std::abs(a[0][1] * a[1][0]);
  double det = 0, det_size = 0;
  for (int c = 0; c < 3; ++c) {  // the six terms of the Leibniz expansion
    const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
    const double plus = a[0][c] * a[1][c1] * a[2][c2], minus = a[0][c] * a[1][c2] * a[2][c1];
    det += plus - minus;
    det_size += std::abs(plus) + std::abs(minus);
  }
  if (minor2 < -band * minor2_size || det < -band * det_size) return false;
  if (minor2 > band * minor2_size && det > band * det_size) return true;
  return std::nullopt;
}

// The JSON path of a value, spelled out only when a message needs it: a path string made for every
// number was a tenth of the time `batch` spends reading a case. A Where refers to its parent, so it
// lives no longer than the call that made it.
class Where {
 public:
  explicit Where(std::string_view path) : whole_(path) {}
  Where(const Where& parent, std::string_view key) : parent_(&parent), key_(key) {}
  Where(const Where& parent, std::size_t index) : parent_(&parent), index_(index) {}
  std::string str() const {
    if (!parent_) return std::string(whole_);
    return index_ == kNone ? member_path(parent_->str(), key_) : element_path(parent_->str(), index_);
  }

 private:
  static constexpr std::size_t kNone = ~std::size_t{0};
  std::string_view whole_;
  const Where* parent_ = nullptr;
  std::string_view key_;
  std::size_t index_ = kNone;
};

// Decided on the double when it is correctly rounded from the literal and a factor of two inside the
// limits (no rounding comes near that), else on the decimal as written.
const double kFastMax = 0.5 * std::strtod(limits::kMaxMagnitude, nullptr), kFastMin = 2 * std::strtod(limits::kMinMagnitude, nullptr);
bool in_magnitude_range(const Number& n) {
  const double a = std::abs(n.value);
  return a != 0 && a <= kFastMax && a >= kFastMin;
}
// A literal whose digits are all zeros is zero whatever its exponent, and its double is ±0, which
// answers sign and range as the decimal does: a case's dozen zeros need no decimal parsed.
bool zero_literal(const Number& n) {
  if (n.value != 0) return false;
  for (const char c : n.text) {
    if (c == 'e' || c == 'E') break;
    if (c >= '1' && c <= '9') return false;
  }
  return true;
}
bool decided_by_double(const Number& n) { return in_magnitude_range(n) || zero_literal(n); }

class Reader {
 public:

  [[noreturn]] void fail(const Where& at, const std::string& msg) const {
    throw CaseError(at.str(), msg);
  }

  template <typename Keys>
  const JsonValue& object(const JsonValue& v, const Where& at, const Keys& allowed) const {
    if (!v.is(Type::object)) fail(at, fmt::format("expected an object, got {}", type_name(v)));
    // The first unknown key in byte order, whatever order the file has them in.
    const std::string* unknown = nullptr;
    for (const auto& k : v.keys) {
      if (!k.empty() && k[0] == '_') continue;  // comments and private extensions
      if (std::none_of(allowed.begin(), allowed.end(), [&](std::string_view a) { return same_key(a, k); }) &&
          (!unknown || k < *unknown))
        unknown = &k;
    }
    if (unknown) {
      const std::vector<std::string_view> known(allowed.begin(), allowed.end());
      fail(Where(at, *unknown), "unknown key" + did_you_mean(*unknown, known) + " (keys starting with '_' are ignored)");
    }
    return v;
  }
  const JsonValue& object(const JsonValue& v, const Where& at, std::initializer_list<std::string_view> allowed) const {
    return object<std::initializer_list<std::string_view>>(v, at, allowed);
  }

  const JsonValue* optional(const JsonValue& obj, std::string_view key) const { return obj.find(key); }

  const JsonValue& required(const JsonValue& obj, const Where& at, std::string_view key) const {
    auto* v = optional(obj, key);
    if (!v) fail(Where(at, key), "missing");
    return *v;
  }

  // The overloads with `out` write a field of the spec being read: its literal is copied once, where a
  // returned Number was made and then moved twice, into the vehicle and the vehicle into the case (a
  // case has some fifty numbers).
  void number(const JsonValue& v, const Where& at, Number& out) const {
    if (!v.is(Type::number)) fail(at, fmt::format("expected a number, got {}", type_name(v)));
    out.text = v.text;
    out.value = v.number;
    const Number& n = out;
    if (!std::isfinite(n.value)) fail(at, fmt::format("not a finite number ({})", n.text));
    if (decided_by_double(n)) return;
    const Decimal d = decimal(n);
    if (compare_magnitude(d, kMax) > 0)
      fail(at, fmt::format("out of range: magnitude {} exceeds {:g}", n.text, std::stod(limits::kMaxMagnitude)));
    if (!d.zero() && compare_magnitude(d, kMin) < 0)
      fail(at, fmt::format("out of range: {} is not zero but below {:g} in magnitude", n.text, std::stod(limits::kMinMagnitude)));
  }
  Number number(const JsonValue& v, const Where& at) const {
    Number n;
    number(v, at, n);
    return n;
  }

  void number_or(const JsonValue& obj, const Where& at, std::string_view key, Number& out) const {
    if (auto* v = optional(obj, key)) return number(*v, Where(at, key), out);
    out = Number{"0", 0.0};
  }

  // A number in range is positive exactly when its double is: rounding keeps the sign and no literal in
  // range rounds to zero.
  static bool positive_value(const Number& n) { return decided_by_double(n) ? n.value > 0 : compare(decimal(n), kZero) > 0; }

  void positive(const JsonValue& v, const Where& at, Number& out) const {
    number(v, at, out);
    if (!positive_value(out)) fail(at, fmt::format("must be > 0 (got {})", out.text));
  }
  Number positive(const JsonValue& v, const Where& at) const {
    Number n;
    positive(v, at, n);
    return n;
  }

  void vector3(const JsonValue& v, const Where& at, Vector3& out) const {
    if (!v.is(Type::array)) fail(at, fmt::format("expected an array of 3 numbers, got {}", type_name(v)));
    if (v.size() != 3) fail(at, fmt::format("expected 3 numbers, got {}", v.size()));
    for (std::size_t i = 0; i < 3; ++i) number(v.items[i], Where(at, i), out[i]);
  }

  void vector3_or_zero(const JsonValue& obj, const Where& at, std::string_view key, Vector3& out) const {
    if (auto* v = optional(obj, key)) return vector3(*v, Where(at, key), out);
    out = {Number{"0", 0.0}, Number{"0", 0.0}, Number{"0", 0.0}};
  }

  std::string string(const JsonValue& v, const Where& at) const {
    if (!v.is(Type::string)) fail(at, fmt::format("expected a string, got {}", type_name(v)));
    return v.text;
  }

  EnergySplitSpec energy_split(const JsonValue& v, const Where& at) const {
    object(v, at, {"share", "stiffness"});
    const JsonValue* share = optional(v, "share");
    const JsonValue* stiffness = optional(v, "stiffness");
    if ((share != nullptr) == (stiffness != nullptr)) fail(at, "give one of \"share\" and \"stiffness\"");
    EnergySplitSpec e;
    e.rule = share ? "share" : "stiffness";
    e.path = at.str();
    const Where here(at, e.rule);
    const JsonValue& a = share ? *share : *stiffness;
    if (!a.is(Type::array)) fail(here, fmt::format("expected an array of 2 numbers, got {}", type_name(a)));
    if (a.size() != 2) fail(here, fmt::format("expected 2 numbers, one per vehicle, got {}", a.size()));
    for (std::size_t i = 0; i < 2; ++i) {
      const Where w(here, i);
      if (!share) {
        e.values[i] = positive(a.items[i], w);
        continue;
      }
      // In range or zero (number() refuses the rest), a literal has its double's sign.
      e.values[i] = number(a.items[i], w);
      if (e.values[i].value < 0) fail(w, fmt::format("must be >= 0 (got {})", e.values[i].text));
    }
    if (share && e.values[0].value == 0 && e.values[1].value == 0) fail(here, "both shares are 0");
    return e;
  }

  void inertia(VehicleSpec& veh, const JsonValue& v, const Where& at) const {
    veh.inertia_path = at.str();
    if (v.is(Type::object)) {
      object(v, at, {"Ixx", "Iyy", "Izz"});
      veh.inertia_principal = true;
      const char* keys[3] = {"Ixx", "Iyy", "Izz"};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          if (i == j) positive(required(v, at, keys[i]), Where(at, keys[i]), veh.inertia[i][j]);
          else veh.inertia[i][j] = Number{"0", 0.0};
      return;
    }
    if (!v.is(Type::array) || v.size() != 3)
      fail(at, "expected a 3x3 tensor [[Ixx, Ixy, Ixz], ...] or {\"Ixx\", \"Iyy\", \"Izz\"}");
    for (std::size_t i = 0; i < 3; ++i) vector3(v.items[i], Where(at, i), veh.inertia[i]);
    for (int i = 0; i < 3; ++i) {
      if (!positive_value(veh.inertia[i][i]))
        fail(at, fmt::format("not positive definite: diagonal entry [{}][{}] = {}", i, i, veh.inertia[i][i].text));
      for (int j = i + 1; j < 3; ++j)
        if (veh.inertia[i][j].text != veh.inertia[j][i].text && !(decimal(veh.inertia[i][j]) == decimal(veh.inertia[j][i])))
          fail(at, fmt::format("not symmetric: [{}][{}] = {} but [{}][{}] = {}", i, j, veh.inertia[i][j].text, j, i,
                               veh.inertia[j][i].text));
    }
    // Positive definite as written (Sylvester: the leading minors), so that every precision computes with
    // the same admissible tensor; a precision that rounds it to an indefinite one flags its results.
    if (const auto decided = positive_definite_by_double(veh.inertia)) {
      if (!*decided) fail(at, "not positive definite");
      return;
    }
    rational J[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) J[i][j] = scalar_from_text<rational>(veh.inertia[i][j].text);
    const rational minor2 = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    const rational det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
    if (!(minor2 > 0) || !(det > 0)) fail(at, "not positive definite");
  }

  void vehicle(const JsonValue& v, const Where& at, VehicleSpec& veh) const {
    object(v, at, {"name", "mass", "inertia", "orientation_deg", "orientation_matrix", "velocity", "angular_velocity",
                   "impulse_center", "dimensions"});
    if (auto* n = optional(v, "name")) veh.name = string(*n, Where(at, "name"));
    positive(required(v, at, "mass"), Where(at, "mass"), veh.mass);
    inertia(veh, required(v, at, "inertia"), Where(at, "inertia"));
    static const JsonValue empty = [] {
      JsonValue e;
      e.type = Type::object;
      return e;
    }();
    const JsonValue* o = optional(v, "orientation_deg");
    if (const JsonValue* m = optional(v, "orientation_matrix")) {
      const Where mat(at, "orientation_matrix");
      if (o) fail(mat, "give either orientation_deg or orientation_matrix, not both");
      if (!m->is(Type::array) || m->size() != 3) fail(mat, "expected a 3x3 rotation matrix (rows of R_WB)");
      std::array<Vector3, 3> rows;
      for (std::size_t i = 0; i < 3; ++i) vector3(m->items[i], Where(mat, i), rows[i]);
      veh.orientation_matrix = rows;
      veh.orientation_path = mat.str();
    }
    const Where angles(at, "orientation_deg");
    if (o) object(*o, angles, {"yaw", "pitch", "roll"});
    const JsonValue& orient = o ? *o : empty;
    number_or(orient, angles, "yaw", veh.yaw);
    number_or(orient, angles, "pitch", veh.pitch);
    number_or(orient, angles, "roll", veh.roll);
    vector3(required(v, at, "velocity"), Where(at, "velocity"), veh.velocity);
    vector3_or_zero(v, at, "angular_velocity", veh.angular_velocity);
    vector3(required(v, at, "impulse_center"), Where(at, "impulse_center"), veh.impulse_center);
    if (const JsonValue* d = optional(v, "dimensions")) veh.dimensions = dimensions(*d, Where(at, "dimensions"));
  }

  DimensionsSpec dimensions(const JsonValue& v, const Where& at) const {
    object(v, at, {"length", "width", "height", "cg_to_front"});
    DimensionsSpec d;
    d.length = positive(required(v, at, "length"), Where(at, "length"));
    d.width = positive(required(v, at, "width"), Where(at, "width"));
    if (const JsonValue* h = optional(v, "height")) d.height = positive(*h, Where(at, "height"));
    if (const JsonValue* f = optional(v, "cg_to_front")) {
      d.cg_to_front = positive(*f, Where(at, "cg_to_front"));
      if (!(d.cg_to_front->value < d.length.value))
        fail(Where(at, "cg_to_front"), fmt::format("must be less than the length (got {})", d.cg_to_front->text));
    }
    return d;
  }

  void contact(const JsonValue& v, const Where& at, ContactSpec& c) const {
    object(v, at, {"normal_yaw_deg", "normal_pitch_deg", "tangent_roll_deg", "normal", "tangent"});
    c.path = at.str();
    const bool angles = optional(v, "normal_yaw_deg") || optional(v, "normal_pitch_deg") || optional(v, "tangent_roll_deg");
    const bool vectors = optional(v, "normal") || optional(v, "tangent");
    if (angles && vectors) fail(at, "give either the angles (normal_yaw_deg, ...) or the vectors (normal, tangent), not both");
    if (!angles && !vectors) fail(Where(at, "normal_yaw_deg"), "missing (or give \"normal\" and \"tangent\" vectors)");
    c.by_vectors = vectors;
    if (vectors) {
      vector3(required(v, at, "normal"), Where(at, "normal"), c.normal);
      vector3(required(v, at, "tangent"), Where(at, "tangent"), c.tangent);
    } else {
      number(required(v, at, "normal_yaw_deg"), Where(at, "normal_yaw_deg"), c.normal_yaw);
      number_or(v, at, "normal_pitch_deg", c.normal_pitch);
      number_or(v, at, "tangent_roll_deg", c.tangent_roll);
    }
  }

  Number non_negative(const JsonValue& obj, const Where& at, std::string_view key) const {
    const Where here(at, key);
    Number n = number(required(obj, at, key), here);
    if (decided_by_double(n) ? n.value < 0 : compare(decimal(n), kZero) < 0) fail(here, fmt::format("must be >= 0 (got {})", n.text));
    return n;
  }

  std::optional<Number> ratio_or_critical(const JsonValue& obj, const Where& at, std::string_view key) const {
    const JsonValue& v = required(obj, at, key);
    const Where here(at, key);
    if (v.is(Type::string)) {
      if (v.text == "critical") return std::nullopt;
      fail(here, fmt::format("expected a number or \"critical\", got {}", case_format::quoted(v.text)));
    }
    if (!v.is(Type::number)) fail(here, fmt::format("expected a number or \"critical\", got {}", type_name(v)));
    return number(v, here);
  }

  // "\"cir\" or \"gir\"", "\"energetic\", \"poisson\" or \"newton\"".
  static std::string one_of(std::span<const std::string_view> choices) {
    std::string s;
    for (std::size_t i = 0; i < choices.size(); ++i)
      s += fmt::format("{}\"{}\"", i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ", choices[i]);
    return s;
  }

  StrategySpec strategy(const JsonValue& v, const Where& at) const {
    if (!v.is(Type::object)) fail(at, fmt::format("expected an object, got {}", type_name(v)));
    const std::string name = string(required(v, at, "name"), Where(at, "name"));
    const auto kind = find_strategy_kind(name);
    if (!kind) fail(Where(at, "name"), fmt::format("unknown strategy {} (expected {})", case_format::quoted(name), strategy_kind_names()));
    const KindRow row = strategy_kind(*kind);
    std::vector<std::string_view> keys{"name"};
    for (const auto& p : row.parameters) keys.emplace_back(p.key);
    object(v, at, keys);
    StrategySpec s;
    s.kind = *kind;
    s.path = at.str();
    for (const auto& p : row.parameters) {
      const std::string key(p.key);
      const Where here(at, p.key);
      switch (p.type) {
        case ParameterType::non_negative: s.numbers[key] = non_negative(v, at, key); break;
        case ParameterType::ratio_or_critical: s.numbers[key] = ratio_or_critical(v, at, key); break;
        case ParameterType::choice: {
          std::string value(p.choices[0]);
          if (auto* given = optional(v, key)) value = string(*given, here);
          if (std::find(p.choices.begin(), p.choices.end(), value) == p.choices.end())
            fail(here, fmt::format("expected {}, got {}", one_of(p.choices), case_format::quoted(value)));
          s.choices[key] = value;
          break;
        }
      }
    }
    return s;
  }

  CaseSpec read(const JsonValue& root) const {
    const Where top("$");
    object(root, top, {"name", "description", "units", "vehicles", "contact", "restitution", "energy_split", "strategy"});
    CaseSpec c;
    if (auto* n = optional(root, "name")) c.name = string(*n, Where("$.name"));
    if (auto* d = optional(root, "description")) c.description = string(*d, Where("$.description"));
    if (auto* u = optional(root, "units")) {
      const std::string units = string(*u, Where("$.units"));
      if (units == "US") c.units = Units::US;
      else if (units != "SI") fail(Where("$.units"), fmt::format("unknown unit system {} (expected \"SI\" or \"US\")", case_format::quoted(units)));
    }
    const Where vehicles("$.vehicles");
    const JsonValue& vs = required(root, top, "vehicles");
    if (!vs.is(Type::array)) fail(vehicles, fmt::format("expected an array of 2 vehicles, got {}", type_name(vs)));
    if (vs.size() != 2) fail(vehicles, fmt::format("expected 2 vehicles, got {}", vs.size()));
    for (std::size_t i = 0; i < 2; ++i) vehicle(vs.items[i], Where(vehicles, i), c.vehicles[i]);
    contact(required(root, top, "contact"), Where("$.contact"), c.contact);
    const Where restitution("$.restitution");
    number(required(root, top, "restitution"), restitution, c.restitution);
    const bool in_unit = in_magnitude_range(c.restitution) && c.restitution.value < 1
                             ? c.restitution.value > 0
                             : compare(decimal(c.restitution), kZero) >= 0 && compare(decimal(c.restitution), kOne) <= 0;
    if (!in_unit) fail(restitution, fmt::format("must be in [0, 1] (got {})", c.restitution.text));
    if (auto* e = optional(root, "energy_split")) c.energy_split = energy_split(*e, Where("$.energy_split"));
    const Where strategies("$.strategy");
    const JsonValue& st = required(root, top, "strategy");
    if (st.is(Type::array)) {
      if (st.items.empty()) fail(strategies, "empty array: give at least one strategy");
      if (st.size() > limits::kStrategies) fail(strategies, fmt::format("more than {} strategies", limits::kStrategies));
      c.strategy_is_array = true;
      for (std::size_t i = 0; i < st.size(); ++i) c.strategies.push_back(strategy(st.items[i], Where(strategies, i)));
    } else {
      c.strategies.push_back(strategy(st, strategies));
    }
    return c;
  }

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
  return Reader().strategy(parse_json_tree(doc, label), Where(label));
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
  // One tree per thread, read into again for each case: a batch's rows reuse its storage.
  thread_local JsonValue tree;
  parse_json_tree_into(json_text, tree);
  return Reader().read(tree);
}

CaseSpec read_case_tree(const JsonValue& root) { return Reader().read(root); }

}  // namespace impact3d::case_format
