// Interreflection (host/radiosity) on PoCL: the transfer's row sums and reciprocity, energy
// balance in closed rooms, CIE 171:2006 case 5.8, an independent collocation reference, and the
// invariants of the total illuminance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>

#include "box_room_radiosity.hpp"
#include "geometry/tolerance.hpp"
#include "illuminance/estimator.hpp"
#include "radiosity/element_transfer.hpp"
#include "radiosity/interreflection.hpp"
#include "radiosity/transfer_row_sums.hpp"
#include "sanitized_build.hpp"
#include "scene/daylight.hpp"
#include "scene/scene_loader.hpp"
#include "test_device.hpp"
#include "test_files.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;
constexpr double kPi = std::numbers::pi;

// A room of one material `paint` (ρ = 0.5 unless the test sets it on the mesh), one source (a
// YAML flow map) and `extra` YAML (solids).
Scene paintedRoom(const TempDir& dir, const std::string& size, const std::string& source,
                  const std::string& extra = "") {
  const auto file = dir.path() / "room.yaml";
  std::ofstream(file) << "penumbra: 1\nmaterials:\n  paint: 0.5\nroom:\n  size: " << size
                      << "\n  materials: {floor: paint, ceiling: paint, walls: paint}\n"
                         "sources:\n  - "
                      << source << "\n"
                      << extra;
  return loadScene(file);
}

// The same with a 0.6 m ceiling panel of 3000 lm.
Scene closedRoom(const TempDir& dir, const std::string& size, const std::string& extra = "") {
  return paintedRoom(dir, size,
                     "{name: panel, rect: {center: [1.3, 1.7, 2.99], size: [0.6, 0.6], normal: "
                     "[0, 0, -1]}, flux: 3000}",
                     extra);
}

void setReflectance(SurfaceMesh& mesh, double rho) {
  for (SurfaceElement& element : mesh.elements) element.reflectance = Vec3::Constant(rho);
}

// Σ A·E over the elements, per unit of the whole surface: the area average (lx).
double areaAverage(const SurfaceMesh& mesh, const Eigen::VectorXd& e) {
  double sum = 0.0;
  for (std::size_t i = 0; i < mesh.elements.size(); ++i) sum += mesh.elements[i].area * e[i];
  return sum / mesh.area();
}

// A scene's interreflection with the default mesh and its transfer matrix, which the tests
// solve again for other reflectances (the transfer depends on the geometry only).
struct SolvedRoom {
  explicit SolvedRoom(const Scene& scene)
      : direct(cpuDevice(), scene),
        solved(std::make_unique<Interreflection>(cpuDevice(), scene, direct)),
        elements(elementScene(scene, solved->mesh())),
        engine(cpuDevice(), elements),
        transfer(elementTransfer(engine, solved->mesh())) {}
  IlluminanceEngine direct;
  std::unique_ptr<Interreflection> solved;
  Scene elements;
  IlluminanceEngine engine;
  Eigen::MatrixXd transfer;
};

TEST(Transfer, RowsOfAClosedRoomSumToPiAndReciprocityHolds) {
  TempDir dir("interreflection");
  const Scene scene = closedRoom(dir, "[4, 3, 3]");
  double previousAsymmetry = INFINITY;
  for (int order : {2, 4, 6}) {
    const SurfaceMesh mesh = buildSurfaceMesh(scene, MeshOptions{1.0, order});
    Scene elements = elementScene(scene, mesh);
    IlluminanceEngine engine(cpuDevice(), elements);
    const Eigen::MatrixXd t = elementTransfer(engine, mesh);
    // Each node sees a whole hemisphere of elements: E = π·L exactly, to the kernel's float.
    for (Eigen::Index i = 0; i < t.rows(); ++i) EXPECT_NEAR(t.row(i).sum(), kPi, 1e-6 * kPi) << i;
    // A_i T_ij = A_j T_ji to the quadrature's error, which falls as the order grows.
    double asymmetry = 0.0, flux = 0.0;
    for (Eigen::Index i = 0; i < t.rows(); ++i)
      for (Eigen::Index j = 0; j < t.rows(); ++j) {
        asymmetry += std::abs(mesh.elements[i].area * t(i, j) - mesh.elements[j].area * t(j, i));
        flux += mesh.elements[i].area * t(i, j);
      }
    EXPECT_LT(asymmetry / flux, previousAsymmetry) << order;
    previousAsymmetry = asymmetry / flux;
  }
  EXPECT_LT(previousAsymmetry, 1e-3);
}

// Elements that share their block's shadow casters (elementSceneSharingCasters, what the dense
// transfer uses) get the transfer of elements with their own: a block's volumes hold its
// elements' and only list more candidates. The blocks themselves give nothing.
TEST(Transfer, ElementsSharingTheirBlocksCastersGiveTheSameTransfer) {
  TempDir dir("interreflection");
  const Scene scene =
      closedRoom(dir, "[4, 3, 3]",
                 "solids:\n  - {name: desk, box: {min: [1.0, 1.0, 0.7], max: "
                 "[2.6, 1.8, 0.75]}, material: paint}\n  - {name: cabinet, box: "
                 "{min: [3.0, 0.2, 0.0], max: [3.8, 0.8, 1.8]}, material: paint}\n");
  MeshOptions options;
  options.quadratureOrder = 2;
  const SurfaceMesh mesh = buildSurfaceMesh(scene, options);
  const std::size_t blocks = mesh.casterBlocks.size();
  ASSERT_LT(4 * blocks, mesh.elements.size());  // most blocks hold several elements
  for (const SurfaceElement& element : mesh.elements) {
    ASSERT_GE(element.casterBlock, 0);
    // The block holds the element: its vertices lie in the block's plane, inside its edges.
    const ConvexPolygon& block = mesh.casterBlocks[static_cast<std::size_t>(element.casterBlock)];
    for (const Vec3& v : element.polygon.vertices()) {
      EXPECT_NEAR(block.plane().signedDistance(v), 0.0, 1e-9);
      const std::vector<Vec3>& b = block.vertices();
      for (std::size_t k = 0; k < b.size(); ++k)
        EXPECT_GE(block.normal().dot((b[(k + 1) % b.size()] - b[k]).cross(v - b[k])), -1e-9);
    }
  }
  const Scene own = elementScene(scene, mesh);
  const Scene shared = elementSceneSharingCasters(scene, mesh);
  IlluminanceEngine ownEngine(cpuDevice(), own), sharedEngine(cpuDevice(), shared);
  const Eigen::MatrixXd expected = elementTransfer(ownEngine, mesh);
  const Eigen::MatrixXd t = elementTransfer(sharedEngine, mesh, blocks);
  // E at unit luminance is at most π: the kernel's relative tolerance of that.
  EXPECT_LT((t - expected).cwiseAbs().maxCoeff(), Tolerance::kKernelRelative * kPi);
  std::size_t stride = 0;
  const std::vector<float> e = sharedEngine.illuminanceBySource(mesh.nodes, stride);
  for (std::size_t b = 0; b < blocks; ++b)
    for (std::size_t p = 0; p < mesh.nodes.size(); ++p) ASSERT_EQ(e[b * stride + p], 0.0f);
}

// In a closed room of uniform ρ, the area average of the indirect E over all surfaces is
// ρ/(1 - ρ) times that of the direct E (every reflected lumen lands on a surface again).
TEST(Interreflection, ClosedRoomsConserveEnergy) {
  TempDir dir("interreflection");
  const std::vector<std::pair<std::string, std::string>> rooms{
      {"[4, 4, 4]", ""},
      {"[10, 3, 3]", ""},
      {"[5, 4, 3]",
       "solids:\n  - {name: desk, box: {min: [1.0, 1.0, 0.72], max: [2.6, 1.8, 0.75]}, material: "
       "paint}\n  - {name: cabinet, box: {min: [4.4, 0.0, 0.0], max: [5.0, 1.2, 1.8]}, material: "
       "paint}\n"},
  };
  for (const auto& [size, extra] : rooms) {
    const Scene scene = closedRoom(dir, size, extra);
    const SolvedRoom room(scene);
    SurfaceMesh mesh = room.solved->mesh();
    const Eigen::MatrixXd& t = room.transfer;
    const double directAverage = areaAverage(mesh, room.solved->direct().col(1));
    for (double rho : {0.2, 0.5, 0.8, 0.95}) {
      setReflectance(mesh, rho);
      const RadiositySolution s = solveRadiosity(t, mesh, room.solved->direct());
      EXPECT_LT(s.residual, 1e-9);
      const double expected = rho / (1.0 - rho) * directAverage;
      EXPECT_NEAR(areaAverage(mesh, s.indirect.col(1)), expected, 1e-4 * expected)
          << size << " rho " << rho;
    }
  }
}

// The transfer the product computes by default takes the senders far from a receiver at four
// points (FarFieldRule): in a closed room with furniture where most pairs are far, its rows still
// sum to π, reciprocity holds about as well as with every sender averaged over the nodes, and
// the energy balance holds to 1e-4 up to ρ = 0.95.
TEST(Interreflection, FarFieldTransferKeepsTheBalance) {
  TempDir dir("interreflection");
  // The sanitizer build, where the host's part runs many times slower, takes the smaller
  // furnished room of ClosedRoomsConserveEnergy: the same assertions on fewer far pairs (a
  // coarser mesh would miss the balance with every sender at the nodes too).
  const Scene scene =
      kSanitizedBuild
          ? closedRoom(dir, "[5, 4, 3]",
                       "solids:\n  - {name: desk, box: {min: [1.0, 1.0, 0.72], max: [2.6, 1.8, "
                       "0.75]}, material: paint}\n  - {name: cabinet, box: {min: [4.4, 0.0, "
                       "0.0], max: [5.0, 1.2, 1.8]}, material: paint}\n")
          : closedRoom(dir, "[9, 6, 3]",
                       "solids:\n  - {name: desk, box: {min: [1.0, 1.0, 0.72], max: [2.6, 1.8, "
                       "0.75]}, material: paint}\n  - {name: desk-2, box: {min: [5.0, 3.5, "
                       "0.72], max: [6.6, 4.3, 0.75]}, material: paint}\n  - {name: cabinet, "
                       "box: {min: [8.4, 0.0, 0.0], max: [9.0, 1.2, 1.8]}, material: paint}\n");
  IlluminanceEngine direct(cpuDevice(), scene);
  const Interreflection solved(cpuDevice(), scene, direct);
  SurfaceMesh mesh = solved.mesh();
  const Scene elements = elementScene(scene, mesh);
  IlluminanceEngine engine(cpuDevice(), elements);
  const Eigen::MatrixXd exact = elementTransfer(engine, mesh);
  // Nothing but elements in sight: every row sums to π, and a far pair is computed one way.
  const std::optional<Eigen::VectorXd> sums = transferRowSums(cpuDevice(), scene, mesh);
  ASSERT_TRUE(sums.has_value());
  EXPECT_EQ(*sums, Eigen::VectorXd::Constant(sums->size(), kPi));
  const Eigen::MatrixXd t = elementTransfer(engine, mesh, FarFieldRule{}, 0, &*sums);
  // The far pairs: the near ones are the node averages, the same floats as `exact`'s.
  std::size_t far = 0;
  for (Eigen::Index i = 0; i < t.rows(); ++i)
    for (Eigen::Index j = 0; j < t.cols(); ++j) far += t(i, j) != exact(i, j) ? 1 : 0;
  std::printf("%zu elements, %zu of %zu pairs far\n", mesh.elements.size(), far,
              static_cast<std::size_t>(t.size()));
  if (!kSanitizedBuild) {
    EXPECT_GT(far, static_cast<std::size_t>(t.size()) / 2);
  }

  // A row sums to the kernel's E from the whole hemisphere at four points: π to the kernel's
  // relative tolerance.
  for (Eigen::Index i = 0; i < t.rows(); ++i)
    EXPECT_NEAR(t.row(i).sum(), kPi, Tolerance::kKernelRelative * kPi) << i;
  const auto asymmetry = [&](const Eigen::MatrixXd& m) {
    double difference = 0.0, flux = 0.0;
    for (Eigen::Index i = 0; i < m.rows(); ++i)
      for (Eigen::Index j = 0; j < m.rows(); ++j) {
        difference += std::abs(mesh.elements[i].area * m(i, j) - mesh.elements[j].area * m(j, i));
        flux += mesh.elements[i].area * m(i, j);
      }
    return difference / flux;
  };
  EXPECT_LT(asymmetry(t), 2.0 * asymmetry(exact));

  const double directAverage = areaAverage(mesh, solved.direct().col(1));
  for (double rho : {0.5, 0.8, 0.95}) {
    setReflectance(mesh, rho);
    const RadiositySolution s = solveRadiosity(t, mesh, solved.direct());
    const RadiositySolution reference = solveRadiosity(exact, mesh, solved.direct());
    const double expected = rho / (1.0 - rho) * directAverage;
    std::printf("rho %.2f: balance %.2e, every sender at the nodes %.2e\n", rho,
                areaAverage(mesh, s.indirect.col(1)) / expected - 1.0,
                areaAverage(mesh, reference.indirect.col(1)) / expected - 1.0);
    EXPECT_NEAR(areaAverage(mesh, s.indirect.col(1)), expected, 1e-4 * expected) << rho;
  }
}

// What the product's transfer takes in a room whose only openings are the room's own: each row's
// sum found from the faces that are no element (transferRowSums: the opening, the black
// cabinet), far pairs computed one way and the other by reciprocity. Against the transfer with
// every sender averaged over the nodes (the kernel at every node, no rule): the row sums agree
// to the kernel's tolerance, where the far points' own sum departs by up to 1e-2 near the
// window; and the solved indirect E stays as close to that transfer's as with every far pair
// computed both ways, element by element and over the room.
TEST(Interreflection, RowSumsFromWhatNoElementCovers) {
  TempDir dir("interreflection");
  const auto file = dir.path() / "room.yaml";
  std::ofstream(file)
      << "penumbra: 1\nmaterials:\n  paint: 0.5\nroom:\n  size: [9, 6, 3]\n"
         "  wall_thickness: 0.2\n  materials: {floor: paint, ceiling: paint, walls: paint}\n"
         "  openings:\n    - {name: window, wall: y0, x: 1.5, z: 0.9, width: 3.0, height: 1.6}\n"
         "sources:\n  - {name: panel, rect: {center: [4.3, 3.7, 2.99], size: [0.6, 0.6], "
         "normal: [0, 0, -1]}, flux: 3000}\n"
         "solids:\n  - {name: desk, box: {min: [1.0, 1.0, 0.72], max: [2.6, 1.8, 0.75]}, "
         "material: paint}\n"
         "  - {name: cabinet, box: {min: [8.4, 0.0, 0.0], max: [9.0, 1.2, 1.8]}}\n";
  const Scene scene = loadScene(file);
  IlluminanceEngine direct(cpuDevice(), scene);
  const Interreflection solved(cpuDevice(), scene, direct);
  SurfaceMesh mesh = solved.mesh();
  IlluminanceEngine engine(cpuDevice(), elementScene(scene, mesh));
  const Eigen::MatrixXd exact = elementTransfer(engine, mesh);
  const std::optional<Eigen::VectorXd> sums = transferRowSums(cpuDevice(), scene, mesh);
  ASSERT_TRUE(sums.has_value());
  const Eigen::MatrixXd bothWays = elementTransfer(engine, mesh, FarFieldRule{});
  const Eigen::MatrixXd t = elementTransfer(engine, mesh, FarFieldRule{}, 0, &*sums);
  double farPointsDeparture = 0.0;
  for (Eigen::Index i = 0; i < t.rows(); ++i) {
    EXPECT_NEAR((*sums)[i], exact.row(i).sum(), Tolerance::kKernelRelative * kPi) << i;
    EXPECT_NEAR(t.row(i).sum(), exact.row(i).sum(), Tolerance::kKernelRelative * kPi) << i;
    farPointsDeparture =
        std::max(farPointsDeparture, std::abs(bothWays.row(i).sum() - exact.row(i).sum()));
  }
  std::printf("%zu elements; the far points' row sums depart by up to %.2e\n", mesh.elements.size(),
              farPointsDeparture);
  for (double rho : {0.5, 0.8, 0.95}) {
    setReflectance(mesh, rho);
    const RadiositySolution reference = solveRadiosity(exact, mesh, solved.direct());
    const RadiositySolution s = solveRadiosity(t, mesh, solved.direct());
    const RadiositySolution b = solveRadiosity(bothWays, mesh, solved.direct());
    double worst = 0.0, worstBothWays = 0.0;
    for (Eigen::Index i = 0; i < s.indirect.rows(); ++i) {
      const double e = reference.indirect(i, 1);
      worst = std::max(worst, std::abs(s.indirect(i, 1) / e - 1.0));
      worstBothWays = std::max(worstBothWays, std::abs(b.indirect(i, 1) / e - 1.0));
    }
    const double average = areaAverage(mesh, reference.indirect.col(1));
    const double departure = areaAverage(mesh, s.indirect.col(1)) / average - 1.0;
    std::printf("rho %.2f: worst element %.2e (both ways %.2e), room average %.2e\n", rho, worst,
                worstBothWays, departure);
    EXPECT_LE(worst, worstBothWays) << rho;
    EXPECT_LT(std::abs(departure), 1e-4) << rho;
  }
}

// CIE 171:2006 test case 5.8: a 4 m cube, an isotropic source of 10 000 lm at its centre (here a
// small luminous sphere: its flux is what it emits), every surface of reflectance ρ. The average
// indirect illuminance over the 96 m² is ρΦ/(S(1 - ρ)).
TEST(Interreflection, Cie171Case5_8) {
  TempDir dir("interreflection");
  const Scene scene = paintedRoom(
      dir, "[4, 4, 4]", "{name: lamp, sphere: {center: [2, 2, 2], radius: 0.05}, flux: 10000}");
  const SolvedRoom room(scene);
  SurfaceMesh mesh = room.solved->mesh();
  // The room's six inner faces, to the geometry's tolerance (slivers thinner than 1e-9 of the
  // scene's size are dropped where the slabs overlap).
  ASSERT_NEAR(mesh.area(), 96.0, 1e-7 * 96.0);
  const Eigen::MatrixXd& t = room.transfer;
  const std::vector<std::pair<double, double>> published{
      {0.05, 5.48}, {0.1, 11.6}, {0.2, 26.0}, {0.3, 44.6}, {0.4, 69.4}, {0.5, 104},
      {0.6, 156},   {0.7, 243},  {0.8, 417},  {0.9, 937},  {0.95, 1979}};
  for (const auto& [rho, rounded] : published) {
    setReflectance(mesh, rho);
    const RadiositySolution s = solveRadiosity(t, mesh, room.solved->direct());
    const double expected = rho * 10000.0 / (96.0 * (1.0 - rho));
    ASSERT_NEAR(expected, rounded, 0.006 * rounded);  // the published figures, to 3 digits
    EXPECT_NEAR(areaAverage(mesh, s.indirect.col(1)), expected, 1e-3 * expected) << rho;
  }
}

// An empty box room against piecewise-constant collocation in double (box_room_radiosity.hpp),
// extrapolated from three patch sizes: within 1e-3 of it on the work plane with the default mesh
// (0.5 m elements, the luminance linear across each in the final gather), and closer as the
// elements shrink; each element's luminance taken uniform (and hierarchical links) within 1e-3
// at 0.25 m.
TEST(Interreflection, BoxRoomAgainstCollocation) {
  TempDir dir("interreflection");
  const Scene scene = paintedRoom(dir, "[4, 3, 3]",
                                  "{name: panel, rect: {center: [1.3, 1.7, 2.99], size: [0.6, "
                                  "0.6], normal: [0, 0, -1]}, luminance: 1000}");
  std::vector<SamplePoint> points;
  for (double x : {0.5, 1.3, 2.0, 3.5})
    for (double y : {0.5, 1.7, 2.5}) points.push_back({Vec3(x, y, 0.8), Vec3::UnitZ(), -1});

  // Collocation converges like n^-p with p near 1.5: the limit from n, 1.5n and 2n.
  // The sanitizer build checks the code path on a coarse reference (its dense LU runs slowly
  // under ASan); the Release build holds the numbers.
  const std::array<int, 3> n = kSanitizedBuild ? std::array{4, 6, 8} : std::array{16, 24, 32};
  std::vector<std::vector<double>> byN;
  for (int patches : n) {
    const BoxRoomReference reference(BoxRoomCase{}, patches);
    byN.emplace_back();
    for (const SamplePoint& p : points)
      byN.back().push_back(reference.totalIlluminance(p.position, p.normal));
  }
  std::vector<double> limit;
  for (std::size_t k = 0; k < points.size(); ++k)
    limit.push_back(collocationLimit(byN[0][k], byN[1][k], byN[2][k]));

  IlluminanceEngine direct(cpuDevice(), scene);
  const std::vector<double> e0 = direct.illuminance(points);
  // The dense transfer, and hierarchical links (on the element trees' leaves) at the bound
  // --link-error takes by default.
  std::map<double, double> uniformGather;  // element size → worst, dense transfer
  for (double linkError : {0.0, MeshOptions::kDefaultLinkError}) {
    double previous = INFINITY;
    for (double size : {0.5, 0.25}) {
      MeshOptions options;
      options.elementSize = size;
      options.linkError = linkError;
      options.linearGather = false;
      Interreflection solved(cpuDevice(), scene, direct, options);
      EXPECT_FALSE(solved.report().linearGather);
      const std::vector<double> indirect = solved.indirect(points);
      double worst = 0.0;
      for (std::size_t k = 0; k < points.size(); ++k)
        worst = std::max(worst, std::abs(e0[k] + indirect[k] - limit[k]) / limit[k]);
      std::printf(
          "link error %g, element size %.3f m: %zu elements, worst relative difference "
          "%.2e\n",
          linkError, size, solved.mesh().elements.size(), worst);
      if (linkError == 0.0) uniformGather[size] = worst;
      if (kSanitizedBuild) continue;
      if (size == 0.25) {
        EXPECT_LT(worst, 1e-3) << linkError;
      }
      EXPECT_LT(worst, previous) << linkError;
      previous = worst;
    }
  }
  // The default mesh, each element's luminance linear across it in the final gather: within
  // 1e-3 at the default 0.5 m, below the uniform gather at each size, and closer as the elements
  // shrink.
  double previous = INFINITY;
  for (auto it = uniformGather.rbegin(); it != uniformGather.rend(); ++it) {  // 0.5 m first
    const auto [size, uniform] = *it;
    MeshOptions options;
    options.elementSize = size;
    Interreflection solved(cpuDevice(), scene, direct, options);
    EXPECT_TRUE(solved.report().linearGather);
    const std::vector<double> indirect = solved.indirect(points);
    double worst = 0.0;
    for (std::size_t k = 0; k < points.size(); ++k)
      worst = std::max(worst, std::abs(e0[k] + indirect[k] - limit[k]) / limit[k]);
    std::printf("linear gather, element size %.3f m: worst relative difference %.2e\n", size,
                worst);
    if (kSanitizedBuild) continue;
    EXPECT_LT(worst, std::min(1e-3, uniform)) << size;
    EXPECT_LT(worst, previous) << size;
    previous = worst;
  }
}

// The dense solver's limit: a mesh larger before refinement is refused with an element size
// that fits; refinement stops at the limit, splitting the most uneven elements first.
// A window cuts its wall into four slabs that meet at its sides. The floor and ceiling under
// them are cut along each slab's planes grown by the scene's tolerance, so at a window side the
// cuts of two slabs lie twice the tolerance apart: a strip that narrow must not become elements
// (its two long edges coincide in the kernel's float, and such a sliver gave light on lines where
// an occluder's edge met it in one plane). Every element is a cell of at least the window's
// 0.3 m wall strips, and the floor's elements cover its 4 × 3 m.
TEST(Interreflection, NoSliverElementsWhereAWindowsSlabsMeet) {
  TempDir dir("interreflection");
  const auto file = dir.path() / "window.yaml";
  std::ofstream(file) << "penumbra: 1\nmaterials:\n  paint: 0.5\nroom:\n  size: [4, 3, 3]\n"
                         "  materials: {floor: paint, ceiling: paint, walls: paint}\n"
                         "  openings:\n    - {name: window, wall: y0, x: 1.0, z: 0.9, width: "
                         "2.0, height: 1.5}\nsources:\n  - {name: sky, opening: window, "
                         "luminance: 4000}\n";
  const Scene scene = loadScene(file);
  const SurfaceMesh mesh = buildSurfaceMesh(skyFacesScene(scene), MeshOptions{});
  ASSERT_FALSE(mesh.elements.empty());
  double floorArea = 0.0, narrowest = INFINITY;
  for (const SurfaceElement& element : mesh.elements) {
    narrowest = std::min(narrowest, element.area / longestEdge(element.polygon));
    const Vec3 centre = element.polygon.centroid();
    if (element.polygon.normal().z() > 0.5 && std::abs(centre.z()) < 1e-6)
      floorArea += element.area;
  }
  EXPECT_GT(narrowest, 0.1) << "m: area / longest edge of the narrowest element";
  EXPECT_NEAR(floorArea, 12.0, 1e-6 * 12.0);
}

TEST(Interreflection, DenseMeshesStayWithinTheLimitAndLinksTakeOverPastIt) {
  TempDir dir("interreflection");
  const Scene scene = closedRoom(dir, "[4, 3, 3]");
  IlluminanceEngine direct(cpuDevice(), scene);
  MeshOptions options;
  const Interreflection free(cpuDevice(), scene, direct, options);
  EXPECT_FALSE(free.report().refinementCapped);
  const std::size_t base = buildSurfaceMesh(scene, options).elements.size();
  ASSERT_GT(free.report().elements, base + 30);

  options.maxElements = base + 30;
  const Interreflection capped(cpuDevice(), scene, direct, options);
  EXPECT_TRUE(capped.report().refinementCapped);
  EXPECT_LE(capped.report().elements, options.maxElements);
  EXPECT_GT(capped.report().elements, base);

  // Past the limit before any refinement: hierarchical links at the default bound take over,
  // the same solution as when they are asked for (1 m elements: the same rule, less work).
  options.elementSize = 1.0;
  const std::size_t coarse = buildSurfaceMesh(scene, options).elements.size();
  options.maxElements = coarse - 1;
  const Interreflection switched(cpuDevice(), scene, direct, options);
  EXPECT_EQ(switched.report().denseElements, coarse);
  EXPECT_EQ(switched.report().linkError, MeshOptions::kDefaultLinkError);
  EXPECT_GT(switched.report().links, 0u);
  MeshOptions linked;
  linked.elementSize = options.elementSize;
  linked.linkError = MeshOptions::kDefaultLinkError;
  const Interreflection asked(cpuDevice(), scene, direct, linked);
  EXPECT_EQ(asked.report().denseElements, 0u);
  EXPECT_EQ(switched.report().elements, asked.report().elements);
  EXPECT_EQ(switched.report().links, asked.report().links);
  const Eigen::MatrixX3d difference = switched.solution().indirect - asked.solution().indirect;
  EXPECT_EQ(difference.cwiseAbs().maxCoeff(), 0.0);
}

// The total through Estimator: ρ = 0 gives the direct E bit for bit, a higher ρ never lowers E,
// twice the light gives twice E.
class TotalIlluminance : public ::testing::Test {
 protected:
  static Scene office(const ParameterValues& values = {}) {
    return loadScene(std::filesystem::path(PENUMBRA_SOURCE_DIR) / "data/office.yaml", values);
  }
  static std::vector<SamplePoint> workPlane(const Scene& scene) {
    std::vector<SamplePoint> points;
    for (const CalculationGrid& grid : scene.grids)
      for (std::size_t i = 0; i < grid.size(); ++i)
        points.push_back({grid.position(i), grid.normal(i), -1});
    return points;
  }
  // The relations these tests hold (ρ = 0 is the direct light, monotony, linearity, the cached
  // transfer equal to a fresh one) hold on any mesh. The sanitizer build, where the host's part
  // of a solve runs many times slower, takes the office's faces whole in 1 m elements unrefined.
  static EstimatorOptions cpuOptions() {
    EstimatorOptions options;
    options.device = "cpu";
    if (testing::kSanitizedBuild) {
      options.mesh.elementSize = 1.0;
      options.mesh.refinementLevels = 0;
    }
    return options;
  }
  static PointIlluminance total(const Scene& scene, const std::vector<SamplePoint>& points) {
    Estimator estimator(cpuOptions(), scene);
    return estimator.illuminance(points);
  }
};

TEST_F(TotalIlluminance, BlackRoomGivesTheDirectLight) {
  Scene scene = office();
  for (Material& m : scene.materials) m.reflectance = Vec3::Zero();
  const std::vector<SamplePoint> points = workPlane(scene);
  const PointIlluminance e = total(scene, points);
  EstimatorOptions directOnly = cpuOptions();
  directOnly.interreflection = false;
  const PointIlluminance d = Estimator(directOnly, scene).illuminance(points);
  EXPECT_TRUE(d.direct.empty());
  ASSERT_EQ(e.total.size(), d.total.size());
  for (std::size_t i = 0; i < e.total.size(); ++i) {
    EXPECT_EQ(e.total[i], d.total[i]) << i;
    EXPECT_EQ(e.direct[i], d.total[i]) << i;
  }
}

TEST_F(TotalIlluminance, HigherReflectanceNeverLowersAndLightScales) {
  const Scene base = office();
  const std::vector<SamplePoint> points = workPlane(base);
  const PointIlluminance e = total(base, points);
  const PointIlluminance brighterFloor = total(office({{"floor_reflectance", 0.5}}), points);
  const PointIlluminance twice =
      total(office({{"sky_luminance_cdm2", 8000}, {"panel_flux_lm", 6800}}), points);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_GT(e.total[i], e.direct[i]) << i;
    EXPECT_GE(brighterFloor.total[i], e.total[i]) << i;
    EXPECT_EQ(brighterFloor.direct[i], e.direct[i]) << i;
    EXPECT_NEAR(twice.total[i], 2.0 * e.total[i], 1e-12 * e.total[i]) << i;
  }
}

// A sweep keeps one estimator: a case that changes only reflectances or the sources' output takes
// the transfer from the cache and gives what a fresh solve gives, bit for bit; a case that
// changes the geometry computes its own.
TEST_F(TotalIlluminance, CasesThatKeepTheGeometryReuseTheTransfer) {
  const Scene base = office();
  const std::vector<SamplePoint> points = workPlane(base);
  Estimator sweep(cpuOptions(), base);
  EXPECT_FALSE(sweep.interreflection()->transferReused);
  struct Case {
    ParameterValues values;
    bool reused;
  };
  const std::vector<Case> cases = {{{{"floor_reflectance", 0.6}}, true},
                                   {{{"panel_flux_lm", 5000}}, true},
                                   {{{"window_width_m", 1.2}}, false},
                                   {{{"floor_reflectance", 0.3}}, true}};
  for (const Case& c : cases) {
    const Scene scene = office(c.values);
    sweep.setScene(scene);
    EXPECT_EQ(sweep.interreflection()->transferReused, c.reused) << c.values.front().name;
    const PointIlluminance cached = sweep.illuminance(points);
    const PointIlluminance fresh = total(scene, points);
    for (std::size_t i = 0; i < points.size(); ++i)
      ASSERT_EQ(cached.total[i], fresh.total[i]) << c.values.front().name << " point " << i;
  }
}

}  // namespace
}  // namespace penumbra
