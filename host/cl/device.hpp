#pragma once
// The only OpenCL-facing API the rest of penumbra sees (DESIGN.md: only host/cl includes
// <CL/opencl.hpp>). Implementation details live behind a pimpl.
#include <cstddef>
#include <memory>
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
};

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
