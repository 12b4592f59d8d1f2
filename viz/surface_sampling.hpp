#pragma once
// Sample points on every face of every solid, for the false-colour view of the room: each face
// is covered by a lattice of cells at most `spacing` wide, cut to the face's outline, and E is
// computed at the cells' corners.
#include <vector>

#include "geometry/sample_point.hpp"
#include "scene/scene.hpp"

namespace penumbra::viz {

struct SurfaceMesh {
  std::vector<SamplePoint> points;      // outward normal; `solid` is the face's solid
  std::vector<std::vector<int>> cells;  // convex, counter-clockwise seen from outside
  std::vector<int> cellSolid;           // index into Scene::solids
  std::vector<int> cellFace;            // index into that solid's faces
};

// A round spacing (1-2-5 series) of about 1/75 of the scene's size: 0.1 m for a 6 × 4 × 3 m
// office, 1 m for a 60 m hall.
double autoSurfaceSpacing(const Scene& scene);

// Points on a face are its own (two faces meeting at an edge each have points there, with their
// own normals). Throws std::invalid_argument for spacing <= 0.
SurfaceMesh sampleSurfaces(const Scene& scene, double spacing);

}  // namespace penumbra::viz
