// Loading a scene in two passes: read the YAML into a SceneSpec (keys, types, ranges, names),
// then build the geometry with tolerances relative to the scene's size (scene_spec.hpp says why).
#include "scene/scene_loader.hpp"

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>
#include <variant>

#include <yaml-cpp/yaml.h>

#include "geometry/tolerance.hpp"
#include "scene/grid_builder.hpp"
#include "scene/room_builder.hpp"
#include "scene/shape_builder.hpp"
#include "scene/shape_reader.hpp"
#include "scene/source_builder.hpp"
#include "scene/spec_reader.hpp"

namespace penumbra {
namespace {

using namespace scenefile;

// The diagonal of the bounding box of every coordinate in the spec: what Scene::size() will be,
// known before any geometry is built.
double specSize(const SceneSpec& spec) {
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 high = -low;
  const auto add = [&](const Vec3& p) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  };
  if (spec.room) {
    const double t = spec.room->wallThickness;
    add(Vec3::Constant(-t));
    add(spec.room->size + Vec3::Constant(t));
  }
  for (const SolidSpec& solid : spec.solids) {
    for (const Vec3& p : shapeExtentPoints(solid.shape)) add(p);
  }
  for (const SourceSpec& source : spec.sources) {
    for (const Vec3& p : shapeExtentPoints(source.shape)) add(p);
  }
  for (const GridSpec& grid : spec.grids) {
    if (const auto* rect = std::get_if<RectGridSpec>(&grid.layout)) {
      add(rect->origin);
      add(rect->origin + rect->u + rect->v);
    } else if (const auto* points = std::get_if<PointsSpec>(&grid.layout)) {
      for (const Vec3& p : points->positions) add(p);
    }  // a work plane lies inside the room
  }
  return (high.array() >= low.array()).all() ? (high - low).norm() : 0.0;
}

Scene buildScene(const SceneSpec& spec, const std::filesystem::path& file) {
  const BuildContext context{file, Tolerance::kRelativeInput * std::max(specSize(spec), 1.0)};
  Scene scene;
  scene.file = file;
  scene.materials = spec.materials;
  if (spec.room) {
    BuiltRoom built = buildRoom(*spec.room, context);
    scene.room = std::move(built.room);
    scene.solids = std::move(built.slabs);
  }
  for (const SolidSpec& solid : spec.solids) {
    scene.solids.push_back(
        Solid{solid.name, buildPolyhedron(solid.shape, solid.shapeWhere, context), solid.material});
  }
  for (const SourceSpec& source : spec.sources) {
    scene.sources.push_back(buildSource(source, scene.room, context));
  }
  for (const GridSpec& grid : spec.grids) {
    scene.grids.push_back(buildGrid(grid, scene.room, context));
  }
  return scene;
}

}  // namespace

Scene parseScene(const std::string& yamlText, const std::filesystem::path& file) {
  YAML::Node document;
  try {
    document = YAML::Load(yamlText);
  } catch (const YAML::Exception& e) {
    throw SceneError(file, e.mark.line + 1, "", "this is not valid YAML: " + e.msg);
  }
  const Reader reader(file);
  return buildScene(readSceneSpec(reader, document), file);
}

Scene loadScene(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in || std::filesystem::is_directory(file)) {
    throw SceneError(file, 0, "", "cannot read the scene file (does it exist?)");
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parseScene(text.str(), file);
}

}  // namespace penumbra
