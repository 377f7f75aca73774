#pragma once
// Finite rotations in 3D, for the integrator's Rotation::Spatial and the models that use
// it. An orientation is a unit quaternion; rotations are composed by multiplying
// quaternions, never by adding rotation vectors, so a rotation of any size stays an exact
// rotation (no drift off the rotation group, no gimbal lock). The rotation vector θ (axis ×
// angle) is only formed for a small rotation (an increment ω Δt) or read back for output,
// with |θ| ≤ π.
#include <array>
#include <cmath>

namespace pdq {

using Vec = std::array<double, 3>;
struct Quat {
  double w, x, y, z;
};

inline double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline Quat mul(const Quat& a, const Quat& b) {
  return {
      a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
      a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
inline Quat conj(const Quat& q) { return {q.w, -q.x, -q.y, -q.z}; }

// R(q) v for a unit quaternion: v + 2w (u × v) + 2 u × (u × v).
inline Vec rotate(const Quat& q, const Vec& v) {
  const Vec u{q.x, q.y, q.z};
  const Vec t = cross(u, v);
  const Vec tt = cross(u, t);
  return {v[0] + 2 * (q.w * t[0] + tt[0]), v[1] + 2 * (q.w * t[1] + tt[1]),
          v[2] + 2 * (q.w * t[2] + tt[2])};
}

// A rotation as a row-major 3 × 3 matrix: formed once, it turns a vector in nine products.
using Mat = std::array<double, 9>;
// R(q) of a unit quaternion (w, x, y, z): I + 2w [u]× + 2 [u]×² (rotate()'s terms), row by
// row into R. T is a double or a vector of doubles (GCC's vector extension), one
// quaternion per lane, each lane the same operations as a double.
template <class T>
inline void rotationEntries(T w, T x, T y, T z, T R[9]) {
  const T xx = x * x, yy = y * y, zz = z * z;
  const T xy = x * y, xz = x * z, yz = y * z;
  const T wx = w * x, wy = w * y, wz = w * z;
  R[0] = 1 - 2 * (yy + zz), R[1] = 2 * (xy - wz), R[2] = 2 * (xz + wy);
  R[3] = 2 * (xy + wz), R[4] = 1 - 2 * (xx + zz), R[5] = 2 * (yz - wx);
  R[6] = 2 * (xz - wy), R[7] = 2 * (yz + wx), R[8] = 1 - 2 * (xx + yy);
}
inline Mat rotationMatrix(const Quat& q) {
  Mat R;
  rotationEntries(q.w, q.x, q.y, q.z, R.data());
  return R;
}
inline Vec apply(const Mat& R, const Vec& v) {
  return {R[0] * v[0] + R[1] * v[1] + R[2] * v[2], R[3] * v[0] + R[4] * v[1] + R[5] * v[2],
          R[6] * v[0] + R[7] * v[1] + R[8] * v[2]};
}

// The unit quaternion of rotation vector θ. Small angles (|θ|/2 ≤ 0.1, the common case):
// Taylor series of cos and sin(x)/x, exact to round-off there and cheaper than sin and cos.
inline Quat expRot(const Vec& th) {
  const double t2 = 0.25 * dot(th, th);  // (|θ|/2)²
  double c, sx;                          // cos(|θ|/2), sin(|θ|/2)/(|θ|/2)
  if (t2 <= 0.01) {
    c = 1 - t2 * (1.0 / 2 -
                  t2 * (1.0 / 24 - t2 * (1.0 / 720 - t2 * (1.0 / 40320 - t2 * (1.0 / 3628800)))));
    sx = 1 - t2 * (1.0 / 6 - t2 * (1.0 / 120 - t2 * (1.0 / 5040 -
                                                     t2 * (1.0 / 362880 - t2 * (1.0 / 39916800)))));
  } else {
    const double h = std::sqrt(t2);
    c = std::cos(h);
    sx = std::sin(h) / h;
  }
  const double k = 0.5 * sx;
  return {c, k * th[0], k * th[1], k * th[2]};
}

// The rotation vector of a unit quaternion, |θ| ≤ π (q and −q are the same rotation).
// Near the identity (|u|/w ≤ 0.1): θ = 2 u atan(t)/t with t = |u|/w, by its series.
inline Vec logRot(Quat q) {
  if (q.w < 0) q = {-q.w, -q.x, -q.y, -q.z};
  const double u2 = q.x * q.x + q.y * q.y + q.z * q.z;
  double k;  // θ = k u
  if (u2 <= 0.01 * q.w * q.w) {
    const double t2 = u2 / (q.w * q.w);
    k = 2 / q.w *
        (1 - t2 * (1.0 / 3 -
                   t2 * (1.0 / 5 -
                         t2 * (1.0 / 7 -
                               t2 * (1.0 / 9 - t2 * (1.0 / 11 - t2 * (1.0 / 13 - t2 / 15)))))));
  } else {
    const double u = std::sqrt(u2);
    k = 2 * std::atan2(u, q.w) / u;
  }
  return {k * q.x, k * q.y, k * q.z};
}

inline Quat normalised(const Quat& q) {
  const double inv = 1 / std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w * inv, q.x * inv, q.y * inv, q.z * inv};
}

}  // namespace pdq
