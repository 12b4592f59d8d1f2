#pragma once
// A sky of patches (docs/method.md, "CIE general skies"): the hemisphere above the horizon cut
// into Tregenza's 145 patches (subdivision 1) or Reinhart's 144 m² + 1 (subdivision m), each
// patch of one luminance, its value at the patch's centre direction.
//
// Rows of equal altitude step 90°/(7m + ½) (12° for m = 1), m rows per Tregenza band, of
// 30, 30, 24, 24, 18, 12, 6 patches per band times m, and a cap of half a step about the zenith.
// A patch is bounded by two meridians and by two rings; each ring is the polygon of great-circle
// arcs through the patch corners of both rows it separates (the horizon is its own great circle),
// so the patches tile the hemisphere exactly with no gap and no overlap. A patch is cut along the
// meridians through its rings' corners into pieces, each a convex spherical polygon (three or
// four great-circle arcs), which a point sees as a planar polygon placed beyond every solid
// (far_polygon.hpp): its light through an opening past every solid is then exact, as the
// uniform sky's is. The only approximation is each patch's uniform luminance.
#include <functional>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "geometry/vec.hpp"

namespace penumbra {

struct SkyPiece {
  std::vector<Vec3> corners;  // unit directions, the piece's great-circle polygon, in order
  Vec3 centre;                // unit: the mean of the corners, inside the piece
  int patch = 0;              // the patch it belongs to
};

struct SkySubdivision {
  int subdivision = 1;             // m
  std::vector<Vec3> patchCentres;  // unit; 144 m² + 1, the cap's (the zenith) last
  std::vector<SkyPiece> pieces;    // every patch's pieces, each patch's together
};

// The tiling of subdivision m (>= 1; std::invalid_argument otherwise).
SkySubdivision skySubdivision(int subdivision);

// The piece seen from `point`, as a planar convex polygon in the plane perpendicular to its
// centre direction at `distance` (m) from the point, its normal towards the point.
ConvexPolygon piecePolygon(const SkyPiece& piece, const Vec3& point, double distance);

// A sky of patches: the tiling and a luminance per patch (cd/m²).
struct PatchSky {
  SkySubdivision division;
  std::vector<double> luminance;  // per patch
};

// Each patch at `luminance(centre)` (cd/m²; the centre a unit direction).
PatchSky patchSky(int subdivision, const std::function<double(const Vec3&)>& luminance);

// The illuminance (lx) that `sky` gives an unobstructed horizontal plane: Σ L_patch M_0, M_0 each
// piece's exact projected solid angle on the horizontal.
double horizontalIlluminance(const PatchSky& sky);

}  // namespace penumbra
