// The illuminance kernel's launch interface, host against device on PoCL: the layout of the
// structs that cross (kernels/shared_types.h) as the kernel compiler lays them out, a
// PnLaunchParams passed by value arriving field for field, and the kernel's argument names in the
// order the host binds them (engine/kernel_scene.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

#include "cl/buffer.hpp"
#include "engine/kernel_scene.hpp"
#include "test_device.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;

// What kernels/interface_layout.cl writes, in its order, as the host lays the structs out.
std::vector<int> hostLayout(const PnLaunchParams& params) {
  std::vector<int> layout = {
      static_cast<int>(sizeof(PnLaunchParams)),
      static_cast<int>(offsetof(PnLaunchParams, faceCount)),
      static_cast<int>(offsetof(PnLaunchParams, epsLength)),
      static_cast<int>(offsetof(PnLaunchParams, paths)),
      static_cast<int>(offsetof(PnLaunchParams, bySource)),
      static_cast<int>(offsetof(PnLaunchParams, sourceStride)),
      static_cast<int>(offsetof(PnLaunchParams, linked)),
      static_cast<int>(sizeof(PnSourceFace)),
      static_cast<int>(sizeof(PnAperture)),
      static_cast<int>(sizeof(PnOccluder)),
      static_cast<int>(sizeof(PnPatchFace)),
      static_cast<int>(sizeof(PnVisibleObject)),
      static_cast<int>(sizeof(PnLuminancePolynomial)),
      static_cast<int>(offsetof(PnLuminancePolynomial, coefficient)),
      static_cast<int>(offsetof(PnLuminancePolynomial, order)),
      static_cast<int>(sizeof(PnPosition)),
      static_cast<int>(offsetof(PnPosition, lo)),
  };
  int eps = 0;
  std::memcpy(&eps, &params.epsLength, sizeof eps);
  for (int v :
       {params.faceCount, eps, params.paths, params.bySource, params.sourceStride, params.linked})
    layout.push_back(v);
  return layout;
}

TEST(LaunchInterface, StructLayoutsAndParamsAgreeWithTheKernel) {
  PnLaunchParams params{};
  params.faceCount = 17;
  params.epsLength = 3.5e-5f;
  params.paths = PN_PATH_CULLING | PN_PATH_LANES;
  params.bySource = 1;
  params.sourceStride = 4096;
  params.linked = 1;
  const std::vector<int> expected = hostLayout(params);

  compute::Device& device = cpuDevice();
  compute::Program program(device, "interface_layout", illuminanceBuildOptions());
  compute::DeviceBuffer out = compute::DeviceBuffer::allocate(device, 64 * sizeof(int));
  compute::KernelLaunch launch(program, "interface_layout");
  launch.arg(0, &params, sizeof params).arg(1, out);
  launch.run(1, 1);
  std::vector<int> written(64, -1);
  out.download(written.data(), written.size() * sizeof(int));
  const int count = written[0];
  ASSERT_EQ(count, static_cast<int>(expected.size()))
      << "kernels/interface_layout.cl and this test list different fields";
  const std::vector<int> device_layout(written.begin() + 1, written.begin() + 1 + count);
  EXPECT_EQ(device_layout, expected);
}

// Positions cross as double-float pairs (PnPosition): hi + lo carries x − origin to about 2^-48
// of its size, where hi alone is off by up to half a float spacing (1e-6 m at 30 m).
TEST(LaunchInterface, PositionsCrossAsHiAndLoPartsThatCarryTheDouble) {
  const Vec3 origin(30.0, 15.0, 1.5);
  for (const Vec3& x : {Vec3(58.049, 27.499, 1.0018), Vec3(2.6500000000000004, 2.35, 0.8),
                        Vec3(-1234.5678, 0.1, 1e-3)}) {
    const PnPosition p = toPosition(x, origin);
    for (int k = 0; k < 3; ++k) {
      const double d = x[k] - origin[k];
      const double hi = p.hi.s[k], lo = p.lo.s[k];
      const volatile float rounded = static_cast<float>(d);  // (toPosition says why volatile)
      EXPECT_EQ(hi, static_cast<double>(rounded)) << "coordinate " << k;
      EXPECT_LE(std::abs(lo), 0.5 * std::abs(hi) * 0x1p-23) << "coordinate " << k;
      EXPECT_LE(std::abs(hi + lo - d), std::abs(d) * 0x1p-47) << "coordinate " << k;
    }
  }
}

TEST(LaunchInterface, KernelArgumentsAreTheHostBindingInOrder) {
  compute::Program program(cpuDevice(), "illuminance",
                           illuminanceBuildOptions() + " -cl-kernel-arg-info");
  compute::KernelLaunch kernel(program, "illuminance");
  EXPECT_EQ(kernel.argumentNames(), illuminanceArgumentNames());
}

}  // namespace
}  // namespace penumbra
