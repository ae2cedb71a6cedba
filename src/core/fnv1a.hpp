// FNV-1a, 64 bits: a fast hash of bytes and numbers (not cryptographic), for
// content hashes (a sweep's variants) and digests of what a figure draws.
#pragma once

#include <bit>
#include <cstdint>
#include <string_view>

namespace pita {

class Fnv1a {
 public:
  void add(std::string_view bytes) {
    for (const unsigned char c : bytes) {
      hash_ ^= c;
      hash_ *= kPrime;
    }
  }
  // The number's bits, little end first (-0.0 and 0.0 differ, as they may draw differently).
  void add(std::uint64_t bits) {
    for (int i = 0; i < 8; ++i) {
      hash_ ^= (bits >> (8 * i)) & 0xFFU;
      hash_ *= kPrime;
    }
  }
  void add(double x) { add(std::bit_cast<std::uint64_t>(x)); }
  std::uint64_t value() const { return hash_; }

 private:
  static constexpr std::uint64_t kPrime = 1099511628211ULL;
  std::uint64_t hash_ = 14695981039346656037ULL;
};

}  // namespace pita
