#pragma once
// How a chart names a study parameter. A parameter carries its unit in its name, as the table's
// column headers do (docs/sweeps.md): `window_width_m` is in metres, `panel_flux_lm` in lumens.
// For people the name reads "window width [m]", in the "[unit]" form of every other label.
#include <string>
#include <string_view>

namespace penumbra {

// The unit a parameter name ends with ("_m" → "m", "_cdm2" → "cd/m²"), or "" when its last part
// is no unit penumbra knows (then the value is taken as unitless: a reflectance, a count).
std::string parameterUnit(std::string_view name);

// "window_width_m" → "window width [m]"; "floor_reflectance" → "floor reflectance".
std::string parameterLabel(std::string_view name);

}  // namespace penumbra
