#pragma once
// Numbers as the result files write them: the text fmt::format("{}", v) gives (the shortest that
// reads back to the same double; fixed notation for decimal exponents in [-4, 16), otherwise
// "1e-05" style), written straight into a caller's buffer.
#include <fmt/compile.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace penumbra {

// The longest text writeNumber gives is 24 characters ("-2.2250738585072014e-308").
inline constexpr std::size_t kMaxNumberText = 32;

// Writes `value` at `out` as fmt::format("{}", value) does and returns the end; needs
// kMaxNumberText bytes at `out`.
inline char* writeNumber(char* out, double value) {
  return fmt::format_to(out, FMT_COMPILE("{}"), value);
}

// writeNumber for values that repeat: the text of recent values is kept by their bits, so that a
// grid's coordinates and normals (a row's y and z, a column's x, one normal for a whole plane)
// are copied instead of converted again. Direct-mapped, 2^14 slots (512 KiB): a value whose slot
// another one took is converted again; the text is the same either way.
class NumberTextCache {
 public:
  NumberTextCache();
  // Needs kMaxNumberText bytes at `out`, like writeNumber.
  char* write(char* out, double value);

 private:
  struct Entry {
    std::uint64_t bits;
    std::uint8_t size;
    char text[23];  // a longer text is written but not kept
  };
  static constexpr int kSlotBits = 14;
  std::vector<Entry> entries_;
};

}  // namespace penumbra
