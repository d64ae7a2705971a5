// simdjson's On Demand walk hands over each scalar's raw token, a view into the text: its place.
#include "impact3d/case_format/number_literals.hpp"

#include <stdexcept>

#include <simdjson.h>

namespace impact3d::case_format {
namespace {

namespace od = simdjson::ondemand;

struct Walk {
  const char* base;
  std::vector<NumberLiteral>& out;

  void fail(const std::string& path) const {
    throw std::logic_error("a document of impact3d's own does not parse at " + (path.empty() ? "$" : path));
  }

  void value(od::value v, const std::string& path) {
    od::json_type type;
    if (v.type().get(type)) fail(path);
    switch (type) {
      case od::json_type::number:
      case od::json_type::null: {
        std::string_view raw = v.raw_json_token();
        while (!raw.empty() && (raw.back() == ' ' || raw.back() == '\n' || raw.back() == '\r' || raw.back() == '\t'))
          raw.remove_suffix(1);
        const auto at = static_cast<std::size_t>(raw.data() - base);
        out.push_back({path, at, at + raw.size(), type == od::json_type::null});
        return;
      }
      case od::json_type::array: {
        od::array a;
        if (v.get_array().get(a)) fail(path);
        std::size_t i = 0;
        for (auto element : a) {
          od::value e;
          if (element.get(e)) fail(path);
          value(e, path + "[" + std::to_string(i++) + "]");
        }
        return;
      }
      case od::json_type::object: {
        od::object o;
        if (v.get_object().get(o)) fail(path);
        for (auto field : o) {
          std::string_view key;
          od::value v;
          if (field.unescaped_key().get(key) || field.value().get(v)) fail(path);
          value(v, path.empty() ? std::string(key) : path + "." + std::string(key));
        }
        return;
      }
      default: return;  // strings and booleans: nothing to place
    }
  }
};

}  // namespace

std::vector<NumberLiteral> number_literals(std::string_view own_document) {
  std::vector<NumberLiteral> out;
  od::parser parser;
  const simdjson::padded_string padded(own_document);
  od::document doc;
  od::value root;
  if (parser.iterate(padded).get(doc) || doc.get_value().get(root))
    throw std::logic_error("a document of impact3d's own does not parse");
  Walk{padded.data(), out}.value(root, "");
  return out;
}

}  // namespace impact3d::case_format
