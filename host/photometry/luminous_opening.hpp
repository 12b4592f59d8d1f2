#pragma once
// The luminous opening from the dimensions a file gives: IES LM-63 encodes the shape in the
// signs of width, length and height (LM-63-2002 table 1); EULUMDAT gives the luminous area's
// length (or diameter) and width (0 for a disk) and its heights at C0, C90, C180 and C270.
#include <optional>
#include <string>
#include <vector>

#include "geometry/vec.hpp"
#include "photometry/photometric_data.hpp"

namespace penumbra::photometry {

struct SignedOpening {
  double width = 0;   // along C90-C270, in the file's unit
  double length = 0;  // along C0-C180
  double height = 0;
};

// The shape LM-63 assigns to the signs of `dimensions` (scaled to metres by `metresPerUnit`), or
// nothing when the combination is not in LM-63's table.
std::optional<LuminousOpening> openingFromIes(const SignedOpening& dimensions,
                                              double metresPerUnit);

// The luminous area of a EULUMDAT file: dimensions in mm, heights at C0, C90, C180, C270.
LuminousOpening openingFromEulumdat(double lengthMm, double widthMm, const double heightsMm[4]);

// The outline of a flat opening (rectangle, disk, ellipse) in the luminaire's local frame: in the
// plane z = 0, centred on the photometric centre, ordered so that its right-hand normal is the
// nadir (−z). A disk or ellipse is the regular kRoundOpeningSides-gon of the same area (its
// vertices on an ellipse scaled by sqrt(area ratio)). Empty for other shapes and for an opening
// without area.
constexpr int kRoundOpeningSides = 32;
std::vector<Vec3> flatOutline(const LuminousOpening& opening);

}  // namespace penumbra::photometry
