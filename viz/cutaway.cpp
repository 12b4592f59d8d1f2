#include "viz/cutaway.hpp"

#include <fmt/format.h>

#include <array>
#include <limits>
#include <map>

namespace penumbra::viz {

namespace {

// Solids of the room whose names start with `prefix`: "room.wall-x0" and its pieces
// "room.wall-x0.1", … (docs/scene-format.md).
bool isRoomPart(const std::string& name, const std::string& prefix) {
  return name == prefix || name.starts_with(prefix + ".");
}

}  // namespace

Cutaway chooseCutaway(const Scene& scene) {
  Cutaway view;
  view.hidden.assign(scene.solids.size(), 0);
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  for (const Solid& s : scene.solids) {
    for (const Vec3& v : s.shape.vertices()) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
  }
  if (scene.solids.empty()) lo = hi = Vec3::Zero();
  view.lo = lo;
  view.hi = hi;
  if (!scene.room) return view;

  std::map<std::string, int> openings;
  for (const Opening& o : scene.room->openings) ++openings[o.wall];
  // Corners in order of preference when the openings do not decide: the first shows walls x1 and
  // y0, the usual facade of a plan drawn with the window at the bottom.
  constexpr std::array<std::array<int, 2>, 4> kCorners{{{-1, 1}, {1, 1}, {-1, -1}, {1, -1}}};
  std::array<int, 2> best = kCorners[0];
  int bestShown = -1;
  for (const auto& corner : kCorners) {
    // The camera on the +x side hides wall x1 and shows wall x0, and so on.
    const int shown = openings[corner[0] > 0 ? "x0" : "x1"] + openings[corner[1] > 0 ? "y0" : "y1"];
    if (shown > bestShown) {
      bestShown = shown;
      best = corner;
    }
  }
  const std::string hiddenX = best[0] > 0 ? "x1" : "x0";
  const std::string hiddenY = best[1] > 0 ? "y1" : "y0";
  for (std::size_t i = 0; i < scene.solids.size(); ++i) {
    const std::string& name = scene.solids[i].name;
    view.hidden[i] = isRoomPart(name, "room.ceiling") || isRoomPart(name, "room.wall-" + hiddenX) ||
                     isRoomPart(name, "room.wall-" + hiddenY);
  }
  view.note = fmt::format("ceiling and walls {}, {}", hiddenX, hiddenY);
  view.fromFocus = Vec3(best[0], best[1], 1.1).normalized();
  // Frame the interior and the slabs around it, not the hidden ones' far sides.
  const double t = scene.room->wallThickness;
  view.lo = Vec3(-t, -t, -t);
  view.hi = scene.room->size + Vec3(t, t, 0.0);
  return view;
}

}  // namespace penumbra::viz
