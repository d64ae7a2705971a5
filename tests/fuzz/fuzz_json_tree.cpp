// libFuzzer harness, differential: whatever the fast reader (simdjson) accepts, the checking reader
// (nlohmann, with the limits) must accept too and read to the same tree, number texts and values
// included; the fast reader may refuse what the checker accepts (it then reads it). Any disagreement
// aborts.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "impact3d/io/case_spec.hpp"
#include "impact3d/io/json_tree.hpp"
#include "json_tree_equal.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace impact3d::io;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  JsonValue fast;
  if (!parse_json_tree_fast(text, fast)) return 0;
  try {
    if (!json_tree_equal(fast, parse_json_tree_checked(text))) std::abort();
  } catch (const CaseError&) {
    std::abort();  // the fast reader accepted what the checker refuses
  }
  return 0;
}
