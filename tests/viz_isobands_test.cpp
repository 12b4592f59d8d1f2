// Iso-band vector drawings: band polygons tile every face, contour vertices carry the
// exact E of their level, and the SVG, rasterised by a browser-grade renderer, shows what the
// raster render shows.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdlib>
#include <random>

#include "engine/illuminance_engine.hpp"
#include "grid/iso_bands.hpp"
#include "output/image_files.hpp"
#include "render/renderer.hpp"
#include "scene/scene_loader.hpp"
#include "test_device.hpp"
#include "test_files.hpp"
#include "viz/isoband_svg.hpp"

namespace penumbra {
namespace {

using testing::cpuDevice;

double polygonArea(const std::vector<Vec3>& v) {
  return v.size() < 3 ? 0.0 : ConvexPolygon(v).area();
}

// Is p (on the polygon's plane) inside the convex polygon, by more than `margin` from its edges?
// Returns +1 inside, -1 outside, 0 within the margin.
int sideOf(const std::vector<Vec3>& polygon, const Vec3& normal, const Vec3& p, double margin) {
  int result = 1;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec3 edge = polygon[(i + 1) % polygon.size()] - polygon[i];
    const double d = normal.cross(edge).normalized().dot(p - polygon[i]);
    if (d < -margin) return -1;
    if (d < margin) result = 0;
  }
  return result;
}

class OfficeBands : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new Scene(loadScene(PENUMBRA_SOURCE_DIR "/data/office.yaml"));
    engine_ = new IlluminanceEngine(cpuDevice(), *scene_);
    view_ = scene_->views.front();
    faces_ = new std::vector<viz::FaceBands>(
        viz::viewFaceBands(*scene_, view_, viz::directLight(*engine_), levels_, 12, 0.0));
  }
  static void TearDownTestSuite() {
    delete faces_;
    delete engine_;
    delete scene_;
  }
  static Scene* scene_;
  static IlluminanceEngine* engine_;
  static View view_;
  static std::vector<double> levels_;
  static std::vector<viz::FaceBands>* faces_;
};
Scene* OfficeBands::scene_ = nullptr;
IlluminanceEngine* OfficeBands::engine_ = nullptr;
View OfficeBands::view_;
std::vector<double> OfficeBands::levels_;
std::vector<viz::FaceBands>* OfficeBands::faces_ = nullptr;

TEST_F(OfficeBands, BandPolygonsTileEveryFace) {
  ASSERT_GT(faces_->size(), 10u);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0.0;
  int probes = 0;
  for (const viz::FaceBands& face : *faces_) {
    double sum = 0.0;
    for (const IsoBandPolygon& p : face.bands.polygons) sum += polygonArea(p.vertices);
    const double area = face.polygon.area();
    worst = std::max(worst, std::abs(sum - area) / area);
    // No overlaps: random points of the face lie in exactly one band polygon.
    const Vec3 normal = face.polygon.normal();
    const auto& v = face.polygon.vertices();
    for (int k = 0; k < 200; ++k) {
      // A random point of a random fan triangle.
      const std::size_t t = 1 + random() % (v.size() - 2);
      double a = u(random), b = u(random);
      if (a + b > 1) a = 1 - a, b = 1 - b;
      const Vec3 p = v[0] + a * (v[t] - v[0]) + b * (v[t + 1] - v[0]);
      int inside = 0, unsure = 0;
      for (const IsoBandPolygon& polygon : face.bands.polygons) {
        const int side = sideOf(polygon.vertices, normal, p, 1e-9);
        inside += side > 0;
        unsure += side == 0;
      }
      if (unsure > 0) continue;
      ++probes;
      EXPECT_EQ(inside, 1) << "a point of face " << face.face << " of solid " << face.solid;
    }
  }
  EXPECT_LE(worst, 1e-3) << "band areas against the face's visible area";
  EXPECT_GT(probes, 1000);
  std::printf("%zu face pieces: band areas sum to the face area within %.1e; %d probe points\n",
              faces_->size(), worst, probes);
}

TEST_F(OfficeBands, ContourVerticesCarryTheirLevelExactly) {
  IlluminanceEngine independent(cpuDevice(), *scene_);
  std::vector<SamplePoint> points, before, after;
  std::vector<double> expected;
  std::size_t jumps = 0;
  for (const viz::FaceBands& face : *faces_) {
    const Vec3 normal = scene_->solids[face.solid].shape.faces()[face.face].plane.normal;
    for (const ContourVertex& c : face.bands.contourVertices) {
      if (c.atJump) {
        ++jumps;
        continue;
      }
      points.push_back(SamplePoint{c.position, normal, face.solid});
      expected.push_back(levels_[c.level]);
    }
  }
  ASSERT_GT(points.size(), 100u);
  const std::vector<double> e = independent.illuminance(points);
  double worst = 0.0;
  for (std::size_t i = 0; i < e.size(); ++i)
    worst = std::max(worst, std::abs(e[i] - expected[i]) / expected[i]);
  EXPECT_LE(worst, 5e-3);
  // Jumps are few: the edges of shadows cast by sources' own edges, the feet of solids.
  EXPECT_LT(jumps, points.size() / 5);
  std::printf("%zu contour vertices: worst |E - level| / level = %.2e; %zu more on jumps of E\n",
              points.size(), worst, jumps);
}

TEST(GridBands, TheWorkPlaneIsTiledAndDrawn) {
  const Scene scene = loadScene(PENUMBRA_SOURCE_DIR "/data/office.yaml");
  const CalculationGrid& grid = scene.grids.front();
  IlluminanceEngine engine(cpuDevice(), scene);
  std::vector<SamplePoint> points;
  for (std::size_t i = 0; i < grid.size(); ++i)
    points.push_back(SamplePoint{grid.position(i), grid.normal(i), -1});
  const std::vector<double> e = engine.illuminance(points);
  testing::TempDir dir("penumbra-isobands");
  const viz::IsobandFigure figure =
      viz::writeGridIsobands(grid, e, viz::directLight(engine), 12, dir.path() / "work-plane.svg");
  EXPECT_GT(figure.polygons, 0u);
  EXPECT_GT(figure.contourSegments, 0u);
  const std::string svg = testing::readText(dir.path() / "work-plane.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("E [lx]"), std::string::npos);
}

TEST_F(OfficeBands, TheSvgShowsWhatTheRenderShows) {
  if (std::system("command -v rsvg-convert > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "rsvg-convert (librsvg2-bin) is not installed";
  }
  testing::TempDir dir("penumbra-isobands");
  View view = view_;
  view.width = 320;
  view.height = 180;
  viz::writeViewIsobands(*scene_, view, viz::directLight(*engine_), 12, dir.path() / "view.svg");
  const std::string command = "rsvg-convert '" + (dir.path() / "view.svg").string() + "' -o '" +
                              (dir.path() / "view.png").string() + "'";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const RgbImage svg = readRgbExr(dir.path() / "view.png");  // any image OIIO reads
  // The raster render of the same view: each surface pixel's band, and its colour in the SVG.
  Renderer renderer(cpuDevice(), *scene_);
  const RenderedView raster = renderer.render(view, RenderOptions{1, 1, {}});
  const std::vector<double> levels = [&] {
    std::vector<double> l;
    viz::viewFaceBands(*scene_, view, viz::directLight(*engine_), l, 12, 0.0);
    return l;
  }();
  const int bandCount = static_cast<int>(levels.size()) + 1;
  std::size_t solidFaces = 0;  // face ids above this are sources (render/visible_scene.hpp)
  for (const Solid& s : scene_->solids) solidFaces += s.shape.faces().size();
  const auto bandAt = [&](int x, int y) { return bandOf(raster.illuminance.at(x, y), levels); };
  int surface = 0, same = 0;
  for (int y = 2; y + 2 < view.height; ++y)
    for (int x = 2; x + 2 < view.width; ++x) {
      const uint32_t id = raster.faces.at(x, y);
      if (id == 0 || id > solidFaces) continue;  // nothing, or a source
      const int band = bandAt(x, y);
      // Away from band and face boundaries (the contour lines and anti-aliased edges are there).
      bool interior = true;
      for (int dy = -2; dy <= 2 && interior; ++dy)
        for (int dx = -2; dx <= 2 && interior; ++dx)
          interior = raster.faces.at(x + dx, y + dy) == id && bandAt(x + dx, y + dy) == band;
      if (!interior) continue;
      ++surface;
      const viz::Rgb expected = viz::bandRgb(band, bandCount);
      const float* got = svg.pixel(x, y);
      const double difference = std::abs(got[0] - expected[0]) + std::abs(got[1] - expected[1]) +
                                std::abs(got[2] - expected[2]);
      same += difference < 0.03;
    }
  ASSERT_GT(surface, view.width * view.height / 3);
  const double share = static_cast<double>(same) / surface;
  // The rest: where the painter's order or the mesh's straight contour segments differ from the
  // pixel-exact raster by more than two pixels.
  EXPECT_GT(share, 0.97);
  std::printf("SVG vs raster: %.1f %% of %d surface pixels in the same band's colour\n",
              100.0 * share, surface);
}

}  // namespace
}  // namespace penumbra
