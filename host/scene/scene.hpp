#pragma once
// The scene after parsing and validation: everything in metres, cd/m², lx; sources expanded
// to emitting convex polygons. Produced by loadScene (scene_loader.hpp); read by every stage.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geometry/bounding_box.hpp"
#include "geometry/convex_polyhedron.hpp"
#include "scene/luminaire.hpp"
#include "scene/parameters.hpp"
#include "scene/scene_warning.hpp"
#include "scene/solar_position.hpp"

namespace penumbra {

struct Material {
  std::string name;
  Vec3 reflectance = Vec3::Constant(0.8);  // diffuse, per RGB channel, each in [0, 1]
};

struct Solid {
  std::string name;
  ConvexPolyhedron shape;
  int material = -1;  // index into Scene::materials, -1 for none
};

enum class SourceShape { Polygon, Polyhedron };

// A Lambertian source of uniform luminance. An area source has one face; a polyhedron source
// has all its faces (every face emits outwards). Each face's vertices run counter-clockwise
// about its emission direction, so face.normal() is where it emits to.
//
// A source may have a luminance that depends on the direction ω from the receiving point
// towards it: L(ω) = luminance · Σ_k c_k (w·ω)^k, c = luminanceCoefficients (empty: uniform) and
// w = polynomialAxis(face). A photometric luminaire's opening (the area model,
// scene/luminaire.hpp) has w = −N, N the face's emission direction (w·ω = cos φ of the emitted
// direction); such sources exist only in the scene LuminaireEngine hands the illuminance kernel.
// The overcast sky through an opening (scene/daylight.hpp) has w = +z.
struct Source {
  std::string name;
  SourceShape shape = SourceShape::Polygon;
  std::vector<ConvexPolygon> faces;
  double luminance = 0.0;                     // cd/m² (from `flux`: L = Φ / (π·A))
  std::vector<double> luminanceCoefficients;  // c_0..c_order, at most PN_MAX_LUMINANCE_TERMS
  Vec3 luminanceAxis = Vec3::Zero();          // unit w; zero: −N of each face
  Vec3 color = Vec3::Ones();
  std::string opening;  // the room opening an `opening:` source fills; empty for other sources
  // Another source (index into Scene::sources) whose first face holds this source's one face in
  // its own plane: this face's shadow casters are that face's (shadow/scene_shadows.hpp). -1:
  // its own. Set for the element trees' nodes, never read from a scene file.
  int castersOf = -1;
  // Emits nothing: the source's one face only holds shadow casters that later sources share
  // (castersOf), and the engine gives it E = 0 without evaluating it. Set for the dense
  // transfer's element blocks, never read from a scene file.
  bool castersOnly = false;
  double emittingArea() const;  // m², all faces
  Vec3 polynomialAxis(const ConvexPolygon& face) const {
    return luminanceAxis.isZero() ? Vec3(-face.normal()) : luminanceAxis;
  }
};

enum class GridKind { WorkPlane, Rect, Points };

// The points where illuminance is wanted. A planar grid (work plane, rect) is described, not
// stored: its points are the centres of the columns × rows cells of the parallelogram
// origin + [0,1]·u + [0,1]·v, row-major (index = row · columns + column, rows along v), all with
// the plane's normal; a 10^7-point grid costs no more memory than a 10-point one. A point list
// keeps what was given (it is input-sized). Every user reads points through size(), position(i)
// and normal(i), so that the layout is worked out in one place.
class CalculationGrid {
 public:
  std::string name;
  GridKind kind = GridKind::Points;
  double spacing = 0.0;       // m; 0 for point lists
  int columns = 0, rows = 0;  // planar grids; 0 × 0 for point lists

  CalculationGrid() = default;
  static CalculationGrid planar(std::string name, GridKind kind, const Vec3& origin, const Vec3& u,
                                const Vec3& v, int columns, int rows, double spacing);
  // Positions in m, normals unit, one normal per position (std::invalid_argument otherwise).
  static CalculationGrid pointList(std::string name, std::vector<Vec3> positions,
                                   std::vector<Vec3> normals);

  std::size_t size() const;
  Vec3 position(std::size_t i) const;  // m; i < size()
  Vec3 normal(std::size_t i) const;    // unit

  // Planar grids: the parallelogram the cells cut (zero for point lists).
  const Vec3& origin() const { return origin_; }
  const Vec3& u() const { return u_; }
  const Vec3& v() const { return v_; }

 private:
  Vec3 origin_ = Vec3::Zero(), u_ = Vec3::Zero(), v_ = Vec3::Zero();
  Vec3 planeNormal_ = Vec3::UnitZ();
  std::vector<Vec3> positions_;  // point lists only
  std::vector<Vec3> normals_;
};

struct Opening {
  std::string name;
  std::string wall;            // x0 x1 y0 y1
  double transmittance = 1.0;  // of its glazing, diffuse, in [0, 1]: scales the sky and ground
  ConvexPolygon
      inner;  // the hole on the wall's room-side face, counter-clockwise seen from the room
  ConvexPolygon outer;  // the hole on the wall's outside face, same orientation
};

struct Room {
  Vec3 size = Vec3::Zero();  // interior extent; interior corner at the origin
  double wallThickness = 0.2;
  std::vector<Opening> openings;
};

// The standard sky of a daylight scene (docs/method.md, "Daylight"): its luminance from the
// unobstructed horizontal illuminance it gives, and the ground below the horizon, uniform of
// luminance ρ_g·E_h/π. The sky is seen through the room's openings (scene/daylight.hpp).
// `cie-general` is one of the 15 CIE standard general skies (scene/cie_general_sky.hpp) as a sky
// of patches (illuminance/patch_sky.hpp), scaled so that it gives E_h.
enum class SkyModel { Uniform, CieOvercast, CieGeneral };
// The model's name in the scene file: "uniform", "cie-overcast", "cie-general".
std::string skyModelName(SkyModel model);

struct Sky {
  SkyModel model = SkyModel::CieOvercast;
  double horizontalIlluminance = 10000.0;  // lx: E_h, outdoors on an unobstructed horizontal plane
  double groundReflectance = 0.2;          // ρ_g in [0, 1]
  int cieType = 1;      // CieGeneral: the type, 1..15 (ISO 15469 / CIE S 011, Table 1)
  int subdivision = 1;  // CieGeneral: 1 Tregenza's 145 patches, m > 1 Reinhart's 144 m² + 1
  // L at the zenith (cd/m²): E_h = 7π·L_z/9 for the CIE overcast sky, π·L for the uniform one.
  // For CieGeneral, whose scale comes from its patches, the uniform sky's E_h/π: only where the
  // openings let light in is read from it (the interreflection's mesh).
  double zenithLuminance() const;
  double groundLuminance() const;  // cd/m²: ρ_g·E_h/π
};

// Where a daylight scene is (`site:`): its position places the sun (solar_position.hpp); its
// median external diffuse illuminance gives the EN 17037 daylight-factor targets
// (grid_metrics.hpp, DaylightProvision).
struct Site {
  double latitudeDegrees = 0.0, longitudeDegrees = 0.0;  // °, north and east positive
  double timezoneHours = 0.0;                            // h east of UTC
  // °: true north, counter-clockwise from the scene's +y seen from above (0: north +y, east +x)
  double northDegrees = 0.0;
  // lx: E_v,d,med, the median of the site's diffuse horizontal illuminance over the 4380 daylit
  // hours of the year; no EN 17037 verdict without it.
  std::optional<double> medianDiffuseIlluminance;
};

// The sun of a daylight scene (`sun:`, docs/method.md "The sun"): a disk of kSunDiameterDegrees
// whose direct normal illuminance is E_dn, at its position for the site's date and clock time.
// It lights grids through the host's exact evaluation (illuminance/sunlight.hpp).
inline constexpr double kSunDiameterDegrees = 0.53;

struct Sun {
  LocalInstant instant;                // the site's standard time
  double directNormalIlluminance = 0;  // lx: E_dn, on a plane facing the sun, unobstructed
  SolarPosition position;              // at the site, at `instant`
  // Unit, towards the disk's centre at its apparent elevation, in the scene's frame (north at
  // Site::northDegrees).
  Vec3 direction = Vec3::UnitZ();
  // Whether the centre is above the horizon (apparent elevation > 0°); below it the sun gives 0.
  bool aboveHorizon() const { return position.apparentElevationDegrees > 0.0; }
};

// A camera for `penumbra render`: a pinhole at `eye` looking at `target`, `up` tilting the image
// (it need not be perpendicular to the line of sight), `fovDegrees` the horizontal angle of view.
struct View {
  std::string name;
  Vec3 eye = Vec3::Zero(), target = Vec3::UnitX(), up = Vec3::UnitZ();  // m, m, unit
  double fovDegrees = 60.0;
  int width = 1280, height = 720;  // pixels
};

// An eye for `penumbra glare` (docs/glare.md): where it is and the lines of sight along which its
// UGR is rated, unit vectors, each with a horizontal component (the Guth position index measures
// a source's height above a line of sight in the vertical plane through it). An observer grid
// of the scene file is expanded into one Observer per point, named name[column,row] (1-based).
struct Observer {
  std::string name;
  std::string entry;        // the `observers:` entry it comes from (its name for a single eye)
  Vec3 eye = Vec3::Zero();  // m
  std::vector<Vec3> looks;  // unit; the scene's `look`, or +x, +y, −x, −y
};

struct Scene {
  std::filesystem::path file;
  std::vector<Material> materials;
  std::vector<Solid> solids;  // includes the room's slabs (named room.floor, room.wall-y0.1, ...)
  std::vector<Source> sources;
  std::vector<Luminaire> luminaires;  // photometric luminaires, each with its instances
  std::vector<CalculationGrid> grids;
  std::vector<View> views;
  std::vector<Observer> observers;
  std::optional<Room> room;
  std::optional<Sky> sky;  // daylight through the room's openings (scene/daylight.hpp)
  std::optional<Site> site;
  std::optional<Sun> sun;      // direct sunlight (illuminance/sunlight.hpp)
  ParameterValues parameters;  // the values it was built with: its defaults unless overridden
  // What loaded but is probably a mistake (docs/scene-format.md, "Warnings"), in file order.
  std::vector<SceneWarning> warnings;

  // The bounding box of all geometry: solids, sources, luminaires' photometric centres and
  // calculation points (m).
  BoundingBox bounds() const;
  // The same without the calculation points: what the scene is made of (m).
  BoundingBox geometryBounds() const;
  // The point the kernels' positions are relative to (m): the centre of geometryBounds(), or of
  // bounds() in a scene of calculation points only. A solid's distance from it sets the thinnest
  // the kernels resolve it (Tolerance::minimumThickness); grids do not move it.
  Vec3 kernelOrigin() const;
  // Its diagonal (m); the scale of Tolerance.
  double size() const;
};

}  // namespace penumbra
