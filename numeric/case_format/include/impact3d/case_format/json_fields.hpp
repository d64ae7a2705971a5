// The fields of a small input file other than a case (an uncertainty file, an evidence file), read as
// hostile input: each check throws one CaseError naming the JSON path of the field and the problem.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>

#include "impact3d/case_format/json_tree.hpp"

namespace impact3d::case_format::fields {

[[noreturn]] void fail(const std::string& at, const std::string& problem);

// "at.key".
std::string member(const std::string& at, std::string_view key);

// Refuses a key not in `allowed`; keys starting with '_' are comments, as in a case file.
void only_keys(const JsonValue& v, const std::string& at, std::initializer_list<std::string_view> allowed);

// The member `key` of `v`, which must be there and of `type` (`what` says so in the message).
const JsonValue& need(const JsonValue& v, const std::string& at, std::string_view key, JsonValue::Type type, const char* what);

// A count written as a plain non-negative integer literal, from `least` to `most`.
std::uint64_t count(const JsonValue& v, const std::string& at, std::uint64_t least, std::uint64_t most);

// A finite number within the case numbers' magnitude limit (limits.hpp).
bool within_magnitude(const JsonValue& x);
double number(const JsonValue& x, const std::string& at);
// The member `key`, a number within the magnitude limit; `positive` also requires > 0.
double parameter(const JsonValue& v, const std::string& at, std::string_view key);
double positive(const JsonValue& v, const std::string& at, std::string_view key);

}  // namespace impact3d::case_format::fields
