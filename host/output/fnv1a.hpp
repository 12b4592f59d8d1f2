#pragma once
// FNV-1a, 64 bits: tells changed inputs apart (case fingerprints, drawn charts); nothing here
// needs a cryptographic hash.
#include <bit>
#include <cstdint>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "geometry/vec.hpp"

namespace penumbra {

class Fnv1a {
 public:
  void add(std::string_view text) {
    for (unsigned char c : text) {
      hash_ ^= c;
      hash_ *= 0x100000001b3ULL;
    }
    add('\n');
  }
  void add(char c) {
    hash_ ^= static_cast<unsigned char>(c);
    hash_ *= 0x100000001b3ULL;
  }
  // The bits of the double: exact, and fast enough for grids of millions of points.
  void add(double value) {
    const auto bits = std::bit_cast<std::uint64_t>(value);
    for (int byte = 0; byte < 8; ++byte) add(static_cast<char>((bits >> (8 * byte)) & 0xff));
  }
  void add(const Vec3& v) {
    add(v.x());
    add(v.y());
    add(v.z());
  }
  std::string hex() const { return fmt::format("{:016x}", hash_); }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

}  // namespace penumbra
