#pragma once
// An independent reference for interreflection, written apart from host/radiosity: an empty box
// room [0, X] × [0, Y] × [0, Z] of one reflectance, lit by one downward rectangle just below the
// ceiling or by any light from outside given as E at a point (BoxRoomLighting: daylight through
// a window, with the window a hole in its wall), solved by piecewise-constant collocation in
// double. Every face sees every other face whole, so the transfer from a patch to a point is
// Lambert's contour integral of the patch with no occlusion; each face is cut into n × n patches
// and the equations are met at the patch centres. The error falls as n grows; tests compare at
// several n and extrapolate (collocationLimit).
#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <utility>
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

// Light that enters the room from outside, and where it enters.
struct BoxRoomLighting {
  std::function<double(const V3& point, const V3& normal)> direct;  // E (lx) before reflection
  // Holes in the wall y = 0, each [x0, x1] × [z0, z1] (m): the patches whose centre lies in one are
  // left out (they neither receive nor reflect). Their edges must fall on the patch grid.
  std::vector<std::array<double, 4>> wallHoles;
};

struct BoxRoomPatch {
  std::vector<V3> corners;
  V3 centre, normal;
};

class BoxRoomReference {
 public:
  BoxRoomReference(const BoxRoomCase& room, int n)
      : BoxRoomReference(room, n,
                         BoxRoomLighting{[room](const V3& p, const V3& normal) {
                                           return panelIlluminance(room, p, normal);
                                         },
                                         {}}) {}

  BoxRoomReference(const BoxRoomCase& room, int n, BoxRoomLighting lighting)
      : lighting_(std::move(lighting)) {
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
    // Positions in half patch steps along each axis (s/2n), exact integers on the patch grid.
    using Steps = std::array<int, 3>;
    std::vector<Steps> centreSteps, cornerSteps;
    const auto steps = [&](const V3& v) {
      Steps h;
      for (int k = 0; k < 3; ++k) h[k] = static_cast<int>(std::lround(2.0 * n * v[k] / s[k]));
      return h;
    };
    std::array<std::size_t, 7> faceBegin{};
    for (std::size_t f = 0; f < faces.size(); ++f) {
      faceBegin[f] = patches_.size();
      const auto& face = faces[f];
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const V3 a = face[0] + face[1] * i / n + face[2] * j / n;
          const V3 du = face[1] / n, dv = face[2] / n;
          const BoxRoomPatch patch{{a, a + du, a + du + dv, a + dv}, a + 0.5 * (du + dv), face[3]};
          if (inHole(patch)) continue;
          patches_.push_back(patch);
          centreSteps.push_back(steps(patch.centre));
          cornerSteps.push_back(steps(a));
        }
    }
    faceBegin[faces.size()] = patches_.size();
    const auto count = static_cast<Eigen::Index>(patches_.size());
    Eigen::VectorXd direct(count);
    for (Eigen::Index i = 0; i < count; ++i)
      direct[i] = lighting_.direct(patches_[i].centre, patches_[i].normal);
    // The patches of a face are translates of one another, so the transfer from a patch of face
    // fj to a centre on face fi depends on the two faces and the offset between the two alone:
    // it is computed once per offset and serves every pair at that offset (1 pair in 24 at
    // n = 32 is computed).
    Eigen::MatrixXd g = Eigen::MatrixXd::Zero(count, count);
    const int span = 4 * n + 1;  // offsets -2n..2n half steps on each axis
    std::vector<double> byOffset;
    for (std::size_t fi = 0; fi < faces.size(); ++fi)
      for (std::size_t fj = 0; fj < faces.size(); ++fj) {
        if (faces[fi][3] == faces[fj][3]) continue;  // one plane: no transfer
        byOffset.assign(static_cast<std::size_t>(span) * span * span, std::nan(""));
        for (std::size_t i = faceBegin[fi]; i < faceBegin[fi + 1]; ++i)
          for (std::size_t j = faceBegin[fj]; j < faceBegin[fj + 1]; ++j) {
            std::size_t at = 0;
            for (int k = 0; k < 3; ++k)
              at = at * span +
                   static_cast<std::size_t>(centreSteps[i][k] - cornerSteps[j][k] + 2 * n);
            double& transfer = byOffset[at];
            if (std::isnan(transfer))
              transfer =
                  polygonIlluminance(patches_[i].centre, patches_[i].normal, patches_[j].corners);
            g(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = transfer;
          }
      }
    // E_ind = G·(ρ/π)(E_dir + E_ind), iterated: a row of G/π sums to at most 1 (the centre's
    // whole hemisphere), so each pass shrinks the error at least ρ-fold, and the pass that
    // changes E_ind by under 1e-13 of it leaves it within ρ/(1 − ρ) of that.
    const double k = room.reflectance / std::numbers::pi;
    const Eigen::MatrixXd kg = k * g;
    Eigen::VectorXd indirect = kg * direct;
    for (int pass = 0;; ++pass) {
      if (pass == 10000) throw std::runtime_error("box room reference: no convergence");
      Eigen::VectorXd next = kg * (direct + indirect);
      const double change = (next - indirect).norm();
      indirect.swap(next);
      if (change <= 1e-13 * indirect.norm()) break;
    }
    luminance_ = k * (direct + indirect);
  }

  // E (lx) at p from the case's panel.
  static double panelIlluminance(const BoxRoomCase& room, const V3& p, const V3& normal) {
    if (p.z() >= room.z) return 0.0;
    const std::vector<V3> source{V3(room.x0, room.y0, room.z), V3(room.x1, room.y0, room.z),
                                 V3(room.x1, room.y1, room.z), V3(room.x0, room.y1, room.z)};
    return room.luminance * polygonIlluminance(p, normal, source);
  }

  // Total E at a point inside the room facing `normal` (not on a face).
  double totalIlluminance(const V3& p, const V3& normal) const {
    double e = lighting_.direct(p, normal);
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

  bool inHole(const BoxRoomPatch& patch) const {
    const V3& c = patch.centre;
    if (c.y() != 0.0) return false;
    for (const auto& [x0, x1, z0, z1] : lighting_.wallHoles)
      if (c.x() > x0 && c.x() < x1 && c.z() > z0 && c.z() < z1) return true;
    return false;
  }

  BoxRoomLighting lighting_;
  std::vector<BoxRoomPatch> patches_;
  Eigen::VectorXd luminance_;
};

// The limit of values taken at n, 1.5n and 2n patches a face, for a collocation error falling like
// n^-p: d2/d1 = (1.5^-p - 2^-p) / (1 - 1.5^-p) fixes p (bisected in [0.5, 4]), and the error left
// at 2n is d2·2^-p/(1.5^-p - 2^-p).
inline double collocationLimit(double atN, double at1_5N, double at2N) {
  const double d1 = atN - at1_5N, d2 = at1_5N - at2N;
  double lo = 0.5, hi = 4.0;
  for (int it = 0; it < 60; ++it) {
    const double p = 0.5 * (lo + hi);
    const double ratio = (std::pow(1.5, -p) - std::pow(2.0, -p)) / (1.0 - std::pow(1.5, -p));
    (ratio > d2 / d1 ? lo : hi) = p;
  }
  const double p = 0.5 * (lo + hi);
  return at2N - d2 * std::pow(2.0, -p) / (std::pow(1.5, -p) - std::pow(2.0, -p));
}

}  // namespace penumbra::testing
