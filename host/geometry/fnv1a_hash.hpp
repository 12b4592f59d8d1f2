#pragma once
// FNV-1a over the exact bits of numbers and the bytes of names: a 64-bit fingerprint that tells
// changed inputs apart (a case's fingerprint, the charts a sweep drew, the interreflection's
// transfer cache). Nothing here needs a cryptographic hash.
#include <bit>
#include <cstdint>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "geometry/convex_polygon.hpp"
#include "geometry/vec.hpp"

namespace penumbra {

class Fnv1a {
 public:
  void add(std::string_view text) {
    for (unsigned char c : text) addByte(c);
    addByte('\n');
  }
  void add(char c) { addByte(static_cast<unsigned char>(c)); }
  // The bits of the double: exact, and fast enough for grids of millions of points.
  void add(double value) {
    const auto bits = std::bit_cast<std::uint64_t>(value);
    for (int byte = 0; byte < 8; ++byte) addByte(static_cast<unsigned char>(bits >> (8 * byte)));
  }
  void add(const Vec3& v) {
    add(v.x());
    add(v.y());
    add(v.z());
  }
  void add(const ConvexPolygon& polygon) {
    add(std::string_view("polygon"));
    for (const Vec3& v : polygon.vertices()) add(v);
  }
  std::uint64_t value() const { return hash_; }
  std::string hex() const { return fmt::format("{:016x}", hash_); }

 private:
  void addByte(unsigned char byte) {
    hash_ ^= byte;
    hash_ *= 0x100000001b3ULL;
  }
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

}  // namespace penumbra
