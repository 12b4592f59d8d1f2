// The example luminaires of data/luminaires/: each reads, and its zonal flux equals the file's
// lamp lumens x LOR within 0.1 %.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "photometry/light_distribution.hpp"
#include "photometry/photometric_file.hpp"
#include "photometry/zonal_flux.hpp"

namespace {

using namespace penumbra::photometry;

const std::filesystem::path kFolder =
    std::filesystem::path(PENUMBRA_SOURCE_DIR) / "data/luminaires";

struct Example {
  const char* file;
  PhotometricFormat format;
  const char* version;
  HorizontalSymmetry symmetry;
  OpeningShape opening;
  double lampLumens;
  double lor;
};

TEST(ExampleLuminaires, ReadAndConserveTheirFlux) {
  const Example examples[] = {
      {"lambertian-panel.ldt", PhotometricFormat::Eulumdat, "EULUMDAT",
       HorizontalSymmetry::Rotational, OpeningShape::Rectangle, 3600, 0.9999},
      {"narrow-downlight.ies", PhotometricFormat::Ies, "LM-63-2002", HorizontalSymmetry::Rotational,
       OpeningShape::Disk, 2000, 0.85},
      {"batwing.ldt", PhotometricFormat::Eulumdat, "EULUMDAT", HorizontalSymmetry::Quadrant,
       OpeningShape::Rectangle, 4400, 0.90},
      {"asymmetric-wallwasher.ies", PhotometricFormat::Ies, "LM-63-2019", HorizontalSymmetry::None,
       OpeningShape::Rectangle, 1500, 0.75},
  };
  int files = 0;
  for (const Example& e : examples) {
    const PhotometricData data = readPhotometricFile(kFolder / e.file);
    EXPECT_EQ(data.format, e.format) << e.file;
    EXPECT_EQ(data.version, e.version) << e.file;
    EXPECT_EQ(data.symmetry, e.symmetry) << e.file;
    EXPECT_EQ(data.opening.shape, e.opening) << e.file;
    EXPECT_EQ(data.lampLumens, e.lampLumens) << e.file;
    ASSERT_TRUE(data.lightOutputRatio.has_value()) << e.file;
    EXPECT_DOUBLE_EQ(*data.lightOutputRatio, e.lor) << e.file;
    EXPECT_TRUE(data.warnings.empty()) << e.file << ": " << data.warnings.front();
    const LightDistribution distribution(data);
    const FluxComparison flux = compareFlux(data, distribution);
    ASSERT_TRUE(flux.relativeDifference.has_value()) << e.file;
    EXPECT_DOUBLE_EQ(*flux.fileLm, e.lampLumens * e.lor) << e.file;
    EXPECT_LT(std::abs(*flux.relativeDifference), 1e-3)
        << e.file << ": zonal " << flux.zonalLm << " lm, file " << *flux.fileLm << " lm";
    ++files;
  }
  // Every file of the folder is one of the above.
  int onDisk = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kFolder))
    onDisk += entry.is_regular_file();
  EXPECT_EQ(onDisk, files);
}

TEST(ExampleLuminaires, ShapesAreWhatTheirNamesSay) {
  const auto load = [](const char* name) {
    return LightDistribution(readPhotometricFile(kFolder / name));
  };
  // The downlight's half-intensity angle lies between 10 and 11.5° (a beam of about 21°).
  const LightDistribution downlight = load("narrow-downlight.ies");
  const double peak = downlight.intensity(TableAngles{0, 0});
  EXPECT_EQ(downlight.peak().candela, peak);
  EXPECT_GT(downlight.intensity(TableAngles{0, 10}), peak / 2);
  EXPECT_LT(downlight.intensity(TableAngles{0, 11.5}), peak / 2);
  // The batwing's peak lies off-axis, across the luminaire (C90), at twice the nadir intensity
  // (its shape cos γ (1 + 4 sin²γ) peaks at γ = acos(sqrt(5/12)) = 49.8°).
  const LightDistribution batwing = load("batwing.ldt");
  const PeakIntensity bat = batwing.peak();
  EXPECT_EQ(bat.at.verticalDeg, 50);
  EXPECT_EQ(std::fmod(bat.at.horizontalDeg, 180.0), 90);
  EXPECT_GT(bat.candela, 2 * batwing.intensity(TableAngles{0, 0}));
  // The wall-washer throws towards C0 (its lobe is centred on C8): at γ = 60° its formula gives
  // 9.5 times more at C10 than opposite, at C190, and more at C10 than at C350.
  const LightDistribution washer = load("asymmetric-wallwasher.ies");
  EXPECT_GT(washer.intensity(TableAngles{10, 60}), 9 * washer.intensity(TableAngles{190, 60}));
  EXPECT_GT(washer.intensity(TableAngles{10, 60}), washer.intensity(TableAngles{350, 60}));
  // The panel: I(γ) = I(0) cos γ at the nodes, to the table's rounding: each value is within
  // 0.05 cd/klm x 3.6 klm = 0.18 cd of the formula, so the difference within 0.18 (1 + cos γ).
  const LightDistribution panel = load("lambertian-panel.ldt");
  const double i0 = panel.intensity(TableAngles{0, 0});
  for (double g = 0; g < 90; g += 5) {
    const double c = std::cos(g * M_PI / 180);
    EXPECT_NEAR(panel.intensity(TableAngles{0, g}), i0 * c, 0.18 * (1 + c) + 1e-9);
  }
}

}  // namespace
