#pragma once
// Exact direct illuminance at sample points: the Lambertian sources by kernels/illuminance.cl,
// the photometric luminaires by LuminaireEngine (the point model by kernels/luminaire.cl, the area
// model's openings by kernels/illuminance.cl in a scene of their own).
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "cl/device.hpp"
#include "engine/engine_options.hpp"
#include "geometry/sample_point.hpp"
#include "scene/scene.hpp"
#include "shadow/shadow_class.hpp"

namespace penumbra {

struct IlluminanceResult {
  std::vector<double> illuminance;       // lx, per point, summed over all sources and luminaires
  std::vector<ShadowClass> shadowClass;  // [point * sourceCount + source]
  std::vector<double> bySource;          // lx, [point * sourceCount + source], when asked for
  int sourceCount = 0;
  // lx per point from the photometric luminaires (included in `illuminance`); empty when the
  // scene has none. They are white: a render adds them to every channel.
  std::vector<double> luminaires;
  // [point * luminaireCount + l]: placed luminaire l's shadow class (LuminaireEngine::Result).
  std::vector<ShadowClass> luminaireShadow;
  int luminaireCount = 0;
  ShadowClass shadow(std::size_t point, int source) const {
    return shadowClass[point * static_cast<std::size_t>(sourceCount) + source];
  }
};

class IlluminanceEngine {
 public:
  // Builds the program, the shadow geometry (host/shadow) and uploads the scene once;
  // illuminance() may then be called many times.
  IlluminanceEngine(compute::Device& device, const Scene& scene, EngineOptions options = {});
  ~IlluminanceEngine();

  // Replaces the scene and keeps the compiled program and the device: what a sweep does between
  // cases. Afterwards illuminance() answers for `scene` only.
  void setScene(const Scene& scene);

  // E in lx at every point, summed over all sources and luminaires: evaluate()'s values without
  // the shadow classes.
  std::vector<double> illuminance(std::span<const SamplePoint> points);
  // E and each point's shadow class per source. With culling off the classes come from the
  // plain path's tests: Lit or Penumbra ("some occluder may block"), never Umbra.
  // With `bySource`, also E from each source separately (a render needs it when sources differ
  // in colour).
  IlluminanceResult evaluate(std::span<const SamplePoint> points, bool bySource = false);
  // E from each source separately, in float as the kernel computes it, for points in the order
  // given (no reordering, no shadow classes): value [source · stride + point]. What the
  // interreflection's element-to-element transfer reads, where per-source values are the
  // whole output and copying them would cost more than computing them.
  std::vector<float> illuminanceBySource(std::span<const SamplePoint> points, std::size_t& stride);
  // illuminanceBySource for each of `batches` in turn, handed to `consume` in order with the
  // batch's index: the same values as one call per batch. The host's part of the next batch
  // (its patch table) is built on a second thread while the kernel computes this one, so that
  // the tail of either leaves no core idle. With `computes`, batch b's values of a source s for
  // which computes(b, s) is false are not computed (their share of the kernel's and the host's
  // work is skipped) and are not to be read.
  using BatchValues =
      std::function<void(std::size_t batch, const std::vector<float>& values, std::size_t stride)>;
  using BatchSources = std::function<bool(std::size_t batch, std::size_t source)>;
  void illuminanceBySourceBatches(std::span<const std::span<const SamplePoint>> batches,
                                  const BatchValues& consume, const BatchSources& computes = {});
  // E from single source faces at groups of PN_LANES points (links): the points are work-items of
  // PN_LANES in order (the caller pads each group as it likes), and work-item w takes the faces
  // faces[k], k in [start[w], start[w + 1]) (start: one entry per work-item and one more, ending
  // at faces.size()). Value [k · PN_LANES + lane]: lx from face k alone at its source's
  // luminance, as illuminanceBySource computes it (the same arithmetic, so the same floats).
  // What the hierarchical transfer evaluates, where each group of points needs a few faces.
  // A work-item whose occluders overflow the kernel's fixed room throws std::runtime_error, or,
  // with `overflow`, sets that work-item's entry there (PN_ERROR_* bits, 0 where it fitted) and
  // leaves its values undefined: the caller splits its links and asks again.
  // `receiver` (optional, one per work-item): consecutive work-items with the same value have
  // the same faces, which lets the host search their occluders once.
  std::vector<float> linkedIlluminance(std::span<const SamplePoint> points,
                                       std::span<const std::int32_t> start,
                                       std::span<const std::int32_t> faces,
                                       std::vector<int>* overflow = nullptr,
                                       std::span<const std::int32_t> receiver = {});

 private:
  // One launch (or several, on a device too small for the batch): E per source ([source][padded
  // point]) or summed ([padded point]), and the classes ([source][padded point]) when asked.
  struct KernelOutput {
    std::size_t padded = 0;
    std::vector<float> illuminance;
    std::vector<std::uint8_t> classes;
  };
  struct LinkedLaunch {
    std::span<const std::int32_t> start, faces;  // linkedIlluminance's
    std::vector<int>* overflow = nullptr;
    std::span<const std::int32_t> receiver;
  };
  KernelOutput launch(std::span<const SamplePoint> points, bool bySource, bool withClasses,
                      const LinkedLaunch* linked = nullptr);
  // A launch's host part (the points packed for the kernel and their patch table), which reads
  // the scene only and may run beside another launch's run(); and the rest (upload, kernel,
  // download). launch() is run(prepare(...)).
  struct PreparedLaunch;
  PreparedLaunch prepare(std::span<const SamplePoint> points, bool bySource, bool withClasses,
                         const LinkedLaunch* linked, std::span<const char> skipFace = {}) const;
  KernelOutput run(PreparedLaunch& prepared);

  // What a call asks for beyond E: E per source, the shadow classes (illuminance() asks for
  // neither, and skips downloading and reordering the classes).
  struct Parts {
    bool bySource = false;
    bool classes = true;
  };
  // evaluate() with the classes only when `parts` asks for them.
  IlluminanceResult evaluateParts(std::span<const SamplePoint> points, Parts parts);
  // The Lambertian sources' part of evaluate().
  IlluminanceResult evaluateSources(std::span<const SamplePoint> points, Parts parts);
  // evaluate() for points in the order the kernel's work-items take them.
  IlluminanceResult evaluateInOrder(std::span<const SamplePoint> points, Parts parts);

  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace penumbra
