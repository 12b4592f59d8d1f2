#pragma once
// Scenes with photometric luminaires for the point-model tests: a luminaire built from a file the
// way the scene loader builds it, and the kernel's and the host reference's E.
#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <vector>

#include "engine/illuminance_engine.hpp"
#include "reference/luminaire_illuminance.hpp"
#include "scene/luminaire_builder.hpp"
#include "test_device.hpp"

namespace penumbra::testing {

inline const std::filesystem::path kExampleLuminaires = PENUMBRA_SOURCE_DIR "/data/luminaires";

// Writes `text` to `dir`/`name` and returns the path.
inline std::filesystem::path writeFile(const std::filesystem::path& dir, const std::string& name,
                                       const std::string& text) {
  std::ofstream(dir / name) << text;
  return dir / name;
}

struct PlacedLuminaire {
  std::filesystem::path file;  // absolute
  Vec3 position = Vec3::Zero();
  LuminaireAim aim;
  double maintenanceFactor = 1.0;
};

inline Luminaire placeLuminaire(const PlacedLuminaire& placed) {
  scenefile::LuminaireSpec spec;
  spec.name = placed.file.stem().string();
  spec.file = placed.file.string();
  spec.position = placed.position;
  spec.aim = placed.aim;
  spec.maintenanceFactor = placed.maintenanceFactor;
  return scenefile::buildLuminaire(spec, scenefile::BuildContext{"test.yaml", 1e-6, {}});
}

inline std::vector<double> kernelE(const Scene& scene, std::span<const SamplePoint> points) {
  IlluminanceEngine engine(cpuDevice(), scene);
  return engine.illuminance(points);
}

inline std::vector<double> referenceE(const Scene& scene, std::span<const SamplePoint> points) {
  return referenceLuminaireIlluminance(scene, points);
}

}  // namespace penumbra::testing
