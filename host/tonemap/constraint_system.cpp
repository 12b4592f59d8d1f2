#include "tonemap/constraint_system.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace penumbra {
namespace {

// log Space-0 V at a pixel.
double logAt(const LogScene& scene, const RegionMap& regions, int x, int y) {
  return scene.logValue[regions.index(x, y)];
}

// A vertex of region `other` that lies on its edge with region `own`.
bool facesRegion(const RegionMap& regions, const MeshVertex& v, int32_t own) {
  const int x = v.x, y = v.y;
  return (x > 0 && regions.at(x - 1, y) == own) ||
         (x + 1 < regions.width && regions.at(x + 1, y) == own) ||
         (y > 0 && regions.at(x, y - 1) == own) ||
         (y + 1 < regions.height && regions.at(x, y + 1) == own);
}

// Thesis Fig. 4.5: vertex j (pixel p, region A) and its partner, the pixel q across the edge in
// region B. If q is a vertex: eq. 4.21. Otherwise q lies between two vertices k, l of B's side of
// the same edge, at β = |kq| / |kl|: eq. 4.22 when p is the brighter side, eq. 4.24 when q is.
void addEdgeRow(ConstraintRows& rows, int& threeVariableRows, const VertexMesh& mesh,
                const RegionMap& regions, const LogScene& scene, double weight, int j, int qx,
                int qy) {
  const MeshVertex& p = mesh.vertices[j];
  const double lp = logAt(scene, regions, p.x, p.y), lq = logAt(scene, regions, qx, qy);
  const int32_t regionB = regions.at(qx, qy);
  const int32_t direct = mesh.vertexAt[regions.index(qx, qy)];
  const auto twoVariable = [&](int k, double lk) {
    rows.add(ConstraintLevel::Strong, weight, {{j, 1.0}, {k, -1.0}}, scene.edgeTarget(lp - lk));
  };
  if (direct != VertexMesh::kNone) {
    // Both sides are vertices: the row is the same seen from either, so it is made once.
    if (regions.index(p.x, p.y) < regions.index(qx, qy)) twoVariable(direct, lq);
    return;
  }
  // B's vertices on this edge near q. Vertices lie at most `lattice` apart along a straight edge,
  // so the two that bracket q are within that distance of it.
  const int radius = mesh.lattice + 1;
  std::vector<int> candidates;
  for (int y = std::max(0, qy - radius); y <= std::min(regions.height - 1, qy + radius); ++y) {
    for (int x = std::max(0, qx - radius); x <= std::min(regions.width - 1, qx + radius); ++x) {
      const int32_t v = mesh.vertexAt[regions.index(x, y)];
      if (v != VertexMesh::kNone && mesh.vertices[v].region == regionB &&
          facesRegion(regions, mesh.vertices[v], p.region)) {
        candidates.push_back(v);
      }
    }
  }
  if (candidates.empty()) return;
  // The closest pair k, l with q between them (0 < β < 1) and at most a pixel off the line kl.
  int bestK = -1, bestL = -1;
  double bestLength = std::numeric_limits<double>::infinity(), bestBeta = 0;
  for (size_t a = 0; a < candidates.size(); ++a) {
    for (size_t c = a + 1; c < candidates.size(); ++c) {
      const MeshVertex& k = mesh.vertices[candidates[a]];
      const MeshVertex& l = mesh.vertices[candidates[c]];
      const double ex = l.x - k.x, ey = l.y - k.y, qxk = qx - k.x, qyk = qy - k.y;
      const double length2 = ex * ex + ey * ey;
      const double beta = (qxk * ex + qyk * ey) / length2;
      const double offLine = std::abs(qxk * ey - qyk * ex) / std::sqrt(length2);
      if (beta > 0 && beta < 1 && offLine <= 1.0 && length2 < bestLength) {
        bestLength = length2;
        bestK = candidates[a];
        bestL = candidates[c];
        bestBeta = beta;
      }
    }
  }
  if (bestK < 0) {
    // q lies beyond the last vertex of B's side (the end of an edge): the nearest one stands in.
    int nearest = candidates.front();
    double nearestDistance = std::numeric_limits<double>::infinity();
    for (int v : candidates) {
      const double d = std::hypot(mesh.vertices[v].x - qx, mesh.vertices[v].y - qy);
      if (d < nearestDistance) nearestDistance = d, nearest = v;
    }
    twoVariable(nearest, logAt(scene, regions, mesh.vertices[nearest].x, mesh.vertices[nearest].y));
    return;
  }
  ++threeVariableRows;
  // Eq. 4.22/4.24 in the log domain: q's value is interpolated between k and l.
  const double beta = bestBeta;
  rows.add(ConstraintLevel::Strong, weight, {{j, 1.0}, {bestK, -(1 - beta)}, {bestL, -beta}},
           scene.edgeTarget(lp - lq));
}

// Every pixel on the segment from a to b lies in the region: the two vertices see each other
// inside it, so a row between them never reaches across another face.
bool seesInside(const RegionMap& regions, const MeshVertex& a, const MeshVertex& b) {
  const int steps = std::max(std::abs(b.x - a.x), std::abs(b.y - a.y));
  for (int s = 1; s < steps; ++s) {
    const int x = a.x + static_cast<int>(std::lround(double(b.x - a.x) * s / steps));
    const int y = a.y + static_cast<int>(std::lround(double(b.y - a.y) * s / steps));
    if (regions.at(x, y) != a.region) return false;
  }
  return true;
}

// Neighbours of vertex i in its region: in each quarter-plane around it the nearest vertex of the
// region within one lattice spacing that it sees inside the region. On the interior lattice that
// is the 4-neighbourhood; near the boundary it links lattice and boundary vertices.
void addRegionNeighbours(std::vector<std::pair<int, int>>& pairs, const VertexMesh& mesh,
                         const RegionMap& regions, int i) {
  const MeshVertex& v = mesh.vertices[i];
  const int radius = mesh.lattice;
  int best[4] = {-1, -1, -1, -1};
  int bestDistance[4] = {0, 0, 0, 0};
  for (int y = std::max(0, v.y - radius); y <= std::min(regions.height - 1, v.y + radius); ++y) {
    for (int x = std::max(0, v.x - radius); x <= std::min(regions.width - 1, v.x + radius); ++x) {
      const int32_t u = mesh.vertexAt[regions.index(x, y)];
      if (u == VertexMesh::kNone || u == i || mesh.vertices[u].region != v.region) continue;
      const int dx = x - v.x, dy = y - v.y;
      const int quarter = (dx > 0 && dy >= 0) ? 0 : (dx <= 0 && dy > 0) ? 1 : (dx < 0) ? 2 : 3;
      const int distance = dx * dx + dy * dy;
      if (best[quarter] < 0 || distance < bestDistance[quarter]) {
        if (!seesInside(regions, v, mesh.vertices[u])) continue;
        best[quarter] = u;
        bestDistance[quarter] = distance;
      }
    }
  }
  for (int u : best) {
    if (u >= 0) pairs.emplace_back(std::min(i, u), std::max(i, u));
  }
}

}  // namespace

ConstraintSystem buildConstraintSystem(const VertexMesh& mesh, const RegionMap& regions,
                                       const LogScene& scene, const ConstraintWeights& weights) {
  const int n = static_cast<int>(mesh.vertices.size());
  ConstraintRows rows;
  ConstraintSystem system;

  // Strong: from every boundary vertex to each 4-neighbour pixel in another region.
  for (int j = 0; j < n; ++j) {
    const MeshVertex& p = mesh.vertices[j];
    if (!p.boundary) continue;
    const int offsets[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
    for (const auto& offset : offsets) {
      const int qx = p.x + offset[0], qy = p.y + offset[1];
      if (qx < 0 || qy < 0 || qx >= regions.width || qy >= regions.height) continue;
      const int32_t other = regions.at(qx, qy);
      if (other == p.region || other == RegionMap::kNone) continue;
      addEdgeRow(rows, system.threeVariableRows, mesh, regions, scene, weights.strong, j, qx, qy);
    }
  }

  // Medium: neighbouring vertices of one region, their attenuated Space-0 log ratio.
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < n; ++i) addRegionNeighbours(pairs, mesh, regions, i);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  for (const auto& [a, b] : pairs) {
    const MeshVertex& va = mesh.vertices[a];
    const MeshVertex& vb = mesh.vertices[b];
    rows.add(
        ConstraintLevel::Medium, weights.medium, {{a, 1.0}, {b, -1.0}},
        scene.insideTarget(logAt(scene, regions, va.x, va.y) - logAt(scene, regions, vb.x, vb.y),
                           std::hypot(va.x - vb.x, va.y - vb.y), regions.index(va.x, va.y),
                           regions.index(vb.x, vb.y)));
  }

  // Weak: every vertex near its Space-3 value, the exposure curve. Also the start of the solve
  // (thesis 5.4).
  system.start.resize(n);
  for (int i = 0; i < n; ++i) {
    const MeshVertex& v = mesh.vertices[i];
    system.start[i] = scene.exposedValue(regions.index(v.x, v.y));
    rows.add(ConstraintLevel::Weak, weights.weak, {{i, 1.0}}, system.start[i]);
  }

  rows.fill(system, n, scene.logLowerBound);
  return system;
}

void ConstraintRows::add(ConstraintLevel rowLevel, double rowWeight,
                         std::initializer_list<std::pair<int, double>> terms, double rhs) {
  const int row = static_cast<int>(target.size());
  for (const auto& [column, value] : terms) entries.emplace_back(row, column, rowWeight * value);
  target.push_back(rowWeight * rhs);
  level.push_back(rowLevel);
  weight.push_back(rowWeight);
}

void ConstraintRows::fill(ConstraintSystem& system, int variables, double logLowerBound) {
  const int m = static_cast<int>(target.size());
  system.matrix.resize(m, variables);
  system.matrix.setFromTriplets(entries.begin(), entries.end());
  system.target = Eigen::Map<const Eigen::VectorXd>(target.data(), m);
  system.lower = Eigen::VectorXd::Constant(variables, logLowerBound);
  system.upper = Eigen::VectorXd::Constant(variables, 0.0);
  system.level = std::move(level);
  system.weight = std::move(weight);
}

}  // namespace penumbra
