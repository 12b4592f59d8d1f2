#pragma once
// What the display step is asked to do (ToneMapOptions) and what it reports back (ToneMapStats).
// Plain values: the CLI fills the options, the output layer writes the stats as JSON.
#include <string>

#include "tonemap/display_model.hpp"

namespace penumbra {

// clip and linear are the thesis's two straightforward maps (Fang, Fig. 4.1(b), eq. 4.2), shipped
// beside the constraint map so that the three can be compared through the same output path.
enum class DisplayMethod { Clip, Linear, Constraint };

std::string displayMethodName(DisplayMethod method);
// "clip", "linear", "constraint" (any case); throws std::invalid_argument otherwise.
DisplayMethod displayMethodFromName(const std::string& name);

// Where the constraint map's vertices lie: on a lattice of luminance levels of each region (each
// region shown as one curve of its own luminance; luminance_lattice.hpp), or on a lattice of
// pixels (the thesis's mesh, vertex_mesh.hpp), which shows a region with a gain that may change
// across it.
enum class VertexLattice { Levels, Image };

std::string vertexLatticeName(VertexLattice lattice);
// "levels", "image" (any case); throws std::invalid_argument otherwise.
VertexLattice vertexLatticeFromName(const std::string& name);

struct ToneMapOptions {
  DisplayMethod method = DisplayMethod::Constraint;
  // LowerBound (eq. 4.17): the display's black as a fraction of its white. 0.02 is a screen in a
  // dim room; the thesis measured 5-15 % with ambient light.
  double black = 0.02;
  // Weights of the constraint hierarchy (one weighted row each, on log V; docs/tonemap.md). The
  // thesis leaves them open. The region rows (medium) outweigh the edge rows (strong) tenfold so
  // that an edge cannot bend the region beside it (a halo: tests/tonemap_halo_test.cpp measures
  // 0.79 with medium 1 and below 1e-3 with 100); the weak rows only set the level of what the
  // others leave free (the office's S moves by under 1e-3 from weak 0.01 to 0.1).
  double strong = 10.0;
  double medium = 100.0;
  double weak = 0.1;
  VertexLattice vertices = VertexLattice::Levels;
  // The image lattice only: largest spacing in pixels between the vertices of a region (interior
  // lattice and boundary).
  int lattice = 8;
  // clip only: the luminance shown as white, cd/m² (a fixed exposure: the same cd/m² gives the
  // same display value in every picture). 0: automatic, from each picture's own log average.
  double white = 0;
  // The target display (display_model.hpp): its white in cd/m² and the illuminance on its
  // screen from the room around it in lx. 100 cd/m² is an office monitor (sRGB's reference
  // display is 80); ambient light raises the display's black and so the tone map's lower bound.
  double displayLuminance = 100.0;
  double ambient = 0.0;

  // The display model of these options; its lowerBound() is the tone map's LowerBound.
  DisplayModel targetDisplay() const { return DisplayModel{displayLuminance, black, ambient}; }
};

struct ToneMapStats {
  std::string method;
  double black = 0;
  double strong = 0, medium = 0, weak = 0;
  std::string vertices;  // "levels" or "image"
  int lattice = 0;
  double white = 0;  // clip: the luminance shown as white, cd/m², fixed or automatic; 0 otherwise
  double displayLuminance = 0;  // the target display's white, cd/m²
  double ambient = 0;           // lx on its screen
  double lowerBound = 0;        // the display's black over its white with the ambient light
  int width = 0, height = 0;
  int regions = 0;    // connected visible parts of faces
  int variables = 0;  // vertices, one V each
  int strongRows = 0, mediumRows = 0, weakRows = 0;
  int threeVariableRows = 0;  // strong rows of the form eq. 4.22 / 4.24
  int outerIterations = 0;    // factorisations: the two stages below together
  int activeSetIterations = 0, projectedNewtonIterations = 0;
  bool converged = true;
  int atLowerBound = 0, atUpperBound = 0;  // vertices shown at black / white
  // log V added to every solved vertex so that the brightest is at white (0 when one was).
  double raisedToWhite = 0;
  // Root mean square and largest |residual| of each level's rows, unweighted (in log V units).
  double strongRms = 0, strongMax = 0;
  double mediumRms = 0, mediumMax = 0;
  double weakRms = 0, weakMax = 0;
  double buildSeconds = 0, solveSeconds = 0, pixelSeconds = 0, totalSeconds = 0;
};

}  // namespace penumbra
