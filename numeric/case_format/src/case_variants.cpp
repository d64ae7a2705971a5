#include "impact3d/case_format/case_variants.hpp"

#include <cmath>

#include <fmt/format.h>

#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/format_double.hpp"

namespace impact3d::case_format {

CaseVariants::CaseVariants(const std::string& case_text, const std::vector<JsonPath>& paths, const std::vector<std::string>& where)
    : root_(parse_json_tree(case_text)), paths_(paths), base_(read_case_tree(root_)) {
  resolve(&where);
}

CaseVariants::CaseVariants(const CaseVariants& other) : root_(other.root_), paths_(other.paths_), base_(other.base_) {
  resolve(nullptr);
}

void CaseVariants::resolve(const std::vector<std::string>* where) {
  slots_.clear();
  for (std::size_t i = 0; i < paths_.size(); ++i) {
    JsonValue* v = &root_;
    for (const PathStep& step : paths_[i]) {
      if (!v) break;
      if (step.kind == PathStep::Kind::key) {
        JsonValue* next = nullptr;
        if (v->is(JsonValue::Type::object))
          for (std::size_t k = 0; k < v->keys.size(); ++k)
            if (v->keys[k] == step.key) next = &v->items[k];
        v = next;
      } else {
        v = v->is(JsonValue::Type::array) && step.index < v->size() ? &v->items[step.index] : nullptr;
      }
    }
    if (!v || !v->is(JsonValue::Type::number)) {
      const std::string at = where && i < where->size() ? (*where)[i] : "$";
      throw CaseError(at, fmt::format("{} is {} of the case", case_format::quoted(path_text(paths_[i])), v ? "not a number" : "no field"));
    }
    slots_.push_back(v);
  }
}

std::vector<double> CaseVariants::values() const {
  std::vector<double> out;
  for (const JsonValue* slot : slots_) out.push_back(slot->number);
  return out;
}

CaseSpec CaseVariants::with(const double* values) {
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    if (!std::isfinite(values[i])) throw CaseError(path_text(paths_[i]), "the sampled value is not finite");
    char buf[32];
    slots_[i]->number = values[i];
    slots_[i]->text.assign(buf, format_g17(buf, values[i]));
  }
  return read_case_tree(root_);
}

}  // namespace impact3d::case_format
