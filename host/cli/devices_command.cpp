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
  using Row = std::array<std::string, 5>;
  std::vector<Row> rows{{"Index", "Type", "Name", "Platform", "Compute units"}};
  for (const auto& d : devices) {
    rows.push_back({fmt::format("{}", d.index), d.type, d.name, d.platform,
                    fmt::format("{}", d.computeUnits)});
  }
  std::array<std::size_t, 5> width{};
  for (const Row& row : rows) {
    for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
  }
  for (const Row& row : rows) {
    fmt::print("{:>{}}  {:<{}}  {:<{}}  {:<{}}  {:>{}}\n", row[0], width[0], row[1], width[1],
               row[2], width[2], row[3], width[3], row[4], width[4]);
  }
  return 0;
}

}  // namespace penumbra
