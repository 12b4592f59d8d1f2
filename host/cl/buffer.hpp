#pragma once
// Device memory and kernel launches without OpenCL types (only host/cl sees <CL/opencl.hpp>).
#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "cl/device.hpp"

namespace penumbra::compute {

// The bytes the elements of `v` take, as a buffer of them would.
template <class T>
std::size_t byteSize(const std::vector<T>& v) {
  return v.size() * sizeof(T);
}

class DeviceBuffer {
 public:
  DeviceBuffer();
  ~DeviceBuffer();
  DeviceBuffer(DeviceBuffer&&) noexcept;
  DeviceBuffer& operator=(DeviceBuffer&&) noexcept;

  // Read-only device copy of host data (at least one byte is allocated for empty spans, since
  // OpenCL has no zero-sized buffers).
  static DeviceBuffer upload(Device& device, const void* data, std::size_t bytes);
  template <class T>
  static DeviceBuffer upload(Device& device, std::span<const T> data) {
    return upload(device, data.data(), data.size_bytes());
  }
  static DeviceBuffer allocate(Device& device, std::size_t bytes);  // read-write
  // A read-write buffer of at least `bytes`, kept from one call to the next: `buffer` itself
  // while it is large enough, a new one otherwise. What a launch repeated batch after batch
  // uses, so that the device memory of every batch after the first is written, not allocated
  // and faulted in again (on a CPU device, fresh pages cost about as much as the copy).
  static void reserve(Device& device, DeviceBuffer& buffer, std::size_t bytes);
  // reserve, then copies `bytes` from `data` into the buffer's start.
  static void uploadInto(Device& device, DeviceBuffer& buffer, const void* data, std::size_t bytes);
  template <class T>
  static void uploadInto(Device& device, DeviceBuffer& buffer, std::span<const T> data) {
    uploadInto(device, buffer, data.data(), data.size_bytes());
  }
  void download(void* destination, std::size_t bytes) const;
  std::size_t bytes() const;  // as asked for (reserve: the largest asked for so far)

  struct Impl;
  Impl& impl() const { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

// A program built from one of the embedded kernel sources (kernels/<name>.cl).
class Program {
 public:
  // Throws std::runtime_error with the build log when compilation fails.
  Program(Device& device, const std::string& sourceName, const std::string& options);
  ~Program();
  Program(Program&&) noexcept;

  struct Impl;
  Impl& impl() const { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

class KernelLaunch {
 public:
  KernelLaunch(const Program& program, const std::string& kernelName);
  ~KernelLaunch();
  KernelLaunch& arg(unsigned index, const DeviceBuffer& buffer);
  KernelLaunch& arg(unsigned index, int value);
  KernelLaunch& arg(unsigned index, float value);
  KernelLaunch& arg(unsigned index, const std::array<float, 4>& value);  // a float4
  // A struct of `bytes` bytes passed by value: a kernel argument whose type is a struct declared
  // in kernels/shared_types.h (the host's copy of the same declaration).
  KernelLaunch& arg(unsigned index, const void* value, std::size_t bytes);
  // The kernel's argument names, in order. The program must be built with -cl-kernel-arg-info.
  std::vector<std::string> argumentNames() const;
  // Enqueues over `globalSize` work-items in work-groups of `localSize` (globalSize must be a
  // multiple of it) and waits for completion. A fixed work-group size matters on PoCL, which
  // compiles a specialised kernel for every new (global, local) shape it is handed: letting it
  // choose costs 0.3-0.4 s per new grid size.
  void run(std::size_t globalSize, std::size_t localSize);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace penumbra::compute
