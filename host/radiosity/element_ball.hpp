#pragma once
// A polygon as the transfer's distance rules see it: the ball about its centroid through its
// farthest vertex.
#include <algorithm>

#include "geometry/convex_polygon.hpp"

namespace penumbra {

struct Ball {
  Vec3 centre = Vec3::Zero();
  double radius = 0.0;
};

inline Ball ballOf(const ConvexPolygon& polygon) {
  Ball ball{polygon.centroid(), 0.0};
  for (const Vec3& v : polygon.vertices())
    ball.radius = std::max(ball.radius, (v - ball.centre).norm());
  return ball;
}

// The distance between two balls' surfaces; 0 or less where they meet.
inline double ballGap(const Ball& a, const Ball& b) {
  return (a.centre - b.centre).norm() - a.radius - b.radius;
}

}  // namespace penumbra
