#pragma once
// Reads one entry of `grids:` (a work plane, a rectangle or a list of points, inline or from a
// Radiance .pts file next to the scene). The points of planar grids are laid out by grid_builder.
#include "scene/scene_spec.hpp"
#include "scene/yaml_reader.hpp"

namespace penumbra::scenefile {

GridSpec readGrid(const Reader& reader, const Field& field);

}  // namespace penumbra::scenefile
