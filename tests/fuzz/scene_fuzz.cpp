// libFuzzer target: scene text (YAML, format v1) → a validated scene or one SceneError.
// The file name sits in the source tree's data/ so that relative `.pts` paths in the corpus
// resolve to data/sensors.pts, as they do for the shipped scenes. A scene that loads must be fit
// for the kernel: finite points, unit normals, finite luminances.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.hpp"

namespace {

void expectUsable(const penumbra::Scene& scene) {
  using penumbra::fuzz::reject;
  for (const auto& grid : scene.grids) {
    // A planar grid's points are worked out from its frame: check every one (the loader caps a
    // grid at 10^7 points, and the fuzzer's scenes are far smaller).
    if (grid.size() == 0) reject("grid has no points", grid.name);
    for (std::size_t i = 0; i < grid.size(); ++i) {
      if (!grid.position(i).allFinite()) reject("grid point not finite", grid.name);
      if (!(std::abs(grid.normal(i).norm() - 1.0) <= 1e-9)) reject("normal not unit", grid.name);
    }
  }
  for (const auto& source : scene.sources) {
    if (!std::isfinite(source.luminance)) reject("luminance not finite", source.name);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path file =
      std::filesystem::path(PENUMBRA_SOURCE_DIR) / "data" / "fuzz.yaml";
  const std::string text(reinterpret_cast<const char*>(data), size);
  penumbra::fuzz::expectValueOrSceneError([&] { expectUsable(penumbra::parseScene(text, file)); });
  return 0;
}
