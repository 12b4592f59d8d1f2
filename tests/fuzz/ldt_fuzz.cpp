// libFuzzer target: EULUMDAT text → photometric data with a finite distribution, or one
// PhotometricError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "photometry/ldt_reader.hpp"
#include "photometry_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  penumbra::fuzz::checkPhotometricInput(penumbra::photometry::parseLdt, text, "fuzz.ldt");
  return 0;
}
