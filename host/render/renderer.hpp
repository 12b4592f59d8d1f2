#pragma once
// A view of the scene as a luminance image (cd/m² per RGB channel) with its illuminance and
// face-id AOVs: primary visibility (visibility_engine), exact illuminance at the visible points
// through the same IlluminanceEngine as the grids (no second implementation of the integral),
// interval sampling along rows, the interreflected light from the field over the solved mesh
// (radiosity/indirect_field.hpp) when it is asked for, L = ρ·(E_direct + E_indirect)/π per channel,
// optional supersampling.
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "cl/device.hpp"
#include "engine/illuminance_engine.hpp"
#include "image/images.hpp"
#include "radiosity/indirect_field.hpp"
#include "radiosity/interreflection.hpp"
#include "scene/scene.hpp"

namespace penumbra {

struct RenderOptions {
  int interval = 1;  // k: exact every k samples of a row (1: every sample)
  int spp = 1;       // samples per pixel, a square (1, 4, 9, 16, ...)
  // Called after each batch with the fraction done, in [0, 1].
  std::function<void(double)> progress;
  // With interreflection: the interreflected light is gathered exactly at every sample (the
  // reference) instead of taken from the field over the solved mesh (radiosity/indirect_field).
  bool exactIndirect = false;
};

struct RenderStats {
  std::size_t samples = 0;         // all, supersampling included
  std::size_t surfaceSamples = 0;  // samples that show a solid (and need illuminance)
  std::size_t exactSamples = 0;    // of those, computed exactly
  double objectTestsPerSample = 0.0;
  // Points where the interreflected light was gathered exactly in this render: every surface
  // sample with exactIndirect, else the field's new nodes and the samples on no element.
  std::size_t gatheredSamples = 0;
  double visibilitySeconds = 0.0, illuminanceSeconds = 0.0, shadingSeconds = 0.0;
  double indirectSeconds = 0.0;  // the interreflected light's gather and interpolation
  // Mpixel·sources/s over the illuminance part: surface samples × sources / time.
  double exactShare() const {
    return surfaceSamples ? static_cast<double>(exactSamples) / surfaceSamples : 1.0;
  }
};

struct RenderedView {
  View view;
  RgbImage luminance;  // cd/m², linear RGB
  // lx at each pixel centre's visible point, the total (direct + interreflected) when the
  // renderer computes interreflection; 0 on sources and sky
  ScalarImage illuminance;
  FaceIdImage faces;  // at each pixel centre (render/visible_scene.hpp numbers the faces)
  RenderStats stats;
};

// The colour of a source as a factor on its luminance: colour / Y(colour) with Rec.709 weights,
// so that a coloured source keeps the luminance (and the illuminance) it was given.
Vec3 luminanceColour(const Vec3& colour);

class Renderer {
 public:
  // With `interreflection`, the scene's interreflection is solved on that mesh (and again at
  // every setScene) and the images show the total light; without, the direct light only.
  Renderer(compute::Device& device, const Scene& scene, EngineOptions engine = {},
           std::optional<MeshOptions> interreflection = std::nullopt);
  ~Renderer();
  void setScene(const Scene& scene);
  // The interreflection's solver report; null when the renderer shows direct light only.
  const InterreflectionReport* interreflection() const;
  // What the field of interreflected light has gathered so far (every view and render since
  // the last setScene); null when the renderer shows direct light only.
  const IndirectFieldStats* indirectField() const;

  // Throws std::invalid_argument for an interval below 1 or an spp that is not a square.
  RenderedView render(const View& view, const RenderOptions& options);
  // The point each pixel centre sees on a solid, as the grids' SamplePoint (what render() computes
  // E at); nullopt for pixels that show a source or nothing. For picking, and for tests.
  std::vector<std::optional<SamplePoint>> visiblePoints(const View& view);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace penumbra
