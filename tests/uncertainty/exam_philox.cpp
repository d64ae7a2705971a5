// Philox4x32-10 (uncertainty/philox.hpp) against the known answers Random123 publishes with its
// generators (DEShawResearch/random123, tests/kat_vectors: the three philox4x32 lines with 10 rounds:
// counter and key all zeros, all ones, and the digits of pi).
#include <catch2/catch.hpp>

#include "impact3d/uncertainty/philox.hpp"

namespace exam_philox {

using impact3d::uncertainty::philox4x32_10;
using impact3d::uncertainty::PhiloxCounter;
using impact3d::uncertainty::PhiloxKey;

TEST_CASE("Philox4x32-10 gives Random123's known answers") {
  struct Known {
    PhiloxCounter counter;
    PhiloxKey key;
    PhiloxCounter out;
  };
  constexpr Known known[] = {
      {{0, 0, 0, 0}, {0, 0}, {0x6627e8d5, 0xe169c58d, 0xbc57ac4c, 0x9b00dbd8}},
      {{0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff}, {0xffffffff, 0xffffffff}, {0x408f276d, 0x41c83b0e, 0xa20bc7c6, 0x6d5451fd}},
      {{0x243f6a88, 0x85a308d3, 0x13198a2e, 0x03707344}, {0xa4093822, 0x299f31d0}, {0xd16cfe09, 0x94fdcceb, 0x5001e420, 0x24126ea1}},
  };
  for (const Known& k : known) CHECK(philox4x32_10(k.counter, k.key) == k.out);
  // And at compile time, where the function is also used.
  static_assert(philox4x32_10(known[2].counter, known[2].key) == known[2].out);
}

}  // namespace exam_philox
