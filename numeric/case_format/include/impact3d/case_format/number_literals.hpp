// Where each number of one of impact3d's own JSON documents stands: its path and its literal's place in
// the text. For reading back what this program wrote (the certified enclosures, the reference suite's
// proof), not for input: no input limit applies, since at thousands of bits a literal is longer than any
// case's may be.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace impact3d::case_format {

struct NumberLiteral {
  std::string path;  // `results[0].impulse.contact[2]`: keys joined by '.', elements by [i]
  std::size_t begin = 0, end = 0;  // the literal is text.substr(begin, end - begin); "null" for a null
  bool null = false;               // a number that is not finite is written null
};

// Every number and null of `own_document`, in order. Throws std::logic_error if it does not parse.
std::vector<NumberLiteral> number_literals(std::string_view own_document);

}  // namespace impact3d::case_format
