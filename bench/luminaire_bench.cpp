// Throughput of the luminaire models in point·sources per second, beside the Lambertian source,
// on a work plane under one 0.6 × 0.6 m opening in a room with a desk that shades part of it:
//  - lambertian-rect: the Lambertian `rect` source of the same flux, on the device (kernel) and
//    by the exact host reference in double (exactIlluminance);
//  - point: a luminaire's point model on the device (kernels/luminaire.cl) and on the host;
//  - area: the area model at the fitted order, on the device (the illuminance kernel's moment
//    term, kernels/luminance_moments.cl) and on the host in double, for the Lambertian panel
//    (order 0) and the narrow downlight (its fitted order), and the panel's opening with a
//    luminance of order 9, L ∝ 0.25 + 0.75 cos⁹φ (what the moment term costs at that order).
// Prints one JSON line per case.
//   usage: luminaire_bench [--device cpu|gpu|<index>] [--points N] [--repeat R]
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstring>
#include <functional>
#include <iostream>
#include <string>

#include "cl/device.hpp"
#include "engine/illuminance_engine.hpp"
#include "reference/exact_illuminance.hpp"
#include "reference/luminaire_illuminance.hpp"
#include "reference/opening_illuminance.hpp"
#include "scene/luminaire_builder.hpp"

namespace {

using namespace penumbra;

const std::filesystem::path kLuminaires = PENUMBRA_SOURCE_DIR "/data/luminaires";
const Vec3 kCentre(2.0, 1.5, 2.95);

std::vector<SamplePoint> workPlane(int count) {
  std::vector<SamplePoint> points;
  const int side = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(count))));
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j)
      points.push_back(
          {Vec3(4.0 * (i + 0.5) / side, 3.0 * (j + 0.5) / side, 0.8), Vec3::UnitZ(), -1});
  return points;
}

Scene room() {
  Scene scene;
  // A desk between the opening and part of the work plane.
  scene.solids.push_back(
      Solid{"desk", ConvexPolyhedron::box({1.2, 0.8, 1.0}, {2.4, 1.6, 1.05}), -1});
  return scene;
}

Luminaire luminaire(const std::string& file, LuminaireModel model) {
  scenefile::LuminaireSpec spec;
  spec.name = file;
  spec.file = (kLuminaires / file).string();
  spec.position = kCentre;
  spec.model = model;
  return scenefile::buildLuminaire(spec, scenefile::BuildContext{"bench.yaml", 1e-6, {}});
}

double seconds(const std::function<void()>& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double best(int repeat, const std::function<void()>& f) {
  double t = 1e30;
  for (int r = 0; r < repeat; ++r) t = std::min(t, seconds(f));
  return t;
}

void report(const std::string& name, const std::string& where, std::size_t points, double s,
            const nlohmann::json& extra = nlohmann::json::object()) {
  nlohmann::json line = {
      {"case", name}, {"where", where}, {"points", points},
      {"sources", 1}, {"seconds", s},   {"point_sources_per_s", static_cast<double>(points) / s}};
  line.update(extra);
  std::cout << line.dump() << std::endl;
}

}  // namespace

int main(int argc, char** argv) {
  std::string deviceSpec = "cpu";
  int count = 128 * 128, repeat = 3;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--device"))
      deviceSpec = argv[i + 1];
    else if (!std::strcmp(argv[i], "--points"))
      count = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--repeat"))
      repeat = std::atoi(argv[i + 1]);
  }
  compute::Device device = compute::Device::select(deviceSpec);
  const std::vector<SamplePoint> points = workPlane(count);
  const std::span<const SamplePoint> all(points);
  const std::string deviceName = device.info().name;

  // The Lambertian rect source of the panel's flux over the panel's opening.
  const Luminaire panel = luminaire("lambertian-panel.ldt", LuminaireModel::Area);
  const ConvexPolygon opening = placedOpening(*panel.opening, panel.instances.front());
  Scene rect = room();
  Source source;
  source.name = "rect";
  source.faces.push_back(opening);
  source.luminance = panel.intensityScale * panel.opening->fit.coefficients[0];
  rect.sources.push_back(source);
  {
    IlluminanceEngine engine(device, rect);
    engine.illuminance(all.first(64));
    report("lambertian-rect", deviceName, points.size(),
           best(repeat, [&] { engine.illuminance(all); }));
    report("lambertian-rect", "host exact reference (double)", points.size(),
           best(repeat, [&] { exactIlluminance(rect, all); }));
  }
  for (const char* file : {"lambertian-panel.ldt", "narrow-downlight.ies"}) {
    Scene scene = room();
    scene.luminaires.push_back(luminaire(file, LuminaireModel::Point));
    IlluminanceEngine engine(device, scene);
    engine.illuminance(all.first(64));
    report(std::string("point ") + file, deviceName, points.size(),
           best(repeat, [&] { engine.illuminance(all); }));
    report(std::string("point ") + file, "host reference (double)", points.size(),
           best(repeat, [&] { referenceLuminaireIlluminance(scene, all); }));
    Scene area = room();
    area.luminaires.push_back(luminaire(file, LuminaireModel::Area));
    const LuminaireOpening& o = *area.luminaires.front().opening;
    const nlohmann::json fit = {{"fit_order", o.fit.order()},
                                {"fit_error", o.fit.peakRelativeError},
                                {"parts", {o.partsAlongLength, o.partsAlongWidth}},
                                {"opening_vertices", o.outline.size()}};
    IlluminanceEngine areaEngine(device, area);
    areaEngine.illuminance(all.first(64));
    report(std::string("area ") + file, deviceName, points.size(),
           best(repeat, [&] { areaEngine.illuminance(all); }), fit);
    report(std::string("area ") + file, "host (double)", points.size(),
           best(repeat, [&] { referenceLuminaireIlluminance(area, all); }), fit);
  }
  {
    Luminaire ordered = panel;
    const double c0 = panel.opening->fit.coefficients[0];
    ordered.opening->fit.coefficients.assign(10, 0.0);
    ordered.opening->fit.coefficients[0] = 0.25 * c0;
    ordered.opening->fit.coefficients[9] = 0.75 * c0;
    Scene area = room();
    area.luminaires.push_back(ordered);
    IlluminanceEngine engine(device, area);
    engine.illuminance(all.first(64));
    const nlohmann::json fit = {{"fit_order", 9}, {"opening_vertices", 4}};
    report("area panel opening, order 9", deviceName, points.size(),
           best(repeat, [&] { engine.illuminance(all); }), fit);
    report("area panel opening, order 9", "host (double)", points.size(),
           best(repeat, [&] { referenceLuminaireIlluminance(area, all); }), fit);
  }
  return 0;
}
