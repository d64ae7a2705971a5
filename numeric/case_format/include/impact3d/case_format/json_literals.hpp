// JSON parsing within the input limits (limits.hpp), and JSON paths as messages print them:
// "$.vehicles[0].mass".
#pragma once

#include <map>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "impact3d/case_format/limits.hpp"

namespace impact3d::case_format {

// Throws CaseError naming the path on a syntax error, a duplicated key, a NUL byte, or a limit exceeded
// (depth, number of values, length of a key or of a number literal, written exponent). `root` is the
// root's name in messages ("$", or e.g. "--strategy[0]"). With nesting at most `depth`, for documents
// whose number text is not needed (compare's results); cases are read by parse_json_tree (json_tree.hpp).
nlohmann::json parse_json_bounded(std::string_view text, const std::string& root = "$", int depth = limits::kDepth);

// Paths as printed: a member is ".key" when the key is an identifier, else ["key"] quoted and escaped;
// an element is [index].
std::string member_path(const std::string& parent, std::string_view key);
std::string element_path(const std::string& parent, std::size_t index);

}  // namespace impact3d::case_format
