// FNV-1a, 64 bits (src/core/fnv1a.hpp), against the published test vectors
// of its authors (Fowler, Noll, Vo: "" and "a", "foobar").
#include <gtest/gtest.h>

#include "core/fnv1a.hpp"

namespace pita {
namespace {

std::uint64_t of(std::string_view text) {
  Fnv1a hash;
  hash.add(text);
  return hash.value();
}

TEST(Fnv1a, PublishedVectors) {
  EXPECT_EQ(of(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(of("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(of("foobar"), 0x85944171f73967e8ULL);
}

TEST(Fnv1a, NumbersAddTheirEightBytesLittleEndFirst) {
  Fnv1a number;
  number.add(std::uint64_t{0x0000000000000061ULL});  // 'a' then seven zero bytes
  EXPECT_EQ(number.value(), of(std::string_view("a\0\0\0\0\0\0\0", 8)));
  Fnv1a zero, negative_zero;
  zero.add(0.0);
  negative_zero.add(-0.0);
  EXPECT_NE(zero.value(), negative_zero.value());
}

}  // namespace
}  // namespace pita
