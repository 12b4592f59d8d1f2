#pragma once
// Exact direct illuminance at sample points: the Lambertian sources by kernels/illuminance.cl,
// the photometric luminaires' point model by kernels/luminaire.cl (LuminaireEngine).
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "cl/device.hpp"
#include "geometry/sample_point.hpp"
#include "scene/scene.hpp"
#include "shadow/shadow_class.hpp"

namespace penumbra {

struct EngineOptions {
  // Shadow volumes and face classes (PN_PATH_CULLING, docs/method.md): each sample tests only the
  // occluders whose penumbra volume meets its patch, umbra samples get 0 at once, lit ones the
  // plain contour integral. Off: the plain path, every sample considers every occluder; slower,
  // the same numbers to float rounding, for comparison.
  bool culling = true;
  // With culling only: a window's sky on the wall's outer plane is seen through the opening
  // (shadow/aperture.hpp), and the wall around it is skipped. Off: the reveals are occluders like
  // any other (tests compare that with the plain path).
  bool apertures = true;
  // With culling only: points in a penumbra take the eight-lane penumbra path (PN_PATH_LANES,
  // kernels/penumbra_lanes.cl). Off: the scalar path (kernels/penumbra_scalar.cl), as the plain
  // path does.
  bool vectorPenumbra = true;
};

struct IlluminanceResult {
  std::vector<double> illuminance;       // lx, per point, summed over all sources and luminaires
  std::vector<ShadowClass> shadowClass;  // [point * sourceCount + source]
  std::vector<double> bySource;          // lx, [point * sourceCount + source], when asked for
  int sourceCount = 0;
  // lx per point from the photometric luminaires (included in `illuminance`); empty when the
  // scene has none. They are white: a render adds them to every channel.
  std::vector<double> luminaires;
  // [point * luminaireCount + l]: whether the point sees placed luminaire l (LuminaireEngine).
  std::vector<std::uint8_t> luminaireSeen;
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

  // E in lx at every point, summed over all sources and luminaires.
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

 private:
  // One launch (or several, on a device too small for the batch): E per source ([source][padded
  // point]) or summed ([padded point]), and the classes ([source][padded point]) when asked.
  struct KernelOutput {
    std::size_t padded = 0;
    std::vector<float> illuminance;
    std::vector<std::uint8_t> classes;
  };
  KernelOutput launch(std::span<const SamplePoint> points, bool bySource, bool withClasses);

  // The Lambertian sources' part of evaluate().
  IlluminanceResult evaluateSources(std::span<const SamplePoint> points, bool bySource);
  // evaluate() for points in the order the kernel's work-items take them.
  IlluminanceResult evaluateInOrder(std::span<const SamplePoint> points, bool bySource);

  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace penumbra
