// The proof of the reference suite's digits (issue 14): every number a reference result writes is
// checked against the certified enclosure of the same number (impact3d solve --precision certified).
// A number whose enclosure lies inside its rounding interval at the digits written is the exact result
// for the inputs as written, correctly rounded: proven. A number whose enclosure holds zero is rounding
// noise of the 100-digit solve and is written 0, within the enclosure's reach. Strings, booleans and
// nulls equal the certified result's. Where a decision is undecided in ball arithmetic (an exact zero
// that is not rational), a field may instead equal, or lie in the enclosure of, the other branch's.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include "impact3d/case_format/json_writer.hpp"

namespace impact3d::verification {

struct ReferenceProof {
  std::string document;  // the reference with each result's decisions and a "certified" block
  std::string failure;   // empty when every digit is proven; else the first field that is not
};

// Writes the reference document at the proof's digits; `extra` adds to the top level, `per_result` to
// result k (result_json's hooks).
using RenderReference = std::function<std::string(const std::function<void(case_format::JsonWriter&)>& extra,
                                                  const std::function<void(case_format::JsonWriter&, std::size_t)>& per_result)>;

// `render` writes the reference at `digits` significant digits; `certified` is the certified result
// document of the same case.
ReferenceProof prove_reference(const RenderReference& render, const std::string& certified, int digits);

}  // namespace impact3d::verification
