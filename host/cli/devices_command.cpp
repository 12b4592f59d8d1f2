#include "cli/devices_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "cl/device.hpp"

namespace penumbra {

int runDevicesCommand() {
  const std::vector<compute::DeviceInfo> devices = compute::listDevices();
  if (devices.empty()) {
    fmt::print(stderr,
               "penumbra: no OpenCL device found. For the CPU install PoCL "
               "(apt-get install pocl-opencl-icd); `penumbra grid --reference` needs no device.\n");
    return 1;
  }
  using Row = std::array<std::string, 7>;
  std::vector<Row> rows{
      {"Index", "Type", "Name", "Platform", "Compute units", "Memory [MB]", "Largest buffer [MB]"}};
  for (const auto& d : devices) {
    rows.push_back({fmt::format("{}", d.index), d.type, d.name, d.platform,
                    fmt::format("{}", d.computeUnits), fmt::format("{:.0f}", d.globalMemory / 1e6),
                    fmt::format("{:.0f}", d.largestAllocation / 1e6)});
  }
  std::array<std::size_t, 7> width{};
  for (const Row& row : rows) {
    for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
  }
  for (const Row& row : rows) {
    fmt::print("{:>{}}  {:<{}}  {:<{}}  {:<{}}  {:>{}}  {:>{}}  {:>{}}\n", row[0], width[0], row[1],
               width[1], row[2], width[2], row[3], width[3], row[4], width[4], row[5], width[5],
               row[6], width[6]);
  }
  return 0;
}

}  // namespace penumbra
