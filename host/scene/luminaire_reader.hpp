#pragma once
// Reads one `luminaires:` entry (docs/scene-format.md): name, file, position, aim, array,
// flux_lm, maintenance_factor, model. Numbers may be "${expressions}" like any other key; the
// photometric file itself is read when the scene is built (luminaire_builder.hpp).
#include "scene/scene_spec.hpp"
#include "scene/yaml_reader.hpp"

namespace penumbra::scenefile {

LuminaireSpec readLuminaire(const Reader& reader, const Field& field);

}  // namespace penumbra::scenefile
