// The kernel with shadow-volume culling: the same illuminance as the plain
// path on every example scene, shadow classes that agree with the exact answer, face classes
// and per-face candidates that never drop an occluder that blocks.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "bench/office_floor.hpp"
#include "bench/open_office.hpp"
#include "engine/illuminance_engine.hpp"
#include "engine/kernel_scene.hpp"
#include "engine/patch_table.hpp"
#include "geometry/tolerance.hpp"
#include "grid/grid_evaluation.hpp"
#include "reference/exact_illuminance.hpp"
#include "reference/pyramid_oracle.hpp"
#include "reference/reference_illuminance.hpp"
#include "sanitized_build.hpp"
#include "scene/scene_loader.hpp"
#include "shadow/receiver_candidates.hpp"
#include "shadow/scene_shadows.hpp"
#include "study/study_cases.hpp"
#include "study/study_plan.hpp"
#include "study/study_reader.hpp"
#include "test_device.hpp"
#include "test_scenes.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;

// The points of every grid of a scene that lie outside solids.
std::vector<SamplePoint> allGridPoints(const Scene& scene) {
  std::vector<SamplePoint> points;
  for (const CalculationGrid& grid : scene.grids) {
    const std::vector<SamplePoint> outside = gridSamples(scene, grid).outsideSolids();
    points.insert(points.end(), outside.begin(), outside.end());
  }
  return points;
}

Scene withoutSolids(Scene scene) {
  scene.solids.clear();
  return scene;
}

// Culling changes which occluders a sample considers, never the answer: per point, the default
// path and the plain one (--no-culling) agree to 1e-6 of the point's unoccluded illuminance.
// E_unoccluded is the scale because it is the size of the terms the kernel sums in float: a
// heavily shaded point's E is a small difference of such terms.
//
// Each path errs by its float rounding, and the two differ by the sum of both. They meet 1e-6 on
// the example scenes because every sum of contour terms and of faces is compensated
// (kernels/prelude.cl, PnSum) and positions are relative to the scene's centre
// (engine/kernel_scene.hpp). Measured (defaults): office 4.0e-7, open office 8.3e-7, CIE 171
// cases 1.2e-7. `culling` alone (apertures off, the scalar penumbra path: the plain path's
// arithmetic) is held the same way: 7.6e-7 on the open office.
//
// Both paths are also held against the exact reference in double (reference/exact_illuminance):
// to kKernelRelative of E_unoccluded at every point. Measured: 1.2e-6 on the open office, 4.4e-6
// at 400 solids. Centred coordinates keep the rounding of the positions to float small (within
// 4 m of the centre floats are 2.4e-7 m apart): 2 cm from a chair back, a shadow edge on a panel
// 2.3 m away moves a hundred times as far as the rounding moves the point, so with coordinates
// from the room's corner that rounding alone would cost up to 4.0e-6 of E_unoccluded.
//
// Variants that are not example scenes (the bench's 400-solid office, the example studies'
// cases) are held to the exact reference only, and their agreement is printed: it is the float
// floor of the two paths, not a property of culling. The daylight-only window-width cases show
// it: the sky's bottom edge 0.1 m above the work plane's horizon makes its terms cancel, each
// path errs up to 1.7e-6 of the sky's light, and the two differ by up to 2.0e-6.
constexpr double kPathAgreement = 1e-6;
// The sanitizer build checks the exact reference at every 16th point (it runs about 20× slower).
constexpr std::size_t kExactStride = kSanitizedBuild ? 16 : 1;

// agreement: the bound on |culled - plain| / E_unoccluded, or none (printed only).
void expectCullingChangesNothing(const Scene& scene, const std::string& file,
                                 EngineOptions culling = {},
                                 std::optional<double> agreement = kPathAgreement) {
  const std::vector<SamplePoint> points = allGridPoints(scene);
  ASSERT_FALSE(points.empty()) << file;
  const std::vector<double> a = IlluminanceEngine(cpuDevice(), scene, culling).illuminance(points);
  const std::vector<double> b =
      IlluminanceEngine(cpuDevice(), scene, EngineOptions{false}).illuminance(points);
  const std::vector<double> scale =
      IlluminanceEngine(cpuDevice(), withoutSolids(scene)).illuminance(points);
  // A point no source reaches has scale 0: both paths must give exactly 0 there.
  auto relative = [&](double difference, std::size_t i) {
    return std::abs(difference) / std::max(scale[i], 1e-300);
  };
  double worst = 0.0;
  int overCriterion = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    worst = std::max(worst, relative(a[i] - b[i], i));
    overCriterion += relative(a[i] - b[i], i) > kPathAgreement;
    if (agreement) {
      EXPECT_LE(std::abs(a[i] - b[i]), *agreement * scale[i])
          << file << " point " << i << " at (" << points[i].position.transpose() << ")";
    }
  }
  std::vector<SamplePoint> checked;
  for (std::size_t i = 0; i < points.size(); i += kExactStride) checked.push_back(points[i]);
  const std::vector<double> exact = exactIlluminance(scene, checked)[0];
  double culledError = 0.0, plainError = 0.0;
  for (std::size_t k = 0; k < checked.size(); ++k) {
    const std::size_t i = k * kExactStride;
    const double ec = relative(a[i] - exact[k], i);
    const double ep = relative(b[i] - exact[k], i);
    culledError = std::max(culledError, ec);
    plainError = std::max(plainError, ep);
    EXPECT_LE(ec, Tolerance::kKernelRelative) << file << " culled at " << i;
    EXPECT_LE(ep, Tolerance::kKernelRelative) << file << " plain at " << i;
  }
  std::printf(
      "%s: %zu points, worst |culled - plain| / E_unoccluded = %.2e (%d above 1e-6); against the "
      "exact reference (%zu points) %.2e culled, %.2e plain\n",
      file.c_str(), points.size(), worst, overCriterion, checked.size(), culledError, plainError);
}

void expectCullingChangesNothing(const std::string& file, EngineOptions culling = {}) {
  expectCullingChangesNothing(loadScene(file), file, culling);
}

// Culling alone: apertures off and the scalar penumbra path, the plain path's arithmetic.
constexpr EngineOptions kCullingOnly{true, false, false};

TEST(Culling, SameIlluminanceOnTheOffice) {
  expectCullingChangesNothing(PENUMBRA_SOURCE_DIR "/data/office.yaml", kCullingOnly);
}

TEST(Culling, SameIlluminanceOnTheOpenOffice) {
  expectCullingChangesNothing(PENUMBRA_SOURCE_DIR "/data/open-office.yaml", kCullingOnly);
}

// The defaults add apertures (a window's visible rectangle instead of the sky minus the reveals)
// and the eight-lane penumbra path (the same method in float8, with its own rounding).
TEST(Culling, FastPathsOnTheOffice) {
  expectCullingChangesNothing(PENUMBRA_SOURCE_DIR "/data/office.yaml");
}

TEST(Culling, FastPathsOnTheOpenOffice) {
  expectCullingChangesNothing(PENUMBRA_SOURCE_DIR "/data/open-office.yaml");
}

// The open office at 400 solids (bench/open_office.hpp, culling_bench's largest scene): work-items
// whose lanes see 16 to 30 occluders at once, so the eight-lane path's large unions, its
// hidden-occluder drops and its bounding-cone skips all run. Not an example scene (measured:
// 1.02e-6 apart at one point of 7 624, (11.35, 5.35) m, where the default path lies 2.6e-7 and
// the plain one 7.6e-7 from the exact value).
TEST(Culling, FastPathsOnTheDenseOpenOffice) {
  expectCullingChangesNothing(parseScene(bench::openOfficeYaml(400), "open-office-400.yaml"),
                              "open office, 400 solids", {}, std::nullopt);
}

// Four offices off a corridor (bench/office_floor.hpp, culling_bench's second curve): most of
// every point's sources are behind a wall, and the patch table gives whole patches class UMBRA.
// Not an example scene: held to the exact reference, agreement printed.
TEST(Culling, FastPathsOnAFloorOfOffices) {
  expectCullingChangesNothing(parseScene(bench::officeFloorYaml(4), "office-floor-4.yaml"),
                              "floor of 4 offices", {}, std::nullopt);
}

// The example studies' cases are the scenes the bundled example and the sweeps compute: every
// window width, panel spacing and flux, floor reflectance of the office (37 cases).
TEST(Culling, SameIlluminanceOnEveryCaseOfTheExampleStudies) {
  int cases = 0;
  for (const char* name : {"window-width", "panel-spacing-flux", "floor-reflectance"}) {
    const Study study = loadStudy(PENUMBRA_SOURCE_DIR "/studies/" + std::string(name) + ".yaml");
    for (const StudyCase& c : studyCases(study)) {
      const Scene scene = loadCaseScene(study, PlannedCase{c.id, c.values, ""});
      expectCullingChangesNothing(scene, std::string(name) + " " + c.id, {}, std::nullopt);
      ++cases;
    }
  }
  EXPECT_EQ(cases, 37);
}

class CullingOnCie171 : public ::testing::TestWithParam<std::string> {};

TEST_P(CullingOnCie171, SameIlluminance) {
  expectCullingChangesNothing(
      PENUMBRA_SOURCE_DIR "/tests/validation/cie171/" + GetParam() + ".yaml", kCullingOnly);
}

TEST_P(CullingOnCie171, FastPathsAsAccurate) {
  expectCullingChangesNothing(PENUMBRA_SOURCE_DIR "/tests/validation/cie171/" + GetParam() +
                              ".yaml");
}

INSTANTIATE_TEST_SUITE_P(Validation, CullingOnCie171,
                         ::testing::Values("tc5.3", "tc5.6", "tc5.7", "tc5.11"),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (c == '.') c = '_';
                           return name;
                         });

// A panel over a floor with a hanging box: a line of floor points crosses umbra, penumbra and
// light. Each point's class must agree with the reference (an independent computation).
TEST(ShadowClasses, AgreeWithTheReferenceAcrossAShadow) {
  Scene scene;
  scene.sources.push_back(ceilingRect(-0.5, -0.5, 0.5, 0.5, 3.0, 1000.0));
  scene.solids.push_back(boxSolid({-0.6, -0.6, 2.0}, {0.6, 0.6, 2.1}));
  const std::vector<SamplePoint> points = floorLine(-4.0, 4.0, 401);
  IlluminanceEngine engine(cpuDevice(), scene);
  const IlluminanceResult result = engine.evaluate(points);
  const std::vector<double> unoccluded =
      IlluminanceEngine(cpuDevice(), withoutSolids(scene)).illuminance(points);
  const std::vector<double> reference = referenceIlluminance(scene, points, 256);
  int counts[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ShadowClass c = result.shadow(i, 0);
    ++counts[static_cast<int>(c)];
    const double e = result.illuminance[i], u = unoccluded[i];
    switch (c) {
      case ShadowClass::Umbra:  // nothing arrives: exactly 0, and the reference agrees
        EXPECT_EQ(e, 0.0) << i;
        EXPECT_LE(reference[i], 1e-9 * u) << i;
        break;
      case ShadowClass::Lit:  // the plain contour integral, bit for bit
        EXPECT_EQ(e, u) << i;
        EXPECT_NEAR(reference[i], u, 1e-3 * u) << i;
        break;
      case ShadowClass::Penumbra:
        EXPECT_LE(e, u * (1 + 1e-6)) << i;
        break;
      case ShadowClass::Unlit:
        ADD_FAILURE() << "floor point " << i << " faces the panel";
        break;
    }
    // Where the reference sees a clear partial shadow, the class must say so.
    if (reference[i] > 1e-3 * u && reference[i] < (1 - 1e-3) * u) {
      EXPECT_EQ(c, ShadowClass::Penumbra) << i;
    }
  }
  EXPECT_GT(counts[static_cast<int>(ShadowClass::Umbra)], 10);
  EXPECT_GT(counts[static_cast<int>(ShadowClass::Penumbra)], 10);
  EXPECT_GT(counts[static_cast<int>(ShadowClass::Lit)], 10);
}

// Nishita's class C: a point facing away from the source, or behind it, gets 0 and Unlit.
TEST(ShadowClasses, FacesThatSeeNothingAreUnlit) {
  Scene scene;
  scene.sources.push_back(ceilingRect(-0.5, -0.5, 0.5, 0.5, 3.0, 1000.0));
  std::vector<SamplePoint> points;
  for (int i = 0; i < 20; ++i) {
    points.push_back({Vec3(0.1 * i, 0.0, 1.0), -Vec3::UnitZ(), -1});  // facing down
    points.push_back({Vec3(0.1 * i, 0.0, 3.5), Vec3::UnitZ(), -1});   // above the panel
  }
  const IlluminanceResult result = IlluminanceEngine(cpuDevice(), scene).evaluate(points);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(result.illuminance[i], 0.0) << i;
    EXPECT_EQ(result.shadow(i, 0), ShadowClass::Unlit) << i;
  }
}

// Two offices on either side of a corridor: from the first office's work plane, the corridor's
// wall hides the whole of each of the second office's lights (its window and four panels). The
// patch table says so for every patch (PN_CLASS_UMBRA: the kernel skips the face), and those
// sources give exactly 0 and class Umbra, as the exact reference (every solid projected onto
// each face, in double) says they must.
TEST(ShadowClasses, LightsBehindAWallAreUmbraForWholePatches) {
  const Scene scene = parseScene(bench::officeFloorYaml(2), "office-floor-2.yaml");
  // The first office's work plane.
  const std::vector<SamplePoint> points = gridSamples(scene, scene.grids.at(0)).outsideSolids();
  ASSERT_GT(points.size(), 1000u);
  std::vector<int> hiddenSources;  // the second office's
  for (std::size_t s = 0; s < scene.sources.size(); ++s)
    if (scene.sources[s].name.find("-2") != std::string::npos)
      hiddenSources.push_back(static_cast<int>(s));
  ASSERT_EQ(hiddenSources.size(), 5u);

  const SceneShadows shadows = buildSceneShadows(scene);
  const std::vector<FaceVolumes> volumes = flattenVolumes(shadows);
  const KernelScene packed = packScene(scene, shadows);
  const std::size_t workItems = (points.size() + PN_LANES - 1) / PN_LANES;
  const PatchTable table = buildPatchTable(shadows, volumes, packed, points, workItems, true,
                                           2.0 * kernelLengthAt(packed, points));
  int umbraEntries = 0, hiddenEntries = 0;
  for (std::size_t f = 0; f < shadows.faces.size(); ++f) {
    const bool hidden =
        std::count(hiddenSources.begin(), hiddenSources.end(), shadows.faces[f].source) > 0;
    for (std::size_t w = 0; w < workItems; ++w) {
      const PnPatchFace& entry = table.entries[w * shadows.faces.size() + f];
      umbraEntries += entry.faceClass == PN_CLASS_UMBRA;
      hiddenEntries += hidden;
      if (hidden) {
        EXPECT_EQ(entry.faceClass, PN_CLASS_UMBRA) << "face " << f << ", work-item " << w;
        EXPECT_EQ(entry.facingLanes, (1 << PN_LANES) - 1) << "face " << f << ", work-item " << w;
      }
    }
  }
  EXPECT_EQ(umbraEntries, hiddenEntries);  // the first office's own lights reach every patch

  const IlluminanceResult result = IlluminanceEngine(cpuDevice(), scene).evaluate(points, true);
  const std::vector<std::vector<double>> exact = exactIlluminance(scene, points, true);
  for (int s : hiddenSources)
    for (std::size_t i = 0; i < points.size(); ++i) {
      EXPECT_EQ(exact[s][i], 0.0) << scene.sources[s].name << " at " << i;
      EXPECT_EQ(result.bySource[i * result.sourceCount + s], 0.0)
          << scene.sources[s].name << " at " << i;
      EXPECT_EQ(result.shadow(i, s), ShadowClass::Umbra) << scene.sources[s].name << " at " << i;
    }
}

// §2.4 step v: the candidates of a receiving face are every caster whose penumbra volume meets
// it. Held against the oracle at points spread over the face: an occluder that blocks part of
// the source from any of them must be listed.
TEST(FaceCandidates, ListEveryOccluderThatBlocksFromTheFace) {
  const Scene scene = loadScene(PENUMBRA_SOURCE_DIR "/data/office.yaml");
  const SceneShadows shadows = buildSceneShadows(scene);
  // The floor slab's top face.
  int floorSolid = -1;
  for (std::size_t s = 0; s < scene.solids.size(); ++s)
    if (scene.solids[s].name == "room.floor") floorSolid = static_cast<int>(s);
  ASSERT_GE(floorSolid, 0);
  const ConvexPolyhedron& floor = scene.solids[floorSolid].shape;
  int top = -1;
  for (int f = 0; f < static_cast<int>(floor.faces().size()); ++f)
    if (floor.faces()[f].plane.normal.z() > 0.99) top = f;
  ASSERT_GE(top, 0);
  const ConvexPolygon face = floor.facePolygon(top);

  int listedTotal = 0, blockingTotal = 0;
  for (const EmittingFaceShadows& emitting : shadows.faces) {
    const std::vector<int> listed = candidatesForFace(emitting, face, 1e-9);
    listedTotal += static_cast<int>(listed.size());
    EXPECT_LT(listed.size(), emitting.casters.size());  // some are culled
    for (int k = 0; k < static_cast<int>(emitting.casters.size()); ++k) {
      if (emitting.casters[k].solid == floorSolid) continue;
      bool blocks = false;
      for (int i = 0; i <= 24 && !blocks; ++i)
        for (int j = 0; j <= 16 && !blocks; ++j) {
          const Vec3 p(0.25 * i, 0.25 * j, 0.0);
          blocks = pyramidSeparation(p, emitting.face.vertices(), emitting.casters[k].shape,
                                     1e-12) < -1e-9;
        }
      if (!blocks) continue;
      ++blockingTotal;
      EXPECT_NE(std::find(listed.begin(), listed.end(), k), listed.end())
          << "source " << emitting.source << ", solid "
          << scene.solids[emitting.casters[k].solid].name;
    }
  }
  std::printf("floor: %d candidates listed over all source faces, %d block somewhere\n",
              listedTotal, blockingTotal);
  EXPECT_GT(blockingTotal, 0);
}

// A face inside another and in its plane may use that face's shadow casters
// (EmittingFaceShadows::casterOwner, what the element trees' nodes do): the looser volumes only
// list more candidates, so each face's illuminance stays its own. On the open office, a 2 × 1.2 m
// ceiling area and four smaller areas inside it (one touching its corner, one a strip along an
// edge), at the work-plane points within 2.5 m of them horizontally (light from within 50° of
// the zenith: at grazing light the kernel's float floor exceeds these bounds whichever casters
// it reads): per point and face, the shared casters' E against the exact reference within
// kKernelRelative of the face's unoccluded E. Their agreement with the own casters' E is printed:
// extra candidates change the float rounding as any other path does (measured 1.7e-6; the
// measured error against the exact reference is 7.1e-6, at light from 50° off the zenith).
TEST(SharedCasters, GiveEachFaceItsOwnIlluminance) {
  Scene own = loadScene(PENUMBRA_SOURCE_DIR "/data/open-office.yaml");
  const double ceiling = 2.9;  // 0.1 m below the ceiling
  const auto area = [&](double x0, double y0, double x1, double y1) {
    Source s;
    s.name = fmt::format("area-{}-{}", x0, y0);
    s.faces = {ConvexPolygon({Vec3(x0, y0, ceiling), Vec3(x0, y1, ceiling), Vec3(x1, y1, ceiling),
                              Vec3(x1, y0, ceiling)})};
    s.luminance = 1000.0;
    return s;
  };
  own.sources = {area(6.0, 4.0, 8.0, 5.2), area(6.0, 4.0, 6.5, 4.5), area(7.1, 4.3, 7.4, 4.9),
                 area(6.0, 5.1, 8.0, 5.2), area(7.5, 4.0, 8.0, 5.2)};
  Scene shared = own;
  for (std::size_t s = 1; s < shared.sources.size(); ++s) shared.sources[s].castersOf = 0;
  std::vector<SamplePoint> points;
  for (const SamplePoint& p : allGridPoints(own))
    if (std::hypot(p.position.x() - 7.0, p.position.y() - 4.6) < 2.5) points.push_back(p);
  ASSERT_GT(points.size(), 100u);
  std::size_t stride = 0, strideShared = 0, strideScale = 0;
  const std::vector<float> a =
      IlluminanceEngine(cpuDevice(), own).illuminanceBySource(points, stride);
  const std::vector<float> b =
      IlluminanceEngine(cpuDevice(), shared).illuminanceBySource(points, strideShared);
  const std::vector<float> scale =
      IlluminanceEngine(cpuDevice(), withoutSolids(own)).illuminanceBySource(points, strideScale);
  ASSERT_EQ(stride, strideShared);
  std::vector<SamplePoint> checked;
  for (std::size_t i = 0; i < points.size(); i += kExactStride) checked.push_back(points[i]);
  const std::vector<std::vector<double>> exact = exactIlluminance(shared, checked, true);
  double worstOwn = 0.0, worstExact = 0.0;
  int shaded = 0;
  for (std::size_t s = 1; s < own.sources.size(); ++s)
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double unoccluded = std::max<double>(scale[s * strideScale + i], 1e-300);
      const double ownE = a[s * stride + i], sharedE = b[s * stride + i];
      worstOwn = std::max(worstOwn, std::abs(sharedE - ownE) / unoccluded);
      shaded += ownE < 0.999 * unoccluded;
      if (i % kExactStride != 0) continue;
      const double error = std::abs(sharedE - exact[s][i / kExactStride]) / unoccluded;
      worstExact = std::max(worstExact, error);
      EXPECT_LE(error, Tolerance::kKernelRelative) << own.sources[s].name << " at " << i;
    }
  std::printf(
      "%zu points, %d shaded point-faces: shared against own casters %.2e, against the exact "
      "reference %.2e of E_unoccluded\n",
      points.size(), shaded, worstOwn, worstExact);
  EXPECT_GT(shaded, 50);  // the check covers shadows, not only open light
}

}  // namespace
}  // namespace penumbra
