#include "scene/spec_reader.hpp"

#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include "scene/cie_general_sky.hpp"
#include "scene/grid_reader.hpp"
#include "scene/luminaire_reader.hpp"
#include "scene/observer_reader.hpp"
#include "scene/shape_reader.hpp"
#include "scene/sun_reader.hpp"
#include "scene/view_reader.hpp"

namespace penumbra::scenefile {
namespace {

// Names must be unique within each list (solids, sources, grids, openings): results, logs and
// error messages refer to things by name.
class NameRegistry {
 public:
  NameRegistry(const Reader& reader, std::string listKey)
      : reader_(reader), listKey_(std::move(listKey)) {}

  void add(const std::string& name, const Field& field) {
    const auto [it, inserted] = seen_.emplace(name, field.where);
    if (!inserted) {
      reader_.fail(field.where, "the name '" + name + "' is already used in " + listKey_ + " by " +
                                    it->second.key + " (line " + std::to_string(it->second.line) +
                                    "); names must be unique");
    }
  }

 private:
  const Reader& reader_;
  std::string listKey_;
  std::map<std::string, Where> seen_;
};

void checkVersion(const Reader& reader, const Field& field) {
  const std::string expected = std::to_string(kFormatVersion);
  if (!field.node.IsScalar() || field.node.Scalar() != expected) {
    const std::string got = field.node.IsScalar() ? field.node.Scalar() : "not a number";
    reader.fail(field.where, "this penumbra reads scene format version " + expected +
                                 " ('penumbra: " + expected + "'), but the file says '" + got +
                                 "'");
  }
}

// A reflectance is a grey number or an [r, g, b] list, each in [0, 1].
Vec3 readReflectance(const Reader& reader, const Field& field) {
  Vec3 rgb;
  if (field.node.IsSequence()) {
    const std::vector<double> v = reader.numbers(field, 3);
    rgb = Vec3(v[0], v[1], v[2]);
  } else {
    rgb = Vec3::Constant(reader.number(field));
  }
  for (int i = 0; i < 3; ++i) {
    if (rgb[i] < 0.0 || rgb[i] > 1.0) {
      const std::string hint = rgb[i] > 1.0 ? " (a percentage? write 0.8 for 80 %)" : "";
      reader.fail(field.where,
                  "a diffuse reflectance must lie in [0, 1], got " + formatNumber(rgb[i]) + hint);
    }
  }
  return rgb;
}

std::vector<Material> readMaterials(const Reader& reader, const Field& field) {
  std::vector<Material> materials;
  const MapView map = reader.map(field, "materials {name: reflectance, ...}");
  for (const MapView::Entry& e : map.entries()) {
    materials.push_back(Material{e.key, readReflectance(reader, e.value)});
  }
  return materials;
}

class MaterialLookup {
 public:
  MaterialLookup(const Reader& reader, const std::vector<Material>& materials)
      : reader_(reader), materials_(materials) {}

  int operator()(const Field& field) const {
    const std::string name = reader_.text(field);
    for (std::size_t i = 0; i < materials_.size(); ++i) {
      if (materials_[i].name == name) return static_cast<int>(i);
    }
    std::string defined;
    for (const Material& m : materials_) defined += (defined.empty() ? "" : ", ") + m.name;
    reader_.fail(field.where, "unknown material '" + name + "'; " +
                                  (defined.empty() ? "the scene defines no materials (add them "
                                                     "under 'materials:')"
                                                   : "materials defined: " + defined));
  }
  int optional(const MapView& entry, std::string_view key) const {
    const std::optional<Field> field = entry.find(key);
    return field ? (*this)(*field) : -1;
  }

 private:
  const Reader& reader_;
  const std::vector<Material>& materials_;
};

// A number in [0, 1]: a transmittance or a reflectance.
double readFraction(const Reader& reader, const Field& field, std::string_view what) {
  const double value = reader.number(field);
  if (value < 0.0 || value > 1.0) {
    const std::string hint = value > 1.0 ? " (a percentage? write 0.7 for 70 %)" : "";
    reader.fail(field.where,
                std::string(what) + " must lie in [0, 1], got " + formatNumber(value) + hint);
  }
  return value;
}

// A whole number in [lo, hi].
int readWholeNumber(const Reader& reader, const Field& field, int lo, int hi,
                    std::string_view what) {
  const double value = reader.number(field);
  if (!(value >= lo && value <= hi && value == std::floor(value)))
    reader.fail(field.where, std::string(what) + " is a whole number from " + std::to_string(lo) +
                                 " to " + std::to_string(hi) + ", got " + formatNumber(value));
  return static_cast<int>(value);
}

OpeningSpec readOpening(const Reader& reader, const Field& field) {
  const MapView map = reader.map(field, "an opening");
  map.allowOnly({"name", "wall", "x", "z", "width", "height", "transmittance"}, "an opening");
  OpeningSpec spec;
  spec.where = field.where;
  spec.name = reader.text(map.require("name"));
  const Field wall = map.require("wall");
  spec.wall = reader.text(wall);
  if (spec.wall != "x0" && spec.wall != "x1" && spec.wall != "y0" && spec.wall != "y1") {
    reader.fail(wall.where, "unknown wall '" + spec.wall +
                                "'; walls are x0, x1 (at x = 0 and x = room width), y0, y1");
  }
  spec.along = reader.number(map.require("x"));
  spec.sill = reader.number(map.require("z"));
  spec.width = reader.positive(map.require("width"), "m");
  spec.height = reader.positive(map.require("height"), "m");
  if (const std::optional<Field> t = map.find("transmittance"))
    spec.transmittance = readFraction(reader, *t, "a transmittance");
  return spec;
}

// `sky: {model: cie-overcast | uniform, horizontal_illuminance_lx: E_h, ground_reflectance: ρ_g}`
Sky readSky(const Reader& reader, const Field& field) {
  const MapView map = reader.map(field, "the sky");
  map.allowOnly({"model", "horizontal_illuminance_lx", "ground_reflectance", "type", "subdivision"},
                "the sky");
  Sky sky;
  const Field model = map.require("model");
  const std::string name = reader.text(model);
  if (name == "cie-overcast") {
    sky.model = SkyModel::CieOvercast;
  } else if (name == "uniform") {
    sky.model = SkyModel::Uniform;
  } else if (name == "cie-general") {
    sky.model = SkyModel::CieGeneral;
  } else {
    const std::string models =
        "cie-overcast (the CIE standard overcast sky), uniform and cie-general (the 15 CIE "
        "standard general skies)";
    reader.fail(model.where, "unknown sky model '" + name + "'; the models are " + models);
  }
  const std::optional<Field> type = map.find("type");
  const std::optional<Field> subdivision = map.find("subdivision");
  if (sky.model != SkyModel::CieGeneral) {
    for (const std::optional<Field>& key : {type, subdivision})
      if (key) reader.fail(key->where, "only a 'cie-general' sky takes 'type' and 'subdivision'");
  } else {
    if (!type) reader.fail(model.where, "a 'cie-general' sky needs 'type' (1 to 15)");
    sky.cieType = readWholeNumber(reader, *type, 1, kCieSkyTypes, "a CIE sky type");
    if (subdivision)
      sky.subdivision = readWholeNumber(reader, *subdivision, 1, 8, "a sky subdivision");
  }
  sky.horizontalIlluminance = reader.positive(map.require("horizontal_illuminance_lx"), "lx");
  if (const std::optional<Field> g = map.find("ground_reflectance"))
    sky.groundReflectance = readFraction(reader, *g, "a ground reflectance");
  return sky;
}

// `site: {latitude_deg, longitude_deg, timezone_h, north_deg, median_diffuse_illuminance_lx}`:
// the position that places the sun, E_v,d,med for the EN 17037 verdict.
Site readSite(const Reader& reader, const Field& field) {
  const MapView map = reader.map(field, "the site");
  map.allowOnly(
      {"latitude_deg", "longitude_deg", "timezone_h", "north_deg", "median_diffuse_illuminance_lx"},
      "the site");
  Site site;
  const Field latitude = map.require("latitude_deg");
  site.latitudeDegrees = reader.number(latitude);
  if (std::abs(site.latitudeDegrees) > 90.0)
    reader.fail(latitude.where,
                "a latitude lies in [-90, 90]°, got " + formatNumber(site.latitudeDegrees) + "°");
  site.longitudeDegrees = reader.number(map.require("longitude_deg"));
  if (const std::optional<Field> t = map.find("timezone_h")) site.timezoneHours = reader.number(*t);
  if (const std::optional<Field> n = map.find("north_deg")) site.northDegrees = reader.number(*n);
  if (const std::optional<Field> d = map.find("median_diffuse_illuminance_lx"))
    site.medianDiffuseIlluminance = reader.positive(*d, "lx");
  return site;
}

RoomSpec readRoom(const Reader& reader, const Field& field, const MaterialLookup& material) {
  const MapView map = reader.map(field, "the room");
  map.allowOnly({"size", "wall_thickness", "materials", "openings"}, "the room");
  RoomSpec room;
  room.where = field.where;
  const Field size = map.require("size");
  room.size = reader.vec3(size);
  if ((room.size.array() <= 0.0).any()) {
    reader.fail(size.where,
                "the room's size [x, y, z] must be greater than 0 in every direction, "
                "got " +
                    formatVec3(room.size) + " m");
  }
  if (const std::optional<Field> t = map.find("wall_thickness")) {
    room.wallThickness = reader.positive(*t, "m");
  }
  if (const std::optional<Field> m = map.find("materials")) {
    const MapView mats = reader.map(*m, "the room's materials {floor: .., ceiling: .., walls: ..}");
    mats.allowOnly({"floor", "ceiling", "walls"}, "the room's materials");
    room.floorMaterial = material.optional(mats, "floor");
    room.ceilingMaterial = material.optional(mats, "ceiling");
    room.wallMaterial = material.optional(mats, "walls");
  }
  if (const std::optional<Field> openings = map.find("openings")) {
    NameRegistry names(reader, openings->where.key);
    for (const Field& item : reader.list(*openings, "openings")) {
      room.openings.push_back(readOpening(reader, item));
      names.add(room.openings.back().name, item);
    }
  }
  return room;
}

SolidSpec readSolid(const Reader& reader, const Field& field, const MaterialLookup& material) {
  const MapView map = reader.map(field, "a solid");
  const std::string_view shapeKey =
      shapeKeyOf(reader, map, ShapeUse::Solid, "a solid", {"name", "material"});
  map.allowOnly({"name", "material", shapeKey}, "a solid");
  SolidSpec spec;
  spec.name = reader.text(map.require("name"));
  if (spec.name.starts_with("room.")) {
    reader.fail(map.require("name").where,
                "names starting with 'room.' are kept for the room's floor, ceiling and walls");
  }
  std::tie(spec.shape, spec.shapeWhere) = readShape(reader, map, shapeKey);
  spec.material = material.optional(map, "material");
  return spec;
}

SourceSpec readSource(const Reader& reader, const Field& field) {
  const MapView map = reader.map(field, "a source");
  const std::string_view shapeKey =
      shapeKeyOf(reader, map, ShapeUse::Source, "a source",
                 {"name", "luminance", "flux", "color", "normal", "plane"});
  std::vector<std::string_view> accepted{"name", shapeKey, "luminance", "flux", "color"};
  for (std::string_view key : shapeSiblingKeys(shapeKey)) accepted.push_back(key);
  map.allowOnly(accepted, "a source with '" + std::string(shapeKey) + "'");

  SourceSpec spec;
  spec.name = reader.text(map.require("name"));
  spec.where = field.where;
  std::tie(spec.shape, spec.shapeWhere) = readShape(reader, map, shapeKey);
  const std::optional<Field> luminance = map.find("luminance");
  const std::optional<Field> flux = map.find("flux");
  if (luminance && flux) {
    reader.fail(flux->where, "give either 'luminance' (cd/m²) or 'flux' (lm), not both");
  }
  if (!luminance && !flux) {
    reader.fail(map.where(), "a source needs its output: 'luminance' (cd/m²) or 'flux' (lm)");
  }
  if (luminance) spec.luminance = reader.nonNegative(*luminance, "cd/m²");
  if (flux) spec.flux = reader.nonNegative(*flux, "lm");
  if (const std::optional<Field> color = map.find("color")) {
    spec.color = reader.vec3(*color);
    if ((spec.color.array() < 0.0).any() || spec.color.isZero()) {
      reader.fail(color->where, "a colour [r, g, b] needs components >= 0, not all 0; got " +
                                    formatVec3(spec.color));
    }
  }
  return spec;
}

template <typename Spec, typename ReadOne>
std::vector<Spec> readList(const Reader& reader, const MapView& root, std::string_view key,
                           ReadOne readOne) {
  std::vector<Spec> out;
  const std::optional<Field> field = root.find(key);
  if (!field) return out;
  NameRegistry names(reader, std::string(key));
  for (const Field& item : reader.list(*field, key)) {
    out.push_back(readOne(item));
    names.add(out.back().name, item);
  }
  return out;
}

}  // namespace

SceneSpec readSceneSpec(const Reader& reader, const YAML::Node& document) {
  if (!document.IsDefined() || document.IsNull()) {
    reader.fail(Where{0, ""}, "the scene file is empty; it starts with 'penumbra: " +
                                  std::to_string(kFormatVersion) + "'");
  }
  const MapView root = reader.map(reader.root(document), "the scene");
  // `parameters` was read first (parameter_reader.hpp): the other sections may use them.
  root.allowOnly({"penumbra", "parameters", "materials", "room", "solids", "sources", "grids",
                  "views", "luminaires", "observers", "sky", "site", "sun"},
                 "a scene");
  if (!root.has("penumbra")) {
    reader.fail(
        Where{root.where().line, "penumbra"},
        "the scene must state its format: 'penumbra: " + std::to_string(kFormatVersion) + "'");
  }
  checkVersion(reader, root.require("penumbra"));

  SceneSpec spec;
  if (const std::optional<Field> m = root.find("materials")) {
    spec.materials = readMaterials(reader, *m);
  }
  const MaterialLookup material(reader, spec.materials);
  if (const std::optional<Field> room = root.find("room")) {
    spec.room = readRoom(reader, *room, material);
  }
  if (const std::optional<Field> sky = root.find("sky")) {
    spec.sky = readSky(reader, *sky);
    spec.skyWhere = sky->where;
  }
  if (const std::optional<Field> site = root.find("site")) spec.site = readSite(reader, *site);
  if (const std::optional<Field> sun = root.find("sun")) spec.sun = readSun(reader, *sun);
  spec.solids = readList<SolidSpec>(
      reader, root, "solids", [&](const Field& item) { return readSolid(reader, item, material); });
  spec.sources = readList<SourceSpec>(reader, root, "sources",
                                      [&](const Field& item) { return readSource(reader, item); });
  spec.luminaires = readList<LuminaireSpec>(
      reader, root, "luminaires", [&](const Field& item) { return readLuminaire(reader, item); });
  spec.grids = readList<GridSpec>(reader, root, "grids",
                                  [&](const Field& item) { return readGrid(reader, item); });
  spec.views = readList<ViewSpec>(reader, root, "views",
                                  [&](const Field& item) { return readView(reader, item); });
  spec.observers = readList<ObserverSpec>(
      reader, root, "observers", [&](const Field& item) { return readObserver(reader, item); });
  return spec;
}

}  // namespace penumbra::scenefile
