#pragma once
// `sun:` (docs/scene-format.md, "sun"): the date, the clock time and the direct normal
// illuminance of the sun; its position follows from the `site:` when the scene is built
// (placeSun).
#include "scene/build_context.hpp"
#include "scene/scene_spec.hpp"

namespace penumbra::scenefile {

// `sun: {date: YYYY-MM-DD, time: "HH:MM" or "HH:MM:SS", direct_normal_illuminance_lx: E_dn}`:
// a calendar date (the Gregorian calendar), a time of day in the site's standard time, E_dn > 0.
SunSpec readSun(const Reader& reader, const Field& field);

// The sun of `spec` at `site` (NOAA's solar position, north at site.northDegrees); a sun without
// a site is an error at the `sun:` key.
Sun placeSun(const SunSpec& spec, const std::optional<Site>& site, const BuildContext& context);

}  // namespace penumbra::scenefile
