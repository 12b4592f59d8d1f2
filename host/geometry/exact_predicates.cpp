#include "geometry/exact_predicates.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace penumbra {
namespace {

// Error-free transformations (Shewchuk 1997, "Adaptive Precision Floating-Point Arithmetic and
// Fast Robust Geometric Predicates"): a op b == x + y exactly.
void twoSum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bVirtual = x - a;
  const double aVirtual = x - bVirtual;
  y = (a - aVirtual) + (b - bVirtual);
}

void twoDiff(double a, double b, double& x, double& y) {
  x = a - b;
  const double bVirtual = a - x;
  const double aVirtual = x + bVirtual;
  y = (a - aVirtual) + (bVirtual - b);
}

void twoProduct(double a, double b, double& x, double& y) {
  x = a * b;
  y = std::fma(a, b, -x);  // the rounding error of a * b, exactly
}

// An exact real as a sum of non-overlapping doubles in increasing magnitude, zeros removed
// (zero has no components). Its sign is the sign of its largest component. Fixed capacity, on
// the stack: the exact path runs for every exactly coplanar point of a hull, which is common
// (box faces, polygon caps), so it must not allocate. 192 is the largest size this
// determinant can reach: differences 2, 2x2 products 8, minors 16, 2x16 products 64, sum 192.
struct Expansion {
  static constexpr int kCapacity = 192;
  std::array<double, kCapacity> component;
  int size = 0;
};

void copy(const Expansion& from, Expansion& to) {
  std::copy_n(from.component.begin(), from.size, to.component.begin());
  to.size = from.size;
}

// h = e + f by merging the components in order of magnitude (Shewchuk's
// FAST-EXPANSION-SUM with zero elimination, valid under IEEE round-to-nearest-even; TWO-SUM
// in place of FAST-TWO-SUM, which gives the same result without its ordering precondition).
void sum(const Expansion& e, const Expansion& f, Expansion& h) {
  if (e.size == 0 || f.size == 0) {
    copy(e.size == 0 ? f : e, h);
    return;
  }
  int ei = 0, fi = 0;
  auto takeSmaller = [&] {
    const double a = e.component[ei], b = f.component[fi];
    if ((b > a) == (b > -a)) {  // |a| < |b|, or equal magnitudes
      ++ei;
      return a;
    }
    ++fi;
    return b;
  };
  double q = takeSmaller();
  h.size = 0;
  while (ei < e.size || fi < f.size) {
    const double next = ei == e.size   ? f.component[fi++]
                        : fi == f.size ? e.component[ei++]
                                       : takeSmaller();
    double total, error;
    twoSum(q, next, total, error);
    if (error != 0.0) h.component[h.size++] = error;
    q = total;
  }
  if (q != 0.0) h.component[h.size++] = q;
}

void add(Expansion& e, const Expansion& f) {
  Expansion total;
  sum(e, f, total);
  copy(total, e);
}

void negate(Expansion& e) {
  for (int i = 0; i < e.size; ++i) e.component[i] = -e.component[i];
}

// h = e * b (Shewchuk's SCALE-EXPANSION with zero elimination; TWO-SUM in place of
// FAST-TWO-SUM, which gives the same result without its ordering precondition).
void scale(const Expansion& e, double b, Expansion& h) {
  h.size = 0;
  if (e.size == 0 || b == 0.0) return;
  double q, error;
  twoProduct(e.component[0], b, q, error);
  if (error != 0.0) h.component[h.size++] = error;
  for (int i = 1; i < e.size; ++i) {
    double product, productError, sum;
    twoProduct(e.component[i], b, product, productError);
    twoSum(q, productError, sum, error);
    if (error != 0.0) h.component[h.size++] = error;
    twoSum(product, sum, q, error);
    if (error != 0.0) h.component[h.size++] = error;
  }
  if (q != 0.0) h.component[h.size++] = q;
}

void multiply(const Expansion& e, const Expansion& f, Expansion& product) {
  product.size = 0;
  Expansion partial;
  for (int i = 0; i < f.size; ++i) {
    scale(e, f.component[i], partial);
    add(product, partial);
  }
}

void difference(double a, double b, Expansion& e) {
  double x, y;
  twoDiff(a, b, x, y);
  e.size = 0;
  if (y != 0.0) e.component[e.size++] = y;
  if (x != 0.0) e.component[e.size++] = x;
}

int sign(double x) {
  return (x > 0.0) - (x < 0.0);
}

int exactOrientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p) {
  Expansion u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) {
    difference(b[k], a[k], u[k]);
    difference(c[k], a[k], v[k]);
    difference(p[k], a[k], w[k]);
  }
  Expansion det, minor, term, scratch;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    multiply(v[i], w[j], minor);  // minor = v_i w_j - v_j w_i
    multiply(v[j], w[i], scratch);
    negate(scratch);
    add(minor, scratch);
    multiply(u[k], minor, term);
    add(det, term);
  }
  return det.size == 0 ? 0 : sign(det.component[det.size - 1]);
}

}  // namespace

int orientationSign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p) {
  const Vec3 u = b - a, v = c - a, w = p - a;
  const double m0 = v.y() * w.z() - v.z() * w.y();
  const double m1 = v.z() * w.x() - v.x() * w.z();
  const double m2 = v.x() * w.y() - v.y() * w.x();
  const double det = u.x() * m0 + u.y() * m1 + u.z() * m2;
  const double permanent = std::abs(u.x()) * (std::abs(v.y() * w.z()) + std::abs(v.z() * w.y())) +
                           std::abs(u.y()) * (std::abs(v.z() * w.x()) + std::abs(v.x() * w.z())) +
                           std::abs(u.z()) * (std::abs(v.x() * w.y()) + std::abs(v.y() * w.x()));
  // Shewchuk's bound for this expression with rounded differences: (7 + 56 eps) eps, eps = 2^-53.
  constexpr double kEpsilon = 0x1p-53;
  constexpr double kErrorBound = (7.0 + 56.0 * kEpsilon) * kEpsilon;
  if (std::abs(det) > kErrorBound * permanent) return sign(det);
  // Every product zero: the determinant is exactly zero unless a product of nonzero
  // differences underflowed, which needs differences below 2^-300 (three of them reach the
  // smallest normal 2^-1022 only below that). This is the common exact case (points on an axis
  // plane: a box face, a horizontal cap) and skips the slow path.
  if (permanent == 0.0) {
    constexpr double kNoUnderflow = 0x1p-300;
    bool representable = true;
    for (const Vec3* d : {&u, &v, &w}) {
      for (int k = 0; k < 3; ++k) {
        const double magnitude = std::abs((*d)[k]);
        representable = representable && (magnitude == 0.0 || magnitude >= kNoUnderflow);
      }
    }
    if (representable) return 0;
  }
  return exactOrientation(a, b, c, p);
}

}  // namespace penumbra
