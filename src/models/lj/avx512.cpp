// The Lennard-Jones model's loops for x86-64-v4 (this file is compiled with
// -march=x86-64-v4 and called only where the processor has it): the list build's distance
// filter and the force kernel's first pass take eight candidates at a time and compress
// those within the radius into their outputs, without a branch or a scalar step per
// candidate.
#include <immintrin.h>

#include <bit>

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

std::size_t keepWithinAvx512(const double* pos, std::size_t stride, const std::uint32_t* first,
                             const std::uint32_t* last, const double* xi, double rc2,
                             const Kept& out, std::size_t m) {
  const __m512d X = _mm512_set1_pd(xi[0]), Y = _mm512_set1_pd(xi[1]), Z = _mm512_set1_pd(xi[2]),
                R = _mm512_set1_pd(rc2);
  const __m512i S = _mm512_set1_epi64(static_cast<long long>(stride));
  const std::size_t n = static_cast<std::size_t>(last - first);
  for (std::size_t k = 0; k < n; k += 8) {
    const std::size_t left = n - k;
    const __mmask8 in = left >= 8 ? 0xff : static_cast<__mmask8>((1u << left) - 1);
    const __m256i j = _mm256_maskz_loadu_epi32(in, first + k);
    // Row offsets in 64 bits: local index × stride may pass 2^31.
    const __m512i row = _mm512_mullo_epi64(_mm512_maskz_cvtepu32_epi64(in, j), S);
    const __m512d zero = _mm512_setzero_pd();
    const __m512d xj = _mm512_mask_i64gather_pd(zero, in, row, pos, 8);
    const __m512d yj = _mm512_mask_i64gather_pd(zero, in, row, pos + 1, 8);
    const __m512d zj = _mm512_mask_i64gather_pd(zero, in, row, pos + 2, 8);
    const __m512d ex = _mm512_sub_pd(X, xj), ey = _mm512_sub_pd(Y, yj), ez = _mm512_sub_pd(Z, zj);
    const __m512d d2 = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(ex, ex), _mm512_mul_pd(ey, ey)),
                                     _mm512_mul_pd(ez, ez));
    const __mmask8 near = _mm512_mask_cmp_pd_mask(in, d2, R, _CMP_LT_OQ);
    _mm512_storeu_pd(out.dx + m, _mm512_maskz_compress_pd(near, ex));
    _mm512_storeu_pd(out.dy + m, _mm512_maskz_compress_pd(near, ey));
    _mm512_storeu_pd(out.dz + m, _mm512_maskz_compress_pd(near, ez));
    _mm512_storeu_pd(out.r2 + m, _mm512_maskz_compress_pd(near, d2));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out.j + m),
                        _mm256_maskz_compress_epi32(near, j));
    m += std::popcount(static_cast<unsigned>(near));
  }
  return m;
}

}  // namespace pdq::lj
