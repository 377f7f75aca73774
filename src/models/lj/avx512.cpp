// The Lennard-Jones model's loops for x86-64-v4 (this file is compiled with
// -march=x86-64-v4 and called only where the processor has it): the list build's distance
// filter takes eight candidates at a time and compresses the indices of those within the
// radius into the list, without a branch or a scalar step per candidate.
#include <immintrin.h>

#include <bit>

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

}  // namespace pdq::lj
