#pragma once
// Eight bonds at a time for the AVX-512 kernels (functions compiled for x86-64-v4, called
// only where the processor has it; the files are not, so that no inline function of a
// header they include comes out in AVX-512 for the rest of the library to call): the
// partners' position rows transposed, and the bonds' (length, weight) rows. Lane L holds
// bond kLane8[L] of the eight, so that each half holds bonds 0, 2, 1, 3 of its four (the
// order one in-lane unpack gives; the AVX2 PMB kernel's too); a kernel adds the low half's four
// bonds to its four lane sums and then the high half's, the very order of the four-wide kernels, so
// the sums keep their bits.
#include <immintrin.h>

// GCC 12's intrinsics leave the lanes they are told to overwrite uninitialised
// (_mm512_undefined_pd), which its own warnings then report.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"

#include <cstddef>
#include <cstdint>

#include "models/peri/bond_classes.hpp"

namespace pdq::peri {

inline constexpr int kLane8[8] = {0, 2, 1, 3, 4, 6, 5, 7};

// A particle's position (x, y, z) in all eight lanes, or two particles' (the first in
// lanes 0-3, the second in 4-7).
struct Xi8 {
  __m512d x, y, z;
};

[[gnu::target("arch=x86-64-v4")]] inline Xi8 xi8(const double* a) {
  return {_mm512_set1_pd(a[0]), _mm512_set1_pd(a[1]), _mm512_set1_pd(a[2])};
}

[[gnu::target("arch=x86-64-v4")]] inline __m512d both(double a, double b) {
  return _mm512_insertf64x4(_mm512_set1_pd(a), _mm256_set1_pd(b), 1);
}

[[gnu::target("arch=x86-64-v4")]] inline Xi8 xi8(const double* a, const double* b) {
  return {both(a[0], b[0]), both(a[1], b[1]), both(a[2], b[2])};
}

// Columns 0-3 of the eight partners' rows, less xi in 0-2; len = |(dx, dy, dz)|.
struct Rows8 {
  __m512d dx, dy, dz, c3, len;
};

[[gnu::target("arch=x86-64-v4")]] inline __m512d twoRows(const double* a, const double* b) {
  return _mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_loadu_pd(a)), _mm256_loadu_pd(b), 1);
}

// The rows at x + nA j for j = lo[0..3] (lanes 0-3) and hi[0..3] (lanes 4-7): the
// partners' indices and nA the doubles of a row, or their rows' offsets (BondRows::at) and
// nA 1, which spares a multiplication each. One particle's eight bonds: hi = lo + 4.
[[gnu::target("arch=x86-64-v4")]] inline Rows8 rows8(const double* x, std::size_t nA,
                                                     const std::int32_t* lo, const std::int32_t* hi,
                                                     const Xi8& xi) {
  const __m512d r01 = twoRows(x + lo[0] * nA, x + lo[1] * nA),
                r23 = twoRows(x + lo[2] * nA, x + lo[3] * nA),
                r45 = twoRows(x + hi[0] * nA, x + hi[1] * nA),
                r67 = twoRows(x + hi[2] * nA, x + hi[3] * nA);
  // [x0 x2 z0 z2 x1 x3 z1 z3] and [y0 y2 c0 c2 y1 y3 c1 c3], and the same for 4-7.
  const __m512d lo0 = _mm512_unpacklo_pd(r01, r23), hi0 = _mm512_unpackhi_pd(r01, r23);
  const __m512d lo1 = _mm512_unpacklo_pd(r45, r67), hi1 = _mm512_unpackhi_pd(r45, r67);
  // Blocks of two lanes: [x0 x2 | x1 x3 | x4 x6 | x5 x7] are blocks 0 and 2 of lo0, then of lo1.
  Rows8 r;
  r.dx = _mm512_sub_pd(_mm512_shuffle_f64x2(lo0, lo1, 0x88), xi.x);
  r.dy = _mm512_sub_pd(_mm512_shuffle_f64x2(hi0, hi1, 0x88), xi.y);
  r.dz = _mm512_sub_pd(_mm512_shuffle_f64x2(lo0, lo1, 0xdd), xi.z);
  r.c3 = _mm512_shuffle_f64x2(hi0, hi1, 0xdd);
  r.len = _mm512_sqrt_pd(
      _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(r.dx, r.dx), _mm512_mul_pd(r.dy, r.dy)),
                    _mm512_mul_pd(r.dz, r.dz)));
  return r;
}

// Reference length and weight of the eight bonds whose pair offsets are lo[0..3] (lanes 0-3)
// and hi[0..3] (lanes 4-7); those of bonds 0 and 2 of each four are read.
struct Pairs8 {
  __m512d len0, w;
};

[[gnu::target("arch=x86-64-v4")]] inline Pairs8 pairs8(const BondRows& r, const std::uint32_t* lo,
                                                       const std::uint32_t* hi) {
  // Rows [bonds 0 1 | 4 5] and [2 3 | 6 7]: one unpack each gives the lanes in order.
  const __m512d a = twoRows(r.row + lo[0], r.row + hi[0]);
  const __m512d b = twoRows(r.row + lo[2], r.row + hi[2]);
  return {_mm512_unpacklo_pd(a, b), _mm512_unpackhi_pd(a, b)};
}

// The lanes that hold bonds 0 .. n - 1 of eight (bit L: lane L, which holds bond kLane8[L]:
// bits 1 and 2 of each four trade places).
inline __mmask8 lanes8(std::size_t n) {
  const unsigned has = (1u << n) - 1;
  return static_cast<__mmask8>((has & 0x99) | ((has & 0x22) << 1) | ((has & 0x44) >> 1));
}

// The one to seven bonds [b, b1) left after the groups of eight: their partners (indices or
// row offsets, as the kernel reads them) and pair offsets (j, k, eight of each) and the lanes
// that hold them. Read in place where eight bonds remain in the arrays (`count` bonds in
// all): the lanes beyond hold the next particle's, valid entries whose results are masked.
// Else copied into `copy`, with the particle's first bond in the lanes beyond its bonds.
struct Last8 {
  const std::int32_t* j;
  const std::uint32_t* k;
  __mmask8 in;
};
struct Copy8 {
  std::int32_t j[8];
  std::uint32_t k[8];
};

[[gnu::target("arch=x86-64-v4")]] inline Last8 last8(const std::int32_t* partner,
                                                     const std::uint32_t* pair, std::size_t b,
                                                     std::size_t b1, std::size_t count,
                                                     Copy8& copy) {
  const __mmask8 in = lanes8(b1 - b);
  if (b + 8 <= count) return {partner + b, pair + b, in};
  const auto has = static_cast<__mmask8>((1u << (b1 - b)) - 1);  // bit o: bond o
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(copy.j),
                      _mm256_mask_loadu_epi32(_mm256_set1_epi32(partner[b]), has, partner + b));
  _mm256_storeu_si256(
      reinterpret_cast<__m256i*>(copy.k),
      _mm256_mask_loadu_epi32(_mm256_set1_epi32(static_cast<int>(pair[b])), has, pair + b));
  return {copy.j, copy.k, in};
}

// Breaks the bonds of the lanes `over` holds, of bonds b .. b + 7 (attributes `stride`
// doubles a bond, the weight second) of the particle whose bonds start at b0: weight 0,
// killed, and its pair rows to the broken ones.
inline void break8(__mmask8 over, std::size_t b0, std::size_t b, double* attr, int stride,
                   Bonds* bonds, const BondRows& rows) {
  for (int L = 0; L < 8; ++L)
    if (over & (1 << L)) {
      const std::size_t bk = b + kLane8[L];
      attr[stride * bk + 1] = 0;
      bonds->kill(bk);
      breakRows(rows, b0, bk);
    }
}

// a[j[0]], ..., a[j[7]] in lane order.
[[gnu::target("arch=x86-64-v4")]] inline __m512d pick8(const double* a, const std::int32_t* j) {
  return _mm512_setr_pd(a[j[0]], a[j[2]], a[j[1]], a[j[3]], a[j[4]], a[j[6]], a[j[5]], a[j[7]]);
}

// The four lane sums (lane L holds bonds kLane8[L] mod 4) added as (0 + 1) + (2 + 3), in
// registers.
[[gnu::target("arch=x86-64-v4")]] inline double finish8(__m256d sum) {
  const __m128d t = _mm_add_pd(_mm256_castpd256_pd128(sum), _mm256_extractf128_pd(sum, 1));
  return _mm_cvtsd_f64(_mm_add_sd(t, _mm_unpackhi_pd(t, t)));
}

// Adds the low half of v to the four lane sums, then the high half, in the lanes `in`
// holds (bit L: lane L is a bond of the particle).
[[gnu::target("arch=x86-64-v4")]] inline __m256d addHalves(__m256d sum, __m512d v, __mmask8 in) {
  sum = _mm256_mask_add_pd(sum, in & 0xf, sum, _mm512_castpd512_pd256(v));
  return _mm256_mask_add_pd(sum, in >> 4, sum, _mm512_extractf64x4_pd(v, 1));
}

// Half h of v (0: lanes 0-3).
[[gnu::target("arch=x86-64-v4")]] inline __m256d half(__m512d v, int h) {
  return h ? _mm512_extractf64x4_pd(v, 1) : _mm512_castpd512_pd256(v);
}

}  // namespace pdq::peri

#pragma GCC diagnostic pop
