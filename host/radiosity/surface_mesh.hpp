#pragma once
// The surfaces that exchange light, cut into elements: every face of every solid with a material
// that light from a source can reach (directly or after reflections), minus the parts other
// solids cover, cut into convex elements no larger than the element size. Faces without a
// material are black: they absorb and get no elements.
#include <cstddef>
#include <string>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "geometry/sample_point.hpp"
#include "scene/scene.hpp"

namespace penumbra {

struct MeshOptions {
  // The longest side of an element, m. Elements are the pieces over which the reflected
  // luminance is taken as uniform; the work plane's indirect E converges as it shrinks
  // (docs/method.md, "Interreflection").
  double elementSize = 0.5;
  // Quadrature nodes per axis of an element (elementQuadrature): the transfer to an element is
  // the average of the exact point transfer over these nodes.
  int quadratureOrder = 4;
  // Elements where the direct light is uneven are cut in four, up to `refinementLevels` times:
  // those whose (Emax - Emin)·area over their nodes, each source's E scaled to unit flux onto
  // the elements, exceeds `refinement` times the number of sources that light anything
  // (unevenElements in interreflection.cpp).
  double refinement = 1e-3;
  int refinementLevels = 3;
  // The most elements the dense transfer takes (8 bytes × N²: 0.5 GB at 8 000; the solver works
  // on products with it and holds no other N × N matrix).
  // Refinement stops splitting there (the most uneven elements go first); a mesh larger before
  // any refinement is solved by hierarchical links at kDefaultLinkError instead
  // (InterreflectionReport::denseElements).
  std::size_t maxElements = 8000;
  // The elements of a piece are grouped in square blocks of cells, at most this long (m), that
  // share their shadow casters in the dense transfer (elementSceneSharingCasters): the casters
  // are built per block, not per element (a room of hundreds of solids and thousands of
  // elements would hold millions of shadow volumes), and a block's volumes hold its elements'
  // (EmittingFaceShadows::casterOwner), so they only cull less tightly. 2 m: the size of the
  // hierarchical transfer's caster owners (HierarchyOptions::largestCasterOwner).
  double casterBlockSize = 2.0;
  // The transfer: 0 the dense element-to-element matrix; above 0 hierarchical links whose
  // estimated error is at most this (HierarchyOptions::linkError), with no element limit.
  static constexpr double kDefaultLinkError = 2e-4;
  // The dense transfer's final gather with each element's luminance linear across it
  // (luminance_slopes.hpp) instead of uniform at its mean: on an empty 4 × 3 × 3 m room the
  // work plane's total E comes within 8.6e-4 of the converged reference at 0.5 m elements
  // instead of 1.8e-3. Taken only where the kernel scene of the elements' cells, four per
  // element, stays small: elements × 4 × solids at most `linearGatherLimit` (the open office,
  // 4 944 elements and 240 solids, lies past it); beyond it, and with hierarchical links, each
  // element's luminance is uniform.
  bool linearGather = true;
  std::size_t linearGatherLimit = std::size_t{1} << 20;
  double linkError = 0.0;
};

struct SurfaceElement {
  ConvexPolygon polygon;  // counter-clockwise about the face's outward normal
  int solid = -1;         // index into Scene::solids
  int face = -1;          // face of that solid
  Vec3 reflectance = Vec3::Zero();
  double area = 0.0;     // m²
  int casterBlock = -1;  // index into SurfaceMesh::casterBlocks, -1 none
};

struct SurfaceMesh {
  std::vector<SurfaceElement> elements;
  // The quadrature nodes of every element as receiving points (on the element's solid, facing
  // out), element i's in [nodeStart[i], nodeStart[i + 1]); weights are area fractions.
  std::vector<SamplePoint> nodes;
  std::vector<double> weights;
  std::vector<std::size_t> nodeStart;
  // Convex polygons, each in the plane of a piece, that hold the elements naming them
  // (SurfaceElement::casterBlock; MeshOptions::casterBlockSize).
  std::vector<ConvexPolygon> casterBlocks;
  // Solids that light can reach but that have no material (black), by name: for a warning.
  std::vector<std::string> blackSolids;

  double area() const;  // m², all elements
};

// The parts of the faces light can reach (buildSurfaceMesh says which) that no other solid
// covers, as convex pieces with their face's solid, face and reflectance: what the mesh cuts into
// elements. Reached faces without a material are left out and their solids named in
// `blackSolids`.
using SurfacePiece = SurfaceElement;
std::vector<SurfacePiece> surfacePieces(const Scene& scene, std::vector<std::string>& blackSolids);

// Whether a solid's faces reflect light: it has a material of ρ > 0 in some channel. Faces that
// do not are black: they get no elements.
bool reflectsLight(const Scene& scene, const Solid& solid);

// The scene's solids, materials and room without its sources, grids or views: what the
// interreflection's kernel scenes start from before adding sources of their own.
Scene solidsOf(const Scene& scene);

// Whether polygons a and b can exchange light: each has a vertex more than `tolerance` in front
// of the other's plane.
bool canExchange(const ConvexPolygon& a, const ConvexPolygon& b, double tolerance);
// The same with each polygon's plane known (ConvexPolygon::plane), for callers that test one
// polygon against many.
struct PlanePolygon {
  const ConvexPolygon& polygon;
  const Plane& plane;
};
bool canExchange(const PlanePolygon& a, const PlanePolygon& b, double tolerance);

// Cuts a convex piece into cells of at most `size` along two axes of its plane (the first along
// its longest edge, so that rectangles give rectangles).
std::vector<ConvexPolygon> cutIntoCells(const ConvexPolygon& piece, double size, double tolerance);
double longestEdge(const ConvexPolygon& polygon);
// Cells of half the longest edge: a square becomes four, a long strip two.
std::vector<ConvexPolygon> halved(const ConvexPolygon& polygon, double tolerance);

// Places `order` quadrature nodes per axis on every element (nodes, weights, nodeStart).
void placeNodes(SurfaceMesh& mesh, int order);

// Faces A and B can exchange light only if each has part of the other strictly in front of it.
// Starting from the faces that can see a source or have a luminaire's photometric centre in
// front of them, every face that can see an already reached
// face with a material is reached too: a superset of the faces light can get to.
SurfaceMesh buildSurfaceMesh(const Scene& scene, const MeshOptions& options = {});

// The mesh with every element i where split[i] is set cut into cells of half its longest edge
// (a square into four), the others kept; nodes placed again with `order` per axis.
SurfaceMesh refineMesh(const SurfaceMesh& mesh, const std::vector<char>& split, int order,
                       double tolerance);

}  // namespace penumbra
