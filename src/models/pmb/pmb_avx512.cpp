// The PMB kernel eight bonds at a time (for x86-64-v4, called only where the processor has
// it): one square root and one division instruction for eight bonds. The bits are those of
// the other kernels (rows8.hpp says how).
#include "models/peri/rows8.hpp"
#include "models/pmb/pmb_kernel.hpp"

namespace pdq::peri {
namespace {

// The forces on the particle whose bonds start at b0 from its bonds b .. b + 7 (j: their
// partners' row offsets, k: their pair offsets), before they are added; only the lanes `in` holds
// are bonds of the particle.
struct Force8 {
  __m512d x, y, z;
};

[[gnu::target("arch=x86-64-v4")]] inline Force8 eight(const PmbView& v, const double* xi,
                                                      std::size_t b0, std::size_t b,
                                                      const std::int32_t* j, const std::uint32_t* k,
                                                      __mmask8 in) {
  const Rows8 r = rows8(v.x, 1, j, xi);
  auto [len0, w] = pairs8(v.rows, k);
  const __m512d ext = _mm512_sub_pd(r.len, len0);
  if (v.criticalStretch > 0) {
    const __mmask8 over = _mm512_mask_cmp_pd_mask(
        in, ext, _mm512_mul_pd(_mm512_set1_pd(v.criticalStretch), len0), _CMP_GT_OQ);
    if (over) {
      break8(over, b0, b, v.attr, 2, v.bonds, v.rows);
      w = _mm512_maskz_mov_pd(static_cast<__mmask8>(~over), w);
    }
  }
  const __m512d t = _mm512_div_pd(_mm512_mul_pd(w, ext), r.len);
  return {_mm512_mul_pd(t, r.dx), _mm512_mul_pd(t, r.dy), _mm512_mul_pd(t, r.dz)};
}

[[gnu::target("arch=x86-64-v4")]] inline void add8(const Force8& f, __mmask8 in, __m256d& ax,
                                                   __m256d& ay, __m256d& az) {
  ax = addHalves(ax, f.x, in);
  ay = addHalves(ay, f.y, in);
  az = addHalves(az, f.z, in);
}

}  // namespace

[[gnu::target("arch=x86-64-v4")]] void pmbKernelAvx512(const PmbView& v, std::size_t i,
                                                       std::size_t b0, std::size_t b1,
                                                       double acc[3]) {
  const double* xi = v.x + i * v.nA;
  const std::int32_t* at = v.rows.at;
  __m256d ax = _mm256_setzero_pd(), ay = _mm256_setzero_pd(), az = _mm256_setzero_pd();
  std::size_t b = b0;
  // Two groups at a time: the second's loads and square root overlap the first's division.
  for (; b + 16 <= b1; b += 16) {
    const Force8 f = eight(v, xi, b0, b, at + b, v.rows.pair + b, 0xff);
    const Force8 g = eight(v, xi, b0, b + 8, at + b + 8, v.rows.pair + b + 8, 0xff);
    add8(f, 0xff, ax, ay, az);
    add8(g, 0xff, ax, ay, az);
  }
  for (; b + 8 <= b1; b += 8)
    add8(eight(v, xi, b0, b, at + b, v.rows.pair + b, 0xff), 0xff, ax, ay, az);
  if (b < b1) {
    Copy8 copy;
    const Last8 t = last8(at, v.rows.pair, b, b1, v.bonds->count(), copy);
    add8(eight(v, xi, b0, b, t.j, t.k, t.in), t.in, ax, ay, az);
  }
  acc[0] = finish8(ax);
  acc[1] = finish8(ay);
  acc[2] = finish8(az);
}

}  // namespace pdq::peri
