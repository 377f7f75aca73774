#include "models/lps/lps_kernel.hpp"

#include <immintrin.h>

#include <algorithm>
#include <cmath>

namespace pdq::peri {
namespace {

inline double lengthTo(const double* xi, const double* xj, double r[3]) {
  r[0] = xj[0] - xi[0];
  r[1] = xj[1] - xi[1];
  r[2] = xj[2] - xi[2];
  return std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
}

// A bond's reference length, weight and partner's 1/m: from its attributes (the portable
// kernels), or from its row and the partner's position row (the AVX2 kernels' tails, which
// would otherwise fetch the attributes they no longer stream).
struct Attrs {
  double len0, w, invMj;
};

template <bool kRows>
inline Attrs attrsOf(const LpsView& v, std::size_t b) {
  if constexpr (kRows) {
    const double* r = rowOf(v.rows, b);
    return {r[0], r[1], v.x[v.partner[b] * v.nA + 3]};
  } else {
    const double* ab = v.attr + 3 * b;
    return {ab[0], ab[1], ab[2]};
  }
}

template <bool kRows>
inline double dilatationBond(const LpsView& v, const double* xi, std::size_t b) {
  const Attrs ab = attrsOf<kRows>(v, b);
  double r[3];
  const double len = lengthTo(xi, v.x + v.partner[b] * v.nA, r);
  return ab.w * ab.len0 * (len - ab.len0);
}

// Bond b of the particle whose bonds start at b0.
template <bool kRows>
inline void forceBond(const LpsView& v, const double* xi, std::size_t b0, std::size_t b, double qi,
                      double invMi, double* sx, double* sy, double* sz) {
  const double* xj = v.x + v.partner[b] * v.nA;
  Attrs ab = attrsOf<kRows>(v, b);
  double r[3];
  const double len = lengthTo(xi, xj, r);
  const double ext = len - ab.len0;
  // Both ends judge a bond from the same numbers, so it breaks on both sides at once. A
  // bond of weight 0 has broken already (and is dead): it is not judged again.
  if (v.criticalStretch > 0 && ab.w != 0 && ext > v.criticalStretch * ab.len0) {
    ab.w = 0;
    v.attr[3 * b + 1] = 0;
    v.bonds->kill(b);
    if (kRows) breakRows(v.rows, b0, b);
  }
  const double rk = ab.w * (v.a * ab.len0 * (qi + v.theta[v.partner[b]] * ab.invMj) +
                            v.b * (invMi + ab.invMj) * ext);
  const double t = rk / len;
  *sx += t * r[0];
  *sy += t * r[1];
  *sz += t * r[2];
}

inline double lanes(const double* l) { return (l[0] + l[1]) + (l[2] + l[3]); }

double dilatationPortable(const LpsView& v, std::size_t i, std::size_t b0, std::size_t b1) {
  const double* xi = v.x + i * v.nA;
  double l[4] = {0, 0, 0, 0};
  std::size_t b = b0;
  for (; b + 4 <= b1; b += 4)
    for (int k = 0; k < 4; ++k) l[k] += dilatationBond<false>(v, xi, b + k);
  for (int k = 0; b < b1; ++b, ++k) l[k] += dilatationBond<false>(v, xi, b);
  return lanes(l);
}

void forcePortable(const LpsView& v, std::size_t i, std::size_t b0, std::size_t b1, double qi,
                   double invMi, double acc[3]) {
  const double* xi = v.x + i * v.nA;
  double lx[4] = {0, 0, 0, 0}, ly[4] = {0, 0, 0, 0}, lz[4] = {0, 0, 0, 0};
  std::size_t b = b0;
  for (; b + 4 <= b1; b += 4)
    for (int k = 0; k < 4; ++k)
      forceBond<false>(v, xi, b0, b + k, qi, invMi, &lx[k], &ly[k], &lz[k]);
  for (int k = 0; b < b1; ++b, ++k)
    forceBond<false>(v, xi, b0, b, qi, invMi, &lx[k], &ly[k], &lz[k]);
  acc[0] = lanes(lx);
  acc[1] = lanes(ly);
  acc[2] = lanes(lz);
}

// Four partners' positions (dx, dy, dz relative to xi), the bond length, and the partners'
// 1/m (the rows' fourth column).
struct Four {
  __m256d dx, dy, dz, len, invM;
};

[[gnu::target("avx2")]] inline Four four(const LpsView& v, const double* xi, std::size_t b) {
  const std::int32_t* j = v.partner + b;
  const __m256d r0 = _mm256_loadu_pd(v.x + j[0] * v.nA), r1 = _mm256_loadu_pd(v.x + j[1] * v.nA);
  const __m256d r2 = _mm256_loadu_pd(v.x + j[2] * v.nA), r3 = _mm256_loadu_pd(v.x + j[3] * v.nA);
  const __m256d t0 = _mm256_unpacklo_pd(r0, r1), t1 = _mm256_unpackhi_pd(r0, r1);
  const __m256d t2 = _mm256_unpacklo_pd(r2, r3), t3 = _mm256_unpackhi_pd(r2, r3);
  Four f;
  f.dx = _mm256_sub_pd(_mm256_permute2f128_pd(t0, t2, 0x20), _mm256_set1_pd(xi[0]));
  f.dy = _mm256_sub_pd(_mm256_permute2f128_pd(t1, t3, 0x20), _mm256_set1_pd(xi[1]));
  f.dz = _mm256_sub_pd(_mm256_permute2f128_pd(t0, t2, 0x31), _mm256_set1_pd(xi[2]));
  f.invM = _mm256_permute2f128_pd(t1, t3, 0x31);
  f.len = _mm256_sqrt_pd(
      _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(f.dx, f.dx), _mm256_mul_pd(f.dy, f.dy)),
                    _mm256_mul_pd(f.dz, f.dz)));
  return f;
}

// Reference length and weight of bonds b .. b + 3, from the pair rows of b and b + 2.
struct Pairs {
  __m256d len0, w;
};

[[gnu::target("avx2")]] inline Pairs pairs(const BondRows& r, std::size_t b) {
  const __m256d p01 = _mm256_loadu_pd(rowOf(r, b)), p23 = _mm256_loadu_pd(rowOf(r, b + 2));
  // Halves (bond 0 | bond 2) and (bond 1 | bond 3): one unpack each gives lanes 0, 1, 2, 3.
  const __m256d p02 = _mm256_permute2f128_pd(p01, p23, 0x20);
  const __m256d p13 = _mm256_permute2f128_pd(p01, p23, 0x31);
  return {_mm256_unpacklo_pd(p02, p13), _mm256_unpackhi_pd(p02, p13)};
}

[[gnu::target("avx2")]] double dilatationAvx2(const LpsView& v, std::size_t i, std::size_t b0,
                                              std::size_t b1) {
  const double* xi = v.x + i * v.nA;
  __m256d s = _mm256_setzero_pd();
  std::size_t b = b0;
  for (; b + 4 <= b1; b += 4) {
    const Four f = four(v, xi, b);
    const auto [len0, w] = pairs(v.rows, b);
    s = _mm256_add_pd(s, _mm256_mul_pd(_mm256_mul_pd(w, len0), _mm256_sub_pd(f.len, len0)));
  }
  alignas(32) double l[4];
  _mm256_store_pd(l, s);
  for (int k = 0; b < b1; ++b, ++k) l[k] += dilatationBond<true>(v, xi, b);
  return lanes(l);
}

[[gnu::target("avx2")]] void forceAvx2(const LpsView& v, std::size_t i, std::size_t b0,
                                       std::size_t b1, double qi, double invMi, double acc[3]) {
  const double* xi = v.x + i * v.nA;
  const __m256d A = _mm256_set1_pd(v.a), Bc = _mm256_set1_pd(v.b), Q = _mm256_set1_pd(qi),
                IM = _mm256_set1_pd(invMi), sc = _mm256_set1_pd(v.criticalStretch);
  __m256d ax = _mm256_setzero_pd(), ay = _mm256_setzero_pd(), az = _mm256_setzero_pd();
  std::size_t b = b0;
  for (; b + 4 <= b1; b += 4) {
    const Four f = four(v, xi, b);
    const Pairs p = pairs(v.rows, b);
    const __m256d len0 = p.len0, invMj = f.invM;
    __m256d w = p.w;
    const std::int32_t* j = v.partner + b;
    const __m256d thj = _mm256_set_pd(v.theta[j[3]], v.theta[j[2]], v.theta[j[1]], v.theta[j[0]]);
    const __m256d ext = _mm256_sub_pd(f.len, len0);
    if (v.criticalStretch > 0) {
      const __m256d over = _mm256_and_pd(_mm256_cmp_pd(ext, _mm256_mul_pd(sc, len0), _CMP_GT_OQ),
                                         _mm256_cmp_pd(w, _mm256_setzero_pd(), _CMP_NEQ_UQ));
      if (const int m = _mm256_movemask_pd(over)) {
        for (int k = 0; k < 4; ++k)
          if (m & (1 << k)) {
            v.attr[3 * (b + k) + 1] = 0;
            v.bonds->kill(b + k);
            breakRows(v.rows, b0, b + k);
          }
        w = _mm256_andnot_pd(over, w);
      }
    }
    const __m256d dil =
        _mm256_mul_pd(_mm256_mul_pd(A, len0), _mm256_add_pd(Q, _mm256_mul_pd(thj, invMj)));
    const __m256d dev = _mm256_mul_pd(_mm256_mul_pd(Bc, _mm256_add_pd(IM, invMj)), ext);
    const __m256d t = _mm256_div_pd(_mm256_mul_pd(w, _mm256_add_pd(dil, dev)), f.len);
    ax = _mm256_add_pd(ax, _mm256_mul_pd(t, f.dx));
    ay = _mm256_add_pd(ay, _mm256_mul_pd(t, f.dy));
    az = _mm256_add_pd(az, _mm256_mul_pd(t, f.dz));
  }
  alignas(32) double lx[4], ly[4], lz[4];
  _mm256_store_pd(lx, ax);
  _mm256_store_pd(ly, ay);
  _mm256_store_pd(lz, az);
  for (int k = 0; b < b1; ++b, ++k)
    forceBond<true>(v, xi, b0, b, qi, invMi, &lx[k], &ly[k], &lz[k]);
  acc[0] = lanes(lx);
  acc[1] = lanes(ly);
  acc[2] = lanes(lz);
}

}  // namespace

LpsKernels lpsKernelsPortable() { return {dilatationPortable, forcePortable, false}; }

LpsKernels lpsKernels(Simd width) {
  switch (std::min(width, processorSimd())) {
    case Simd::avx512:
      return lpsKernelsAvx512();
    case Simd::avx2:
      return {dilatationAvx2, forceAvx2, true};
    case Simd::portable:
      break;
  }
  return lpsKernelsPortable();
}

}  // namespace pdq::peri
