#pragma once
// The `parameters:` section of a scene: names and default values, read before the rest of the
// document because every other section may use them in expressions (in any order).
#include <yaml-cpp/yaml.h>

#include "scene/parameters.hpp"
#include "scene/yaml_reader.hpp"

namespace penumbra::scenefile {

struct DeclaredParameters {
  ParameterValues defaults;  // declaration order
  Where where;               // the `parameters` key; line 0 when the scene has none
};

// Defaults are plain numbers. A document that is not a map gives none (readSceneSpec says why).
DeclaredParameters readDeclaredParameters(const Reader& reader, const YAML::Node& document);

// The defaults with `overrides` applied (by name). Overriding an undeclared name is an error at
// the `parameters` key that lists the declared ones.
ParameterValues applyOverrides(const Reader& reader, const DeclaredParameters& declared,
                               const ParameterValues& overrides);

}  // namespace penumbra::scenefile
