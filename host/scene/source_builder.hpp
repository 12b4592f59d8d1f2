#pragma once
// Builds a Source from its spec: emitting faces counter-clockwise about their emission direction
// and the luminance (given, or from the flux: L = Φ / (π·A)).
#include <optional>

#include "scene/build_context.hpp"
#include "scene/scene.hpp"
#include "scene/scene_spec.hpp"

namespace penumbra::scenefile {

// `room` is needed by `opening:` sources; it is empty when the scene has no room.
Source buildSource(const SourceSpec& spec, const std::optional<Room>& room,
                   const BuildContext& context);

// The rectangle of a `rect:` source. Width runs along the projection of +x onto its plane (of +y
// when the normal is parallel to x), height along normal × that; counter-clockwise about normal.
ConvexPolygon rectPolygon(const Vec3& center, double width, double height, const Vec3& normal);

}  // namespace penumbra::scenefile
