// The dense transfer's far-field rule against the transfer it stands for: on a scene (by default
// data/open-office.yaml) the mesh the product builds, and three transfers of it:
//  * every sender averaged over every receiver's 16 nodes (no rule: the reference);
//  * far senders at the receiver's four far points, every far pair computed both ways, each row
//    keeping its sum over the far points (what a scene without a room gets);
//  * what the product computes in a room: rows summing to transferRowSums, far pairs small
//    against their gap computed one way and taken the other by reciprocity.
// For each: seconds, and the solved indirect E on the elements against the reference's
// (worst relative departure, and the area-weighted mean departure, signed), at the scene's
// reflectances.
//   usage: far_field_bench [--device cpu|gpu|N] [scene.yaml]
// Run from the repository root; POCL_MAX_PTHREAD_COUNT=2 pins PoCL to two threads.
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <optional>
#include <string>

#include "cl/device.hpp"
#include "engine/illuminance_engine.hpp"
#include "radiosity/element_transfer.hpp"
#include "radiosity/interreflection.hpp"
#include "radiosity/radiosity_solver.hpp"
#include "radiosity/transfer_row_sums.hpp"
#include "scene/scene_loader.hpp"
#include "timing/seconds_since.hpp"

namespace {

using namespace penumbra;

void compare(const char* name, double seconds, const SurfaceMesh& mesh,
             const RadiositySolution& reference, const RadiositySolution& s) {
  double worst = 0.0, signedSum = 0.0, weight = 0.0;
  for (Eigen::Index i = 0; i < s.indirect.rows(); ++i) {
    const double e = reference.indirect(i, 1);
    if (e > 0.0) worst = std::max(worst, std::abs(s.indirect(i, 1) / e - 1.0));
    signedSum += mesh.elements[i].area * (s.indirect(i, 1) - e);
    weight += mesh.elements[i].area * e;
  }
  fmt::print("{:<44} {:8.1f} s   worst {:.2e}   mean {:+.2e}\n", name, seconds, worst,
             signedSum / weight);
}

}  // namespace

int main(int argc, char** argv) {
  std::string deviceSpec = "cpu", file = "data/open-office.yaml";
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--device" && a + 1 < argc)
      deviceSpec = argv[++a];
    else
      file = arg;
  }
  compute::Device device = compute::Device::select(deviceSpec);
  const Scene scene = loadScene(file);
  IlluminanceEngine direct(device, scene);
  const Interreflection solved(device, scene, direct);
  const SurfaceMesh& mesh = solved.mesh();
  fmt::print(
      "{}: {} elements, {} nodes; indirect E on the elements against every sender at "
      "every node\n",
      file, mesh.elements.size(), mesh.nodes.size());
  IlluminanceEngine engine(device, elementSceneSharingCasters(scene, mesh));
  const std::size_t first = mesh.casterBlocks.size();

  auto start = Clock::now();
  const Eigen::MatrixXd exact = elementTransfer(engine, mesh, first);
  const double exactSeconds = secondsSince(start);
  const RadiositySolution reference = solveRadiosity(exact, mesh, solved.direct());
  fmt::print("{:<44} {:8.1f} s\n", "every sender at every node", exactSeconds);

  start = Clock::now();
  const Eigen::MatrixXd bothWays = elementTransfer(engine, mesh, FarFieldRule{}, first);
  compare("far points, both ways, rows over far points", secondsSince(start), mesh, reference,
          solveRadiosity(bothWays, mesh, solved.direct()));

  start = Clock::now();
  const std::optional<Eigen::VectorXd> sums = transferRowSums(device, scene, mesh);
  if (!sums) {
    fmt::print("no room: no row sums, the product takes the transfer both ways\n");
    return 0;
  }
  fmt::print("{:<44} {:8.1f} s\n", "row sums (transferRowSums)", secondsSince(start));
  for (double ratio : {FarFieldRule{}.reciprocalRatio, FarFieldRule{}.farRatio}) {
    start = Clock::now();
    const Eigen::MatrixXd t =
        elementTransfer(engine, mesh, FarFieldRule{FarFieldRule{}.farRatio, ratio}, first, &*sums);
    compare(fmt::format("row sums, reciprocity where (d/g)² <= {}", ratio).c_str(),
            secondsSince(start), mesh, reference, solveRadiosity(t, mesh, solved.direct()));
  }
  return 0;
}
