#include "models/pmb/pmb_kernel.hpp"

#include <immintrin.h>

#include <algorithm>
#include <cmath>

namespace pdq::peri {
namespace {

// The bond (of four) that each vector lane holds in the AVX2 kernel.
constexpr int kLaneBond[4] = {0, 2, 1, 3};

// Bond b of the particle whose bonds start at b0 into lane sums s[3]: breaks the bond when
// overstretched. Its partner's row and its length and weight come from the partner's index
// and its attributes (the portable kernel) or from BondRows (the AVX2 kernel's tail, which
// would otherwise fetch, a cache miss each, the arrays it no longer streams).
template <bool kRows>
inline void bond(const PmbView& v, const double* xi, std::size_t b0, std::size_t b, double* sx,
                 double* sy, double* sz) {
  const double* xj = kRows ? v.x + v.rows.at[b] : v.x + v.partner[b] * v.nA;
  const double* ab = kRows ? rowOf(v.rows, b) : v.attr + 2 * b;
  const double len0 = ab[0];
  double w = ab[1];
  const double r0 = xj[0] - xi[0], r1 = xj[1] - xi[1], r2 = xj[2] - xi[2];
  const double len = std::sqrt(r0 * r0 + r1 * r1 + r2 * r2);
  const double ext = len - len0;
  // Both ends judge a bond from the same numbers, so it breaks on both sides at once. A
  // bond of weight 0 has broken already (and is dead): it is not judged again.
  if (v.criticalStretch > 0 && w != 0 && ext > v.criticalStretch * len0) {
    w = 0;
    v.attr[2 * b + 1] = 0;
    v.bonds->kill(b);
    if (kRows) breakRows(v.rows, b0, b);
  }
  const double t = w * ext / len;
  *sx += t * r0;
  *sy += t * r1;
  *sz += t * r2;
}

inline void finish(const double* lx, const double* ly, const double* lz, double acc[3]) {
  acc[0] = (lx[0] + lx[1]) + (lx[2] + lx[3]);
  acc[1] = (ly[0] + ly[1]) + (ly[2] + ly[3]);
  acc[2] = (lz[0] + lz[1]) + (lz[2] + lz[3]);
}

[[gnu::target("avx2")]] void pmbParticleAvx2(const PmbView& v, std::size_t i, std::size_t b0,
                                             std::size_t b1, double acc[3]) {
  const double* xi = v.x + i * v.nA;
  const __m256d xi0 = _mm256_set1_pd(xi[0]), xi1 = _mm256_set1_pd(xi[1]),
                xi2 = _mm256_set1_pd(xi[2]), sc = _mm256_set1_pd(v.criticalStretch);
  __m256d ax = _mm256_setzero_pd(), ay = _mm256_setzero_pd(), az = _mm256_setzero_pd();
  std::size_t b = b0;
  // The lanes hold bonds b, b + 2, b + 1, b + 3 (the order in which the attributes come
  // out of one unpack per 128-bit half); each lane still sums its own bonds in order.
  for (; b + 4 <= b1; b += 4) {
    // Rows of the four partners (x, y, z, and one more column), transposed.
    const __m256d r0 = _mm256_loadu_pd(v.x + v.rows.at[b]);
    const __m256d r1 = _mm256_loadu_pd(v.x + v.rows.at[b + 1]);
    const __m256d r2 = _mm256_loadu_pd(v.x + v.rows.at[b + 2]);
    const __m256d r3 = _mm256_loadu_pd(v.x + v.rows.at[b + 3]);
    const __m256d t0 = _mm256_unpacklo_pd(r0, r2), t1 = _mm256_unpackhi_pd(r0, r2);
    const __m256d t2 = _mm256_unpacklo_pd(r1, r3), t3 = _mm256_unpackhi_pd(r1, r3);
    const __m256d dx = _mm256_sub_pd(_mm256_permute2f128_pd(t0, t2, 0x20), xi0);
    const __m256d dy = _mm256_sub_pd(_mm256_permute2f128_pd(t1, t3, 0x20), xi1);
    const __m256d dz = _mm256_sub_pd(_mm256_permute2f128_pd(t0, t2, 0x31), xi2);
    // Length and weight of the four bonds, from the pair rows of bonds 0, 1 and 2, 3.
    const __m256d a01 = _mm256_loadu_pd(rowOf(v.rows, b)),
                  a23 = _mm256_loadu_pd(rowOf(v.rows, b + 2));
    const __m256d len0 = _mm256_unpacklo_pd(a01, a23);
    __m256d w = _mm256_unpackhi_pd(a01, a23);
    const __m256d len = _mm256_sqrt_pd(_mm256_add_pd(
        _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz)));
    const __m256d ext = _mm256_sub_pd(len, len0);
    if (v.criticalStretch > 0) {
      const __m256d over = _mm256_and_pd(_mm256_cmp_pd(ext, _mm256_mul_pd(sc, len0), _CMP_GT_OQ),
                                         _mm256_cmp_pd(w, _mm256_setzero_pd(), _CMP_NEQ_UQ));
      if (const int m = _mm256_movemask_pd(over)) {
        for (int k = 0; k < 4; ++k)
          if (m & (1 << k)) {
            const std::size_t bk = b + kLaneBond[k];
            v.attr[2 * bk + 1] = 0;
            v.bonds->kill(bk);
            breakRows(v.rows, b0, bk);
          }
        w = _mm256_andnot_pd(over, w);
      }
    }
    const __m256d t = _mm256_div_pd(_mm256_mul_pd(w, ext), len);
    ax = _mm256_add_pd(ax, _mm256_mul_pd(t, dx));
    ay = _mm256_add_pd(ay, _mm256_mul_pd(t, dy));
    az = _mm256_add_pd(az, _mm256_mul_pd(t, dz));
  }
  alignas(32) double sx[4], sy[4], sz[4];
  _mm256_store_pd(sx, ax);
  _mm256_store_pd(sy, ay);
  _mm256_store_pd(sz, az);
  double lx[4], ly[4], lz[4];
  for (int k = 0; k < 4; ++k) {
    lx[kLaneBond[k]] = sx[k];
    ly[kLaneBond[k]] = sy[k];
    lz[kLaneBond[k]] = sz[k];
  }
  for (int k = 0; b < b1; ++b, ++k) bond<true>(v, xi, b0, b, &lx[k], &ly[k], &lz[k]);
  finish(lx, ly, lz, acc);
}

[[gnu::target("avx2")]] void pmbKernelAvx2(const PmbView& v, std::size_t i0, std::size_t i1,
                                           double* acc, std::size_t stride) {
  for (std::size_t i = i0; i < i1; ++i)
    pmbParticleAvx2(v, i, v.bonds->begin(i), v.bonds->end(i), acc + i * stride);
}

void pmbParticlePortable(const PmbView& v, std::size_t i, std::size_t b0, std::size_t b1,
                         double acc[3]) {
  const double* xi = v.x + i * v.nA;
  double lx[4] = {0, 0, 0, 0}, ly[4] = {0, 0, 0, 0}, lz[4] = {0, 0, 0, 0};
  std::size_t b = b0;
  for (; b + 4 <= b1; b += 4)
    for (int k = 0; k < 4; ++k) bond<false>(v, xi, b0, b + k, &lx[k], &ly[k], &lz[k]);
  for (int k = 0; b < b1; ++b, ++k) bond<false>(v, xi, b0, b, &lx[k], &ly[k], &lz[k]);
  finish(lx, ly, lz, acc);
}

}  // namespace

void pmbKernelPortable(const PmbView& v, std::size_t i0, std::size_t i1, double* acc,
                       std::size_t stride) {
  for (std::size_t i = i0; i < i1; ++i)
    pmbParticlePortable(v, i, v.bonds->begin(i), v.bonds->end(i), acc + i * stride);
}

PmbKernel pmbKernel(Simd width) {
  switch (std::min(width, processorSimd())) {
    case Simd::avx512:
      return {pmbKernelAvx512, true};
    case Simd::avx2:
      return {pmbKernelAvx2, true};
    case Simd::portable:
      break;
  }
  return {pmbKernelPortable, false};
}

}  // namespace pdq::peri
