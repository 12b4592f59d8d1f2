#pragma once
// The one place <CL/opencl.hpp> is included (docs/architecture.md). Version macros come from
// CMake (CL_HPP_TARGET_OPENCL_VERSION=300, CL_HPP_MINIMUM_OPENCL_VERSION=200), the same for
// every file that includes the wrapper: without them it warns and picks its own defaults.
#define CL_HPP_ENABLE_EXCEPTIONS
#include <CL/opencl.hpp>

#include "cl/device.hpp"

namespace penumbra::compute {

struct Device::Impl {
  DeviceInfo info;
  cl::Device device;
  cl::Context context;
  cl::CommandQueue queue;
};

// "clEnqueueNDRangeKernel failed (-5: CL_OUT_OF_RESOURCES)".
std::string describe(const cl::Error& error);

}  // namespace penumbra::compute
