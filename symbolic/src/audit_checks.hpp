// The one maker of comparisons (Check): each decides an identity by exact algebra and, when it fails,
// finds exact inputs that show the difference.
#pragma once

#include <string>
#include <vector>

#include "audit.hpp"

namespace impact3d::symbolic {

class Auditor {
 public:
  // printed (or claimed) against derived; `subs` turns angle identities into rational ones.
  static Check compare(const std::string& what, const ex& printed, const ex& derived, const GiNaC::exmap& subs = {},
                       const char* left_name = "printed", const char* right_name = "derived");
  // A claim that two expressions are not identically equal (it holds when a witness shows them differ).
  static Check differs(const std::string& what, const ex& left, const ex& right, const GiNaC::exmap& subs,
                       const char* left_name, const char* right_name);
  // Componentwise: one check per component, named by `names[i]`.
  static std::vector<Check> compare_each(const std::string& what, const std::vector<std::string>& names,
                                         const matrix& printed, const matrix& derived, const GiNaC::exmap& subs = {});
};

// The cosine/sine symbol pairs of every angle: identities in them are decided through the rational
// parametrization of the circle.
const std::vector<std::pair<std::string, std::string>>& angle_pairs();
// The substitution for all of them at once.
const GiNaC::exmap& all_angles();

// The components of a vector, by meaning.
extern const std::vector<std::string> kContactAxes;  // "n", "t", "z"

}  // namespace impact3d::symbolic
