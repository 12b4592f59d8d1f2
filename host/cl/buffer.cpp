#include "cl/buffer.hpp"

#include <fmt/format.h>

#include <map>
#include <stdexcept>

#include "cl/opencl.hpp"
#include "memory/page_prefault.hpp"

namespace penumbra::embedded {
const std::map<std::string, std::string>& kernelSources();  // generated at build time
}

namespace penumbra::compute {

struct DeviceBuffer::Impl {
  Device::Impl* device = nullptr;
  cl::Buffer buffer;
  std::size_t bytes = 0;
};

DeviceBuffer::DeviceBuffer() : impl_(std::make_unique<Impl>()) {}
DeviceBuffer::~DeviceBuffer() = default;
DeviceBuffer::DeviceBuffer(DeviceBuffer&&) noexcept = default;
DeviceBuffer& DeviceBuffer::operator=(DeviceBuffer&&) noexcept = default;
std::size_t DeviceBuffer::bytes() const {
  return impl_->bytes;
}

DeviceBuffer DeviceBuffer::upload(Device& device, const void* data, std::size_t bytes) {
  DeviceBuffer result;
  result.impl_->device = &device.impl();
  result.impl_->bytes = bytes;
  const std::size_t allocated = std::max<std::size_t>(bytes, 16);
  try {
    result.impl_->buffer = cl::Buffer(device.impl().context, CL_MEM_READ_ONLY, allocated);
    if (bytes > 0)
      device.impl().queue.enqueueWriteBuffer(result.impl_->buffer, CL_TRUE, 0, bytes, data);
  } catch (const cl::Error& error) {
    throw std::runtime_error(fmt::format("uploading {} bytes: {}", bytes, describe(error)));
  }
  return result;
}

DeviceBuffer DeviceBuffer::allocate(Device& device, std::size_t bytes) {
  DeviceBuffer result;
  result.impl_->device = &device.impl();
  result.impl_->bytes = bytes;
  try {
    result.impl_->buffer =
        cl::Buffer(device.impl().context, CL_MEM_READ_WRITE, std::max<std::size_t>(bytes, 16));
  } catch (const cl::Error& error) {
    throw std::runtime_error(fmt::format("allocating {} bytes: {}", bytes, describe(error)));
  }
  // On a CPU device the buffer is host memory (PoCL maps it without a copy): its pages are
  // mapped at once (memory/page_prefault.hpp) rather than faulted in by the first upload or
  // launch. Nothing is written; a runtime that maps through a copy only pays the copy's pages.
  if (device.info().type == "cpu" && bytes >= kPopulateMinBytes) {
    try {
      cl::CommandQueue& queue = device.impl().queue;
      void* host = queue.enqueueMapBuffer(result.impl_->buffer, CL_TRUE,
                                          CL_MAP_WRITE_INVALIDATE_REGION, 0, bytes);
      populatePages(host, bytes);
      queue.enqueueUnmapMemObject(result.impl_->buffer, host);
    } catch (const cl::Error&) {
      // Mapping is an optimisation only: the first use faults the pages in instead.
    }
  }
  return result;
}

void DeviceBuffer::reserve(Device& device, DeviceBuffer& buffer, std::size_t bytes) {
  if (buffer.impl_->device == &device.impl() && buffer.impl_->bytes >= bytes) return;
  buffer = DeviceBuffer();  // the old memory goes before the new is allocated
  buffer = allocate(device, bytes);
}

void DeviceBuffer::uploadInto(Device& device, DeviceBuffer& buffer, const void* data,
                              std::size_t bytes) {
  reserve(device, buffer, bytes);
  if (bytes == 0) return;
  try {
    device.impl().queue.enqueueWriteBuffer(buffer.impl_->buffer, CL_TRUE, 0, bytes, data);
  } catch (const cl::Error& error) {
    throw std::runtime_error(fmt::format("uploading {} bytes: {}", bytes, describe(error)));
  }
}

void DeviceBuffer::download(void* destination, std::size_t bytes) const {
  if (bytes == 0) return;
  try {
    impl_->device->queue.enqueueReadBuffer(impl_->buffer, CL_TRUE, 0, bytes, destination);
  } catch (const cl::Error& error) {
    throw std::runtime_error(fmt::format("downloading {} bytes: {}", bytes, describe(error)));
  }
}

struct Program::Impl {
  Device::Impl* device = nullptr;
  cl::Program program;
};

Program::Program(Device& device, const std::string& sourceName, const std::string& options)
    : impl_(std::make_unique<Impl>()) {
  const auto& sources = embedded::kernelSources();
  const auto found = sources.find(sourceName);
  if (found == sources.end())
    throw std::logic_error(fmt::format("no embedded kernel source '{}'", sourceName));
  impl_->device = &device.impl();
  impl_->program = cl::Program(device.impl().context, found->second);
  try {
    impl_->program.build({device.impl().device}, options.c_str());
  } catch (const cl::Error&) {
    std::string log;
    try {
      log = impl_->program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device.impl().device);
    } catch (const cl::Error&) {
      log = "(no build log)";
    }
    throw std::runtime_error(fmt::format("building kernels/{}.cl for {} failed:\n{}", sourceName,
                                         device.info().name, log));
  }
}
Program::~Program() = default;
Program::Program(Program&&) noexcept = default;

struct KernelLaunch::Impl {
  Device::Impl* device = nullptr;
  cl::Kernel kernel;
  std::string name;
};

KernelLaunch::KernelLaunch(const Program& program, const std::string& kernelName)
    : impl_(std::make_unique<Impl>()) {
  impl_->device = program.impl().device;
  impl_->name = kernelName;
  impl_->kernel = cl::Kernel(program.impl().program, kernelName.c_str());
}
KernelLaunch::~KernelLaunch() = default;

KernelLaunch& KernelLaunch::arg(unsigned index, const DeviceBuffer& buffer) {
  impl_->kernel.setArg(index, buffer.impl().buffer);
  return *this;
}
KernelLaunch& KernelLaunch::arg(unsigned index, int value) {
  impl_->kernel.setArg(index, static_cast<cl_int>(value));
  return *this;
}
KernelLaunch& KernelLaunch::arg(unsigned index, float value) {
  impl_->kernel.setArg(index, static_cast<cl_float>(value));
  return *this;
}

KernelLaunch& KernelLaunch::arg(unsigned index, const std::array<float, 4>& value) {
  impl_->kernel.setArg(index, cl_float4{{value[0], value[1], value[2], value[3]}});
  return *this;
}

KernelLaunch& KernelLaunch::arg(unsigned index, const void* value, std::size_t bytes) {
  impl_->kernel.setArg(index, bytes, value);
  return *this;
}

std::vector<std::string> KernelLaunch::argumentNames() const {
  try {
    const cl_uint count = impl_->kernel.getInfo<CL_KERNEL_NUM_ARGS>();
    std::vector<std::string> names;
    for (cl_uint i = 0; i < count; ++i) {
      // c_str(): a terminating NUL, where the C++ wrapper keeps one, is not part of the name.
      const std::string name = impl_->kernel.getArgInfo<CL_KERNEL_ARG_NAME>(i);
      names.emplace_back(name.c_str());
    }
    return names;
  } catch (const cl::Error& error) {
    throw std::runtime_error(
        fmt::format("reading the arguments of kernel {}: {}", impl_->name, describe(error)));
  }
}

void KernelLaunch::run(std::size_t globalSize, std::size_t localSize) {
  if (globalSize == 0) return;
  try {
    impl_->device->queue.enqueueNDRangeKernel(impl_->kernel, cl::NullRange, cl::NDRange(globalSize),
                                              cl::NDRange(localSize));
    impl_->device->queue.finish();
  } catch (const cl::Error& error) {
    throw std::runtime_error(fmt::format("running kernel {}: {}", impl_->name, describe(error)));
  }
}

}  // namespace penumbra::compute
