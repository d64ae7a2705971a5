// libFuzzer harness, differential: whatever the fast reader (simdjson) accepts, the checking reader
// (nlohmann, with the limits) must accept too and read to the same tree, number texts and values
// included; the fast reader may refuse what the checker accepts (it then reads it). Read into a tree
// that held the inputs before, it gives the same verdict and tree as into a new one. Any disagreement
// aborts.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/json_tree.hpp"
#include "json_tree_equal.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace impact3d::case_format;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  JsonValue fast;
  const bool accepted = parse_json_tree_fast(text, fast);
  // Read again into the tree of the inputs before (as read_case reuses one): the same verdict and tree.
  static JsonValue reused;
  if (parse_json_tree_fast(text, reused) != accepted || (accepted && !json_tree_equal(reused, fast))) std::abort();
  if (!accepted) return 0;
  try {
    if (!json_tree_equal(fast, parse_json_tree_checked(text))) std::abort();
  } catch (const CaseError&) {
    std::abort();  // the fast reader accepted what the checker refuses
  }
  return 0;
}
