#pragma once
// Reads the shape of a solid or a source (box, prism, hull; for sources also polygon, rect and
// opening) from its YAML entry. Only numbers and their ranges are checked here; planarity,
// convexity and the like need the scene's tolerance and are checked in shape_builder.
#include <string_view>
#include <utility>
#include <vector>

#include "scene/scene_spec.hpp"
#include "scene/yaml_reader.hpp"

namespace penumbra::scenefile {

enum class ShapeUse { Solid, Source };

// Facets of a curved primitive when `facets` is not given, and the most it may ask for (a
// sphere of N bands has 2N² faces). The default is the measured choice of docs/primitives.md.
inline constexpr int kDefaultFacets = 16;
inline constexpr int kMaxFacets = 45;

// The one shape key present in `entry` (e.g. "box"); none or several is an error. `otherKeys`
// are the entry's keys besides the shape's (name, material, ...): with no shape, a key that is
// none of them (a misspelt `bx:`) is named in the error, at its line.
std::string_view shapeKeyOf(const Reader& reader, const MapView& entry, ShapeUse use,
                            std::string_view what, const std::vector<std::string_view>& otherKeys);

// Keys that go with the shape key, beside it in the same entry (a polygon's `normal`,
// an opening's `plane`).
std::vector<std::string_view> shapeSiblingKeys(std::string_view shapeKey);

// Reads the shape under `shapeKey` (and its sibling keys) from `entry`.
std::pair<ShapeSpec, Where> readShape(const Reader& reader, const MapView& entry,
                                      std::string_view shapeKey);

// Every point the shape mentions (for the scene's extent); rect corners; nothing for openings.
std::vector<Vec3> shapeExtentPoints(const ShapeSpec& shape);

}  // namespace penumbra::scenefile
