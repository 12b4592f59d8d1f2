#pragma once
// Builds a Luminaire from its spec: reads the photometric file (relative to the scene file), sets
// the intensity scale from the flux override and the maintenance factor, and places the
// instances of its array.
#include "scene/build_context.hpp"
#include "scene/luminaire.hpp"
#include "scene/scene_spec.hpp"

namespace penumbra::scenefile {

// A file that cannot be read or is malformed is a SceneError at the `file` key whose message is
// the photometric reader's own "file:line: field: message".
Luminaire buildLuminaire(const LuminaireSpec& spec, const BuildContext& context);

// The instances' names: `name` alone, or name[i,j] (1-based) in an array of more than one.
std::string instanceName(const std::string& name, int i, int j, bool array);

}  // namespace penumbra::scenefile
