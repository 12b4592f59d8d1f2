#include "scene/view_reader.hpp"

#include <cmath>
#include <numbers>

#include "geometry/tolerance.hpp"

namespace penumbra::scenefile {
namespace {

int readPixels(const Reader& reader, const Field& field, const YAML::Node& node, int index) {
  const Field side{node, Where{field.where.line, indexKey(field.where.key, index)}};
  const double value = reader.positive(side, "pixels");
  if (value != std::floor(value) || value > kMaxViewSide) {
    reader.fail(side.where, "an image side is a whole number of pixels from 1 to " +
                                std::to_string(kMaxViewSide) + ", got " + formatNumber(value));
  }
  return static_cast<int>(value);
}

}  // namespace

ViewSpec readView(const Reader& reader, const Field& field) {
  const MapView map = reader.map(field, "a view");
  map.allowOnly({"name", "eye", "target", "up", "fov", "size"}, "a view");
  ViewSpec spec;
  spec.where = field.where;
  View& view = spec;
  view.name = reader.text(map.require("name"));
  const Field eye = map.require("eye");
  spec.eyeWhere = eye.where;
  view.eye = reader.vec3(eye);
  const Field target = map.require("target");
  view.target = reader.vec3(target);
  const Vec3 sight = view.target - view.eye;
  if (sight.norm() <= Tolerance::kRelativeInput * std::max(view.eye.norm(), 1.0)) {
    reader.fail(target.where,
                "the target must differ from the eye (both are " + formatVec3(view.eye) + " m)");
  }
  if (const std::optional<Field> up = map.find("up")) {
    view.up = reader.direction(*up);
    // sin of the angle between up and the line of sight: a camera cannot roll about its own axis.
    if (view.up.cross(sight.normalized()).norm() < Tolerance::kInputAngle) {
      reader.fail(up->where, "'up' " + formatVec3(view.up) +
                                 " lies along the line of sight; give a direction across it "
                                 "(the default is [0, 0, 1])");
    }
  } else if (view.up.cross(sight.normalized()).norm() < Tolerance::kInputAngle) {
    reader.fail(target.where,
                "the view looks straight up or down, so the default 'up' [0, 0, 1] "
                "lies along the line of sight; give 'up' (e.g. [0, 1, 0])");
  }
  if (const std::optional<Field> fov = map.find("fov")) {
    view.fovDegrees = reader.positive(*fov, "°");
    if (view.fovDegrees > 170.0) {
      reader.fail(fov->where,
                  "the horizontal field of view must be at most 170° (a pinhole "
                  "camera), got " +
                      formatNumber(view.fovDegrees) + "°");
    }
  }
  if (const std::optional<Field> size = map.find("size")) {
    if (!size->node.IsSequence() || size->node.size() != 2) {
      reader.fail(size->where, "expected the image size [width, height] in pixels");
    }
    view.width = readPixels(reader, *size, size->node[0], 0);
    view.height = readPixels(reader, *size, size->node[1], 1);
  }
  return spec;
}

}  // namespace penumbra::scenefile
