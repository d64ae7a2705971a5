#include "impact3d/case_format/json_fields.hpp"

#include <cmath>
#include <cstdlib>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/limits.hpp"
#include "impact3d/case_format/nearest_key.hpp"

namespace impact3d::case_format::fields {

using Type = JsonValue::Type;

void fail(const std::string& at, const std::string& problem) { throw CaseError(at, problem); }

std::string member(const std::string& at, std::string_view key) { return at + "." + std::string(key); }

void only_keys(const JsonValue& v, const std::string& at, std::initializer_list<std::string_view> allowed) {
  for (const std::string& k : v.keys) {
    if (!k.empty() && k[0] == '_') continue;
    bool known = false;
    for (std::string_view a : allowed) known = known || k == a;
    if (!known)
      fail(at, fmt::format("unknown key {}{} (keys starting with '_' are ignored)", case_format::quoted(k),
                           did_you_mean(k, std::vector<std::string_view>(allowed))));
  }
}

const JsonValue& need(const JsonValue& v, const std::string& at, std::string_view key, Type type, const char* what) {
  const JsonValue* m = v.find(key);
  if (!m) fail(at, fmt::format("missing \"{}\"", key));
  if (!m->is(type)) fail(member(at, key), fmt::format("must be {}", what));
  return *m;
}

std::uint64_t count(const JsonValue& v, const std::string& at, std::uint64_t least, std::uint64_t most) {
  if (!v.is(Type::number)) fail(at, "must be a whole number");
  const std::string& t = v.text;
  if (t.empty() || t.size() > 20 || t.find_first_not_of("0123456789") != std::string::npos)
    fail(at, fmt::format("must be a whole number written in digits (got {})", printable(t)));
  std::uint64_t n = 0;
  for (const char c : t) {
    const std::uint64_t digit = static_cast<std::uint64_t>(c - '0');
    if (n > (UINT64_MAX - digit) / 10) fail(at, fmt::format("must be at most {}", most));
    n = n * 10 + digit;
  }
  if (n < least || n > most) fail(at, fmt::format("must be from {} to {} (got {})", least, most, t));
  return n;
}

namespace {
const double kMaxMagnitude = std::strtod(limits::kMaxMagnitude, nullptr);
}  // namespace

bool within_magnitude(const JsonValue& x) {
  return x.is(Type::number) && std::isfinite(x.number) && std::fabs(x.number) <= kMaxMagnitude;
}

double number(const JsonValue& x, const std::string& at) {
  if (!within_magnitude(x))
    fail(at, fmt::format("must be a finite number of magnitude at most {}{}", limits::kMaxMagnitude,
                         x.is(Type::number) ? fmt::format(" (got {})", printable(x.text)) : std::string()));
  return x.number;
}

double parameter(const JsonValue& v, const std::string& at, std::string_view key) {
  const JsonValue& m = need(v, at, key, Type::number, "a number");
  if (!within_magnitude(m))
    fail(member(at, key), fmt::format("must be a finite number of magnitude at most {} (got {})", limits::kMaxMagnitude, printable(m.text)));
  return m.number;
}

double positive(const JsonValue& v, const std::string& at, std::string_view key) {
  const double x = parameter(v, at, key);
  if (!(x > 0)) fail(member(at, key), fmt::format("must be > 0 (got {})", printable(v.find(key)->text)));
  return x;
}

}  // namespace impact3d::case_format::fields
