#pragma once
// First pass of loading: the YAML document → SceneSpec. Checks keys, types, units' ranges,
// names (unique, materials defined) and reads .pts files; builds no geometry.
#include <yaml-cpp/yaml.h>

#include "scene/scene_spec.hpp"
#include "scene/yaml_reader.hpp"

namespace penumbra::scenefile {

// The scene format version this reader understands (the `penumbra:` key).
inline constexpr int kFormatVersion = 1;

SceneSpec readSceneSpec(const Reader& reader, const YAML::Node& document);

}  // namespace penumbra::scenefile
