// JSON parsing that remembers the literal text of every number, keyed by JSON pointer.
#pragma once

#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace impact3d::io {

struct ParsedJson {
  nlohmann::json doc;
  std::map<std::string, std::string> literal;  // JSON pointer -> number text
};

// Throws CaseError (path "$") on a syntax error or a duplicated key.
ParsedJson parse_json_with_literals(const std::string& text);

// "/vehicles/0/mass" -> "$.vehicles[0].mass"
std::string display_path(const std::string& pointer);

}  // namespace impact3d::io
