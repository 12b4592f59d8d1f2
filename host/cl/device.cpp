#include "cl/device.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "cl/opencl.hpp"

namespace penumbra::compute {

namespace {

std::string typeName(cl_device_type type) {
  if (type & CL_DEVICE_TYPE_GPU) return "gpu";
  if (type & CL_DEVICE_TYPE_CPU) return "cpu";
  if (type & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
  return "other";
}

// PENUMBRA_DEVICE_MEMORY=GLOBAL[,LARGEST]: bytes, or with a K, M or G suffix (powers of 1024).
std::size_t parseBytes(const std::string& text) {
  std::size_t used = 0;
  const double value = std::stod(text, &used);
  double unit = 1.0;
  const std::string suffix = text.substr(used);
  if (suffix == "K" || suffix == "k")
    unit = 1024.0;
  else if (suffix == "M" || suffix == "m")
    unit = 1024.0 * 1024.0;
  else if (suffix == "G" || suffix == "g")
    unit = 1024.0 * 1024.0 * 1024.0;
  else if (!suffix.empty())
    throw std::invalid_argument(text);
  if (!(value >= 0.0)) throw std::invalid_argument(text);
  return static_cast<std::size_t>(value * unit);
}

void applyMemoryLimit(DeviceInfo& info) {
  const char* limit = std::getenv("PENUMBRA_DEVICE_MEMORY");
  if (limit == nullptr || *limit == '\0') return;
  const std::string text(limit);
  const std::size_t comma = text.find(',');
  try {
    const std::size_t global = parseBytes(text.substr(0, comma));
    const std::size_t largest =
        comma == std::string::npos ? global : parseBytes(text.substr(comma + 1));
    info.globalMemory = std::min(info.globalMemory, global);
    info.largestAllocation = std::min({info.largestAllocation, largest, info.globalMemory});
  } catch (const std::exception&) {
    throw std::runtime_error(fmt::format(
        "PENUMBRA_DEVICE_MEMORY='{}': expected GLOBAL[,LARGEST] in bytes (K, M or G allowed)",
        text));
  }
}

struct Found {
  DeviceInfo info;
  cl::Device device;
};

std::vector<Found> findDevices() {
  std::vector<Found> found;
  std::vector<cl::Platform> platforms;
  // No ICD or no platform is "no devices", not an error: the caller says what is missing.
  cl_uint platformCount = 0;
  if (clGetPlatformIDs(0, nullptr, &platformCount) != CL_SUCCESS || platformCount == 0)
    return found;
  try {
    cl::Platform::get(&platforms);
  } catch (const cl::Error&) {
    return found;
  }
  for (const cl::Platform& platform : platforms) {
    std::vector<cl::Device> devices;
    try {
      platform.getDevices(CL_DEVICE_TYPE_ALL, &devices);
    } catch (const cl::Error&) {
      continue;  // a platform without devices reports CL_DEVICE_NOT_FOUND
    }
    for (const cl::Device& device : devices) {
      DeviceInfo info;
      info.index = static_cast<int>(found.size());
      info.platform = platform.getInfo<CL_PLATFORM_NAME>();
      info.name = device.getInfo<CL_DEVICE_NAME>();
      info.type = typeName(device.getInfo<CL_DEVICE_TYPE>());
      info.computeUnits = static_cast<int>(device.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>());
      info.version = device.getInfo<CL_DEVICE_VERSION>();
      info.globalMemory = static_cast<std::size_t>(device.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>());
      info.largestAllocation =
          static_cast<std::size_t>(device.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>());
      applyMemoryLimit(info);
      found.push_back({info, device});
    }
  }
  return found;
}

std::string listing(const std::vector<Found>& found) {
  if (found.empty()) return "no OpenCL device found (is pocl-opencl-icd installed?)";
  std::string text = "available devices:";
  for (const Found& f : found)
    text += fmt::format("\n  {}: {} [{}] ({})", f.info.index, f.info.name, f.info.type,
                        f.info.platform);
  return text;
}

}  // namespace

std::string describe(const cl::Error& error) {
  return fmt::format("{} failed (OpenCL error {})", error.what(), error.err());
}

bool fitsDevice(const DeviceInfo& device, const std::vector<std::size_t>& buffers,
                std::size_t inUse) {
  std::size_t total = inUse;
  for (std::size_t b : buffers) {
    if (b > device.largestAllocation) return false;
    total += b;
  }
  return total <= device.globalMemory;
}

void requireDeviceMemory(const DeviceInfo& device, const std::vector<std::size_t>& buffers,
                         std::size_t inUse, const std::string& what, const std::string& advice) {
  if (fitsDevice(device, buffers, inUse)) return;
  std::size_t total = 0, largest = 0;
  for (std::size_t b : buffers) {
    total += b;
    largest = std::max(largest, b);
  }
  const auto amount = [](std::size_t bytes) {
    if (bytes < 10'000) return fmt::format("{} bytes", bytes);
    if (bytes < 10'000'000) return fmt::format("{:.1f} kB", bytes / 1e3);
    if (bytes < 10'000'000'000) return fmt::format("{:.1f} MB", bytes / 1e6);
    return fmt::format("{:.2f} GB", bytes / 1e9);
  };
  std::string need = fmt::format("{} needs {} of device memory in buffers of up to {}", what,
                                 amount(total), amount(largest));
  if (inUse > 0) need += fmt::format(", besides the {} the scene already holds", amount(inUse));
  throw DeviceMemoryError(fmt::format(
      "{}; {} has {} of global memory and allows {} in one buffer: {}", need, device.name,
      amount(device.globalMemory), amount(device.largestAllocation), advice));
}

std::vector<DeviceInfo> listDevices() {
  std::vector<DeviceInfo> infos;
  for (const Found& f : findDevices()) infos.push_back(f.info);
  return infos;
}

Device::Device(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Device::~Device() = default;
Device::Device(Device&&) noexcept = default;
Device& Device::operator=(Device&&) noexcept = default;
const DeviceInfo& Device::info() const {
  return impl_->info;
}

Device Device::select(const std::string& spec) {
  const std::vector<Found> found = findDevices();
  const Found* chosen = nullptr;
  auto firstOfType = [&](const std::string& type) -> const Found* {
    for (const Found& f : found)
      if (f.info.type == type) return &f;
    return nullptr;
  };
  if (spec.empty() || spec == "auto") {
    chosen = firstOfType("gpu");
    if (!chosen) chosen = firstOfType("cpu");
    if (!chosen && !found.empty()) chosen = &found.front();
  } else if (spec == "cpu" || spec == "gpu") {
    chosen = firstOfType(spec);
  } else {
    std::size_t used = 0;
    int index = -1;
    try {
      index = std::stoi(spec, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != spec.size())
      throw std::runtime_error(fmt::format("--device '{}': expected cpu, gpu or a device index\n{}",
                                           spec, listing(found)));
    if (index >= 0 && index < static_cast<int>(found.size())) chosen = &found[index];
  }
  if (!chosen)
    throw std::runtime_error(fmt::format("no OpenCL device matches '{}'\n{}",
                                         spec.empty() ? "auto" : spec, listing(found)));
  auto impl = std::make_unique<Impl>();
  impl->info = chosen->info;
  impl->device = chosen->device;
  try {
    impl->context = cl::Context(chosen->device);
    impl->queue = cl::CommandQueue(impl->context, chosen->device);
  } catch (const cl::Error& error) {
    throw std::runtime_error(
        fmt::format("cannot open OpenCL device '{}': {}", chosen->info.name, describe(error)));
  }
  return Device(std::move(impl));
}

}  // namespace penumbra::compute
