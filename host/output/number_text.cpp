#include "output/number_text.hpp"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>

namespace penumbra {

// Every slot starts as 0.0, whose text is "0": a slot always holds a value and its own text.
NumberTextCache::NumberTextCache() : entries_(std::size_t{1} << kSlotBits, Entry{0, 1, {'0'}}) {}

char* NumberTextCache::write(char* out, double value) {
  const auto bits = std::bit_cast<std::uint64_t>(value);
  Entry& entry = entries_[(bits * 0x9E3779B97F4A7C15ull) >> (64 - kSlotBits)];
  if (entry.bits == bits) {
    std::memcpy(out, entry.text, sizeof entry.text);  // out has room for kMaxNumberText
    return out + entry.size;
  }
  char* end = writeNumber(out, value);
  const auto size = static_cast<std::size_t>(end - out);
  if (size <= sizeof entry.text) {
    entry.bits = bits;
    entry.size = static_cast<std::uint8_t>(size);
    std::memcpy(entry.text, out, size);
  }
  return end;
}

double withDigits(double value, NumberDigits digits) {
  if (digits == NumberDigits::Double || !std::isfinite(value)) return value;
  char text[kMaxNumberText];
  const char* end = writeNumber(text, value, digits);
  double shortest = value;
  std::from_chars(text, end, shortest);
  return shortest;
}

}  // namespace penumbra
