#include "glare/room_transfer.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <utility>

namespace penumbra {
namespace {

using Matrix3 = std::array<std::array<double, 3>, 3>;
using Vector3 = std::array<double, 3>;

// Gaussian elimination with partial pivoting; the matrix (I - diag(ρ) F) with ρ < 1 is regular.
Vector3 solve(Matrix3 a, Vector3 b) {
  for (int col = 0; col < 3; ++col) {
    int pivot = col;
    for (int row = col + 1; row < 3; ++row) {
      if (std::abs(a[row][col]) > std::abs(a[pivot][col])) pivot = row;
    }
    std::swap(a[col], a[pivot]);
    std::swap(b[col], b[pivot]);
    for (int row = 0; row < 3; ++row) {
      if (row == col) continue;
      const double factor = a[row][col] / a[col][col];
      for (int k = col; k < 3; ++k) a[row][k] -= factor * a[col][k];
      b[row] -= factor * b[col];
    }
  }
  return {b[0] / a[0][0], b[1] / a[1][1], b[2] / a[2][2]};
}

}  // namespace

double opposedRectanglesFormFactor(double a, double b, double c) {
  const double x = a / c, y = b / c;
  const double x1 = std::sqrt(1.0 + x * x), y1 = std::sqrt(1.0 + y * y);
  const double sum = std::log(x1 * y1 / std::sqrt(1.0 + x * x + y * y)) +
                     x * y1 * std::atan(x / y1) + y * x1 * std::atan(y / x1) - x * std::atan(x) -
                     y * std::atan(y);
  return 2.0 / (std::numbers::pi * x * y) * sum;
}

WallTransfer wallTransfer(double lengthX, double lengthY, double height,
                          const RoomReflectances& reflectances) {
  // Surfaces in the order floor, walls, ceiling.
  const double planeArea = lengthX * lengthY;
  const double wallArea = 2.0 * height * (lengthX + lengthY);
  const double floorToCeiling = opposedRectanglesFormFactor(lengthX, lengthY, height);
  const double planeToWalls = 1.0 - floorToCeiling;
  const double wallsToPlane = planeArea * planeToWalls / wallArea;
  const Matrix3 formFactor = {{{0.0, planeToWalls, floorToCeiling},
                               {wallsToPlane, 1.0 - 2.0 * wallsToPlane, wallsToPlane},
                               {floorToCeiling, planeToWalls, 0.0}}};
  const Vector3 rho = {reflectances.floor, reflectances.walls, reflectances.ceiling};
  const Vector3 area = {planeArea, wallArea, planeArea};
  Matrix3 system{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) system[i][j] = (i == j ? 1.0 : 0.0) - rho[i] * formFactor[i][j];
  }
  // One lumen first on surface `first`: E0 = 1/A there; the walls' E minus their own E0.
  const auto indirectOnWalls = [&](int first) {
    Vector3 direct{};
    direct[first] = 1.0 / area[first];
    const Vector3 exitance =
        solve(system, {rho[0] * direct[0], rho[1] * direct[1], rho[2] * direct[2]});
    double indirect = 0.0;
    for (int j = 0; j < 3; ++j) indirect += formFactor[1][j] * exitance[j];
    return indirect * wallArea;
  };
  return WallTransfer{indirectOnWalls(0), indirectOnWalls(1), indirectOnWalls(2)};
}

}  // namespace penumbra
