#pragma once
// A photometric luminaire in a scene: the file's light distribution, its flux and maintenance
// factor, and the placed instances (one, or an array), each with the rotation from the
// luminaire's local photometric frame (docs/photometry.md) to the scene.
//
// The aim (docs/scene-format.md, `luminaires:`): the local frame is first tilted by tilt_deg
// about its C0 axis (local +x), right-handed, so that a positive tilt swings the nadir towards
// C90; then turned by rotate_deg about the scene's +z, counter-clockwise seen from above, so that
// C0 points along (cos r, sin r, 0) when the tilt is 0. scene = Rz(rotate) · Rx(tilt) · local.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/vec.hpp"
#include "photometry/light_distribution.hpp"
#include "photometry/luminance_fit.hpp"
#include "photometry/photometric_data.hpp"

namespace penumbra {

using Mat3 = Eigen::Matrix3d;

// How a luminaire emits: `Point` puts the whole distribution at the photometric centre; `Area`
// spreads it over the luminous opening (LuminaireOpening).
enum class LuminaireModel { Point, Area };

// The area model (docs/method.md, "The area model"): the flat luminous opening, centred on the
// photometric centre in the local frame and facing the nadir, emits the fitted luminance
// (photometry/luminance_fit.hpp) uniformly over its area, integrated exactly over the part of it
// each point sees. Where the fit's error exceeds kLuminanceFitTolerance, or its conditioning
// kLuminanceConditioningLimit (the kernel sums the moments in float), the opening's bounding
// rectangle is instead split into cells of at most 5 cm a side (at most 16 along each axis), each
// a point source at its centre carrying an equal share of the file's own distribution (hard
// shadows per cell).
struct LuminaireOpening {
  std::vector<Vec3> outline;  // local frame, z = 0, ordered so that its normal is −z
  double lengthM = 0.0;       // bounding rectangle along local x (C0)
  double widthM = 0.0;        // along local y (C90)
  photometry::LuminanceFit fit;
  int partsAlongLength = 1, partsAlongWidth = 1;  // 1 × 1: the fit integrated exactly

  bool subdivided() const { return partsAlongLength * partsAlongWidth > 1; }
  // The centre of cell (i, j), i along the length, local frame.
  Vec3 partCentre(int i, int j) const;
};

struct LuminaireAim {
  double rotateDeg = 0.0;  // about the scene's +z, counter-clockwise seen from above
  double tiltDeg = 0.0;    // about the luminaire's C0 axis, before the rotation
};

// Columns: the luminaire's local x (C0), y (C90) and z (up) in scene coordinates.
Mat3 aimRotation(const LuminaireAim& aim);

struct LuminaireInstance {
  std::string name;                 // the luminaire's name, or name[i,j] in an array (1-based)
  Vec3 position = Vec3::Zero();     // photometric centre, m
  Mat3 toScene = Mat3::Identity();  // local → scene (aimRotation)
};

struct Luminaire {
  std::string name;
  std::filesystem::path file;  // as resolved against the scene file
  photometry::PhotometricFormat format = photometry::PhotometricFormat::Ies;
  std::shared_ptr<const photometry::LightDistribution> distribution;  // the file's, in cd
  double lampLumens = 0.0;  // lm, after the flux override (0: absolute photometry)
  std::optional<double> lightOutputRatio;
  double maintenanceFactor = 1.0;
  // cd emitted per cd of the file's table: (flux override / file's lamp lumens) × MF.
  double intensityScale = 1.0;
  LuminaireModel model = LuminaireModel::Point;
  std::optional<LuminaireOpening> opening;  // set for the area model
  // The file's luminous opening where it is flat (rectangle, disk, ellipse), whatever the model:
  // photometry::flatOutline in the local frame. Glare ratings see this area (docs/glare.md).
  std::vector<Vec3> luminousOutline;
  std::vector<LuminaireInstance> instances;

  // lm of one instance by the zonal method (photometry/zonal_flux.hpp) on the scaled table, before
  // the maintenance factor: the file's lamp lumens × LOR, or the override's.
  double zonalFluxLm() const;

  // cd towards `localDirection` (the luminaire's frame), scaled and maintained.
  double intensity(const Vec3& localDirection) const {
    return intensityScale * distribution->intensity(localDirection);
  }
};

std::string luminaireModelName(LuminaireModel model);  // "point", "area"

// The area model's opening for `shape` (flat shapes only: rectangle, disk, ellipse), with the
// fit of `distribution` and its parts; nothing for shapes that are not flat or have no area.
std::optional<LuminaireOpening> luminaireOpening(const photometry::LuminousOpening& shape,
                                                 const photometry::LightDistribution& distribution);

}  // namespace penumbra
