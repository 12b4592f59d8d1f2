// The visible boundary of a source face (visible_boundary.hpp). Per point P and face F:
//
//  1. F' = F clipped by P's horizon plane, in 2-D coordinates (u, v) of F's plane with
//     e1 × e2 = F's emission normal, so that F' runs counter-clockwise and, seen from P, the
//     region lies on the left of its boundary.
//  2. Each solid's shadow on that plane: the part of the solid between the plane (moved towards
//     P by the scene tolerance: touching from behind does not block) and the plane through P
//     parallel to it, projected from P; a convex polygon, the 2-D hull of the projected
//     vertices. A segment from P to a point of F meets the solid exactly where it meets that
//     part. Near P's parallel plane projections run off to infinity, so the part is cut at a
//     depth fraction s_min; the points cut away lie closer to P than half its distance to the
//     solid, where no segment from P to F' can meet the solid.
//  3. The visible region V = F' minus the union of the shadows. Every polygon edge is split at
//     the ends of its overlaps with every other polygon; a piece bounds V when one side of it
//     (a point a hair off its midpoint) is in V and the other is not, and is then oriented with
//     V on its left. A piece lying on an earlier polygon's boundary is that polygon's to count
//     (coincident edges: a reveal flush with a window, two solids side by side).
//
// Shares no code with kernels/ or the shadow volumes in host/shadow.
#include "reference/visible_boundary.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace penumbra {
namespace {

using Vec2 = Eigen::Vector2d;
using Polygon2 = std::vector<Vec2>;  // convex, counter-clockwise

double cross2(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Andrew's monotone chain; collinear points are dropped.
Polygon2 convexHull(std::vector<Vec2> p) {
  std::sort(p.begin(), p.end(), [](const Vec2& a, const Vec2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (p.size() < 3) return {};
  Polygon2 hull(2 * p.size());
  std::size_t k = 0;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t start = k;
    for (std::size_t j = 0; j < p.size(); ++j) {
      const Vec2& q = pass == 0 ? p[j] : p[p.size() - 1 - j];
      while (k >= start + 2 && cross2(hull[k - 1] - hull[k - 2], q - hull[k - 2]) <= 0.0) --k;
      hull[k++] = q;
    }
    --k;  // the last point of each chain starts the other
  }
  hull.resize(k);
  // Projections of one vertex along two edges can differ by rounding (1e-16); the chain keeps
  // both when their cross product rounds positive, and an edge that short has no reliable
  // direction for the inside tests. Vertices within 1e-12 of the hull's extent of the previous
  // one are one vertex.
  double extent = 0.0;
  for (const Vec2& x : hull) extent = std::max(extent, (x - hull[0]).norm());
  Polygon2 merged;
  for (const Vec2& x : hull)
    if (merged.empty() || (x - merged.back()).norm() > 1e-12 * extent) merged.push_back(x);
  while (merged.size() > 1 && (merged.back() - merged.front()).norm() <= 1e-12 * extent)
    merged.pop_back();
  return merged.size() >= 3 ? merged : Polygon2{};
}

// Signed distance of x from edge i of q, positive inside.
double edgeDistance(const Polygon2& q, std::size_t i, const Vec2& x) {
  const Vec2& a = q[i];
  const Vec2& b = q[(i + 1) % q.size()];
  const Vec2 e = b - a;
  return cross2(e, x - a) / e.norm();
}

bool inside(const Polygon2& q, const Vec2& x) {
  for (std::size_t i = 0; i < q.size(); ++i)
    if (edgeDistance(q, i, x) <= 0.0) return false;
  return true;
}

bool onBoundary(const Polygon2& q, const Vec2& x, double within) {
  double least = 1e300;
  for (std::size_t i = 0; i < q.size(); ++i) {
    const double d = edgeDistance(q, i, x);
    if (d < -within) return false;
    least = std::min(least, d);
  }
  return least <= within;
}

// The parameters [t0, t1] of a + t·(b − a) inside the closed polygon q; false when none. An end
// within `slack` outside an edge counts as on it: a shadow edge along a face edge, one rounding
// off it, must still split that edge where the shadow's own edges meet it.
bool overlap(const Vec2& a, const Vec2& b, const Polygon2& q, double slack, double& t0,
             double& t1) {
  t0 = 0.0;
  t1 = 1.0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    double fa = edgeDistance(q, i, a), fb = edgeDistance(q, i, b);
    if (fa > -slack) fa = std::max(fa, 0.0);
    if (fb > -slack) fb = std::max(fb, 0.0);
    if (fa < 0.0 && fb < 0.0) return false;
    if (fa < 0.0) t0 = std::max(t0, fa / (fa - fb));
    if (fb < 0.0) t1 = std::min(t1, fa / (fa - fb));
  }
  return t0 <= t1;
}

// The part of the polygon q where a·x <= c (Sutherland-Hodgman; q convex, counter-clockwise).
Polygon2 clipHalfPlane(const Polygon2& q, const Vec2& a, double c) {
  Polygon2 out;
  for (std::size_t i = 0; i < q.size(); ++i) {
    const Vec2& x = q[i];
    const Vec2& y = q[(i + 1) % q.size()];
    const double fx = a.dot(x) - c, fy = a.dot(y) - c;
    if (fx <= 0.0) out.push_back(x);
    if ((fx < 0.0 && fy > 0.0) || (fx > 0.0 && fy < 0.0))
      out.push_back(x + (y - x) * (fx / (fx - fy)));
  }
  return out.size() >= 3 ? out : Polygon2{};
}

// The shadow of `solid` on the face's plane, seen from p at height h above it (2-D, possibly
// empty). `reach` is the farthest distance from p to the clipped face, `frame` within the square
// `bound` (2-D, counter-clockwise) around it.
Polygon2 shadowPolygon(const ConvexPolyhedron& solid, const Vec3& p, double h, double reach,
                       const FaceFrame& frame, const Polygon2& bound, double tolerance) {
  const std::vector<Vec3>& v = solid.vertices();
  double distance = -1e300;  // a lower bound on the distance from p to the solid
  for (const auto& face : solid.faces())
    distance = std::max(distance, face.plane.signedDistance(p));
  if (distance <= tolerance) {
    // p on the solid's boundary (or inside it): a ray from p enters the solid at once, and is
    // blocked, iff it points into every face plane through p; a convex solid that a ray does not
    // enter at once it never enters. The shadow is that cone's section by the face's plane, cut
    // to the square around the face. Inside, no face plane passes through p: all is shadow.
    Polygon2 cone = bound;
    for (const auto& face : solid.faces()) {
      if (face.plane.signedDistance(p) < -tolerance) continue;
      const Vec3& m = face.plane.normal;  // m·(x − p) <= 0 for x = origin + u·e1 + v·e2
      cone = clipHalfPlane(cone, Vec2(m.dot(frame.e1), m.dot(frame.e2)), m.dot(p - frame.origin));
      if (cone.empty()) break;
    }
    return cone;
  }
  const double sMin = std::min(0.5, 0.5 * distance / reach);
  const double dLow = tolerance, dHigh = h * (1.0 - sMin);
  std::vector<double> d(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) d[i] = frame.normal.dot(v[i]) - frame.offset;
  const Vec2 p2 = frame.flat(p);
  std::vector<Vec2> projected;
  auto project = [&](const Vec3& y, double depth) {
    const double k = h / (h - depth);
    const Vec3 w = y - p;
    projected.push_back(p2 + k * Vec2(w.dot(frame.e1), w.dot(frame.e2)));
  };
  for (const auto& edge : solid.edges()) {
    const double da = d[edge.from], db = d[edge.to];
    double t0 = 0.0, t1 = 1.0;
    if (da == db) {
      if (da < dLow || da > dHigh) continue;
    } else {
      const double tl = (dLow - da) / (db - da), th = (dHigh - da) / (db - da);
      t0 = std::max(t0, std::min(tl, th));
      t1 = std::min(t1, std::max(tl, th));
      if (t0 > t1) continue;
    }
    const Vec3& a = v[edge.from];
    const Vec3 e = v[edge.to] - a;
    project(a + t0 * e, da + t0 * (db - da));
    project(a + t1 * e, da + t1 * (db - da));
  }
  return convexHull(std::move(projected));
}

// Whether every point lies strictly beyond the plane {x : normal·x = offset}, by margin.
bool allBeyond(const Vec3& normal, double offset, const std::vector<Vec3>& points, double margin) {
  return std::all_of(points.begin(), points.end(),
                     [&](const Vec3& x) { return normal.dot(x) - offset > margin; });
}

// The pyramid conv(p, face'): its points and its side planes, outward. Built once per point and
// face; every solid is tested against it.
struct Pyramid {
  std::vector<Vec3> points;
  std::vector<Plane> sides;
};

Pyramid pyramidOf(const Vec3& p, const std::vector<Vec3>& face, const Vec3& inward) {
  Pyramid pyramid{face, {}};
  pyramid.points.push_back(p);
  for (std::size_t i = 0; i < face.size(); ++i) {
    Vec3 m = (face[i] - p).cross(face[(i + 1) % face.size()] - p);
    if (m.norm() == 0.0) continue;
    m.normalize();
    if (m.dot(inward) > 0.0) m = -m;  // outward
    pyramid.sides.push_back(Plane{m, m.dot(p)});
  }
  return pyramid;
}

// Whether a solid cannot meet the pyramid: a face plane of the solid with the whole pyramid
// outside it, or a side plane of the pyramid with the whole solid outside it.
bool separated(const ConvexPolyhedron& solid, const Pyramid& pyramid, double tolerance) {
  for (const auto& f : solid.faces())
    if (allBeyond(f.plane.normal, f.plane.offset, pyramid.points, tolerance)) return true;
  for (const Plane& side : pyramid.sides)
    if (allBeyond(side.normal, side.offset, solid.vertices(), tolerance)) return true;
  return false;
}

// +1 for a counter-clockwise polygon, −1 for a clockwise one.
double orientationOf(const Polygon2& q) {
  double twiceArea = 0.0;
  for (std::size_t i = 0; i < q.size(); ++i) twiceArea += cross2(q[i], q[(i + 1) % q.size()]);
  return twiceArea < 0.0 ? -1.0 : 1.0;
}

// Whether some edge of the convex polygon q has every point of `others` on its outer side or
// within `within` of its line.
bool edgeSeparates(const Polygon2& q, const Polygon2& others, double within) {
  const double inward = orientationOf(q);
  for (std::size_t i = 0; i < q.size(); ++i) {
    const bool allOut = std::none_of(others.begin(), others.end(), [&](const Vec2& x) {
      return inward * edgeDistance(q, i, x) > within;
    });
    if (allOut) return true;
  }
  return false;
}

// Whether two convex polygons share no area (to within `within`): a shadow that touches the face
// only along its boundary, as the reveals of an opening the face was cut to do, hides nothing,
// and leaving it out spares boundaryArcs its edges.
bool apart(const Polygon2& a, const Polygon2& b, double within) {
  return edgeSeparates(a, b, within) || edgeSeparates(b, a, within);
}

// Whether every vertex of `inner` lies inside the convex polygon `outer`: a shadow that covers
// the whole face.
bool covers(const Polygon2& outer, const Polygon2& inner) {
  const double inward = orientationOf(outer);
  for (std::size_t i = 0; i < outer.size(); ++i)
    for (const Vec2& x : inner)
      if (inward * edgeDistance(outer, i, x) <= 0.0) return false;
  return true;
}

// The 2-D bounding box of a polygon: {lo, hi}.
std::pair<Vec2, Vec2> boundsOf(const Polygon2& q) {
  Vec2 lo = q[0], hi = lo;
  for (const Vec2& x : q) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  return {lo, hi};
}

// The pieces of the polygons' edges that bound the visible region, as arcs seen from p.
std::vector<VisibleArc> boundaryArcs(const Vec3& p, const FaceFrame& frame,
                                     const std::vector<Polygon2>& polygons) {
  const Polygon2& face = polygons[0];
  double size = 0.0;
  for (const Vec2& x : face) size = std::max(size, (x - face[0]).norm());
  const double hair = 1e-9 * size, coincident = 0.25 * hair;
  auto visible = [&](const Vec2& x) {
    if (!inside(face, x)) return false;
    for (std::size_t k = 1; k < polygons.size(); ++k)
      if (inside(polygons[k], x)) return false;
    return true;
  };
  std::vector<VisibleArc> arcs;
  std::vector<double> cuts;
  for (std::size_t j = 0; j < polygons.size(); ++j) {
    const Polygon2& q = polygons[j];
    for (std::size_t i = 0; i < q.size(); ++i) {
      const Vec2& a = q[i];
      const Vec2& b = q[(i + 1) % q.size()];
      const double length = (b - a).norm();
      if (length <= 0.0) continue;
      cuts.assign({0.0, 1.0});
      for (std::size_t k = 0; k < polygons.size(); ++k) {
        double t0, t1;
        if (k == j || !overlap(a, b, polygons[k], coincident, t0, t1)) continue;
        cuts.push_back(t0);
        cuts.push_back(t1);
      }
      std::sort(cuts.begin(), cuts.end());
      const Vec2 along = (b - a) / length;
      const Vec2 left(-along.y(), along.x());
      for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
        if (cuts[c + 1] - cuts[c] <= 0.0) continue;
        const Vec2 mid = a + 0.5 * (cuts[c] + cuts[c + 1]) * (b - a);
        bool earlier = false;
        for (std::size_t k = 0; k < j && !earlier; ++k)
          earlier = onBoundary(polygons[k], mid, coincident);
        if (earlier) continue;
        const bool l = visible(mid + hair * left), r = visible(mid - hair * left);
        if (l == r) continue;
        Vec3 from = frame.lift(a + cuts[c] * (b - a)) - p;
        Vec3 to = frame.lift(a + cuts[c + 1] * (b - a)) - p;
        if (!l) std::swap(from, to);
        arcs.push_back({from, to});
      }
    }
  }
  return arcs;
}

// The arcs of a polygon nothing hides: its edges, in order, each with the polygon on its left as
// boundaryArcs orients them, and the same end points (a + 1·(b − a), as boundaryArcs lifts an
// edge's far end), without testing each edge's sides: one polygon seen past no solid (the sun's
// disk, a sky patch, an element) is most of the host's work.
std::vector<VisibleArc> wholeOutline(const Vec3& p, const FaceFrame& frame, const Polygon2& q) {
  double twiceArea = 0.0;
  for (std::size_t i = 0; i < q.size(); ++i) twiceArea += cross2(q[i], q[(i + 1) % q.size()]);
  std::vector<VisibleArc> arcs;
  arcs.reserve(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) {
    const Vec2& a = q[i];
    const Vec2& b = q[(i + 1) % q.size()];
    if (!((b - a).norm() > 0.0)) continue;
    Vec3 from = frame.lift(a) - p, to = frame.lift(a + 1.0 * (b - a)) - p;
    if (twiceArea < 0.0) std::swap(from, to);
    arcs.push_back({from, to});
  }
  return arcs;
}

}  // namespace

FaceFrame FaceFrame::of(const ConvexPolygon& polygon) {
  FaceFrame frame;
  const auto& v = polygon.vertices();
  frame.normal = polygon.normal();
  frame.offset = frame.normal.dot(v[0]);
  frame.origin = polygon.centroid();
  frame.e1 = (v[1] - v[0]).normalized();
  frame.e2 = frame.normal.cross(frame.e1);
  return frame;
}

std::vector<VisibleArc> visibleBoundary(const ConvexPolygon& face, const FaceFrame& frame,
                                        const SamplePoint& point, const Scene& scene,
                                        double tolerance) {
  const Vec3& p = point.position;
  const Vec3 n = point.normal.normalized();
  const double h = frame.normal.dot(p) - frame.offset;
  if (h <= tolerance) return {};
  // The horizon: keep n·(x − p) >= 0.
  const ConvexPolygon lit = face.clipped(Plane{-n, -n.dot(p)}, 0.0);
  if (lit.empty()) return {};
  std::vector<Polygon2> polygons(1);
  double reach = 0.0;
  Vec3 centre = Vec3::Zero();
  for (const Vec3& x : lit.vertices()) {
    polygons[0].push_back(frame.flat(x));
    reach = std::max(reach, (x - p).norm());
    centre += x / static_cast<double>(lit.size());
  }
  if (polygons[0].size() < 3) return {};
  const Pyramid pyramid = pyramidOf(p, lit.vertices(), centre - p);
  const auto [lo, hi] = boundsOf(polygons[0]);
  // What counts as on an edge, as boundaryArcs' hair (1e-9 of the face's size).
  const double hair = 1e-9 * (hi - lo).norm();
  const Vec2 margin = hi - lo;
  const Polygon2 bound = {lo - margin, Vec2(hi.x() + margin.x(), lo.y() - margin.y()), hi + margin,
                          Vec2(lo.x() - margin.x(), hi.y() + margin.y())};
  for (int s = 0; s < static_cast<int>(scene.solids.size()); ++s) {
    const ConvexPolyhedron& solid = scene.solids[s].shape;
    if (s == point.solid || solid.empty()) continue;
    if (separated(solid, pyramid, tolerance)) continue;
    Polygon2 shadow = shadowPolygon(solid, p, h, reach, frame, bound, tolerance);
    if (shadow.empty()) continue;
    const auto [slo, shi] = boundsOf(shadow);
    if ((slo.array() > hi.array()).any() || (shi.array() < lo.array()).any()) continue;
    if (apart(polygons[0], shadow, hair)) continue;
    if (covers(shadow, polygons[0])) return {};
    polygons.push_back(std::move(shadow));
  }
  if (polygons.size() == 1) return wholeOutline(p, frame, polygons[0]);
  return boundaryArcs(p, frame, polygons);
}

}  // namespace penumbra
