#include "radiosity/indirect_field.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <unordered_map>

#include "geometry/tolerance.hpp"
#include "radiosity/field_triangle.hpp"
#include "radiosity/radiosity_solver.hpp"
#include "timing/seconds_since.hpp"

namespace penumbra {

struct IndirectField::State {
  using Vec2 = Eigen::Vector2d;

  // One meshed face: its frame (2-D coordinates x·u, y·v about `origin`) and a uniform grid of
  // cells over its triangles' bounding box, each cell listing the fan triangles that touch it.
  struct FieldFace {
    int solid = -1, face = -1;
    Vec3 origin = Vec3::Zero(), u = Vec3::UnitX(), v = Vec3::UnitY(), normal = Vec3::UnitZ();
    Vec2 low = Vec2::Zero();
    double cell = 1.0;
    int columns = 1, rows = 1;
    std::vector<std::vector<int>> cells;
    std::vector<int> roots;  // its fan triangles, while the grid is built
    // The edges of the face's elements that no other element of the face lies beyond.
    std::vector<std::array<Vec2, 2>> boundary;

    Vec2 local(const Vec3& p) const { return Vec2((p - origin).dot(u), (p - origin).dot(v)); }
  };

  struct FieldNode {
    SamplePoint at;  // where it is gathered
    bool gathered = false;
  };

  using TriangleState = FieldTriangleState;
  using TreeLink = FieldTreeLink;

  struct NodeKey {
    int face;
    int64_t x, y;
    bool operator==(const NodeKey&) const = default;
  };

  struct NodeKeyHash {
    std::size_t operator()(const NodeKey& k) const {
      uint64_t h = static_cast<uint64_t>(k.face) * 0x9E3779B97F4A7C15ull;
      h ^= static_cast<uint64_t>(k.x) + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
      h ^= static_cast<uint64_t>(k.y) + 0x94D049BB133111EBull + (h << 6) + (h >> 2);
      return static_cast<std::size_t>(h);
    }
  };

  static double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

  const SurfaceMesh* mesh;
  FieldGather gather;
  FieldOptions options;
  double quantum;  // m: node positions closer than this are one node
  double nudge;    // m: how far inside a boundary node is gathered
  std::vector<FieldFace> faces;
  std::map<std::pair<int, int>, int> faceIndex;  // (solid, face) → faces
  std::vector<FieldTriangle> triangles;
  std::vector<TreeLink> tree;  // one per triangle
  std::vector<FieldNode> nodes;
  // Each node's interreflected light, lx per channel (zero until gathered), apart from the
  // nodes: the interpolation at every pixel reads 24 bytes of a node instead of the whole node.
  std::vector<Eigen::Vector3d> nodeLight;
  std::vector<FieldKeptTriangle> kept;  // the kept triangles' interpolants (TreeLink::children)
  std::unordered_map<NodeKey, int, NodeKeyHash> nodeAt;
  IndirectFieldStats stats;
  // A point's solid and the bits of its coordinates.
  struct PointKey {
    int solid;
    std::array<uint64_t, 3> bits;
    bool operator==(const PointKey&) const = default;
  };
  struct PointKeyHash {
    std::size_t operator()(const PointKey& k) const {
      uint64_t h = static_cast<uint64_t>(k.solid) * 0x9E3779B97F4A7C15ull;
      for (uint64_t b : k.bits) h ^= b + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
      return static_cast<std::size_t>(h);
    }
  };
  static PointKey pointKey(const SamplePoint& p) {
    return PointKey{
        p.solid,
        {std::bit_cast<uint64_t>(p.position.x()), std::bit_cast<uint64_t>(p.position.y()),
         std::bit_cast<uint64_t>(p.position.z())}};
  }
  std::unordered_map<PointKey, Eigen::Vector3d, PointKeyHash> gatheredPoints;

  // `insideSolid` is asked only here, while the boundary edges are found.
  State(const SurfaceMesh& m, double sceneSize, FieldGather g, FieldOptions o,
        const InsideSolid& insideSolid)
      : mesh(&m),
        gather(std::move(g)),
        options(o),
        quantum(Tolerance::kRelativeInput * std::max(sceneSize, 1.0)),
        nudge(kNudgeInKernelTolerances * Tolerance::kernelLength(sceneSize)) {
    for (const SurfaceElement& element : mesh->elements) addElement(element);
    std::vector<std::vector<int>> roots;
    for (FieldFace& face : faces) {
      roots.push_back(face.roots);
      buildGrid(face);
    }
    if (options.boundaryBand > 0.0) {
      for (const SurfaceElement& element : mesh->elements) findBoundary(element, insideSolid);
      for (std::size_t f = 0; f < faces.size(); ++f)
        for (int t : roots[f]) listNearBoundary(static_cast<int>(f), t);
    }
  }

  FieldFace& faceOf(const SurfaceElement& element) {
    const auto [it, added] =
        faceIndex.emplace(std::pair{element.solid, element.face}, static_cast<int>(faces.size()));
    if (added) {
      FieldFace f;
      f.solid = element.solid;
      f.face = element.face;
      const std::vector<Vec3>& v = element.polygon.vertices();
      f.normal = element.polygon.normal();
      f.origin = v[0];
      f.u = (v[1] - v[0]).normalized();
      f.v = f.normal.cross(f.u).normalized();
      faces.push_back(f);
    }
    return faces[it->second];
  }

  // The element's fan triangles from its first vertex; triangles of no area are left out.
  void addElement(const SurfaceElement& element) {
    if (element.polygon.empty()) return;
    FieldFace& face = faceOf(element);
    const int faceId = static_cast<int>(&face - faces.data());
    std::vector<Vec2> p;
    for (const Vec3& x : element.polygon.vertices()) p.push_back(face.local(x));
    for (std::size_t i = 1; i + 1 < p.size(); ++i) {
      const double twiceArea = cross2(p[i] - p[0], p[i + 1] - p[0]);
      const double longest =
          std::max({(p[i] - p[0]).norm(), (p[i + 1] - p[i]).norm(), (p[0] - p[i + 1]).norm()});
      if (twiceArea <= quantum * longest) continue;
      face.roots.push_back(addTriangle(faceId, {p[0], p[i], p[i + 1]}, 0));
    }
  }

  int node(int faceId, const Vec2& x) {
    const NodeKey key{faceId, std::llround(x.x() / quantum), std::llround(x.y() / quantum)};
    const auto [it, added] = nodeAt.emplace(key, static_cast<int>(nodes.size()));
    if (added) {
      const FieldFace& f = faces[faceId];
      FieldNode n;
      n.at.position = f.origin + x.x() * f.u + x.y() * f.v + inward(faceId, x);
      n.at.normal = f.normal;
      n.at.solid = f.solid;
      nodes.push_back(n);
      nodeLight.push_back(Eigen::Vector3d::Zero());
    }
    return it->second;
  }

  int addTriangle(int faceId, const std::array<Vec2, 3>& corner, int depth) {
    FieldTriangle t;
    t.corner = corner;
    t.face = faceId;
    t.depth = depth;
    Eigen::Matrix2d edges;
    edges.col(0) = corner[1] - corner[0];
    edges.col(1) = corner[2] - corner[0];
    t.toBarycentric = edges.inverse();
    const std::array<Vec2, 6> at{corner[0],
                                 corner[1],
                                 corner[2],
                                 0.5 * (corner[0] + corner[1]),
                                 0.5 * (corner[1] + corner[2]),
                                 0.5 * (corner[2] + corner[0])};
    // Nodes are made once the triangles exist: node() probes the face's triangles.
    for (int k = 0; k < 6; ++k) t.node[k] = -1;
    triangles.push_back(t);
    tree.emplace_back();
    pendingNodes.push_back({static_cast<int>(triangles.size()) - 1, at});
    return static_cast<int>(triangles.size()) - 1;
  }

  // Nodes of triangles made before their face's grid existed, placed after it.
  struct PendingNodes {
    int triangle;
    std::array<Vec2, 6> at;
  };
  std::vector<PendingNodes> pendingNodes;

  void placePendingNodes() {
    for (const PendingNodes& p : pendingNodes)
      for (int k = 0; k < 6; ++k)
        triangles[p.triangle].node[k] = node(triangles[p.triangle].face, p.at[k]);
    pendingNodes.clear();
  }

  void buildGrid(FieldFace& face) {
    Vec2 low(INFINITY, INFINITY), high(-INFINITY, -INFINITY);
    double longest = 0.0;
    for (int t : face.roots)
      for (const Vec2& c : triangles[t].corner) {
        low = low.cwiseMin(c);
        high = high.cwiseMax(c);
      }
    for (int t : face.roots) {
      const auto& c = triangles[t].corner;
      longest =
          std::max({longest, (c[1] - c[0]).norm(), (c[2] - c[1]).norm(), (c[0] - c[2]).norm()});
    }
    face.low = low;
    face.cell = std::max(0.5 * longest, quantum);
    face.columns = std::max(1, static_cast<int>(std::ceil((high.x() - low.x()) / face.cell)));
    face.rows = std::max(1, static_cast<int>(std::ceil((high.y() - low.y()) / face.cell)));
    face.cells.assign(static_cast<std::size_t>(face.columns) * face.rows, {});
    for (int t : face.roots) {
      Vec2 a(INFINITY, INFINITY), b(-INFINITY, -INFINITY);
      for (const Vec2& c : triangles[t].corner) {
        a = a.cwiseMin(c);
        b = b.cwiseMax(c);
      }
      const auto [c0, r0] = cellOf(face, a);
      const auto [c1, r1] = cellOf(face, b);
      for (int r = r0; r <= r1; ++r)
        for (int c = c0; c <= c1; ++c)
          face.cells[static_cast<std::size_t>(r) * face.columns + c].push_back(t);
    }
    face.roots.clear();
  }

  std::pair<int, int> cellOf(const FieldFace& face, const Vec2& x) const {
    const int c = static_cast<int>(std::floor((x.x() - face.low.x()) / face.cell));
    const int r = static_cast<int>(std::floor((x.y() - face.low.y()) / face.cell));
    return {std::clamp(c, 0, face.columns - 1), std::clamp(r, 0, face.rows - 1)};
  }

  // The fan triangle of `faceId` that holds x, or the one x lies least outside of; with how far
  // outside (barycentric, 0 inside). -1 when the face has none near.
  int root(int faceId, const Vec2& x, double& outside) const {
    const FieldFace& face = faces[faceId];
    const auto [c, r] = cellOf(face, x);
    int best = -1;
    outside = INFINITY;
    for (int t : face.cells[static_cast<std::size_t>(r) * face.columns + c]) {
      const double miss = std::max(0.0, -triangles[t].barycentric(x).minCoeff());
      if (miss < outside) {
        outside = miss;
        best = t;
        if (miss == 0.0) break;
      }
    }
    return best;
  }

  // How far to move a node at x so that it is gathered inside its face's elements: probes in
  // eight directions at the nudge distance; the move is away from those that leave every
  // element (none inside).
  Vec3 inward(int faceId, const Vec2& x) const {
    Vec2 away = Vec2::Zero();
    for (int k = 0; k < 8; ++k) {
      const double angle = k * std::numbers::pi / 4;
      const Vec2 d(std::cos(angle), std::sin(angle));
      double outside = 0.0;
      if (root(faceId, x + nudge * d, outside) < 0 || outside > 1e-9) away -= d;
    }
    if (away.norm() == 0.0) return Vec3::Zero();
    away *= nudge / away.norm();
    const FieldFace& f = faces[faceId];
    return away.x() * f.u + away.y() * f.v;
  }

  static double distanceToSegment(const Vec2& x, const std::array<Vec2, 2>& segment) {
    const Vec2 d = segment[1] - segment[0];
    const double length2 = d.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp((x - segment[0]).dot(d) / length2, 0.0, 1.0) : 0.0;
    return (x - (segment[0] + t * d)).norm();
  }

  // The element's edges on its face's boundary: probes a nudge outside the edge at a quarter,
  // a half and three quarters of it, any of which lies on no element of the face (an edge partly
  // on the boundary counts whole, which only gathers more points exactly). With `insideSolid`
  // (empty: every boundary edge counts), only the concave ones: a probe moved a nudge off the
  // face's plane, into the room, lies in a solid that stands on the face there.
  void findBoundary(const SurfaceElement& element, const InsideSolid& insideSolid) {
    if (element.polygon.empty()) return;
    const auto it = faceIndex.find({element.solid, element.face});
    if (it == faceIndex.end()) return;
    FieldFace& face = faces[it->second];
    std::vector<Vec2> p;
    for (const Vec3& x : element.polygon.vertices()) p.push_back(face.local(x));
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec2 a = p[i], b = p[(i + 1) % p.size()];
      const Vec2 along = b - a;
      if (along.norm() <= quantum) continue;
      const Vec2 out = Vec2(along.y(), -along.x()).normalized();  // counter-clockwise polygon
      bool onBoundary = false, concave = !insideSolid;
      for (double at : {0.25, 0.5, 0.75}) {
        const Vec2 probe = a + at * along + nudge * out;
        double outside = 0.0;
        if (root(it->second, probe, outside) < 0 || outside > 1e-9) {
          onBoundary = true;
          concave = concave || insideSolid(face.origin + probe.x() * face.u + probe.y() * face.v +
                                           nudge * face.normal);
        }
      }
      if (onBoundary && concave) face.boundary.push_back({a, b});
    }
  }

  // The boundary edges within the band of fan triangle t: those within the band of the ball
  // round its corners.
  void listNearBoundary(int faceId, int t) {
    FieldTriangle& tri = triangles[t];
    const Vec2 centre = (tri.corner[0] + tri.corner[1] + tri.corner[2]) / 3.0;
    double radius = 0.0;
    for (const Vec2& c : tri.corner) radius = std::max(radius, (c - centre).norm());
    const std::vector<std::array<Vec2, 2>>& boundary = faces[faceId].boundary;
    for (std::size_t k = 0; k < boundary.size(); ++k)
      if (distanceToSegment(centre, boundary[k]) <= radius + options.boundaryBand)
        tri.nearBoundary.push_back(static_cast<int>(k));
  }

  // Whether x, in fan triangle t, lies within FieldOptions::boundaryBand of its face's boundary.
  bool nearBoundary(int t, const Vec2& x) const {
    const FieldTriangle& tri = triangles[t];
    for (int k : tri.nearBoundary)
      if (distanceToSegment(x, faces[tri.face].boundary[static_cast<std::size_t>(k)]) <
          options.boundaryBand)
        return true;
    return false;
  }

  // Gathers every node of the open triangles in `open` that is not gathered yet.
  void gatherNodes(const std::vector<int>& open) {
    std::vector<int> wanted;
    for (int t : open)
      for (int n : triangles[t].node)
        if (!nodes[n].gathered) {
          nodes[n].gathered = true;
          wanted.push_back(n);
        }
    if (wanted.empty()) return;
    std::vector<SamplePoint> points;
    for (int n : wanted) points.push_back(nodes[n].at);
    const std::vector<Eigen::Vector3d> indirect = gather(points);
    for (std::size_t k = 0; k < wanted.size(); ++k) {
      nodeLight[wanted[k]] = indirect[k];
    }
    stats.nodes += wanted.size();
  }

  // Keeps the triangle or cuts it in four (its nodes gathered).
  void decide(int t) {
    ++stats.triangles;
    FieldTriangle& tri = triangles[t];
    // Relative to the interreflected E at the midpoint, which no pixel's total E is below,
    // whatever direct shadow crosses the triangle.
    double worst = 0.0;
    for (int side = 0; side < 3; ++side) {
      const Eigen::Vector3d& m = nodeLight[tri.node[3 + side]];
      const Eigen::Vector3d line =
          0.5 * (nodeLight[tri.node[side]] + nodeLight[tri.node[(side + 1) % 3]]);
      const double miss = (m - line).cwiseAbs().maxCoeff();
      if (miss > 0.0) worst = std::max(worst, miss / std::max(photometric(m), 1e-300));
    }
    if (worst <= options.tolerance && tri.depth >= options.minDepth) {
      FieldKeptTriangle k{tri.toBarycentric, tri.corner[0], {}};
      for (int n = 0; n < 6; ++n) k.light[n] = nodeLight[tri.node[n]];
      tree[t].children = static_cast<int>(kept.size());
      tree[t].state = TriangleState::Kept;
      kept.push_back(k);
      return;
    }
    if (tri.depth >= options.maxDepth) {
      tree[t].state = TriangleState::Exact;
      return;
    }
    const std::array<Vec2, 3> c = tri.corner;
    const Vec2 ab = 0.5 * (c[0] + c[1]), bc = 0.5 * (c[1] + c[2]), ca = 0.5 * (c[2] + c[0]);
    const int face = tri.face, depth = tri.depth + 1;
    const int first = addTriangle(face, {c[0], ab, ca}, depth);
    addTriangle(face, {ab, c[1], bc}, depth);
    addTriangle(face, {ca, bc, c[2]}, depth);
    addTriangle(face, {ab, bc, ca}, depth);
    placePendingNodes();
    tree[t].children = first;
    tree[t].state = TriangleState::Cut;
  }

  // x's barycentric coordinates in triangle t, from its kept interpolant where it has one.
  Eigen::Vector3d barycentric(int t, const Vec2& x) const {
    return tree[t].state == TriangleState::Kept
               ? kept[static_cast<std::size_t>(tree[t].children)].barycentric(x)
               : triangles[t].barycentric(x);
  }

  // The kept or open triangle below `t` that holds x.
  int descend(int t, const Vec2& x) const {
    if (tree[t].state != TriangleState::Cut) return t;
    Eigen::Vector3d l = triangles[t].barycentric(x);
    while (tree[t].state == TriangleState::Cut) {
      const int q = quarterAt(l);
      l = inQuarter(l, q);
      t = tree[t].children + q;
    }
    return t;
  }

  // Where a run of points lies: neighbouring points mostly share a face, a fan triangle and a
  // leaf below it, so each point first tries the last one's.
  struct Cursor {
    int solid = -2, faceOfSolid = -2, face = -1;
    int root = -1, leaf = -1;
  };

  // How far inside the cursor's leaf (barycentric) a point must lie to take it without the
  // descent: far above the rounding of the descent's own barycentric tests, so that the leaf is
  // the one the descent would reach.
  static constexpr double kInsideLeaf = 1e-9;

  // The leaf (kept, open or exact) below the fan triangle a point lies in, with its face-frame
  // position into `local`; -1 where it is gathered exactly (on no element, outside every
  // triangle, or in the band). The cursor's fan triangle is taken where it holds the point
  // strictly inside (on an edge the search decides, so that a point's triangle does not depend
  // on the order or the company of the points).
  int locate(const FacePoint& p, Vec2& local, Cursor& cursor) const {
    if (p.solid != cursor.solid || p.face != cursor.faceOfSolid) {
      const auto it = faceIndex.find({p.solid, p.face});
      cursor = Cursor{p.solid, p.face, it == faceIndex.end() ? -1 : it->second};
    }
    if (cursor.face < 0) return -1;
    local = faces[cursor.face].local(p.position);
    if (cursor.leaf >= 0 && barycentric(cursor.leaf, local).minCoeff() > kInsideLeaf)
      return nearBoundary(cursor.root, local) ? -1 : cursor.leaf;
    double outside = INFINITY;
    int t = -1;
    if (cursor.root >= 0 && triangles[cursor.root].barycentric(local).minCoeff() > 0.0) {
      t = cursor.root;
      outside = 0.0;
    } else {
      t = root(cursor.face, local, outside);
    }
    cursor.root = t;
    cursor.leaf = -1;
    const double reach = 1e-6;  // barycentric: how far outside its triangle a point may lie
    if (t < 0 || outside > reach || nearBoundary(t, local)) return -1;
    cursor.leaf = descend(t, local);
    return cursor.leaf;
  }

  // Runs body(range) over the point indices in parallel chunks; the field is only read meanwhile.
  template <typename Body>
  static void forEachPoint(std::size_t count, const Body& body) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, kPointsPerTask),
                      [&](const tbb::blocked_range<std::size_t>& range) { body(range); });
  }
  static constexpr std::size_t kPointsPerTask = 4096;

  // The field's value at x on kept triangle t, per channel.
  void interpolate(int t, const Vec2& x, float* channels) const {
    const FieldKeptTriangle& tri = kept[static_cast<std::size_t>(tree[t].children)];
    const std::array<double, 6> w = quadraticWeights(tri.barycentric(x));
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    for (int k = 0; k < 6; ++k) e += w[k] * tri.light[k];
    for (int c = 0; c < 3; ++c) channels[c] = static_cast<float>(e[c]);
  }

  void evaluate(std::span<const FacePoint> points, std::span<float> channels) {
    const auto start = Clock::now();
    const std::size_t count = points.size();
    constexpr int kGatherExactly = -1, kDone = -2;
    // Per point: the open triangle it waits for, kDone once interpolated, or kGatherExactly.
    std::vector<int> leaf(count, kGatherExactly);
    std::vector<Vec2> local(count);
    // Every point on a kept triangle is interpolated in this first pass; the points that reach
    // an open one wait for the rounds below.
    tbb::enumerable_thread_specific<std::vector<std::size_t>> waitingParts;
    forEachPoint(count, [&](const tbb::blocked_range<std::size_t>& range) {
      Cursor cursor;
      std::vector<std::size_t>& waiting = waitingParts.local();
      for (std::size_t i = range.begin(); i < range.end(); ++i) {
        leaf[i] = locate(points[i], local[i], cursor);
        if (leaf[i] < 0) continue;
        if (tree[leaf[i]].state == TriangleState::Kept) {
          interpolate(leaf[i], local[i], &channels[i * 3]);
          leaf[i] = kDone;
        } else if (tree[leaf[i]].state == TriangleState::Exact) {
          leaf[i] = kGatherExactly;
        } else {
          waiting.push_back(i);
        }
      }
    });
    std::vector<std::size_t> waiting;
    for (const std::vector<std::size_t>& part : waitingParts)
      waiting.insert(waiting.end(), part.begin(), part.end());
    std::sort(waiting.begin(), waiting.end());
    // Rounds: gather the open triangles the waiting points reach, decide them, descend again.
    // Only the rounds change the field.
    while (!waiting.empty()) {
      std::vector<int> open;
      for (std::size_t i : waiting) {
        leaf[i] = descend(leaf[i], local[i]);
        if (tree[leaf[i]].state == TriangleState::Open) open.push_back(leaf[i]);
      }
      std::sort(open.begin(), open.end());
      open.erase(std::unique(open.begin(), open.end()), open.end());
      if (open.empty()) break;
      gatherNodes(open);
      for (int t : open) decide(t);
    }
    for (std::size_t i : waiting) {
      if (tree[leaf[i]].state == TriangleState::Exact) {
        leaf[i] = kGatherExactly;
        continue;
      }
      interpolate(leaf[i], local[i], &channels[i * 3]);
      leaf[i] = kDone;
    }
    std::vector<SamplePoint> exact;
    std::vector<std::size_t> exactAt;
    for (std::size_t i = 0; i < count; ++i) {
      if (leaf[i] != kGatherExactly) continue;
      const FacePoint& p = points[i];
      const auto it = faceIndex.find({p.solid, p.face});
      exactAt.push_back(i);
      exact.push_back(SamplePoint{
          p.position, it == faceIndex.end() ? Vec3::UnitZ() : faces[it->second].normal, p.solid});
    }
    // Points gathered one by one are kept by their exact position: the renders of one view
    // (another interval, the AOV and the image) ask for the same points again.
    std::vector<SamplePoint> missing;
    std::vector<PointKey> missingKey;
    for (std::size_t k = 0; k < exact.size(); ++k) {
      const PointKey key = pointKey(exact[k]);
      if (!gatheredPoints.contains(key) && (missingKey.empty() || !(missingKey.back() == key))) {
        missing.push_back(exact[k]);
        missingKey.push_back(key);
      }
    }
    if (!missing.empty()) {
      const std::vector<Eigen::Vector3d> e = gather(missing);
      for (std::size_t k = 0; k < missing.size(); ++k) gatheredPoints[missingKey[k]] = e[k];
      stats.pointsGathered += missing.size();
    }
    for (std::size_t k = 0; k < exact.size(); ++k) {
      const Eigen::Vector3d& e = gatheredPoints.at(pointKey(exact[k]));
      for (int c = 0; c < 3; ++c) channels[exactAt[k] * 3 + c] = static_cast<float>(e[c]);
    }
    stats.seconds += secondsSince(start);
  }
};

IndirectField::IndirectField(const SurfaceMesh& mesh, double sceneSize, FieldGather gather,
                             FieldOptions options, const InsideSolid& insideSolid)
    : state_(std::make_unique<State>(mesh, sceneSize, std::move(gather), options, insideSolid)) {
  state_->placePendingNodes();
}

IndirectField::~IndirectField() = default;

void IndirectField::evaluate(std::span<const FacePoint> points, std::span<float> channels) {
  state_->evaluate(points, channels);
}

const IndirectFieldStats& IndirectField::stats() const {
  return state_->stats;
}

}  // namespace penumbra
