// The LPS kernels eight bonds at a time (for x86-64-v4, called only where the processor has
// it): one square root, and in the force one division, instruction for eight bonds. The
// bits are those of the other kernels (rows8.hpp says how).
#include "models/lps/lps_kernel.hpp"
#include "models/peri/rows8.hpp"

namespace pdq::peri {
namespace {

// Bonds b .. b + 7 (j: their partners, k: their pair offsets) into the dilatation's lane sums.
[[gnu::target("arch=x86-64-v4")]] inline __m256d dilatation8(const LpsView& v, const double* xi,
                                                             const std::int32_t* j,
                                                             const std::uint32_t* k, __mmask8 in,
                                                             __m256d s) {
  const Rows8 r = rows8(v.x, v.nA, j, j + 4, xi8(xi));
  const auto [len0, w] = pairs8(v.rows, k, k + 4);
  return addHalves(s, _mm512_mul_pd(_mm512_mul_pd(w, len0), _mm512_sub_pd(r.len, len0)), in);
}

// The constants of one particle's force.
struct Particle {
  __m512d a, b, q, invM, sc;
};

// The same into the force's lane sums, breaking overstretched bonds.
[[gnu::target("arch=x86-64-v4")]] inline void force8(const LpsView& v, const double* xi,
                                                     const Particle& c, std::size_t b0,
                                                     std::size_t b, const std::int32_t* j,
                                                     const std::uint32_t* k, __mmask8 in,
                                                     __m256d& ax, __m256d& ay, __m256d& az) {
  const Rows8 r = rows8(v.x, v.nA, j, j + 4, xi8(xi));
  auto [len0, w] = pairs8(v.rows, k, k + 4);
  const __m512d invMj = r.c3, thj = pick8(v.theta, j);
  const __m512d ext = _mm512_sub_pd(r.len, len0);
  if (v.criticalStretch > 0) {
    // Bonds of weight 0 have broken already: only the others are judged.
    const __mmask8 live = _mm512_mask_cmp_pd_mask(in, w, _mm512_setzero_pd(), _CMP_NEQ_UQ);
    const __mmask8 over = _mm512_mask_cmp_pd_mask(live, ext, _mm512_mul_pd(c.sc, len0), _CMP_GT_OQ);
    if (over) {
      break8(over, b0, b, v.attr, 3, v.bonds, v.rows);
      w = _mm512_maskz_mov_pd(static_cast<__mmask8>(~over), w);
    }
  }
  const __m512d dil =
      _mm512_mul_pd(_mm512_mul_pd(c.a, len0), _mm512_add_pd(c.q, _mm512_mul_pd(thj, invMj)));
  const __m512d dev = _mm512_mul_pd(_mm512_mul_pd(c.b, _mm512_add_pd(c.invM, invMj)), ext);
  const __m512d t = _mm512_div_pd(_mm512_mul_pd(w, _mm512_add_pd(dil, dev)), r.len);
  ax = addHalves(ax, _mm512_mul_pd(t, r.dx), in);
  ay = addHalves(ay, _mm512_mul_pd(t, r.dy), in);
  az = addHalves(az, _mm512_mul_pd(t, r.dz), in);
}

[[gnu::target("arch=x86-64-v4")]] double dilatationAvx512(const LpsView& v, std::size_t i,
                                                          std::size_t b0, std::size_t b1) {
  const double* xi = v.x + i * v.nA;
  __m256d s = _mm256_setzero_pd();
  std::size_t b = b0;
  for (; b + 8 <= b1; b += 8) s = dilatation8(v, xi, v.partner + b, v.rows.pair + b, 0xff, s);
  if (b < b1) {
    Copy8 copy;
    const Last8 t = last8(v.partner, v.rows.pair, b, b1, v.bonds->count(), copy);
    s = dilatation8(v, xi, t.j, t.k, t.in, s);
  }
  return finish8(s);
}

[[gnu::target("arch=x86-64-v4")]] void forceAvx512(const LpsView& v, std::size_t i, std::size_t b0,
                                                   std::size_t b1, double qi, double invMi,
                                                   double acc[3]) {
  const double* xi = v.x + i * v.nA;
  const Particle c{_mm512_set1_pd(v.a), _mm512_set1_pd(v.b), _mm512_set1_pd(qi),
                   _mm512_set1_pd(invMi), _mm512_set1_pd(v.criticalStretch)};
  __m256d ax = _mm256_setzero_pd(), ay = _mm256_setzero_pd(), az = _mm256_setzero_pd();
  std::size_t b = b0;
  for (; b + 8 <= b1; b += 8)
    force8(v, xi, c, b0, b, v.partner + b, v.rows.pair + b, 0xff, ax, ay, az);
  if (b < b1) {
    Copy8 copy;
    const Last8 t = last8(v.partner, v.rows.pair, b, b1, v.bonds->count(), copy);
    force8(v, xi, c, b0, b, t.j, t.k, t.in, ax, ay, az);
  }
  acc[0] = finish8(ax);
  acc[1] = finish8(ay);
  acc[2] = finish8(az);
}

}  // namespace

LpsKernels lpsKernelsAvx512() { return {dilatationAvx512, forceAvx512, true}; }

}  // namespace pdq::peri
