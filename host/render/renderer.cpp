#include "render/renderer.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "geometry/angles.hpp"
#include "grid/grid_evaluation.hpp"
#include "illuminance/host_daylight.hpp"
#include "illuminance/skylight.hpp"
#include "illuminance/sunlight.hpp"
#include "radiosity/indirect_field.hpp"
#include "render/camera.hpp"
#include "render/interval_sampling.hpp"
#include "render/sky_background.hpp"
#include "render/visibility_engine.hpp"
#include "timing/seconds_since.hpp"

namespace penumbra {
namespace {

// Points per call of the illuminance engine: bounds the memory of one call and gives the progress
// line something to count.
constexpr std::size_t kBatch = 1 << 16;

// Runs body(i) for i in [0, count) in parallel chunks; each i writes only its own outputs.
template <typename Body>
void forEachSample(std::size_t count, const Body& body) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 4096),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i < range.end(); ++i) body(i);
                    });
}

// Everything per sample of one camera's sample grid.
struct SampleLayer {
  VisibilityImage visibility;
  std::vector<float> illuminance;  // lx
  std::vector<float> rgb;          // cd/m², 3 per sample
};

// What one render's exact samples write and count: the layer's values, each sample's shadow
// class per class column (sample × classColumns()) for the interval plan, the render's stats.
struct SampleOutputs {
  SampleLayer& layer;
  std::vector<ShadowClass>& classes;
  RenderStats& stats;
  bool exactIndirect = false;  // gather the interreflected light at each sample, not the field
};

// The sun's shadow class at a point from its sunlight `e` (lx): lit where it gets the whole
// disk's E_dn·cos θ times the transmittance of one glazing (or of none) to within 1e-6 of that;
// umbra where the sun cannot reach it whatever stands in the room (out of the beam through the
// openings: sunlight's `beam`); penumbra elsewhere, in the patch's penumbra and in the shadows
// that solids cast inside the beam, so that the interval plan looks between such samples for
// a sliver of sun and never interpolates across a sun patch's edge. `full` is E_dn·cos θ, 0
// where the disk is not wholly above the point's horizon (there any sunlight is penumbra).
ShadowClass sunShadowClass(double e, bool inBeam, double full,
                           const std::vector<double>& transmittances) {
  if (!inBeam) return ShadowClass::Umbra;
  if (e <= 0.0) return ShadowClass::Penumbra;
  for (const double tau : transmittances)
    if (std::abs(e - tau * full) <= 1e-6 * full) return ShadowClass::Lit;
  return ShadowClass::Penumbra;
}

}  // namespace

Vec3 luminanceColour(const Vec3& colour) {
  const double y = 0.2126 * colour.x() + 0.7152 * colour.y() + 0.0722 * colour.z();
  return colour / y;
}

struct Renderer::State {
  compute::Device* device;
  const Scene* scene;
  EngineOptions engine;
  IlluminanceEngine illuminance;
  VisibilityEngine visibility;
  std::optional<MeshOptions> mesh;                   // set: with interreflection
  std::unique_ptr<Interreflection> interreflection;  // solved for `scene` when `mesh` is set
  // The interreflected light over the solved mesh, shared by every view and interval setting.
  std::unique_ptr<IndirectField> field;
  TransferCache transfers;          // kept across setScene: a sweep's cases share transfers
  std::vector<Vec3> sourceColours;  // luminanceColour per source
  // The interval plan's shadow-class columns, what each one's shadows are (classEdges).
  std::vector<ShadowEdges> shadowEdges;
  std::vector<Vec3> solidReflectance;
  SkyBackground background;            // what rays that meet no solid show
  std::vector<double> transmittances;  // 1 and each opening's τ: the sun's lit levels
  Vec3 sunDirection = Vec3::UnitZ();   // unit, towards the sun's centre
  // The sine of the sun's angular radius: a point whose horizon lies lower than that below the
  // sun sees the whole disk above it.
  static inline const double sunRadiusSine =
      std::sin(0.5 * kSunDiameterDegrees * kRadiansPerDegree);

  State(compute::Device& d, const Scene& s, EngineOptions e, std::optional<MeshOptions> m)
      : device(&d),
        scene(&s),
        engine(e),
        illuminance(d, s, e),
        visibility(d, s),
        mesh(m),
        background(s) {
    prepare();
  }

  void prepare() {
    field.reset();
    interreflection.reset();
    if (mesh) {
      interreflection = std::make_unique<Interreflection>(*device, *scene, illuminance, *mesh,
                                                          engine, &transfers, hostDaylight(*scene));
      // The mesh's direct light leaves the engine on a scene with the sky's sources cut at
      // some height (engine/daylight_evaluation.hpp); the samples take the sky on the host.
      if (scene->sky) illuminance.setScene(*scene);
      // The field's probes lie IndirectField::kNudgeInKernelTolerances inside a solid where
      // one stands on a face, far beyond the locator's input tolerance.
      const SolidLocator solids(*scene);
      field = std::make_unique<IndirectField>(
          interreflection->mesh(), scene->size(),
          [this](std::span<const SamplePoint> points) {
            return interreflection->indirectChannels(points);
          },
          FieldOptions{},
          [&solids](const Vec3& p) {
            SamplePoint probe{p, Vec3::UnitZ(), -1};
            return solids.classify(probe) >= 0;
          });
    }
    background = SkyBackground(*scene);
    if (scene->sun) sunDirection = scene->sun->direction.normalized();
    transmittances = {1.0};
    if (scene->room)
      for (const Opening& opening : scene->room->openings)
        transmittances.push_back(opening.transmittance);
    sourceColours.clear();
    for (const Source& source : scene->sources)
      sourceColours.push_back(luminanceColour(source.color));
    shadowEdges = classEdges();
    solidReflectance.clear();
    for (const Solid& solid : scene->solids)
      solidReflectance.push_back(solid.material >= 0 ? scene->materials[solid.material].reflectance
                                                     : Material{}.reflectance);
  }

  // The visible point of sample i, on the face it shows, as the grids' SamplePoint.
  SamplePoint surfacePoint(const Camera& camera, const VisibilityImage& vis, std::size_t i) const {
    const VisibleFace& face = visibility.visible().face(vis.faceIds[i]);
    const int x = static_cast<int>(i % vis.width), y = static_cast<int>(i / vis.width);
    Vec3 p = camera.eye + static_cast<double>(vis.t[i]) * camera.direction(x, y);
    // The kernel's t is float: put the point back on its face's plane.
    p -= face.plane.signedDistance(p) * face.plane.normal;
    return SamplePoint{p, face.plane.normal, face.index};
  }

  // The interval plan's shadow classes per sample: one per source, then one per placed
  // luminaire (LuminaireEngine::Result::shadow: the point model Lit where the sample sees its
  // centre, Umbra where not; the area model its opening's class), then the sun's
  // (sunShadowClass), so that no shadow edge is interpolated across. The sky has none: its
  // shadows are soft, and the plan's checks of the values decide there. Nor has the
  // interreflected light: its bends are the plan's values' (SampleValues::kinks).
  int classColumns() const { return static_cast<int>(shadowEdges.size()); }

  // What each class column's shadows are (IntervalPlan's rules (b) and (c)): the Lambertian
  // sources' and the exact openings' soft, a subdivided opening's a staircase of its cells' hard
  // shadows, the point model's and the sun's sharp.
  std::vector<ShadowEdges> classEdges() const {
    std::vector<ShadowEdges> edges(scene->sources.size(), ShadowEdges::Soft);
    for (const Luminaire& l : scene->luminaires) {
      ShadowEdges e = ShadowEdges::Sharp;
      if (l.model == LuminaireModel::Area && l.opening)
        e = l.opening->subdivided() ? ShadowEdges::Stepped : ShadowEdges::Soft;
      edges.insert(edges.end(), l.instances.size(), e);
    }
    if (scene->sun) edges.push_back(ShadowEdges::Sharp);
    return edges;
  }

  // Exact illuminance and luminance at `indices` (in batches of kBatch), the interreflected
  // light included where the renderer computes it, so that the interval plan checks and
  // interpolates the light the image shows; and each sample's shadow classes. A source that
  // gives a sample nothing counts as umbra there, whatever the volumes said: several occluders
  // together can hide a source that none hides alone.
  void evaluate(const Camera& camera, const std::vector<std::size_t>& indices, SampleOutputs out,
                const std::function<void(std::size_t)>& done) {
    SampleLayer& layer = out.layer;
    std::vector<ShadowClass>& classes = out.classes;
    const int sources = static_cast<int>(scene->sources.size());
    const int columns = classColumns();
    std::vector<SamplePoint> points;
    std::vector<float> indirect;  // lx per channel, 3 per sample of the batch
    for (std::size_t start = 0; start < indices.size(); start += kBatch) {
      const std::size_t end = std::min(indices.size(), start + kBatch);
      points.resize(end - start);
      forEachSample(end - start, [&](std::size_t j) {
        points[j] = surfacePoint(camera, layer.visibility, indices[start + j]);
      });
      if (interreflection) {
        const auto begin = Clock::now();
        indirectLight(layer, std::span(indices).subspan(start, end - start), points,
                      out.exactIndirect, indirect);
        out.stats.indirectSeconds += secondsSince(begin);
      }
      const IlluminanceResult result = illuminance.evaluate(points, true);
      // The daylight on the host, exact in double past every solid: the sky and the ground
      // (outside the room, on an obstruction's faces, the whole sky in front of the point), the
      // sun. White.
      const std::vector<double> sky =
          scene->sky ? surfaceSkylight(*scene, points) : std::vector<double>();
      std::vector<char> beam;
      const std::vector<double> sun =
          scene->sun ? sunlight(*scene, points, &beam) : std::vector<double>();
      forEachSample(end - start, [&](std::size_t local) {
        const std::size_t i = indices[start + local];
        const Vec3& rho = solidReflectance[points[local].solid];
        Vec3 light = Vec3::Zero();  // Σ E_s · colour_s, and the luminaires' E in white
        for (int s = 0; s < sources; ++s) {
          const double e = result.bySource[local * sources + s];
          light += e * sourceColours[s];
          classes[i * columns + s] =
              e > 0.0 ? result.shadowClass[local * sources + s] : ShadowClass::Umbra;
        }
        for (int l = 0; l < result.luminaireCount; ++l) {
          classes[i * columns + sources + l] =
              result.luminaireShadow[local * result.luminaireCount + l];
        }
        if (!result.luminaires.empty()) light += Vec3::Constant(result.luminaires[local]);
        double e = result.illuminance[local];
        if (!sky.empty()) {
          e += sky[local];
          light += Vec3::Constant(sky[local]);
        }
        if (!sun.empty()) {
          e += sun[local];
          light += Vec3::Constant(sun[local]);
          const double cosine = points[local].normal.dot(sunDirection);
          const double full =
              cosine >= sunRadiusSine ? scene->sun->directNormalIlluminance * cosine : 0.0;
          classes[i * columns + columns - 1] =
              sunShadowClass(sun[local], beam[local] != 0, full, transmittances);
        }
        if (interreflection) {
          const Vec3 reflected(indirect[local * 3], indirect[local * 3 + 1],
                               indirect[local * 3 + 2]);
          e += photometric(reflected);
          light += reflected;
        }
        const Vec3 l = rho.cwiseProduct(light) / std::numbers::pi;
        layer.illuminance[i] = static_cast<float>(e);
        for (int c = 0; c < 3; ++c) layer.rgb[i * 3 + c] = static_cast<float>(l[c]);
      });
      done(end - start);
    }
  }

  // The interreflected light (lx per channel, 3 per point) at `points`, the layer's samples
  // `indices`: from the field, or gathered exactly at each point.
  void indirectLight(const SampleLayer& layer, std::span<const std::size_t> indices,
                     const std::vector<SamplePoint>& points, bool exact, std::vector<float>& out) {
    const std::size_t count = points.size();
    out.assign(count * 3, 0.0f);
    if (exact) {
      const std::vector<Eigen::Vector3d> e = interreflection->indirectChannels(points);
      for (std::size_t j = 0; j < count; ++j)
        for (int c = 0; c < 3; ++c) out[j * 3 + c] = static_cast<float>(e[j][c]);
      return;
    }
    std::vector<FacePoint> onFaces(count);
    forEachSample(count, [&](std::size_t j) {
      const VisibleFace& face = visibility.visible().face(layer.visibility.faceIds[indices[j]]);
      onFaces[j] = FacePoint{points[j].position, face.index, face.face};
    });
    field->evaluate(onFaces, out);
  }

  SampleLayer renderSamples(const Camera& camera, int interval, bool exactIndirect,
                            RenderStats& stats,
                            const std::function<void(std::size_t, std::size_t)>& progress) {
    SampleLayer layer;
    auto start = Clock::now();
    layer.visibility = visibility.trace(camera);
    stats.visibilitySeconds += secondsSince(start);
    stats.objectTestsPerSample = layer.visibility.objectTestsPerSample;
    const std::size_t n = layer.visibility.faceIds.size();
    layer.illuminance.assign(n, 0.0f);
    layer.rgb.assign(n * 3, 0.0f);

    start = Clock::now();
    std::vector<uint8_t> needed(n, 0);
    std::vector<std::size_t> surface;
    for (std::size_t i = 0; i < n; ++i) {
      const uint32_t id = layer.visibility.faceIds[i];
      if (id == FaceIdImage::kNoSurface) {
        if (background.lit()) {
          const int x = static_cast<int>(i % camera.width), y = static_cast<int>(i / camera.width);
          const float l = static_cast<float>(
              background.luminance(camera.eye, camera.direction(x, y).normalized()));
          for (int c = 0; c < 3; ++c) layer.rgb[i * 3 + c] = l;
        }
        continue;
      }
      const VisibleFace& face = visibility.visible().face(id);
      if (face.isSource) {
        const Source& source = scene->sources[face.index];
        const Vec3 l = source.luminance * sourceColours[face.index];
        for (int c = 0; c < 3; ++c) layer.rgb[i * 3 + c] = static_cast<float>(l[c]);
      } else {
        needed[i] = 1;
        surface.push_back(i);
      }
    }
    stats.samples += n;
    stats.surfaceSamples += surface.size();
    IntervalPlan plan(camera.width, camera.height, layer.visibility.faceIds, needed, interval);
    const std::size_t work = surface.size();
    stats.shadingSeconds += secondsSince(start);

    start = Clock::now();
    const double indirectBefore = stats.indirectSeconds;
    const IndirectFieldStats fieldBefore = field ? field->stats() : IndirectFieldStats{};
    const std::size_t exactBefore = stats.exactSamples;
    std::vector<ShadowClass> classes(n * classColumns(), ShadowClass::Unlit);
    const SampleOutputs out{layer, classes, stats, exactIndirect};
    const auto advance = [&](std::size_t count) {
      stats.exactSamples += count;
      if (progress) progress(std::min(stats.exactSamples - exactBefore, work), work);
    };
    evaluate(camera, plan.firstPass(), out, advance);
    // The plan checks what the image shows (RGB luminance) and the E AOV, and fills both where
    // it interpolates; the interreflected light in them bends where the field's triangles meet.
    const bool kinks = interreflection != nullptr;
    const SampleValues checked[] = {{layer.illuminance, 1, kinks}, {layer.rgb, 3, kinks}};
    for (std::vector<std::size_t> round = plan.next(classes, shadowEdges, checked); !round.empty();
         round = plan.next(classes, shadowEdges, checked))
      evaluate(camera, round, out, advance);
    stats.illuminanceSeconds += secondsSince(start) - (stats.indirectSeconds - indirectBefore);
    if (interreflection) {
      stats.gatheredSamples += exactIndirect
                                   ? stats.exactSamples - exactBefore
                                   : field->stats().nodes - fieldBefore.nodes +
                                         field->stats().pointsGathered - fieldBefore.pointsGathered;
    }
    if (progress) progress(work, work);
    return layer;
  }
};

Renderer::Renderer(compute::Device& device, const Scene& scene, EngineOptions engine,
                   std::optional<MeshOptions> interreflection)
    : state_(std::make_unique<State>(device, scene, engine, interreflection)) {}
Renderer::~Renderer() = default;

const IndirectFieldStats* Renderer::indirectField() const {
  return state_->field ? &state_->field->stats() : nullptr;
}

const InterreflectionReport* Renderer::interreflection() const {
  return state_->interreflection ? &state_->interreflection->report() : nullptr;
}

void Renderer::setScene(const Scene& scene) {
  state_->scene = &scene;
  state_->illuminance.setScene(scene);
  state_->visibility.setScene(scene);
  state_->prepare();
}

std::vector<std::optional<SamplePoint>> Renderer::visiblePoints(const View& view) {
  const Camera camera = Camera::forView(view, 1);
  const VisibilityImage vis = state_->visibility.trace(camera);
  std::vector<std::optional<SamplePoint>> points(vis.faceIds.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const uint32_t id = vis.faceIds[i];
    if (id != FaceIdImage::kNoSurface && !state_->visibility.visible().face(id).isSource)
      points[i] = state_->surfacePoint(camera, vis, i);
  }
  return points;
}

RenderedView Renderer::render(const View& view, const RenderOptions& options) {
  if (options.interval < 1) {
    throw std::invalid_argument(
        fmt::format("the interval must be 1 or more samples, got {}", options.interval));
  }
  const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(options.spp))));
  if (options.spp < 1 || side * side != options.spp) {
    throw std::invalid_argument(fmt::format(
        "samples per pixel must be a square (1, 4, 9, 16, ...): a side × side grid in each "
        "pixel; got {}",
        options.spp));
  }
  RenderedView out;
  out.view = view;
  // The AOVs are at pixel centres (one sample per pixel); with supersampling the image is the
  // mean of side × side samples per pixel, rendered as a second, finer layer. Progress counts
  // both layers by their share of the samples.
  const double centreShare = side == 1 ? 1.0 : 1.0 / (1.0 + options.spp);
  const auto report = [&](double offset, double share) {
    return [&, offset, share](std::size_t done, std::size_t total) {
      if (options.progress) options.progress(offset + share * (total ? double(done) / total : 1.0));
    };
  };
  const Camera centreCamera = Camera::forView(view, 1);
  SampleLayer centre = state_->renderSamples(centreCamera, options.interval, options.exactIndirect,
                                             out.stats, report(0.0, centreShare));
  // The layer's buffers become the images (moved: 16 bytes a pixel not copied).
  const auto start = Clock::now();
  out.illuminance.width = out.faces.width = out.luminance.width = view.width;
  out.illuminance.height = out.faces.height = out.luminance.height = view.height;
  out.illuminance.values = std::move(centre.illuminance);
  out.faces.ids = std::move(centre.visibility.faceIds);
  out.stats.shadingSeconds += secondsSince(start);
  if (side == 1) {
    out.luminance.rgb = std::move(centre.rgb);
    return out;
  }
  out.luminance = RgbImage(view.width, view.height);
  const SampleLayer fine =
      state_->renderSamples(Camera::forView(view, side), options.interval, options.exactIndirect,
                            out.stats, report(centreShare, 1.0 - centreShare));
  const auto filterStart = Clock::now();
  const int fineWidth = view.width * side;
  for (int y = 0; y < view.height; ++y)
    for (int x = 0; x < view.width; ++x) {
      float* pixel = out.luminance.pixel(x, y);
      for (int sy = 0; sy < side; ++sy)
        for (int sx = 0; sx < side; ++sx) {
          const std::size_t i = static_cast<std::size_t>(y * side + sy) * fineWidth + x * side + sx;
          for (int c = 0; c < 3; ++c) pixel[c] += fine.rgb[i * 3 + c];
        }
      for (int c = 0; c < 3; ++c) pixel[c] /= static_cast<float>(options.spp);
    }
  out.stats.shadingSeconds += secondsSince(filterStart);
  return out;
}

}  // namespace penumbra
