#pragma once
// What the photometry fuzz targets check on a file a reader accepts: the distribution built from
// it is finite everywhere, and so are its flux and its peak.
#include <cmath>
#include <string>

#include "fuzz_check.hpp"
#include "photometry/light_distribution.hpp"
#include "photometry/photometric_error.hpp"
#include "photometry/zonal_flux.hpp"

namespace penumbra::fuzz {

inline void expectUsable(const photometry::PhotometricData& data) {
  if (data.candela.size() != data.horizontalAnglesDeg.size() * data.verticalAnglesDeg.size()) {
    reject("table size differs from the angles", "");
  }
  const photometry::LightDistribution distribution(data);
  const photometry::FluxComparison flux = photometry::compareFlux(data, distribution);
  if (!std::isfinite(flux.zonalLm) || flux.zonalLm < 0) {
    reject("zonal flux not finite and positive", std::to_string(flux.zonalLm));
  }
  if (!std::isfinite(distribution.peak().candela)) reject("peak not finite", "");
  // Directions along the axes, between them and at the poles.
  for (int i = 0; i < 27; ++i) {
    const Vec3 d(i % 3 - 1.0, (i / 3) % 3 - 1.0, i / 9 - 1.0);
    if (d.isZero()) continue;
    const double cd = distribution.intensity(d);
    if (!std::isfinite(cd) || cd < 0) reject("intensity not finite or negative", "");
  }
}

// Parses one input with `parse` (parseIes or parseLdt) as `file`.
template <typename Parse>
void checkPhotometricInput(Parse parse, const std::string& text, const char* file) {
  expectValueOrFileError<photometry::PhotometricError>(
      [&] { expectUsable(parse(text, std::filesystem::path(file))); });
}

}  // namespace penumbra::fuzz
