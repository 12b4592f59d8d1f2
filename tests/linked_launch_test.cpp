// The linked launch of the illuminance kernel (IlluminanceEngine::linkedIlluminance): each group
// of PN_LANES points takes a list of its own source faces, and each (group, face) link gives the
// same floats as the dense launch (illuminanceBySource) gives for that face at those points, in a
// room whose furniture shades part of the elements from each other (patches of classes B, C and
// umbra all occur).
#include <gtest/gtest.h>

#include <fstream>

#include "kernels/shared_types.h"
#include "radiosity/element_transfer.hpp"
#include "radiosity/surface_mesh.hpp"
#include "scene/scene_loader.hpp"
#include "test_device.hpp"
#include "test_files.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;

TEST(LinkedLaunch, EachLinkIsTheDenseLaunchsValueForItsFaceAndPoints) {
  TempDir dir("linked");
  const auto file = dir.path() / "room.yaml";
  std::ofstream(file)
      << "penumbra: 1\nmaterials:\n  paint: 0.5\nroom:\n  size: [4, 3, 3]\n"
         "  materials: {floor: paint, ceiling: paint, walls: paint}\n"
         "sources:\n  - {name: panel, rect: {center: [1.3, 1.7, 2.99], size: [0.6, 0.6], "
         "normal: [0, 0, -1]}, flux: 3000}\n"
         "solids:\n  - {name: desk, box: {min: [1.0, 1.0, 0.7], max: [2.6, 1.8, 0.75]}, "
         "material: paint}\n"
         "  - {name: cabinet, box: {min: [3.0, 0.2, 0.0], max: [3.8, 0.8, 1.8]}, material: "
         "paint}\n";
  const Scene scene = loadScene(file);
  const SurfaceMesh mesh = buildSurfaceMesh(scene, MeshOptions{0.75, 2});
  const Scene elements = elementScene(scene, mesh);
  IlluminanceEngine engine(cpuDevice(), elements);
  const std::vector<SamplePoint>& points = mesh.nodes;
  std::size_t stride = 0;
  const std::vector<float> dense = engine.illuminanceBySource(points, stride);

  // Work-item w takes every third face, starting at w mod 3, and the face of its own element.
  const std::size_t items = (points.size() + PN_LANES - 1) / PN_LANES;
  const auto faces = static_cast<cl_int>(elements.sources.size());
  std::vector<cl_int> start = {0}, linked;
  for (std::size_t w = 0; w < items; ++w) {
    for (cl_int f = static_cast<cl_int>(w % 3); f < faces; f += 3) linked.push_back(f);
    start.push_back(static_cast<cl_int>(linked.size()));
  }
  // The padding repeats the last point, as the dense launch pads.
  std::vector<SamplePoint> padded = points;
  padded.resize(items * PN_LANES, points.back());
  const std::vector<float> e = engine.linkedIlluminance(padded, start, linked);
  ASSERT_EQ(e.size(), linked.size() * PN_LANES);

  std::size_t lit = 0, dark = 0;
  for (std::size_t w = 0; w < items; ++w)
    for (cl_int k = start[w]; k < start[w + 1]; ++k)
      for (std::size_t lane = 0; lane < PN_LANES; ++lane) {
        const std::size_t point = w * PN_LANES + lane;
        if (point >= points.size()) continue;
        const float expected = dense[static_cast<std::size_t>(linked[k]) * stride + point];
        ASSERT_EQ(e[static_cast<std::size_t>(k) * PN_LANES + lane], expected)
            << "work-item " << w << ", face " << linked[k] << ", lane " << lane;
        ++(expected > 0.0f ? lit : dark);
      }
  // Both kinds of links occur: faces a point sees, and faces it cannot see or that are hidden.
  EXPECT_GT(lit, 1000u);
  EXPECT_GT(dark, 1000u);
}

TEST(LinkedLaunch, WorkItemsWithoutLinksAndNoLinksAtAll) {
  TempDir dir("linked-empty");
  const auto file = dir.path() / "room.yaml";
  std::ofstream(file) << "penumbra: 1\nroom:\n  size: [2, 2, 2]\nsources:\n"
                         "  - {name: a, rect: {center: [1, 1, 1.99], size: [0.5, 0.5], normal: "
                         "[0, 0, -1]}, luminance: 1000}\n";
  const Scene scene = loadScene(file);
  IlluminanceEngine engine(cpuDevice(), scene);
  std::vector<SamplePoint> points(2 * PN_LANES);
  for (std::size_t i = 0; i < points.size(); ++i)
    points[i] = SamplePoint{Vec3(0.1 * static_cast<double>(i % PN_LANES) + 0.5, 1.0, 0.0),
                            Vec3::UnitZ(), -1};
  // The first work-item has no link, the second one: only the second's values come back.
  const std::vector<cl_int> start = {0, 0, 1}, faces = {0};
  const std::vector<float> e = engine.linkedIlluminance(points, start, faces);
  ASSERT_EQ(e.size(), PN_LANES);
  const std::vector<double> direct =
      engine.illuminance(std::span<const SamplePoint>(points).subspan(PN_LANES));
  for (std::size_t lane = 0; lane < PN_LANES; ++lane)
    EXPECT_NEAR(e[lane], direct[lane], 1e-6 * direct[lane]) << lane;
  EXPECT_TRUE(engine.linkedIlluminance(points, std::vector<cl_int>{0, 0, 0}, {}).empty());
  EXPECT_THROW(engine.linkedIlluminance(points, std::vector<cl_int>{0, 1}, faces),
               std::logic_error);
}

}  // namespace
}  // namespace penumbra
