#pragma once
// The scene as written in the file, before any geometry is built: plain numbers, each part with
// where it came from. Loading is two passes (read, then build) because the tolerances that decide
// "planar", "convex" or "inside its wall" are relative to the scene's size
// (geometry/tolerance.hpp), and that size is known only once every coordinate in the file has been
// read.
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "geometry/vec.hpp"
#include "scene/scene.hpp"
#include "scene/yaml_reader.hpp"

namespace penumbra::scenefile {

// ---- shapes, shared by solids and sources

struct BoxSpec {
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();
};
struct PrismSpec {
  std::vector<Vec3> base;
  double height = 0.0;
  Where baseWhere;
};
struct HullSpec {
  std::vector<Vec3> points;
};
struct PolygonSpec {  // sources only
  std::vector<Vec3> vertices;
  std::optional<Vec3> normal;  // unit
  Where normalWhere;
};
struct RectSpec {  // sources only
  Vec3 center = Vec3::Zero();
  double width = 0.0, height = 0.0;
  Vec3 normal = Vec3::UnitZ();  // unit
};
struct OpeningRefSpec {  // sources only: fills a room opening
  std::string opening;
  bool outerPlane = true;
};

// Curved primitives (Conway & Cottingham), tessellated into convex polyhedra by shape_builder:
// `sphere`, and `cylinder`, `cone` and `truncus`, which are all a generalised truncus.
struct SphereSpec {
  Vec3 center = Vec3::Zero();
  double radius = 1.0;
  int facets = 0;
};
struct TruncusSpec {
  Vec3 center = Vec3::Zero();  // the middle of the axis
  Vec3 axis = Vec3::UnitZ();   // end r2 → end r1; its length is the height
  double r1 = 1.0, r2 = 1.0;
  int facets = 0;
};

using ShapeSpec = std::variant<BoxSpec, PrismSpec, HullSpec, PolygonSpec, RectSpec, OpeningRefSpec,
                               SphereSpec, TruncusSpec>;

// ---- scene parts

struct OpeningSpec {
  std::string name;
  std::string wall;  // x0 x1 y0 y1
  double along = 0.0, sill = 0.0, width = 0.0, height = 0.0;
  double transmittance = 1.0;
  Where where;
};

struct RoomSpec {
  Vec3 size = Vec3::Zero();
  double wallThickness = 0.2;
  int floorMaterial = -1, ceilingMaterial = -1, wallMaterial = -1;
  std::vector<OpeningSpec> openings;
  Where where;
};

struct SolidSpec {
  std::string name;
  ShapeSpec shape;
  Where shapeWhere;  // the shape's key, e.g. solids[2].prism
  int material = -1;
};

struct SourceSpec {
  std::string name;
  ShapeSpec shape;
  Where shapeWhere;
  Where where;                      // the source's entry, e.g. sources[1]
  std::optional<double> luminance;  // exactly one of luminance, flux
  std::optional<double> flux;
  Vec3 color = Vec3::Ones();
};

struct WorkPlaneSpec {
  double height = 0.80;
  std::optional<double> spacing;  // empty: EN 12464-1 automatic spacing
  double margin = 0.5;
  Where heightWhere, marginWhere;  // the grid's entry when the key is not given
};
struct RectGridSpec {
  Vec3 origin = Vec3::Zero(), u = Vec3::UnitX(), v = Vec3::UnitY();
  std::optional<double> spacing;
  Where uWhere, vWhere;
};
struct PointsSpec {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;  // unit
};

struct GridSpec {
  std::string name;
  std::variant<WorkPlaneSpec, RectGridSpec, PointsSpec> layout;
  Where where;
};

struct ViewSpec : View {
  Where where, eyeWhere;
};

// An `observers:` entry as written: one eye, or a grid of eyes over the parallelogram
// origin + [0,1]·u + [0,1]·v at the centres of cells of at most `spacing` a side.
struct ObserverGridSpec {
  Vec3 origin = Vec3::Zero(), u = Vec3::Zero(), v = Vec3::Zero();
  double spacing = 0.0;  // m
};
struct ObserverSpec {
  std::string name;
  std::variant<Vec3, ObserverGridSpec> eyes;  // m
  std::optional<Vec3> look;                   // unit
  Where where, eyeWhere;
};

// A `luminaires:` entry as written: the file is read when the scene is built.
struct LuminaireSpec {
  std::string name;
  std::string file;  // relative to the scene file
  Where fileWhere;
  Vec3 position = Vec3::Zero();  // photometric centre, m
  LuminaireAim aim;
  int countX = 1, countY = 1;             // array: instances along the scene's x and y
  double spacingX = 0.0, spacingY = 0.0;  // m
  std::optional<double> fluxLm;           // overrides the file's lamp lumens
  Where fluxWhere;
  double maintenanceFactor = 1.0;
  // Absent: the area model where the file gives a flat luminous opening, else the point model.
  std::optional<LuminaireModel> model;
  Where modelWhere;
  Where where;
};

// `sun: {date, time, direct_normal_illuminance_lx}` as read; its position needs the site.
struct SunSpec {
  CivilDate date;
  double secondsOfDay = 0.0;           // s after the site's midnight, standard time
  double directNormalIlluminance = 0;  // lx
  Where where;
};

struct SceneSpec {
  std::vector<Material> materials;
  std::optional<RoomSpec> room;
  std::optional<Sky> sky;
  Where skyWhere;
  std::optional<Site> site;
  std::optional<SunSpec> sun;
  std::vector<SolidSpec> solids;
  std::vector<SourceSpec> sources;
  std::vector<LuminaireSpec> luminaires;
  std::vector<GridSpec> grids;
  std::vector<ViewSpec> views;
  std::vector<ObserverSpec> observers;
};

}  // namespace penumbra::scenefile
