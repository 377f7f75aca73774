// The Lennard-Jones model's loops for x86-64-v4 (this file is compiled with
// -march=x86-64-v4 and called only where the processor has it): the list build's distance
// filter and the force kernel's first pass take eight candidates at a time and compress
// those within the radius into their output, without a branch or a scalar step per
// candidate.
#include <immintrin.h>

#include <bit>

// GCC 12's intrinsics leave the lanes they are told to overwrite uninitialised
// (_mm512_undefined_pd), which its own warning then reports.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "models/lj/kernel.hpp"
#include "models/lj/verlet_list.hpp"

namespace pdq::lj {

std::size_t keepNearAvx512(const double* cx, const double* cy, const double* cz,
                           const std::uint32_t* id, std::size_t from, std::size_t to, double x,
                           double y, double z, double r2max, std::uint32_t* out) {
  const __m512d X = _mm512_set1_pd(x), Y = _mm512_set1_pd(y), Z = _mm512_set1_pd(z),
                R = _mm512_set1_pd(r2max);
  std::size_t m = 0;
  for (std::size_t k = from; k < to; k += 8) {
    const std::size_t left = to - k;
    const __mmask8 in = left >= 8 ? 0xff : static_cast<__mmask8>((1u << left) - 1);
    const __m512d dx = _mm512_sub_pd(_mm512_maskz_loadu_pd(in, cx + k), X);
    const __m512d dy = _mm512_sub_pd(_mm512_maskz_loadu_pd(in, cy + k), Y);
    const __m512d dz = _mm512_sub_pd(_mm512_maskz_loadu_pd(in, cz + k), Z);
    const __m512d d2 = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)),
                                     _mm512_mul_pd(dz, dz));
    const __mmask8 near = _mm512_mask_cmp_pd_mask(in, d2, R, _CMP_LT_OQ);
    const __m256i j = _mm256_maskz_loadu_epi32(in, id + k);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + m), _mm256_maskz_compress_epi32(near, j));
    m += std::popcount(static_cast<unsigned>(near));
  }
  return m;
}

std::size_t keepPairsAvx512(const double* pos, std::size_t stride, const std::uint32_t* first,
                            const std::uint32_t* last, double x, double y, double z, double rc2,
                            KernelScratch& s, std::size_t m) {
  const __m512d X = _mm512_set1_pd(x), Y = _mm512_set1_pd(y), Z = _mm512_set1_pd(z),
                R = _mm512_set1_pd(rc2);
  // Lanes of the x, y and z vectors from the pairs of rows unpacked below.
  const __m512i pickX = _mm512_set_epi64(13, 12, 5, 4, 9, 8, 1, 0);
  const __m512i pickZ = _mm512_set_epi64(15, 14, 7, 6, 11, 10, 3, 2);
  for (const std::uint32_t* k = first; k < last; k += 8) {
    const auto left = static_cast<std::size_t>(last - k);
    const __mmask8 in = left >= 8 ? 0xff : static_cast<__mmask8>((1u << left) - 1);
    // Eight rows (x y z and one more), a row past the list the first row again.
    auto rowOf = [&](std::size_t l) {
      return _mm256_loadu_pd(pos + std::size_t(k[l < left ? l : 0]) * stride);
    };
    // Rows l and h in one vector.
    auto rows = [&](std::size_t l, std::size_t h) {
      return _mm512_insertf64x4(_mm512_castpd256_pd512(rowOf(l)), rowOf(h), 1);
    };
    const __m512d a0 = rows(0, 4);
    const __m512d a1 = rows(1, 5);
    const __m512d a2 = rows(2, 6);
    const __m512d a3 = rows(3, 7);
    // t0 = x0 x1 z0 z1 | x4 x5 z4 z5, t1 = y0 y1 . . | y4 y5 . ., t2 and t3 the same of 2, 3, 6, 7.
    const __m512d t0 = _mm512_unpacklo_pd(a0, a1), t1 = _mm512_unpackhi_pd(a0, a1);
    const __m512d t2 = _mm512_unpacklo_pd(a2, a3), t3 = _mm512_unpackhi_pd(a2, a3);
    // As the portable loop: x_i − x_k per axis, then (ex² + ey²) + ez², no fused operation.
    const __m512d ex = _mm512_sub_pd(X, _mm512_permutex2var_pd(t0, pickX, t2));
    const __m512d ey = _mm512_sub_pd(Y, _mm512_permutex2var_pd(t1, pickX, t3));
    const __m512d ez = _mm512_sub_pd(Z, _mm512_permutex2var_pd(t0, pickZ, t2));
    const __m512d d2 = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(ex, ex), _mm512_mul_pd(ey, ey)),
                                     _mm512_mul_pd(ez, ez));
    const __mmask8 near = _mm512_mask_cmp_pd_mask(in, d2, R, _CMP_LT_OQ);
    const __m256i j = _mm256_maskz_loadu_epi32(in, k);
    _mm512_storeu_pd(s.dx.data() + m, _mm512_maskz_compress_pd(near, ex));
    _mm512_storeu_pd(s.dy.data() + m, _mm512_maskz_compress_pd(near, ey));
    _mm512_storeu_pd(s.dz.data() + m, _mm512_maskz_compress_pd(near, ez));
    _mm512_storeu_pd(s.r2.data() + m, _mm512_maskz_compress_pd(near, d2));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(s.j.data() + m),
                        _mm256_maskz_compress_epi32(near, j));
    m += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(near)));
  }
  return m;
}

void giveForcesAvx512(const KernelScratch& s, std::size_t owned, double* force) {
  for (std::size_t q = 0; q < owned; q += 8) {
    const std::size_t left = owned - q;
    const __mmask8 in = left >= 8 ? 0xff : static_cast<__mmask8>((1u << left) - 1);
    __m512d t[6];
    for (int c = 0; c < 6; ++c) t[c] = _mm512_maskz_loadu_pd(in, s.t[c].data() + q);
    // Pair 2M's components t0 t1, t2 t3 and t4 t5 in 128-bit lane M of e01, e23 and e45,
    // pair 2M + 1's in o01, o23 and o45.
    const __m512d e01 = _mm512_unpacklo_pd(t[0], t[1]), o01 = _mm512_unpackhi_pd(t[0], t[1]);
    const __m512d e23 = _mm512_unpacklo_pd(t[2], t[3]), o23 = _mm512_unpackhi_pd(t[2], t[3]);
    const __m512d e45 = _mm512_unpacklo_pd(t[4], t[5]), o45 = _mm512_unpackhi_pd(t[4], t[5]);
    // A partner's row as four and two doubles, each loaded and stored whole (a masked
    // access of the row would overlap the next row's).
    auto give = [&]<int M>(std::size_t l, __m512d a, __m512d b, __m512d c) {
      if (l >= left) return;
      double* fj = force + std::size_t(s.j[q + l]) * kForceRow;
      const __m256d lo = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm512_extractf64x2_pd(a, M)),
                                              _mm512_extractf64x2_pd(b, M), 1);
      _mm256_storeu_pd(fj, _mm256_sub_pd(_mm256_loadu_pd(fj), lo));
      _mm_storeu_pd(fj + 4, _mm_sub_pd(_mm_loadu_pd(fj + 4), _mm512_extractf64x2_pd(c, M)));
    };
    give.operator()<0>(0, e01, e23, e45);
    give.operator()<0>(1, o01, o23, o45);
    give.operator()<1>(2, e01, e23, e45);
    give.operator()<1>(3, o01, o23, o45);
    give.operator()<2>(4, e01, e23, e45);
    give.operator()<2>(5, o01, o23, o45);
    give.operator()<3>(6, e01, e23, e45);
    give.operator()<3>(7, o01, o23, o45);
  }
}

}  // namespace pdq::lj
