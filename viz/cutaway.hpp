#pragma once
// How the room is looked into for the surfaces view: from above one corner, with the ceiling and
// the two walls on the camera's side left out, choosing the corner that shows the most openings
// (the facade with its windows).
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace penumbra::viz {

struct Cutaway {
  Vec3 fromFocus = Vec3(-1, 1, 1).normalized();  // unit, from the focal point to the camera
  Vec3 lo = Vec3::Zero(), hi = Vec3::Ones();     // the box to frame, m
  std::vector<char> hidden;                      // per solid: left out of the view
  std::string note;  // what is left out, in words ("ceiling and walls x0, y1"); empty for none
};

Cutaway chooseCutaway(const Scene& scene);

}  // namespace penumbra::viz
