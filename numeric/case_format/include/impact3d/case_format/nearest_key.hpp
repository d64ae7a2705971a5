// The known key an unknown one most likely meant, for the one-line refusal of a case, an uncertainty or
// an evidence file ("$.contact.normal_yaw: unknown key; did you mean normal_yaw_deg?").
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace impact3d::case_format {

// The nearest known key by edit distance (a swap of neighbours one edit, letters compared ignoring
// case), if it is within a third of the longer key's length and at most 3 edits (1 for keys of up to
// 5 letters), else the one known key it begins at an underscore (a unit suffix left out: normal_yaw for
// normal_yaw_deg), else the one that begins it so (a suffix added); none when two are equally near, or
// the unknown key is longer than any key could be (64 bytes).
std::optional<std::string_view> nearest_key(std::string_view unknown, std::span<const std::string_view> known);

// "; did you mean K?" for the refusal, or nothing.
std::string did_you_mean(std::string_view unknown, std::span<const std::string_view> known);

}  // namespace impact3d::case_format
