// libFuzzer target: IES LM-63 text → photometric data with a finite distribution, or one
// PhotometricError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "photometry/ies_reader.hpp"
#include "photometry_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  penumbra::fuzz::checkPhotometricInput(penumbra::photometry::parseIes, text, "fuzz.ies");
  return 0;
}
