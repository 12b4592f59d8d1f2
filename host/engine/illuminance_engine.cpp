#include "engine/illuminance_engine.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <future>
#include <stdexcept>
#include <utility>

#include "cl/buffer.hpp"
#include "engine/kernel_scene.hpp"
#include "engine/luminaire_engine.hpp"
#include "engine/patch_table.hpp"
#include "geometry/morton_order.hpp"
#include "memory/page_prefault.hpp"
#include "shadow/scene_shadows.hpp"

namespace penumbra {

using compute::DeviceBuffer;

struct IlluminanceEngine::State {
  compute::Device* device = nullptr;
  EngineOptions options;
  SceneShadows shadows;
  std::vector<FaceVolumes> volumes;  // flattenVolumes(shadows), for the patch tables
  KernelScene packed;
  compute::Program program;
  DeviceBuffer faces, apertures, sourceVertices, luminances, occluders, planes, edges,
      occluderVertices;
  std::size_t sceneBytes = 0;  // what the buffers above take on the device
  // Sources without a face (a sky's part of an opening that a height cut leaves empty): the
  // kernel writes a source's row after its last face, so their rows are zeroed on the host.
  std::vector<int> facelessSources;
  // Built at the first scene with luminaires, kept for later ones (a sweep's cases).
  std::unique_ptr<LuminaireEngine> luminaires;
  bool hasLuminaires = false;
  // The device buffers of a launch, kept from one launch to the next (DeviceBuffer::reserve): a
  // grid's batches have one size, so every batch after the first reuses the first one's memory.
  static constexpr int kPointArrays = 9;  // the position's hi and lo parts, the normal
  // Work-items of PN_LANES points, in work-groups of kWorkGroup work-items (see
  // KernelLaunch::run for why the work-group size is fixed).
  static constexpr std::size_t kWorkGroup = 16;
  struct LaunchBuffers {
    DeviceBuffer points[kPointArrays], pointSolids, patchFaces, candidates, illuminance, errors,
        classes;
  } launchBuffers;

  State(compute::Device& d, const Scene& scene, EngineOptions o)
      : device(&d), options(o), program(d, "illuminance", illuminanceBuildOptions()) {
    upload(scene);
  }

  void upload(const Scene& scene) {
    compute::Device& d = *device;
    // Each face's casters are packed and flattened as soon as they are built, then dropped:
    // the kernel reads the packed copy, the patch tables the flattened volumes.
    packed = packSceneFrame(scene);
    volumes.clear();

    const Tolerance tolerance = Tolerance::forSceneSize(scene.size());
    shadows = buildSceneShadows(scene, [&](EmittingFaceShadows& face) {
      packFace(packed, scene, face, tolerance);
      volumes.push_back(flattenVolumes(face));
      face.casters = {};
    });
    if (!options.apertures)
      for (PnSourceFace& f : packed.faces) f.aperture = -1;
    const std::vector<std::size_t> tables = {
        compute::byteSize(packed.faces),          compute::byteSize(packed.apertures),
        compute::byteSize(packed.sourceVertices), compute::byteSize(packed.luminances),
        compute::byteSize(packed.occluders),      compute::byteSize(packed.planes),
        compute::byteSize(packed.edges),          compute::byteSize(packed.occluderVertices)};
    compute::requireDeviceMemory(
        d.info(), tables, 0,
        fmt::format("the scene (source faces: {}, occluders: {})", packed.faces.size(),
                    packed.occluders.size()),
        "use a smaller scene (fewer solids or sources) or a device with more memory (--device)");
    sceneBytes = 0;
    for (std::size_t b : tables) sceneBytes += b;
    faces = DeviceBuffer::upload<PnSourceFace>(d, packed.faces);
    apertures = DeviceBuffer::upload<PnAperture>(d, packed.apertures);
    sourceVertices = DeviceBuffer::upload<PnPosition>(d, packed.sourceVertices);
    luminances = DeviceBuffer::upload<PnLuminancePolynomial>(d, packed.luminances);
    occluders = DeviceBuffer::upload<PnOccluder>(d, packed.occluders);
    planes = DeviceBuffer::upload<cl_float4>(d, packed.planes);
    edges = DeviceBuffer::upload<cl_int4>(d, packed.edges);
    occluderVertices = DeviceBuffer::upload<PnPosition>(d, packed.occluderVertices);
    // The device holds its copy; the host keeps what the patch tables and launches read.
    packed.occluders = {};
    packed.planes = {};
    packed.edges = {};
    packed.occluderVertices = {};
    facelessSources.clear();
    for (int source = 0; source < static_cast<int>(scene.sources.size()); ++source)
      if (scene.sources[source].faces.empty()) facelessSources.push_back(source);
    hasLuminaires = !scene.luminaires.empty();
    if (hasLuminaires) {
      if (!luminaires) luminaires = std::make_unique<LuminaireEngine>(d, options);
      luminaires->setScene(scene, packed.origin, packed.epsLength);
    }
  }
};

IlluminanceEngine::IlluminanceEngine(compute::Device& device, const Scene& scene,
                                     EngineOptions options)
    : state_(std::make_unique<State>(device, scene, options)) {}
IlluminanceEngine::~IlluminanceEngine() = default;

void IlluminanceEngine::setScene(const Scene& scene) {
  state_->upload(scene);
}

std::vector<double> IlluminanceEngine::illuminance(std::span<const SamplePoint> points) {
  return evaluateParts(points, Parts{false, false}).illuminance;
}

namespace {

std::string kernelError(int bits, const SamplePoint& p) {
  return fmt::format(
      "the illuminance kernel ran out of room near point ({:.3f}, {:.3f}, {:.3f}) m: {}",
      p.position.x(), p.position.y(), p.position.z(),
      (bits & PN_ERROR_TOO_MANY_OCCLUDERS)
          ? fmt::format("more than {} occluders shade it", PN_MAX_ACTIVE_OCCLUDERS)
      : (bits & PN_ERROR_TOO_MANY_CONTOUR_EDGES)
          ? fmt::format("its shading occluders have more than {} contour edges in all",
                        PN_MAX_CONTOUR_EDGES)
      : (bits & PN_ERROR_TOO_MANY_CONTACTS)
          ? fmt::format("it touches more than {} solids", PN_MAX_CONTACTS)
          : fmt::format("more than {} visible pieces on one edge", PN_MAX_VISIBLE_PIECES));
}

}  // namespace

IlluminanceResult IlluminanceEngine::evaluate(std::span<const SamplePoint> points, bool bySource) {
  return evaluateParts(points, Parts{bySource, true});
}

IlluminanceResult IlluminanceEngine::evaluateParts(std::span<const SamplePoint> points,
                                                   Parts parts) {
  IlluminanceResult result = evaluateSources(points, parts);
  if (state_->hasLuminaires) {
    LuminaireEngine::Result luminaires = state_->luminaires->evaluate(points);
    result.luminaires = std::move(luminaires.illuminance);
    result.luminaireShadow = std::move(luminaires.shadow);
    result.luminaireCount = luminaires.luminaires;
    for (std::size_t i = 0; i < result.illuminance.size(); ++i)
      result.illuminance[i] += result.luminaires[i];
  }
  return result;
}

IlluminanceResult IlluminanceEngine::evaluateSources(std::span<const SamplePoint> points,
                                                     Parts parts) {
  // The plain path takes the points as given: its work per point does not
  // depend on the point's neighbours.
  if (!state_->options.culling || points.size() <= PN_LANES) return evaluateInOrder(points, parts);
  const std::vector<std::size_t> order = mortonOrder(points);
  // The copies in and out of Morton order are point by point: in parallel, the same values.
  const auto eachPoint = [](std::size_t n, const auto& body) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t i = range.begin(); i != range.end(); ++i) body(i);
                      });
  };
  std::vector<SamplePoint> sorted(points.size());
  eachPoint(order.size(), [&](std::size_t i) { sorted[i] = points[order[i]]; });
  const IlluminanceResult inOrder = evaluateInOrder(sorted, parts);
  IlluminanceResult result;
  result.sourceCount = inOrder.sourceCount;
  const std::size_t sources = static_cast<std::size_t>(inOrder.sourceCount);
  result.illuminance.resize(inOrder.illuminance.size());
  result.shadowClass.resize(inOrder.shadowClass.size());
  result.bySource.resize(inOrder.bySource.size());
  const bool perSource = !inOrder.shadowClass.empty() || !inOrder.bySource.empty();
  eachPoint(order.size(), [&](std::size_t i) {
    const std::size_t to = order[i];
    result.illuminance[to] = inOrder.illuminance[i];
    for (std::size_t s = 0; perSource && s < sources; ++s) {
      if (!inOrder.shadowClass.empty())
        result.shadowClass[to * sources + s] = inOrder.shadowClass[i * sources + s];
      if (!inOrder.bySource.empty())
        result.bySource[to * sources + s] = inOrder.bySource[i * sources + s];
    }
  });
  return result;
}

IlluminanceResult IlluminanceEngine::evaluateInOrder(std::span<const SamplePoint> points,
                                                     Parts parts) {
  const bool bySource = parts.bySource;
  IlluminanceResult result;
  result.sourceCount = state_->packed.sourceCount;
  const std::size_t n = points.size();
  if (n == 0) return result;
  const KernelOutput output = launch(points, bySource, parts.classes);
  const std::vector<float>& e = output.illuminance;
  const std::size_t padded = output.padded;
  if (bySource) {
    result.bySource.resize(n * result.sourceCount);
    result.illuminance.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      for (int s = 0; s < result.sourceCount; ++s) {
        const double v = e[s * padded + i];
        result.bySource[i * result.sourceCount + s] = v;
        result.illuminance[i] += v;
      }
  } else {
    result.illuminance.assign(e.begin(), e.begin() + static_cast<std::ptrdiff_t>(n));
  }

  if (!parts.classes) return result;
  // The kernel writes classes source by source ([source][padded point]); callers read them point
  // by point.
  result.shadowClass.resize(n * result.sourceCount);
  for (std::size_t i = 0; i < n; ++i)
    for (int s = 0; s < result.sourceCount; ++s)
      result.shadowClass[i * result.sourceCount + s] =
          static_cast<ShadowClass>(output.classes[s * padded + i]);
  return result;
}

std::vector<float> IlluminanceEngine::illuminanceBySource(std::span<const SamplePoint> points,
                                                          std::size_t& stride) {
  stride = 0;
  if (points.empty()) return {};
  KernelOutput output = launch(points, true, false);
  stride = output.padded;
  return std::move(output.illuminance);
}

std::vector<float> IlluminanceEngine::linkedIlluminance(std::span<const SamplePoint> points,
                                                        std::span<const std::int32_t> start,
                                                        std::span<const std::int32_t> faces,
                                                        std::vector<int>* overflow,
                                                        std::span<const std::int32_t> receiver) {
  const std::size_t items = (points.size() + PN_LANES - 1) / PN_LANES;
  if (start.size() != items + 1 || start.back() != static_cast<cl_int>(faces.size()))
    throw std::logic_error("linkedIlluminance: one link range per work-item, ending at the links");
  if (overflow) overflow->assign(items, 0);
  if (faces.empty()) return {};
  if (!receiver.empty() && receiver.size() != items)
    throw std::logic_error("linkedIlluminance: one receiver per work-item");
  const LinkedLaunch linked{start, faces, overflow, receiver};
  return launch(points, false, false, &linked).illuminance;
}

struct IlluminanceEngine::PreparedLaunch {
  std::span<const SamplePoint> points;
  bool bySource = false, withClasses = false;
  const LinkedLaunch* linked = nullptr;
  std::size_t workItems = 0, padded = 0;
  // Structure of arrays, one float8 lane per point: the position's hi parts, its lo parts
  // (toPosition), the normal. Padding repeats the last point.
  std::vector<float> coords[State::kPointArrays];
  std::vector<cl_int> own;
  std::vector<cl_int> linkStart, receiver;  // a linked launch's, padded to the work-items
  PatchTable table;
};

IlluminanceEngine::KernelOutput IlluminanceEngine::launch(std::span<const SamplePoint> points,
                                                          bool bySource, bool withClasses,
                                                          const LinkedLaunch* linked) {
  PreparedLaunch prepared = prepare(points, bySource, withClasses, linked);
  return run(prepared);
}

void IlluminanceEngine::illuminanceBySourceBatches(
    std::span<const std::span<const SamplePoint>> batches, const BatchValues& consume,
    const BatchSources& computes) {
  const auto prepareBatch = [this, batches, &computes](std::size_t b) {
    std::vector<char> skipFace;
    if (computes) {
      const std::vector<EmittingFaceShadows>& faces = state_->shadows.faces;
      skipFace.resize(faces.size());
      for (std::size_t f = 0; f < faces.size(); ++f)
        skipFace[f] = computes(b, static_cast<std::size_t>(faces[f].source)) ? 0 : 1;
    }
    return prepare(batches[b], true, false, nullptr, skipFace);
  };
  std::future<PreparedLaunch> next;
  if (!batches.empty()) next = std::async(std::launch::async, prepareBatch, std::size_t{0});
  for (std::size_t b = 0; b < batches.size(); ++b) {
    PreparedLaunch current = next.get();
    if (b + 1 < batches.size()) next = std::async(std::launch::async, prepareBatch, b + 1);
    if (batches[b].empty()) {
      consume(b, {}, 0);
      continue;
    }
    const KernelOutput output = run(current);
    consume(b, output.illuminance, output.padded);
  }
}

IlluminanceEngine::PreparedLaunch IlluminanceEngine::prepare(std::span<const SamplePoint> points,
                                                             bool bySource, bool withClasses,
                                                             const LinkedLaunch* linked,
                                                             std::span<const char> skipFace) const {
  PreparedLaunch p;
  p.points = points;
  p.bySource = bySource;
  p.withClasses = withClasses;
  p.linked = linked;
  const std::size_t n = points.size();
  if (n == 0) return p;
  constexpr std::size_t kWorkGroup = State::kWorkGroup;
  p.workItems = (n + PN_LANES * kWorkGroup - 1) / (PN_LANES * kWorkGroup) * kWorkGroup;
  p.padded = p.workItems * PN_LANES;
  // A linked launch's work-items past the caller's have no links.
  if (linked) {
    p.linkStart.assign(linked->start.begin(), linked->start.end());
    p.linkStart.resize(p.workItems + 1, linked->start.back());
    if (!linked->receiver.empty()) {
      p.receiver.assign(linked->receiver.begin(), linked->receiver.end());
      p.receiver.resize(p.workItems, -1);
    }
  }
  for (auto& c : p.coords) c.resize(p.padded);
  p.own.resize(p.padded);
  const Vec3& origin = state_->packed.origin;  // the kernel's positions are relative to it
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, p.padded, 4096),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        const SamplePoint& point = points[std::min(i, n - 1)];
                        const PnPosition position = toPosition(point.position, origin);
                        for (int k = 0; k < 3; ++k) {
                          p.coords[k][i] = position.hi.s[k];
                          p.coords[3 + k][i] = position.lo.s[k];
                          p.coords[6 + k][i] = static_cast<float>(point.normal[k]);
                        }
                        p.own[i] = point.solid;
                      }
                    });
  // The volumes are grown by twice the kernel's tolerance at these points: the kernel tests
  // points against them within its tolerance, in float.
  const double margin = 2.0 * kernelLengthAt(state_->packed, points);
  p.table = linked ? buildLinkPatchTable(state_->shadows, state_->volumes, state_->packed, points,
                                         FaceLinks{p.linkStart, linked->faces, p.receiver},
                                         state_->options.culling, margin)
                   : buildPatchTable(state_->shadows, state_->volumes, state_->packed, points,
                                     p.workItems, state_->options.culling, margin, skipFace);
  return p;
}

IlluminanceEngine::KernelOutput IlluminanceEngine::run(PreparedLaunch& prepared) {
  const std::span<const SamplePoint> points = prepared.points;
  const bool bySource = prepared.bySource, withClasses = prepared.withClasses;
  const LinkedLaunch* linked = prepared.linked;
  const int sourceCount = state_->packed.sourceCount;
  const std::size_t n = points.size();
  const std::size_t workItems = prepared.workItems, padded = prepared.padded;
  const std::vector<cl_int>& linkStart = prepared.linkStart;
  const PatchTable& table = prepared.table;
  const std::size_t links = linked ? linked->faces.size() : 0;
  constexpr int kPointArrays = State::kPointArrays;
  constexpr std::size_t kWorkGroup = State::kWorkGroup;
  State::LaunchBuffers& kept = state_->launchBuffers;
  compute::Device& d = *state_->device;
  const std::size_t outValues = linked     ? links * PN_LANES
                                : bySource ? padded * std::max(sourceCount, 1)
                                           : padded;
  // A linked launch writes no classes (kernels/illuminance.cl): one byte keeps the argument.
  const std::size_t classBytes = linked ? 1 : padded * std::max(sourceCount, 1);
  std::vector<std::size_t> batch(kPointArrays, padded * sizeof(float));
  batch.insert(batch.end(), {padded * sizeof(cl_int), compute::byteSize(table.entries),
                             compute::byteSize(table.candidates), compute::byteSize(linkStart),
                             links * sizeof(cl_int), outValues * sizeof(float),
                             workItems * sizeof(cl_int), classBytes});
  if (!compute::fitsDevice(d.info(), batch, state_->sceneBytes)) {
    // Too many points for the device at once: halves cut on a work-group boundary give the same
    // work-items, and so the same values, as one launch would.
    constexpr std::size_t kGroupPoints = PN_LANES * kWorkGroup;
    if (n > kGroupPoints && !linked) {
      const std::size_t half = (n / 2 + kGroupPoints - 1) / kGroupPoints * kGroupPoints;
      const KernelOutput first = launch(points.first(half), bySource, withClasses);
      const KernelOutput second = launch(points.subspan(half), bySource, withClasses);
      // Both halves' rows ([source][point]) side by side in rows of the whole's stride.
      KernelOutput whole;
      whole.padded = first.padded + second.padded;
      const auto join = [&](const auto& a, const auto& b, auto& to) {
        const std::size_t rows = a.size() / first.padded;
        to.resize(rows * whole.padded);
        for (std::size_t r = 0; r < rows; ++r) {
          std::copy_n(a.begin() + r * first.padded, first.padded, to.begin() + r * whole.padded);
          std::copy_n(b.begin() + r * second.padded, second.padded,
                      to.begin() + r * whole.padded + first.padded);
        }
      };
      join(first.illuminance, second.illuminance, whole.illuminance);
      join(first.classes, second.classes, whole.classes);
      return whole;
    }
    compute::requireDeviceMemory(
        d.info(), batch, state_->sceneBytes, fmt::format("a batch of {} points", n),
        "even the smallest batch does not fit beside the scene; use a smaller scene or a device "
        "with more memory (--device)");
  }
  DeviceBuffer(&pointBuffers)[kPointArrays] = kept.points;
  for (int k = 0; k < kPointArrays; ++k)
    DeviceBuffer::uploadInto<float>(d, pointBuffers[k], prepared.coords[k]);
  DeviceBuffer& ownBuffer = kept.pointSolids;
  DeviceBuffer::uploadInto<cl_int>(d, ownBuffer, prepared.own);
  DeviceBuffer& patchBuffer = kept.patchFaces;
  DeviceBuffer::uploadInto<PnPatchFace>(d, patchBuffer, table.entries);
  DeviceBuffer& candidateBuffer = kept.candidates;
  DeviceBuffer::uploadInto<cl_int>(d, candidateBuffer, table.candidates);
  // Unlinked launches do not read the link buffers: the point solids stand in for them.
  DeviceBuffer linkStartBuffer, linkFaceBuffer;
  if (linked) {
    linkStartBuffer = DeviceBuffer::upload<cl_int>(d, linkStart);
    linkFaceBuffer = DeviceBuffer::upload<cl_int>(
        d, std::vector<cl_int>(linked->faces.begin(), linked->faces.end()));
  }
  DeviceBuffer& out = kept.illuminance;
  DeviceBuffer::reserve(d, out, outValues * sizeof(float));
  DeviceBuffer& errors = kept.errors;
  DeviceBuffer::reserve(d, errors, workItems * sizeof(cl_int));
  DeviceBuffer& classes = kept.classes;
  DeviceBuffer::reserve(d, classes, classBytes);

  PnLaunchParams params{};
  params.faceCount = static_cast<cl_int>(state_->packed.faces.size());
  params.epsLength = state_->packed.epsLength;
  params.paths = state_->options.culling ? PN_PATH_CULLING : 0;
  if (state_->options.culling && state_->options.vectorPenumbra) params.paths |= PN_PATH_LANES;
  params.bySource = bySource ? 1 : 0;
  params.sourceStride = static_cast<cl_int>(padded);
  params.linked = linked ? 1 : 0;
  IlluminanceBuffers buffers;
  buffers.pointX = &pointBuffers[0];
  buffers.pointY = &pointBuffers[1];
  buffers.pointZ = &pointBuffers[2];
  buffers.pointXLo = &pointBuffers[3];
  buffers.pointYLo = &pointBuffers[4];
  buffers.pointZLo = &pointBuffers[5];
  buffers.normalX = &pointBuffers[6];
  buffers.normalY = &pointBuffers[7];
  buffers.normalZ = &pointBuffers[8];
  buffers.pointSolid = &ownBuffer;
  buffers.faces = &state_->faces;
  buffers.sourceVertices = &state_->sourceVertices;
  buffers.luminances = &state_->luminances;
  buffers.occluders = &state_->occluders;
  buffers.planes = &state_->planes;
  buffers.edges = &state_->edges;
  buffers.occluderVertices = &state_->occluderVertices;
  buffers.apertures = &state_->apertures;
  buffers.patchFaces = &patchBuffer;
  buffers.candidates = &candidateBuffer;
  buffers.linkStart = linked ? &linkStartBuffer : &ownBuffer;
  buffers.linkFaces = linked ? &linkFaceBuffer : &ownBuffer;
  buffers.illuminance = &out;
  buffers.errors = &errors;
  buffers.classes = &classes;
  compute::KernelLaunch launch(state_->program, "illuminance");
  bindIlluminanceArguments(launch, params, buffers);
  launch.run(workItems, kWorkGroup);

  KernelOutput output;
  output.padded = padded;
  resizePopulated(output.illuminance, outValues);  // per source: up to hundreds of MB
  out.download(output.illuminance.data(), outValues * sizeof(float));
  std::vector<cl_int> errorBits(workItems);
  errors.download(errorBits.data(), workItems * sizeof(cl_int));
  if (linked && linked->overflow) {
    // The caller splits what overflowed: each work-item's bits, no exception.
    linked->overflow->assign(errorBits.begin(), errorBits.begin() + static_cast<std::ptrdiff_t>(
                                                                        linked->start.size() - 1));
  } else {
    for (std::size_t w = 0; w < workItems; ++w)
      if (errorBits[w] != 0)
        throw std::runtime_error(kernelError(errorBits[w], points[std::min(w * PN_LANES, n - 1)]));
  }
  if (withClasses) {
    output.classes.resize(classBytes);
    classes.download(output.classes.data(), classBytes);
  }
  for (int source : state_->facelessSources) {
    const auto row = static_cast<std::ptrdiff_t>(static_cast<std::size_t>(source) * padded);
    const auto length = static_cast<std::ptrdiff_t>(padded);
    if (bySource) std::fill_n(output.illuminance.begin() + row, length, 0.0f);
    if (withClasses)
      std::fill_n(output.classes.begin() + row, length,
                  static_cast<std::uint8_t>(ShadowClass::Unlit));
  }
  return output;
}

}  // namespace penumbra
