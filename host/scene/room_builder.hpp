#pragma once
// The `room:` shorthand → slabs (floor, ceiling, four walls) as convex boxes, with each wall cut
// around its openings, and the openings' polygons.
#include <vector>

#include "scene/build_context.hpp"
#include "scene/scene.hpp"
#include "scene/scene_spec.hpp"

namespace penumbra::scenefile {

struct BuiltRoom {
  Room room;
  std::vector<Solid> slabs;  // room.floor, room.ceiling, room.wall-x0[.1, .2, ...], ...
};

BuiltRoom buildRoom(const RoomSpec& spec, const BuildContext& context);

}  // namespace penumbra::scenefile
