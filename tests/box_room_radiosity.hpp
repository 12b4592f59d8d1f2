#pragma once
// An independent reference for interreflection, written apart from host/radiosity: an empty box
// room [0, X] × [0, Y] × [0, Z] of one reflectance, lit by one downward rectangle just below the
// ceiling, solved by piecewise-constant collocation in double. Every face sees every other face
// whole, so the transfer from a patch to a point is Lambert's contour integral of the patch with
// no occlusion; each face is cut into n × n patches and the equations are met at the patch
// centres. The error falls as n grows; tests compare at several n.
#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace penumbra::testing {

using V3 = Eigen::Vector3d;

// E in lx at p (unit normal n) from a polygon of luminance 1 cd/m² wholly in front of p's
// horizon: E = ½ Σ β_i n·(r_i × r_i+1)/|r_i × r_i+1|, r_i the unit directions to the vertices.
inline double polygonIlluminance(const V3& p, const V3& n, const std::vector<V3>& polygon) {
  double sum = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const V3 a = (polygon[i] - p).normalized();
    const V3 b = (polygon[(i + 1) % polygon.size()] - p).normalized();
    const V3 c = a.cross(b);
    const double s = c.norm();
    if (s < 1e-300) continue;
    sum += std::atan2(s, a.dot(b)) * n.dot(c) / s;
  }
  return 0.5 * std::abs(sum);
}

struct BoxRoomCase {
  V3 size{4.0, 3.0, 3.0};
  double reflectance = 0.5;
  // The source: a rectangle [x0, x1] × [y0, y1] at height z, emitting downwards.
  double x0 = 1.0, x1 = 1.6, y0 = 1.4, y1 = 2.0, z = 2.99;
  double luminance = 1000.0;  // cd/m²
};

struct BoxRoomPatch {
  std::vector<V3> corners;
  V3 centre, normal;
};

class BoxRoomReference {
 public:
  BoxRoomReference(const BoxRoomCase& room, int n) : room_(room) {
    const V3& s = room.size;
    // The six faces: origin, two edge vectors, inward normal.
    const std::array<std::array<V3, 4>, 6> faces{{
        {V3(0, 0, 0), V3(s.x(), 0, 0), V3(0, s.y(), 0), V3(0, 0, 1)},
        {V3(0, 0, s.z()), V3(s.x(), 0, 0), V3(0, s.y(), 0), V3(0, 0, -1)},
        {V3(0, 0, 0), V3(s.x(), 0, 0), V3(0, 0, s.z()), V3(0, 1, 0)},
        {V3(0, s.y(), 0), V3(s.x(), 0, 0), V3(0, 0, s.z()), V3(0, -1, 0)},
        {V3(0, 0, 0), V3(0, s.y(), 0), V3(0, 0, s.z()), V3(1, 0, 0)},
        {V3(s.x(), 0, 0), V3(0, s.y(), 0), V3(0, 0, s.z()), V3(-1, 0, 0)},
    }};
    for (const auto& f : faces) {
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const V3 a = f[0] + f[1] * i / n + f[2] * j / n;
          const V3 du = f[1] / n, dv = f[2] / n;
          patches_.push_back({{a, a + du, a + du + dv, a + dv}, a + 0.5 * (du + dv), f[3]});
        }
    }
    const auto count = static_cast<Eigen::Index>(patches_.size());
    Eigen::VectorXd direct(count);
    Eigen::MatrixXd g(count, count);
    for (Eigen::Index i = 0; i < count; ++i) {
      direct[i] = directIlluminance(patches_[i].centre, patches_[i].normal);
      for (Eigen::Index j = 0; j < count; ++j)
        g(i, j) =
            i == j || patches_[i].normal == patches_[j].normal
                ? 0.0
                : polygonIlluminance(patches_[i].centre, patches_[i].normal, patches_[j].corners);
    }
    // E_ind = G·(ρ/π)(E_dir + E_ind)
    const double k = room.reflectance / std::numbers::pi;
    const Eigen::MatrixXd a = Eigen::MatrixXd::Identity(count, count) - k * g;
    const Eigen::VectorXd indirect = a.partialPivLu().solve(k * g * direct);
    luminance_ = k * (direct + indirect);
  }

  double directIlluminance(const V3& p, const V3& normal) const {
    if (p.z() >= room_.z) return 0.0;
    const std::vector<V3> source{V3(room_.x0, room_.y0, room_.z), V3(room_.x1, room_.y0, room_.z),
                                 V3(room_.x1, room_.y1, room_.z), V3(room_.x0, room_.y1, room_.z)};
    return room_.luminance * polygonIlluminance(p, normal, source);
  }

  // Total E at a point inside the room facing `normal` (not on a face).
  double totalIlluminance(const V3& p, const V3& normal) const {
    double e = directIlluminance(p, normal);
    for (std::size_t j = 0; j < patches_.size(); ++j) {
      // Only the part of a patch above p's horizon counts; work-plane points facing up see the
      // walls' lower parts edge on, so each patch is clipped at the horizon plane.
      e += luminance_[static_cast<Eigen::Index>(j)] * clippedIlluminance(p, normal, patches_[j]);
    }
    return e;
  }

 private:
  static double clippedIlluminance(const V3& p, const V3& normal, const BoxRoomPatch& patch) {
    std::vector<V3> kept;
    const auto& c = patch.corners;
    for (std::size_t i = 0; i < c.size(); ++i) {
      const V3& a = c[i];
      const V3& b = c[(i + 1) % c.size()];
      const double da = normal.dot(a - p), db = normal.dot(b - p);
      if (da >= 0) kept.push_back(a);
      if ((da > 0 && db < 0) || (da < 0 && db > 0)) kept.push_back(a + (b - a) * (da / (da - db)));
    }
    if (kept.size() < 3) return 0.0;
    return polygonIlluminance(p, normal, kept);
  }

  BoxRoomCase room_;
  std::vector<BoxRoomPatch> patches_;
  Eigen::VectorXd luminance_;
};

}  // namespace penumbra::testing
