#include "render/visibility_engine.hpp"

#include "cl/buffer.hpp"
#include "engine/kernel_scene.hpp"
#include "geometry/tolerance.hpp"
#include "render/screen_tiles.hpp"

namespace penumbra {

using compute::DeviceBuffer;

struct VisibilityEngine::State {
  compute::Device* device;
  compute::Program program;
  VisibleScene visible;
  DeviceBuffer objects;

  State(compute::Device& d, const Scene& scene)
      // The illuminance kernel's options: the same relative tolerance (the depth tie rule).
      : device(&d), program(d, "visibility", illuminanceBuildOptions()) {
    upload(scene);
  }
  void upload(const Scene& scene) {
    visible = buildVisibleScene(scene);
    objects = DeviceBuffer::upload<PnVisibleObject>(*device, visible.objects);
  }
};

VisibilityEngine::VisibilityEngine(compute::Device& device, const Scene& scene)
    : state_(std::make_unique<State>(device, scene)) {}
VisibilityEngine::~VisibilityEngine() = default;

void VisibilityEngine::setScene(const Scene& scene) {
  state_->upload(scene);
}

const VisibleScene& VisibilityEngine::visible() const {
  return state_->visible;
}

namespace {

std::array<float, 4> float4(const Vec3& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z()), 0.0f};
}

// The planes relative to the eye, n·(x − eye) = w − n·eye, formed in double and then rounded: the
// kernel traces from the origin, where float resolves a plane a metre away to 1e-7 m whatever
// the scene's coordinates (a thin shelf in site coordinates, a kilometre from their origin, keeps
// its thickness).
std::vector<cl_float4> planesFromTheEye(const std::vector<Plane>& planes, const Vec3& eye) {
  std::vector<cl_float4> packed;
  packed.reserve(planes.size());
  for (const Plane& p : planes)
    packed.push_back(cl_float4{{static_cast<float>(p.normal.x()), static_cast<float>(p.normal.y()),
                                static_cast<float>(p.normal.z()),
                                static_cast<float>(p.offset - p.normal.dot(eye))}});
  return packed;
}

}  // namespace

VisibilityImage VisibilityEngine::trace(const Camera& camera) {
  VisibilityImage image;
  image.width = camera.width;
  image.height = camera.height;
  const std::size_t samples = static_cast<std::size_t>(camera.width) * camera.height;
  // Objects are binned from just in front of the eye: the kernel's length tolerance at its
  // origin, the eye.
  const ScreenTiles tiles = binObjects(state_->visible, camera, Tolerance::kernelLength(0.0));
  double scanned = 0.0;
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) {
      const int t = (y / PN_VISIBILITY_TILE) * tiles.across + x / PN_VISIBILITY_TILE;
      scanned += tiles.start[t + 1] - tiles.start[t];
    }
  image.objectTestsPerSample = samples ? scanned / samples : 0.0;

  compute::Device& d = *state_->device;
  DeviceBuffer tileStart = DeviceBuffer::upload<int>(d, tiles.start);
  DeviceBuffer tileObjects = DeviceBuffer::upload<int>(d, tiles.objects);
  DeviceBuffer planes =
      DeviceBuffer::upload<cl_float4>(d, planesFromTheEye(state_->visible.planes, camera.eye));
  DeviceBuffer ids = DeviceBuffer::allocate(d, samples * sizeof(uint32_t));
  DeviceBuffer t = DeviceBuffer::allocate(d, samples * sizeof(float));
  compute::KernelLaunch launch(state_->program, "visibility");
  // Argument order: kernels/visibility.cl.
  unsigned a = 0;
  launch.arg(a++, float4(camera.forward));
  launch.arg(a++, float4(camera.right));
  launch.arg(a++, float4(camera.up));
  launch.arg(a++, camera.width);
  launch.arg(a++, camera.height);
  launch.arg(a++, tiles.across);
  launch.arg(a++, tileStart);
  launch.arg(a++, tileObjects);
  launch.arg(a++, state_->objects);
  launch.arg(a++, planes);
  launch.arg(a++, ids);
  launch.arg(a++, t);
  // A fixed work-group size (see KernelLaunch::run); the kernel skips the padding.
  constexpr std::size_t kGroup = 64;
  launch.run((samples + kGroup - 1) / kGroup * kGroup, kGroup);
  image.faceIds.resize(samples);
  image.t.resize(samples);
  ids.download(image.faceIds.data(), samples * sizeof(uint32_t));
  t.download(image.t.data(), samples * sizeof(float));
  return image;
}

}  // namespace penumbra
