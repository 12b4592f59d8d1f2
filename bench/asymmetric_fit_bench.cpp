// Why a luminance that is not symmetric about the nadir runs as cells of point sources
// (docs/photometry.md, "The area model of narrow beams"): the area model integrates a polynomial
// in the cosine to one axis per kernel face, so an asymmetric luminance would be a sum of lobes
// about several axes, each one more face over the same opening. This fits such sums to each file's
// intensity at the table's γ in every C plane 5° apart (type C), in front of the opening, and
// prints per basis the worst |fit − table| as a share of the peak, the axes and terms the fit
// uses, its conditioning (Σ |c| over the largest |L| on the front hemisphere: what the kernel's
// float sums may lose, limit photometry::kLuminanceConditioningLimit) and the largest intensity
// the table sends above the opening's plane (which a flat opening cannot emit).
//   usage: asymmetric_fit_bench [file.ies|file.ldt ...]   (default: the two example files)
#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "photometry/light_distribution.hpp"
#include "photometry/nonnegative_least_squares.hpp"
#include "photometry/photometric_file.hpp"

namespace {

using namespace penumbra;
using namespace penumbra::photometry;

struct TableNode {
  Vec3 direction;  // local frame, unit
  double candela;
};

struct LobeBasis {
  const char* name;
  double tiltStepDeg, azimuthStepDeg;  // the tilted axes: every tiltStep in γ, azimuthStep in C
  std::vector<int> tiltedPowers;
  int nadirOrder;    // powers 0..nadirOrder of the nadir
  bool nonnegative;  // nonnegative least squares (else signed)
};

void fit(const std::string& file, const LightDistribution& d, const LobeBasis& basis) {
  std::vector<TableNode> front;
  double above = 0.0;
  for (double c = 0.0; c < 360.0; c += 5.0)
    for (double g : d.inPlaneAnglesDeg()) {
      const Vec3 v = directionOf(PhotometricType::C, {c, g});
      if (v.z() < 0.0)
        front.push_back({v, d.intensity(v)});
      else
        above = std::max(above, d.intensity(v));
    }
  std::vector<Vec3> axes = {Vec3(0, 0, -1)};
  for (double t = basis.tiltStepDeg; t < 89.0; t += basis.tiltStepDeg)
    for (double c = 0.0; c < 360.0; c += basis.azimuthStepDeg)
      axes.push_back(directionOf(PhotometricType::C, {c, t}));
  std::vector<std::pair<int, int>> columns;  // axis, power
  for (int k = 0; k <= basis.nadirOrder; ++k) columns.push_back({0, k});
  for (int a = 1; a < static_cast<int>(axes.size()); ++a)
    for (int k : basis.tiltedPowers) columns.push_back({a, k});
  const auto term = [&](std::size_t j, const Vec3& v) {
    return std::pow(axes[columns[j].first].dot(v), columns[j].second);
  };
  Eigen::MatrixXd design(front.size(), columns.size());
  Eigen::VectorXd target(front.size());
  for (std::size_t i = 0; i < front.size(); ++i) {
    const double cosPhi = -front[i].direction.z();  // I = A cos φ L: A = 1
    for (std::size_t j = 0; j < columns.size(); ++j)
      design(i, j) = cosPhi * term(j, front[i].direction);
    target(i) = front[i].candela;
  }
  const Eigen::VectorXd c = basis.nonnegative
                                ? nonnegativeLeastSquares(design, target)
                                : Eigen::VectorXd(design.colPivHouseholderQr().solve(target));
  const double worst = (target - design * c).cwiseAbs().maxCoeff();
  std::set<int> used;
  int terms = 0;
  double sum = 0.0, largest = 0.0;
  for (std::size_t j = 0; j < columns.size(); ++j)
    if (c(j) != 0.0) {
      used.insert(columns[j].first);
      ++terms;
      sum += std::abs(c(j));
    }
  for (double cDeg = 0.0; cDeg < 360.0; cDeg += 5.0)
    for (double g = 0.0; g < 90.0; g += 1.0) {
      const Vec3 v = directionOf(PhotometricType::C, {cDeg, g});
      double l = 0.0;
      for (std::size_t j = 0; j < columns.size(); ++j) l += c(j) * term(j, v);
      largest = std::max(largest, std::abs(l));
    }
  const double peak = d.peak().candela;
  fmt::print("{:<28} {:<62} {:>7.2f} {:>5} {:>6} {:>12.3g} {:>9.2f}\n", file, basis.name,
             100.0 * worst / peak, used.size(), terms, largest > 0.0 ? sum / largest : 0.0,
             100.0 * above / peak);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) files.push_back(argv[i]);
  if (files.empty())
    files = {PENUMBRA_SOURCE_DIR "/data/luminaires/batwing.ldt",
             PENUMBRA_SOURCE_DIR "/data/luminaires/asymmetric-wallwasher.ies"};
  const LobeBasis bases[] = {
      {"nonnegative: even powers 2-48, axes every 15° γ x 30° C",
       15,
       30,
       {2, 4, 8, 16, 32, 48},
       48,
       true},
      {"nonnegative: even powers 2-48, axes every 10° γ x 15° C",
       10,
       15,
       {2, 4, 6, 8, 12, 16, 24, 32, 48},
       48,
       true},
      {"signed: powers 1-4, nadir and 45° towards C0/90/180/270", 45, 90, {1, 2, 3, 4}, 6, false},
      {"signed: powers 1-6, axes every 30° γ x 45° C", 30, 45, {1, 2, 3, 4, 5, 6}, 8, false},
  };
  fmt::print("{:<28} {:<62} {:>7} {:>5} {:>6} {:>12} {:>9}\n", "file", "lobes", "error%", "axes",
             "terms", "conditioning", "above%");
  for (const std::string& file : files) {
    const LightDistribution d(readPhotometricFile(file));
    if (d.type() != PhotometricType::C) {
      fmt::print("{}: type C tables only\n", file);
      continue;
    }
    const std::string name = file.substr(file.find_last_of('/') + 1);
    for (const LobeBasis& basis : bases) fit(name, d, basis);
  }
  return 0;
}
