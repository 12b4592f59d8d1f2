#include "tonemap/tone_map.hpp"

#include <cctype>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "timing/seconds_since.hpp"
#include "tonemap/baseline_maps.hpp"
#include "tonemap/bounded_least_squares.hpp"
#include "tonemap/constraint_system.hpp"
#include "tonemap/display_spaces.hpp"
#include "tonemap/log_scene.hpp"
#include "tonemap/luminance_lattice.hpp"
#include "tonemap/region_map.hpp"
#include "tonemap/vertex_gain_field.hpp"
#include "tonemap/vertex_mesh.hpp"

namespace penumbra {
namespace {

void checkInputs(const RgbImage& hdr, const FaceIdImage& faces, const ToneMapOptions& options) {
  if (hdr.width != faces.width || hdr.height != faces.height) {
    throw std::invalid_argument("the face-id image is not the size of the HDR image");
  }
  if (options.lattice < 1) throw std::invalid_argument("--lattice must be at least 1 pixel");
  if (!(options.white >= 0) || !std::isfinite(options.white)) {
    throw std::invalid_argument("--exposure: white must be a luminance above 0 cd/m2");
  }
  if (!(options.displayLuminance > 0) || !std::isfinite(options.displayLuminance)) {
    throw std::invalid_argument("--display-luminance: the display's white must be above 0 cd/m2");
  }
  if (!(options.ambient >= 0) || !std::isfinite(options.ambient)) {
    throw std::invalid_argument("--ambient: the illuminance on the screen must be 0 lx or more");
  }
  if (options.white > 0 && options.method != DisplayMethod::Clip) {
    throw std::invalid_argument(
        "a fixed exposure (--exposure) is a clip display: the other maps adapt to each picture");
  }
  if (!(options.strong > 0 && options.medium > 0 && options.weak > 0)) {
    throw std::invalid_argument("the constraint weights must be positive");
  }
}

// Root mean square and largest |residual| per level, in log V (each row divided by its weight).
void reportResiduals(const ConstraintSystem& system, const Eigen::VectorXd& values,
                     ToneMapStats& stats) {
  const Eigen::VectorXd residual = system.matrix * values - system.target;
  double sum[3] = {0, 0, 0}, largest[3] = {0, 0, 0};
  int rows[3] = {0, 0, 0};
  for (Eigen::Index r = 0; r < residual.size(); ++r) {
    const int level = static_cast<int>(system.level[r]);
    const double value = std::abs(residual[r]) / system.weight[r];
    sum[level] += value * value;
    largest[level] = std::max(largest[level], value);
    ++rows[level];
  }
  const auto rms = [&](int level) {
    return rows[level] ? std::sqrt(sum[level] / rows[level]) : 0.0;
  };
  stats.strongRows = rows[0], stats.mediumRows = rows[1], stats.weakRows = rows[2];
  stats.strongRms = rms(0), stats.strongMax = largest[0];
  stats.mediumRms = rms(1), stats.mediumMax = largest[1];
  stats.weakRms = rms(2), stats.weakMax = largest[2];
}

// The solved vertices raised by one gain until the brightest is at white, when none is. The edge
// and region rows fix every difference of log V, and the weak rows, weighted 0.1 against them,
// only set the level; where no vertex reaches the display's white (a view with no window or
// luminaire at its top, from-window in the office), that level leaves the top of the display's
// range unused. A gain keeps every edge and region row as solved, keeps every vertex within
// [LowerBound, 1] (each rises by the brightest one's gap to white), changes only the weak rows'
// residual, and creates no halo (a region's every pixel takes the same factor). It lifts the
// picture where the sRGB code values are denser per log step (the code value's slope in log V
// grows with V), so the same ratios span more code values: the office's from-window view has
// TMQI S 0.891 with the raise and 0.850 without at 640×360 (docs/tonemap.md).
Eigen::VectorXd raisedToWhite(const Eigen::VectorXd& solved, const Eigen::VectorXd& lower,
                              ToneMapStats& stats) {
  Eigen::VectorXd shown = solved;
  const double gap = solved.size() ? -solved.maxCoeff() : 0.0;
  if (gap > 0) shown.array() += gap;
  stats.raisedToWhite = gap > 0 ? gap : 0.0;
  stats.atLowerBound = static_cast<int>((shown.array() <= lower.array()).count());
  stats.atUpperBound = static_cast<int>((shown.array() >= 0.0).count());
  return shown;
}

ScalarImage constraintDisplayValues(const DisplaySpaces& spaces, const RegionMap& regions,
                                    const ToneMapOptions& options, ToneMapStats& stats) {
  auto start = Clock::now();
  const LogScene scene = logScene(spaces, regions);
  const ConstraintWeights weights{options.strong, options.medium, options.weak};
  const bool levels = options.vertices == VertexLattice::Levels;
  const LuminanceLattice knots =
      levels ? buildLuminanceLattice(regions, scene) : LuminanceLattice{};
  const VertexMesh mesh = levels ? VertexMesh{} : buildVertexMesh(regions, options.lattice);
  const ConstraintSystem system = levels
                                      ? buildLevelConstraintSystem(knots, regions, scene, weights)
                                      : buildConstraintSystem(mesh, regions, scene, weights);
  stats.variables = levels ? knots.variables : static_cast<int>(mesh.vertices.size());
  stats.threeVariableRows = system.threeVariableRows;
  stats.buildSeconds = secondsSince(start);

  start = Clock::now();
  const BoundedLeastSquaresResult solved = solveBoundedLeastSquares(
      system.matrix, system.target, system.lower, system.upper, system.start);
  stats.solveSeconds = secondsSince(start);
  stats.outerIterations = solved.outerIterations();
  stats.activeSetIterations = solved.activeSetIterations;
  stats.projectedNewtonIterations = solved.projectedNewtonIterations;
  stats.converged = solved.converged;
  const Eigen::VectorXd shown = raisedToWhite(solved.x, system.lower, stats);
  reportResiduals(system, shown, stats);

  start = Clock::now();
  ScalarImage display = levels ? levelDisplayValues(knots, regions, spaces, scene, shown)
                               : interpolateDisplayValues(mesh, regions, spaces, scene, shown);
  stats.pixelSeconds = secondsSince(start);
  return display;
}

}  // namespace

std::string displayMethodName(DisplayMethod method) {
  switch (method) {
    case DisplayMethod::Clip:
      return "clip";
    case DisplayMethod::Linear:
      return "linear";
    case DisplayMethod::Constraint:
      return "constraint";
  }
  return "unknown";
}

std::string vertexLatticeName(VertexLattice lattice) {
  return lattice == VertexLattice::Levels ? "levels" : "image";
}

VertexLattice vertexLatticeFromName(const std::string& name) {
  std::string lower = name;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (VertexLattice lattice : {VertexLattice::Levels, VertexLattice::Image}) {
    if (vertexLatticeName(lattice) == lower) return lattice;
  }
  throw std::invalid_argument("unknown vertex lattice \"" + name + "\" (levels, image)");
}

DisplayMethod displayMethodFromName(const std::string& name) {
  std::string lower = name;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (DisplayMethod method :
       {DisplayMethod::Clip, DisplayMethod::Linear, DisplayMethod::Constraint}) {
    if (displayMethodName(method) == lower) return method;
  }
  throw std::invalid_argument("unknown display method \"" + name + "\" (clip, linear, constraint)");
}

namespace {

// Both entry points: the spaces are computed once and handed back for the device step.
ScalarImage displayValuesIn(const DisplaySpaces& spaces, const FaceIdImage& faces,
                            const ToneMapOptions& options, ToneMapStats& s) {
  s.method = displayMethodName(options.method);
  s.black = options.black;
  s.displayLuminance = options.displayLuminance;
  s.ambient = options.ambient;
  s.lowerBound = spaces.lowerBound;
  s.strong = options.strong, s.medium = options.medium, s.weak = options.weak;
  s.vertices = vertexLatticeName(options.vertices);
  s.lattice = options.lattice;
  s.width = spaces.width, s.height = spaces.height;
  const RegionMap regions = findRegions(faces);
  s.regions = regions.count;
  switch (options.method) {
    case DisplayMethod::Clip:
      s.white = options.white > 0 ? options.white : automaticWhite(spaces, regions);
      return clipDisplayValues(spaces, s.white);
    case DisplayMethod::Linear:
      return linearDisplayValues(spaces);
    case DisplayMethod::Constraint:
      break;
  }
  return constraintDisplayValues(spaces, regions, options, s);
}

}  // namespace

ScalarImage displayValues(const RgbImage& hdr, const FaceIdImage& faces,
                          const ToneMapOptions& options, ToneMapStats* stats) {
  const auto start = Clock::now();
  checkInputs(hdr, faces, options);
  ToneMapStats local;
  ToneMapStats& s = stats ? *stats : local;
  s = ToneMapStats{};
  ScalarImage display = displayValuesIn(
      displaySpaces(hdr, options.targetDisplay().lowerBound(), &faces), faces, options, s);
  s.totalSeconds = secondsSince(start);
  return display;
}

DisplayImage toneMap(const RgbImage& hdr, const FaceIdImage& faces, const ToneMapOptions& options,
                     ToneMapStats* stats) {
  const auto start = Clock::now();
  checkInputs(hdr, faces, options);
  ToneMapStats local;
  ToneMapStats& s = stats ? *stats : local;
  s = ToneMapStats{};
  const DisplayModel display = options.targetDisplay();
  const DisplaySpaces spaces = displaySpaces(hdr, display.lowerBound(), &faces);
  DisplayImage image =
      encodedImage(hdr, spaces, displayValuesIn(spaces, faces, options, s), display);
  s.totalSeconds = secondsSince(start);
  return image;
}

}  // namespace penumbra
