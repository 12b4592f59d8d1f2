#pragma once
// Numbers as the result files write them: the text fmt::format("{}", v) gives (the shortest that
// reads back to the same double; fixed notation for decimal exponents in [-4, 16), otherwise
// "1e-05" style), written straight into a caller's buffer. A double that holds a single-precision
// value (the kernel computes E in float) is written as that float: the shortest text that reads
// back to the same float, "23.168062" and not the float's exact binary value "23.168062210083008",
// whose last digits the computation never had.
#include <fmt/compile.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace penumbra {

// The longest text writeNumber gives is 24 characters ("-2.2250738585072014e-308").
inline constexpr std::size_t kMaxNumberText = 32;

// True when `value` is exactly a float: a single-precision result held in a double. (A value
// computed in double is one only by a chance of about 2^-29, and for short decimals such as 0.25,
// whose text is the same either way.)
inline bool holdsFloat(double value) {
  return std::fabs(value) <= std::numeric_limits<float>::max() &&
         static_cast<double>(static_cast<float>(value)) == value;
}

// Writes `value` at `out` as fmt::format("{}", value) does, a float held in a double as
// fmt::format("{}", float) does, and returns the end; needs kMaxNumberText bytes at `out`.
inline char* writeNumber(char* out, double value) {
  if (holdsFloat(value)) return fmt::format_to(out, FMT_COMPILE("{}"), static_cast<float>(value));
  return fmt::format_to(out, FMT_COMPILE("{}"), value);
}

// writeNumber's text as a string.
std::string numberText(double value);

// The value to hand a JSON writer (which writes the shortest text of a double): a float held in a
// double becomes the double nearest to the float's shortest text, so that the JSON shows the
// digits writeNumber writes; other values are returned as they are.
double jsonNumber(double value);

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
