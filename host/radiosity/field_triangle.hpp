#pragma once
// One triangle of the interreflected light's field (radiosity/indirect_field.hpp) and its place
// in its fan triangle's tree: the barycentric map, the quadratic interpolation through its six
// nodes, and the quarters it is cut into at its midpoints.
#include <Eigen/Dense>
#include <array>
#include <cstdint>
#include <vector>

namespace penumbra {

enum class FieldTriangleState : uint8_t { Open, Kept, Cut, Exact };

// Where a triangle stands in its fan triangle's tree. The tree lies in an array of its own
// (8 bytes a triangle, a megabyte or two for a room) because the descent reads nothing else of
// the levels it passes: the triangles are a few pixels across at 1280 × 720, so a render
// descends every few pixels, and a level's whole triangle (a few cache lines, tens of MB in
// all) missed the cache at every step.
struct FieldTreeLink {
  // The first of four consecutive triangles once cut; once kept, its FieldKeptTriangle.
  int children = -1;
  FieldTriangleState state = FieldTriangleState::Open;
};

// (λ_a, λ_b, λ_c) of x in the face's frame, from a triangle's map and first corner.
inline Eigen::Vector3d barycentricIn(const Eigen::Matrix2d& toBarycentric,
                                     const Eigen::Vector2d& corner, const Eigen::Vector2d& x) {
  const Eigen::Vector2d l = toBarycentric * (x - corner);
  return Eigen::Vector3d(1.0 - l.x() - l.y(), l.x(), l.y());
}

// What a point's barycentric coordinates need (the map from the first corner, the corner)
// lies in the first cache line, the nodes the interpolation reads in the second.
struct alignas(64) FieldTriangle {
  Eigen::Matrix2d toBarycentric = Eigen::Matrix2d::Identity();
  std::array<Eigen::Vector2d, 3> corner;  // in the face's frame, counter-clockwise
  std::array<int, 6> node{};              // corners a, b, c, then the midpoints of ab, bc, ca
  int face = -1;
  int depth = 0;
  // A fan triangle's: the edges of its face's elements' boundary (FieldFace::boundary) that
  // come within FieldOptions::boundaryBand of it.
  std::vector<int> nearBoundary;

  // (λ_a, λ_b, λ_c) of a point in the face's frame.
  Eigen::Vector3d barycentric(const Eigen::Vector2d& x) const {
    return barycentricIn(toBarycentric, corner[0], x);
  }
};

// A kept triangle's interpolant in three cache lines of its own: the barycentric map and the light
// at its six nodes (FieldTriangle::node's order), copied when the triangle is kept. A point that
// lands on it reads nothing else: a render's exact samples in interval mode lie pixels apart and
// land on another triangle at almost every point, whose FieldTriangle and six scattered nodes
// were as many cache misses.
struct alignas(64) FieldKeptTriangle {
  Eigen::Matrix2d toBarycentric = Eigen::Matrix2d::Identity();
  Eigen::Vector2d corner = Eigen::Vector2d::Zero();  // the first corner, FieldTriangle's
  std::array<Eigen::Vector3d, 6> light{};            // lx per channel

  // As FieldTriangle::barycentric, to the last bit.
  Eigen::Vector3d barycentric(const Eigen::Vector2d& x) const {
    return barycentricIn(toBarycentric, corner, x);
  }
};

// The quadratic Lagrange weights of the six nodes at barycentric λ.
inline std::array<double, 6> quadraticWeights(const Eigen::Vector3d& l) {
  return {l[0] * (2 * l[0] - 1), l[1] * (2 * l[1] - 1), l[2] * (2 * l[2] - 1),
          4 * l[0] * l[1],       4 * l[1] * l[2],       4 * l[2] * l[0]};
}

// The child of a triangle cut at its midpoints that holds barycentric λ: the corner quarters
// 0, 1, 2 where that corner's λ is at least ½, the middle one (3) otherwise.
inline int quarterAt(const Eigen::Vector3d& l) {
  for (int k = 0; k < 3; ++k)
    if (l[k] >= 0.5) return k;
  return 3;
}

// Barycentric λ in quarter q (quarterAt) of the triangle where it is l: the corner quarter k
// (corners: k, and the midpoints of k's sides) has 2l − 1 at k and 2l elsewhere; the middle one
// (the midpoints of ab, bc, ca) has 1 − 2l_c, 1 − 2l_a, 1 − 2l_b. Exact but for the rounding of
// 1 − 2l, far below the descent's need (IndirectField's kInsideLeaf).
inline Eigen::Vector3d inQuarter(const Eigen::Vector3d& l, int q) {
  if (q == 3) return Eigen::Vector3d(1 - 2 * l[2], 1 - 2 * l[0], 1 - 2 * l[1]);
  Eigen::Vector3d child = 2 * l;
  child[q] -= 1;
  return child;
}

}  // namespace penumbra
