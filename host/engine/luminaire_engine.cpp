#include "engine/luminaire_engine.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "cl/buffer.hpp"
#include "engine/illuminance_engine.hpp"
#include "engine/kernel_scene.hpp"
#include "engine/luminaire_scene.hpp"

namespace penumbra {

using compute::DeviceBuffer;

namespace {

// Work-items per work-group: fixed, so that PoCL compiles the kernel once (KernelLaunch::run).
constexpr std::size_t kWorkGroup = 64;

}  // namespace

struct LuminaireEngine::State {
  compute::Device* device = nullptr;
  EngineOptions options;
  compute::Program program;
  Vec3 origin = Vec3::Zero();
  PnLuminaireParams params{};
  DeviceBuffer luminaires, tables, angles, candela, solids, planes;
  std::size_t sceneBytes = 0;
  std::vector<int> instanceOf;  // per point source, its placed instance
  std::vector<int> cellsOf;     // per placed instance, its point sources (0: an exact opening)
  int placed = 0;               // placed instances
  // The area model's openings (built at the first scene that has some, kept for later ones).
  std::unique_ptr<IlluminanceEngine> openings;
  std::vector<int> openingInstance;  // per opening source, its placed instance

  State(compute::Device& d, const EngineOptions& o)
      : device(&d), options(o), program(d, "luminaire", illuminanceBuildOptions()) {}
};

LuminaireEngine::LuminaireEngine(compute::Device& device, const EngineOptions& options)
    : state_(std::make_unique<State>(device, options)) {}
LuminaireEngine::~LuminaireEngine() = default;

void LuminaireEngine::setScene(const Scene& scene, const Vec3& origin, float epsLength) {
  State& s = *state_;
  compute::Device& d = *s.device;
  OpeningScene openings = openingScene(scene);
  s.openingInstance = std::move(openings.instanceOf);
  if (!s.openingInstance.empty()) {
    if (s.openings)
      s.openings->setScene(openings.scene);
    else
      s.openings = std::make_unique<IlluminanceEngine>(d, openings.scene, s.options);
  }
  s.placed = placedInstanceCount(scene);
  LuminaireKernelScene packed = packLuminaires(scene, origin);
  s.instanceOf = std::move(packed.instanceOf);
  s.cellsOf.assign(static_cast<std::size_t>(s.placed), 0);
  for (int instance : s.instanceOf) ++s.cellsOf[static_cast<std::size_t>(instance)];
  const std::vector<std::size_t> tables = {
      compute::byteSize(packed.luminaires), compute::byteSize(packed.tables),
      compute::byteSize(packed.angles),     compute::byteSize(packed.candela),
      compute::byteSize(packed.solids),     compute::byteSize(packed.planes)};
  compute::requireDeviceMemory(d.info(), tables, 0,
                               fmt::format("the luminaires (placed: {}, candela values: {})",
                                           packed.luminaires.size(), packed.candela.size()),
                               "use fewer luminaires or a device with more memory (--device)");
  s.sceneBytes = 0;
  for (std::size_t b : tables) s.sceneBytes += b;
  s.origin = origin;
  s.params = PnLuminaireParams{};
  s.params.luminaireCount = static_cast<cl_int>(packed.luminaires.size());
  s.params.solidCount = static_cast<cl_int>(packed.solids.size());
  s.params.epsLength = epsLength;
  s.luminaires = DeviceBuffer::upload<PnLuminaire>(d, packed.luminaires);
  s.tables = DeviceBuffer::upload<PnCandelaTable>(d, packed.tables);
  s.angles = DeviceBuffer::upload<float>(d, packed.angles);
  s.candela = DeviceBuffer::upload<float>(d, packed.candela);
  s.solids = DeviceBuffer::upload<PnShadowSolid>(d, packed.solids);
  s.planes = DeviceBuffer::upload<cl_float4>(d, packed.planes);
}

LuminaireEngine::Result LuminaireEngine::evaluate(std::span<const SamplePoint> points) {
  State& s = *state_;
  const std::size_t n = points.size();
  const std::size_t placed = static_cast<std::size_t>(s.placed);
  Result result;
  result.luminaires = s.placed;
  result.illuminance.assign(n, 0.0);
  result.shadow.assign(n * placed, ShadowClass::Umbra);
  if (n == 0) return result;
  const PointSources point = evaluatePointSources(points);
  const std::size_t sources = s.instanceOf.size();
  // A subdivided opening's cells are hard-shadowed point sources: where a point sees some of
  // them and not the others, its light is a staircase of their shadows (Penumbra).
  std::vector<int> seen(placed);
  for (std::size_t i = 0; i < n; ++i) {
    result.illuminance[i] = point.illuminance[i];
    std::fill(seen.begin(), seen.end(), 0);
    for (std::size_t l = 0; l < sources; ++l)
      if (point.seen[i * sources + l]) ++seen[static_cast<std::size_t>(s.instanceOf[l])];
    for (std::size_t l = 0; l < placed; ++l)
      if (s.cellsOf[l] > 0 && seen[l] > 0)
        result.shadow[i * placed + l] =
            seen[l] == s.cellsOf[l] ? ShadowClass::Lit : ShadowClass::Penumbra;
  }
  if (s.openingInstance.empty()) return result;
  const IlluminanceResult area = s.openings->evaluate(points, true);
  const std::size_t openings = s.openingInstance.size();
  for (std::size_t i = 0; i < n; ++i) {
    result.illuminance[i] += area.illuminance[i];
    for (std::size_t o = 0; o < openings; ++o) {
      const std::size_t l = static_cast<std::size_t>(s.openingInstance[o]);
      result.shadow[i * placed + l] = area.bySource[i * openings + o] > 0.0
                                          ? area.shadow(i, static_cast<int>(o))
                                          : ShadowClass::Umbra;
    }
  }
  return result;
}

LuminaireEngine::PointSources LuminaireEngine::evaluatePointSources(
    std::span<const SamplePoint> points) {
  State& s = *state_;
  const std::size_t n = points.size();
  const std::size_t count = static_cast<std::size_t>(s.params.luminaireCount);
  PointSources result;
  if (n == 0 || count == 0) {
    result.illuminance.assign(n, 0.0);
    result.seen.assign(n * count, 0);
    return result;
  }
  compute::Device& d = *s.device;
  const std::size_t padded = (n + kWorkGroup - 1) / kWorkGroup * kWorkGroup;
  std::vector<std::size_t> batch(8, padded * sizeof(float));
  batch.push_back(padded * count);
  if (!compute::fitsDevice(d.info(), batch, s.sceneBytes) && n > kWorkGroup) {
    const std::size_t half = (n / 2 + kWorkGroup - 1) / kWorkGroup * kWorkGroup;
    PointSources first = evaluatePointSources(points.first(half));
    const PointSources second = evaluatePointSources(points.subspan(half));
    first.illuminance.insert(first.illuminance.end(), second.illuminance.begin(),
                             second.illuminance.end());
    first.seen.insert(first.seen.end(), second.seen.begin(), second.seen.end());
    return first;
  }
  compute::requireDeviceMemory(d.info(), batch, s.sceneBytes,
                               fmt::format("a batch of {} points", n),
                               "use fewer luminaires or a device with more memory (--device)");
  std::vector<float> coords[6];
  for (auto& c : coords) c.resize(padded);
  std::vector<cl_int> own(padded);
  for (std::size_t i = 0; i < padded; ++i) {
    const SamplePoint& p = points[std::min(i, n - 1)];
    for (int k = 0; k < 3; ++k) {
      coords[k][i] = static_cast<float>(p.position[k] - s.origin[k]);
      coords[3 + k][i] = static_cast<float>(p.normal[k]);
    }
    own[i] = p.solid;
  }
  DeviceBuffer pointBuffers[6];
  for (int k = 0; k < 6; ++k) pointBuffers[k] = DeviceBuffer::upload<float>(d, coords[k]);
  DeviceBuffer ownBuffer = DeviceBuffer::upload<cl_int>(d, own);
  DeviceBuffer out = DeviceBuffer::allocate(d, padded * sizeof(float));
  DeviceBuffer seen = DeviceBuffer::allocate(d, padded * count);
  PnLuminaireParams params = s.params;
  params.pointCount = static_cast<cl_int>(n);
  params.pointStride = static_cast<cl_int>(padded);

  compute::KernelLaunch launch(s.program, "luminaire_illuminance");
  unsigned index = 0;
  launch.arg(index++, &params, sizeof params);
  for (const DeviceBuffer& b : pointBuffers) launch.arg(index++, b);
  launch.arg(index++, ownBuffer);
  for (const DeviceBuffer* b :
       {&s.luminaires, &s.tables, &s.angles, &s.candela, &s.solids, &s.planes, &out, &seen}) {
    launch.arg(index++, *b);
  }
  launch.run(padded, kWorkGroup);
  std::vector<float> e(padded);
  out.download(e.data(), padded * sizeof(float));
  result.illuminance.assign(e.begin(), e.begin() + static_cast<std::ptrdiff_t>(n));
  // The kernel writes luminaire by luminaire; callers read point by point.
  std::vector<std::uint8_t> byLuminaire(padded * count);
  seen.download(byLuminaire.data(), byLuminaire.size());
  result.seen.resize(n * count);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t l = 0; l < count; ++l)
      result.seen[i * count + l] = byLuminaire[l * padded + i];
  return result;
}

}  // namespace penumbra
