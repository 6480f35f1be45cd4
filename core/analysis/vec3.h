// SPDX-License-Identifier: GPL-3.0-or-later
// Small vector helpers private to the analysis code.
#pragma once

#include <cmath>

#include "desia/model.h"
#include "desia/tolerances.h"

namespace desia {

inline Vec3 plus(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline Vec3 scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline Vec3 negated(const Vec3& a) { return {-a[0], -a[1], -a[2]}; }
inline Vec3 normalized(const Vec3& a) {
  double n = norm(a);
  return n > 0 ? scaled(a, 1.0 / n) : a;
}

// Flips a vector so that its first non-negligible component is positive (one of each pair ±d).
inline Vec3 canonicalSign(const Vec3& a) {
  for (double c : a) {
    if (c > tolerance::kDirection) return a;
    if (c < -tolerance::kDirection) return negated(a);
  }
  return a;
}

}  // namespace desia
