// Loading a scene in two passes: read the YAML into a SceneSpec (keys, types, ranges, names),
// then build the geometry with tolerances relative to the scene's size (scene_spec.hpp says why).
#include "scene/scene_loader.hpp"

#include <algorithm>
#include <limits>
#include <variant>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "geometry/tolerance.hpp"
#include "scene/cie_general_sky.hpp"
#include "scene/eye_placement.hpp"
#include "scene/grid_builder.hpp"
#include "scene/grid_placement.hpp"
#include "scene/luminaire_builder.hpp"
#include "scene/observer_builder.hpp"
#include "scene/parameter_reader.hpp"
#include "scene/room_builder.hpp"
#include "scene/shape_builder.hpp"
#include "scene/shape_reader.hpp"
#include "scene/source_builder.hpp"
#include "scene/source_placement.hpp"
#include "scene/spec_reader.hpp"
#include "scene/strongest_source.hpp"
#include "scene/sun_reader.hpp"

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
  for (const LuminaireSpec& luminaire : spec.luminaires) {
    add(luminaire.position);
    add(luminaire.position + Vec3((luminaire.countX - 1) * luminaire.spacingX,
                                  (luminaire.countY - 1) * luminaire.spacingY, 0.0));
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

// A solid thinner than the kernels resolve where it lies would give wrong shadows at its
// boundary, silently: refuse it, naming the solid, its thickness, how far it lies from the
// scene's centre and what would do there (Tolerance::minimumThickness says why the limit).
void requireThickness(const Solid& solid, const Vec3& origin, const std::filesystem::path& file,
                      const Where& where) {
  const double thickness = solid.shape.thickness();
  double reach = 0.0;
  for (const Vec3& v : solid.shape.vertices())
    reach = std::max(reach, (v - origin).cwiseAbs().maxCoeff());
  const double minimum = Tolerance::minimumThickness(reach);
  if (thickness >= minimum) return;
  fail(file, where,
       fmt::format("solid '{}' is {:.3g} mm thick at its thinnest; it reaches {:.3g} m from the "
                   "centre of the scene's geometry, where the float kernels shade solids from "
                   "{:.3g} mm correctly: model it at {:.3g} mm or more, move the scene nearer "
                   "its centre, or leave it out",
                   solid.name, 1e3 * thickness, reach, 1e3 * minimum, 1e3 * minimum));
}

// Sources that light nothing and grids that can only give zeros load, with a warning each.
void addPlacementWarnings(const SceneSpec& spec, Scene& scene, double tolerance) {
  for (std::size_t i = 0; i < spec.sources.size(); ++i) {
    const Where& where = spec.sources[i].where;
    if (auto warning = unlitWarning(scene.sources[i], where, scene, tolerance))
      scene.warnings.push_back(std::move(*warning));
  }
  for (std::size_t i = 0; i < spec.grids.size(); ++i) {
    if (auto warning = misplacedGridWarning(scene.grids[i], spec.grids[i].where, scene, tolerance))
      scene.warnings.push_back(std::move(*warning));
  }
}

Scene buildScene(const SceneSpec& spec, const std::filesystem::path& file) {
  const double sceneSize = std::max(specSize(spec), 1.0);
  BuildContext context{file, Tolerance::kRelativeInput * sceneSize, {}};
  Scene scene;
  scene.file = file;
  scene.materials = spec.materials;
  if (spec.room) {
    BuiltRoom built = buildRoom(*spec.room, context);
    scene.room = std::move(built.room);
    scene.solids = std::move(built.slabs);
  }
  const std::size_t slabs = scene.solids.size();
  if (spec.sky) {
    if (!scene.room || scene.room->openings.empty())
      context.fail(spec.skyWhere,
                   "the sky lights the room through its openings, but the scene has "
                   "no 'room:' with 'openings:'");
    scene.sky = spec.sky;
  }
  scene.site = spec.site;
  if (spec.sun) scene.sun = placeSun(*spec.sun, spec.site, context);
  if (scene.sky && scene.sky->model == SkyModel::CieGeneral && !scene.sun &&
      dependsOnSun(cieSkyParameters(scene.sky->cieType)))
    context.fail(spec.skyWhere, "CIE sky type " + std::to_string(scene.sky->cieType) +
                                    " depends on the sun's position: add 'sun:' (and 'site:'); "
                                    "types 1, 3 and 5 do not");
  // Sources before solids: a curved solid orients its facets towards the strongest source.
  for (const SourceSpec& source : spec.sources) {
    scene.sources.push_back(buildSource(source, scene.room, context));
  }
  for (const LuminaireSpec& luminaire : spec.luminaires) {
    scene.luminaires.push_back(buildLuminaire(luminaire, context));
  }
  context.towardsLight = [&](const Vec3& point) {
    return towardsStrongestSource(scene.sources, point);
  };
  for (const SolidSpec& solid : spec.solids) {
    scene.solids.push_back(
        Solid{solid.name, buildPolyhedron(solid.shape, solid.shapeWhere, context), solid.material});
  }
  // Every solid, source and luminaire is built: the kernels' origin is known, and with it how
  // thin each solid may be where it lies (grids, built next, do not move it).
  const Vec3 origin = scene.kernelOrigin();
  for (std::size_t i = 0; i < scene.solids.size(); ++i)
    requireThickness(scene.solids[i], origin, file,
                     i < slabs ? spec.room->where : spec.solids[i - slabs].shapeWhere);
  for (const GridSpec& grid : spec.grids) {
    scene.grids.push_back(buildGrid(grid, scene.room, context));
  }
  for (std::size_t i = 0; i < spec.sources.size(); ++i) {
    requireSourceOutsideSolids(scene.sources[i], spec.sources[i].shapeWhere, scene.solids, context);
  }
  addPlacementWarnings(spec, scene, context.tolerance);
  for (const ViewSpec& view : spec.views) {
    requireEyeOutsideSolids(view.eye, fmt::format("view '{}'", view.name), view.eyeWhere,
                            scene.solids, context);
    scene.views.push_back(static_cast<const View&>(view));
  }
  for (const ObserverSpec& observer : spec.observers) {
    for (Observer& built : buildObservers(observer, scene.solids, context)) {
      scene.observers.push_back(std::move(built));
    }
  }
  return scene;
}

// `key` is `path` or lies below it ("sources[1]" holds "sources[1].flux", not "sources[10]").
bool isWithin(const std::string& key, const std::string& path) {
  return key.starts_with(path) &&
         (key.size() == path.size() || key[path.size()] == '.' || key[path.size()] == '[');
}

// A value that came from expressions is wrong (a window that no longer fits its wall): the message
// shows the expressions at or below the failing key, what they gave, and the parameters they used.
SceneError withExpressions(const SceneError& error, const Reader& reader) {
  if (error.key().empty() || error.file() != reader.file()) return error;
  std::string notes;
  ParameterValues used;
  for (const EvaluatedExpression& e : reader.evaluated()) {
    if (!isWithin(e.where.key, error.key()) && !isWithin(error.key(), e.where.key)) continue;
    notes += fmt::format("{}{} = ${{{}}} = {}", notes.empty() ? "" : "; ", e.where.key,
                         e.expression, e.value);
    for (const ParameterValue& p : reader.expressions()->used(e.expression)) {
      if (std::find(used.begin(), used.end(), p) == used.end()) used.push_back(p);
    }
  }
  if (notes.empty()) return error;
  if (!used.empty()) notes += "; with " + describeParameters(used);
  return SceneError(error.file(), error.line(), error.key(), error.message() + " (" + notes + ")");
}

}  // namespace

Scene parseScene(const std::string& yamlText, const std::filesystem::path& file,
                 const ParameterValues& parameters) {
  const YAML::Node document = parseYaml(yamlText, file);
  const Reader plain(file);
  const ParameterValues values =
      applyOverrides(plain, readDeclaredParameters(plain, document), parameters);
  ExpressionEvaluator expressions(values);
  const Reader reader(file, &expressions);
  try {
    Scene scene = buildScene(readSceneSpec(reader, document), file);
    scene.parameters = values;
    return scene;
  } catch (const SceneError& e) {
    throw withExpressions(e, reader);
  }
}

Scene loadScene(const std::filesystem::path& file, const ParameterValues& parameters) {
  return parseScene(readInputFile(file, "the scene file"), file, parameters);
}

ParameterValues loadSceneParameters(const std::filesystem::path& file) {
  const Reader plain(file);
  return readDeclaredParameters(plain, parseYaml(readInputFile(file, "the scene file"), file))
      .defaults;
}

}  // namespace penumbra
