#pragma once
// Numbers as the result files write them: the text fmt::format("{}", v) gives (the shortest that
// reads back to the same double; fixed notation for decimal exponents in [-4, 16), otherwise
// "1e-05" style), written straight into a caller's buffer. A value computed in single precision
// is written with the digits of its float (NumberDigits::Float): the shortest text that reads back
// to the same float, at most 9 significant digits, since the further digits of its double hold
// no information.
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

// How many digits a value holds: those of a double, or those of a float (a value the kernels
// computed in single precision, even when the host summed it in double).
enum class NumberDigits { Double, Float };

// writeNumber with the digits `digits` says: Float writes fmt::format("{}", float(value)).
inline char* writeNumber(char* out, double value, NumberDigits digits) {
  if (digits == NumberDigits::Double) return writeNumber(out, value);
  return fmt::format_to(out, FMT_COMPILE("{}"), static_cast<float>(value));
}

// The double whose shortest text is the text writeNumber(value, digits) gives, for writers that
// print doubles shortest themselves (summary.json): `value` itself for Double, and for Float the
// double nearest to its float's shortest decimal (which a double prints back the same, a decimal
// of at most 15 significant digits always reading back from a double unchanged).
double withDigits(double value, NumberDigits digits);

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
