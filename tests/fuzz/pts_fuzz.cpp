// libFuzzer target: Radiance sensor points (.pts text) → points with unit normals or one
// SceneError.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.hpp"
#include "scene/pts_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path file = "fuzz.pts";
  const std::string text(reinterpret_cast<const char*>(data), size);
  penumbra::fuzz::expectValueOrSceneError([&] {
    const auto points = penumbra::scenefile::parsePts(text, file, "grids[0].points");
    if (points.positions.size() != points.normals.size()) {
      penumbra::fuzz::reject("positions and normals differ in number", "");
    }
    // A normal is divided by its length: a huge or tiny but non-zero vector must still come out
    // as a finite unit vector, or the kernel integrates NaN.
    for (const auto& n : points.normals) {
      if (!std::isfinite(n.norm()) || std::abs(n.norm() - 1.0) > 1e-9) {
        penumbra::fuzz::reject("normal is not a finite unit vector", "");
      }
    }
  });
  return 0;
}
