// libFuzzer harness: any bytes as a --strategy option ("wach:mu=0.4,limit=gir" or a JSON object).
#include <cstddef>
#include <cstdint>
#include <string>

#include "impact3d/case_format/read_case.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const auto s = impact3d::case_format::read_strategy_option(std::string(reinterpret_cast<const char*>(data), size), 0);
    (void)impact3d::case_format::to_strategy<double>(s);
    (void)impact3d::case_format::strategy_label(s);
  } catch (const impact3d::case_format::CaseError&) {
  }
  return 0;
}
