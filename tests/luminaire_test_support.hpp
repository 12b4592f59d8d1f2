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
  LuminaireModel model = LuminaireModel::Point;
};

inline Luminaire placeLuminaire(const PlacedLuminaire& placed) {
  scenefile::LuminaireSpec spec;
  spec.name = placed.file.stem().string();
  spec.file = placed.file.string();
  spec.position = placed.position;
  spec.aim = placed.aim;
  spec.maintenanceFactor = placed.maintenanceFactor;
  spec.model = placed.model;
  return scenefile::buildLuminaire(spec, scenefile::BuildContext{"test.yaml", 1e-6, {}});
}

// ∫ E dA over the six faces of the cube [-h, h]³ around a luminaire at the origin: the flux that
// leaves it, by composite Gauss–Legendre quadrature (panels × panels cells per face, 3 × 3
// points per cell).
struct BoxQuadrature {
  std::vector<SamplePoint> points;
  std::vector<double> weights;  // m²

  double received(const std::vector<double>& e) const {
    double sum = 0.0;
    for (std::size_t i = 0; i < e.size(); ++i) sum += e[i] * weights[i];
    return sum;
  }
};

inline BoxQuadrature boxQuadrature(int panels, double h = 1.0) {
  constexpr double kNodes[3] = {0.5 - 0.3872983346207417, 0.5, 0.5 + 0.3872983346207417};
  constexpr double kWeights[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
  BoxQuadrature q;
  const double cell = 2.0 * h / panels;
  for (int axis = 0; axis < 3; ++axis) {
    for (double side : {-h, h}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      Vec3 normal = Vec3::Zero();
      normal[axis] = side > 0 ? -1.0 : 1.0;
      for (int i = 0; i < panels; ++i)
        for (int j = 0; j < panels; ++j)
          for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) {
              Vec3 p;
              p[axis] = side;
              p[u] = -h + (i + kNodes[a]) * cell;
              p[v] = -h + (j + kNodes[b]) * cell;
              q.points.push_back(SamplePoint{p, normal, -1});
              q.weights.push_back(kWeights[a] * kWeights[b] * cell * cell);
            }
    }
  }
  return q;
}

inline std::vector<double> kernelE(const Scene& scene, std::span<const SamplePoint> points) {
  IlluminanceEngine engine(cpuDevice(), scene);
  return engine.illuminance(points);
}

inline std::vector<double> referenceE(const Scene& scene, std::span<const SamplePoint> points) {
  return referenceLuminaireIlluminance(scene, points);
}

}  // namespace penumbra::testing
