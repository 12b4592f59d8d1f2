#pragma once
// The PoCL CPU device, opened once per test process (kernels are tested on PoCL's CPU
// device, which every machine with the packages has; docs/building.md).
#include "cl/device.hpp"

namespace penumbra::testing {

inline compute::Device& cpuDevice() {
  static compute::Device device = compute::Device::select("cpu");
  return device;
}

}  // namespace penumbra::testing
