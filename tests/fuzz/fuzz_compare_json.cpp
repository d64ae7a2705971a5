// libFuzzer harness: any bytes as another tool's result JSON for `impact3d compare`.
#include "fuzz_compare.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { return fuzz_compare(data, size, ".json"); }
