#include "lighting/illuminance_engine.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "cl/buffer.hpp"
#include "lighting/kernel_scene.hpp"

namespace penumbra {

using compute::DeviceBuffer;

struct IlluminanceEngine::State {
  compute::Device* device = nullptr;
  KernelScene packed;
  compute::Program program;
  DeviceBuffer faces, sourceVertices, occluders, planes, edges, occluderVertices;

  State(compute::Device& d, const Scene& scene)
      : device(&d),
        packed(packScene(scene)),
        program(d, "illuminance",
                fmt::format("-cl-std=CL1.2 -DPN_EPS_REL={:.9g}f", Tolerance::kKernelRelative)) {
    faces = DeviceBuffer::upload<PnSourceFace>(d, packed.faces);
    sourceVertices = DeviceBuffer::upload<cl_float4>(d, packed.sourceVertices);
    occluders = DeviceBuffer::upload<PnOccluder>(d, packed.occluders);
    planes = DeviceBuffer::upload<cl_float4>(d, packed.planes);
    edges = DeviceBuffer::upload<cl_int4>(d, packed.edges);
    occluderVertices = DeviceBuffer::upload<cl_float4>(d, packed.occluderVertices);
  }
};

IlluminanceEngine::IlluminanceEngine(compute::Device& device, const Scene& scene)
    : state_(std::make_unique<State>(device, scene)) {}
IlluminanceEngine::~IlluminanceEngine() = default;

std::vector<double> IlluminanceEngine::illuminance(std::span<const SamplePoint> points) {
  const std::size_t n = points.size();
  if (n == 0) return {};
  // Work-items of PN_LANES points, in work-groups of kWorkGroup work-items (see
  // KernelLaunch::run for why the work-group size is fixed).
  constexpr std::size_t kWorkGroup = 16;
  const std::size_t groups = (n + PN_LANES * kWorkGroup - 1) / (PN_LANES * kWorkGroup) * kWorkGroup;
  const std::size_t padded = groups * PN_LANES;
  // Structure of arrays, one float8 lane per point. Padding repeats the last point.
  std::vector<float> coords[6];
  for (auto& c : coords) c.resize(padded);
  std::vector<cl_int> own(padded);
  for (std::size_t i = 0; i < n; ++i) {
    const SamplePoint& p = points[i];
    for (int k = 0; k < 3; ++k) {
      coords[k][i] = static_cast<float>(p.position[k]);
      coords[3 + k][i] = static_cast<float>(p.normal[k]);
    }
    own[i] = p.solid;
  }
  for (std::size_t i = n; i < padded; ++i) {
    for (auto& c : coords) c[i] = c[n - 1];
    own[i] = own[n - 1];
  }
  compute::Device& d = *state_->device;
  DeviceBuffer pointBuffers[6];
  for (int k = 0; k < 6; ++k) pointBuffers[k] = DeviceBuffer::upload<float>(d, coords[k]);
  DeviceBuffer ownBuffer = DeviceBuffer::upload<cl_int>(d, own);
  DeviceBuffer out = DeviceBuffer::allocate(d, padded * sizeof(float));
  DeviceBuffer errors = DeviceBuffer::allocate(d, groups * sizeof(cl_int));

  compute::KernelLaunch launch(state_->program, "illuminance");
  // Argument order: kernels/illuminance.cl, kernel `illuminance`.
  for (unsigned k = 0; k < 6; ++k) launch.arg(k, pointBuffers[k]);
  launch.arg(6, ownBuffer);
  launch.arg(7, state_->faces);
  launch.arg(8, static_cast<int>(state_->packed.faces.size()));
  launch.arg(9, state_->sourceVertices);
  launch.arg(10, state_->occluders);
  launch.arg(11, state_->planes);
  launch.arg(12, state_->edges);
  launch.arg(13, state_->occluderVertices);
  launch.arg(14, state_->packed.epsLength);
  launch.arg(15, out);
  launch.arg(16, errors);
  launch.run(groups, kWorkGroup);

  std::vector<float> e(padded);
  out.download(e.data(), padded * sizeof(float));
  std::vector<cl_int> errorBits(groups);
  errors.download(errorBits.data(), groups * sizeof(cl_int));
  for (std::size_t g = 0; g < groups; ++g) {
    if (errorBits[g] == 0) continue;
    const SamplePoint& p = points[g * PN_LANES];
    throw std::runtime_error(fmt::format(
        "the illuminance kernel ran out of room near point ({:.3f}, {:.3f}, {:.3f}) m: {}",
        p.position.x(), p.position.y(), p.position.z(),
        (errorBits[g] & PN_ERROR_TOO_MANY_OCCLUDERS)
            ? fmt::format("more than {} occluders shade it", PN_MAX_ACTIVE_OCCLUDERS)
        : (errorBits[g] & PN_ERROR_TOO_MANY_CONTACTS)
            ? fmt::format("it touches more than {} solids", PN_MAX_CONTACTS)
            : fmt::format("more than {} visible pieces on one edge", PN_MAX_VISIBLE_PIECES)));
  }
  return std::vector<double>(e.begin(), e.begin() + static_cast<std::ptrdiff_t>(n));
}

}  // namespace penumbra
