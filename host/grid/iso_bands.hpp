#pragma once
// Iso-bands of illuminance over a surface (Conway & Cottingham's isoluminance laminae, drawn as
// bands of constant colour between isolux levels): E is known at the vertices of a triangle mesh
// of the surface; inside each triangle it is taken as linear, so the part of the triangle between
// two levels is one convex polygon. Where a contour crosses a mesh edge, the crossing point is
// then moved along that edge until the exact E there (the kernel, through `evaluate`) equals the
// level, so contour vertices are exact, not read off an interpolated image.
//
// Band b holds values in [levels[b-1], levels[b]); band 0 is below levels[0] and band
// levels.size() at or above the last level. The bands of a triangle tile it.
#include <array>
#include <functional>
#include <span>
#include <vector>

#include "geometry/face_triangulation.hpp"

namespace penumbra {

struct IsoBandPolygon {
  int band = 0;
  std::vector<Vec3> vertices;  // convex, in the mesh's orientation
};

struct ContourVertex {
  Vec3 position;
  int level = 0;  // index into levels
  // E jumps across the level here (a shadow edge cast by a source's own edge, a solid's foot):
  // no point of the edge has E equal to the level, and the vertex sits on the jump. Also set
  // where the refinement ran out of rounds before E settled (a shadow's corner).
  bool atJump = false;
};

struct IsoBands {
  std::vector<IsoBandPolygon> polygons;
  std::vector<std::array<Vec3, 2>> contourSegments;  // pieces of isolux lines
  std::vector<ContourVertex> contourVertices;        // every refined crossing point
};

// Exact E at points of the surface (lx); called once per refinement round with all points.
using SurfaceIlluminance = std::function<std::vector<double>(std::span<const Vec3>)>;

// `illuminance`: E at each mesh vertex. `levels` ascending. Each crossing point is refined by
// regula falsi (Illinois) until its E is within `tolerance` (relative) of its level, for at most
// `rounds` rounds (0: leave them where the linear interpolation puts them).
IsoBands isoBands(const TriangleMesh& mesh, std::span<const double> illuminance,
                  std::span<const double> levels, const SurfaceIlluminance& evaluate,
                  int rounds = 40, double tolerance = 1e-3);

// The band of a value.
int bandOf(double value, std::span<const double> levels);

}  // namespace penumbra
