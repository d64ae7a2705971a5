// JSON parsing within the input limits (limits.hpp), remembering the literal text of every number by
// the JSON path of the value, as messages print it: "$.vehicles[0].mass".
#pragma once

#include <map>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "impact3d/io/limits.hpp"

namespace impact3d::io {

struct ParsedJson {
  nlohmann::json doc;
  std::map<std::string, std::string> literal;  // JSON path -> number text (none below keys starting with '_')
};

// Throws CaseError naming the path on a syntax error, a duplicated key, a NUL byte, or a limit exceeded
// (depth, number of values, length of a key or of a number literal, written exponent). `root` is the
// root's name in messages ("$", or e.g. "--strategy[0]"). Number text is kept only as deep as a case
// holds numbers (limits::kLiteralDepth), so the paths stored stay short whatever the file.
ParsedJson parse_json_with_literals(std::string_view text, const std::string& root = "$");

// The same checks, with nesting at most `depth`, for documents whose number text is not needed
// (compare's results).
nlohmann::json parse_json_bounded(std::string_view text, const std::string& root = "$", int depth = limits::kDepth);

// Paths as printed: a member is ".key" when the key is an identifier, else ["key"] quoted and escaped;
// an element is [index].
std::string member_path(const std::string& parent, std::string_view key);
std::string element_path(const std::string& parent, std::size_t index);

}  // namespace impact3d::io
