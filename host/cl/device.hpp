#pragma once
// The only OpenCL-facing API the rest of penumbra sees (docs/architecture.md: only host/cl includes
// <CL/opencl.hpp>). Implementation details live behind a pimpl.
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace penumbra::compute {

struct DeviceInfo {
  int index = 0;  // position in listDevices(), the number `--device <index>` takes
  std::string platform;
  std::string name;
  std::string type;  // "gpu", "cpu", "accelerator", "other"
  int computeUnits = 0;
  std::string version;
  // CL_DEVICE_GLOBAL_MEM_SIZE and CL_DEVICE_MAX_MEM_ALLOC_SIZE, in bytes. The environment variable
  // PENUMBRA_DEVICE_MEMORY=GLOBAL[,LARGEST] (bytes, or with a K, M or G suffix) lowers them, to
  // check how penumbra behaves on a small device (the tests do).
  std::size_t globalMemory = 0;
  std::size_t largestAllocation = 0;
};

// What a device lacks for a request: thrown before anything is allocated.
class DeviceMemoryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Whether buffers of these sizes (bytes) can live on the device together, besides `inUse` bytes
// already there: each within the largest allocation, all within the global memory.
bool fitsDevice(const DeviceInfo& device, const std::vector<std::size_t>& buffers,
                std::size_t inUse = 0);
// Throws DeviceMemoryError when they cannot, naming `what`, the sizes, the device's limits and
// `advice` (what the user can do about it).
void requireDeviceMemory(const DeviceInfo& device, const std::vector<std::size_t>& buffers,
                         std::size_t inUse, const std::string& what, const std::string& advice);

// Every OpenCL device on every platform, in a stable order.
std::vector<DeviceInfo> listDevices();

class Device {
 public:
  // spec: "" or "auto" = the first GPU, else the first CPU device (PoCL); "cpu"; "gpu"; or an
  // index from listDevices(). Throws std::runtime_error naming what is available.
  static Device select(const std::string& spec);
  ~Device();
  Device(Device&&) noexcept;
  Device& operator=(Device&&) noexcept;

  const DeviceInfo& info() const;

  struct Impl;
  Impl& impl() const { return *impl_; }

 private:
  explicit Device(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace penumbra::compute
