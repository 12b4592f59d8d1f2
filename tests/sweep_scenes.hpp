#pragma once
// A small room with two parameters, for the tests that run studies (the runner, the Slurm
// scripts): a panel whose flux and a room whose depth (y + 1 m) vary, a floor grid of 15 points.
namespace penumbra::testing {

inline constexpr const char* kParameterisedRoom = R"(penumbra: 1
parameters: {flux: 1000, y: 1}
room: {size: [3, "${y + 1}", 3]}
sources:
  - {name: panel, rect: {center: [1.5, 1, 2.99], size: [0.5, 0.5], normal: [0, 0, -1]}, flux: "${flux}"}
grids:
  - {name: floor, height: 0, spacing: 0.5, margin: 0.25}
)";

}  // namespace penumbra::testing
