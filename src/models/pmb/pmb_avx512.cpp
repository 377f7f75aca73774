// The PMB kernel eight bonds at a time (for x86-64-v4, called only where the processor has
// it): one square root and one division instruction for eight bonds. The bits are those of
// the other kernels (rows8.hpp says how).
//
// Particles go two at a time, four bonds of each to a group: the low half of the sums holds
// the first particle's four lane sums and the high half the second's, so a group's forces are
// added in one instruction where one particle's eight take two in turn, and each lane's chain
// of additions is half as long a bond.
#include <algorithm>

#include "models/peri/rows8.hpp"
#include "models/pmb/pmb_kernel.hpp"

namespace pdq::peri {
namespace {

// Four bonds of one particle, b .. b + 3 (the particle's first bond b0): j their partners'
// row offsets, k their pair offsets.
struct Four {
  const std::int32_t* j;
  const std::uint32_t* k;
  std::size_t b0, b;
};

// Four bonds b .. b + 3 read in place.
inline Four four(const PmbView& v, std::size_t b0, std::size_t b) {
  return {v.rows.at + b, v.rows.pair + b, b0, b};
}

struct Force8 {
  __m512d x, y, z;
};

// Breaks the bonds of the lanes `over` holds: bonds a .. a + 3 of the particle whose bonds
// start at a0 in lanes 0-3, bonds b .. b + 3 of the one whose bonds start at b0 in lanes 4-7.
// Out of line, and given numbers rather than the groups, so that the loop keeps its
// registers.
[[gnu::noinline, gnu::cold]] void breakLanes(const PmbView& v, __mmask8 over, std::size_t a0,
                                             std::size_t a, std::size_t b0, std::size_t b) {
  break8(over & 0xf, a0, a, v.attr, 2, v.bonds, v.rows);
  break8(over >> 4, b0, b, v.attr, 2, v.bonds, v.rows);
}

// The forces of bonds lo (lanes 0-3) and hi (lanes 4-7), before they are added; only the
// lanes `in` holds are bonds. kBreaks: bonds can break (a critical stretch is set); the
// kernel is made with and without the test, so that a run whose bonds never break skips it.
template <bool kBreaks>
[[gnu::target("arch=x86-64-v4"), gnu::always_inline]] inline Force8 eight(
    const PmbView& v, const Xi8& xi, const Four& lo, const Four& hi, __mmask8 in) {
  const Rows8 r = rows8(v.x, 1, lo.j, hi.j, xi);
  auto [len0, w] = pairs8(v.rows, lo.k, hi.k);
  const __m512d ext = _mm512_sub_pd(r.len, len0);
  if (kBreaks) {
    // Bonds of weight 0 have broken already: only the others are judged.
    const __mmask8 live = _mm512_mask_cmp_pd_mask(in, w, _mm512_setzero_pd(), _CMP_NEQ_UQ);
    const __mmask8 over = _mm512_mask_cmp_pd_mask(
        live, ext, _mm512_mul_pd(_mm512_set1_pd(v.criticalStretch), len0), _CMP_GT_OQ);
    if (over) {
      breakLanes(v, over, lo.b0, lo.b, hi.b0, hi.b);
      w = _mm512_maskz_mov_pd(static_cast<__mmask8>(~over), w);
    }
  }
  const __m512d t = _mm512_div_pd(_mm512_mul_pd(w, ext), r.len);
  return {_mm512_mul_pd(t, r.dx), _mm512_mul_pd(t, r.dy), _mm512_mul_pd(t, r.dz)};
}

// Lane sums of x, y and z.
struct Sums {
  __m256d x, y, z;
};

[[gnu::target("arch=x86-64-v4")]] inline void add(Sums& s, const Force8& f, __mmask8 in) {
  s.x = addHalves(s.x, f.x, in);
  s.y = addHalves(s.y, f.y, in);
  s.z = addHalves(s.z, f.z, in);
}

// The bonds [b, b1) of particle i (its first b0, b - b0 a multiple of four) added to its lane
// sums s, and the particle's force into acc.
template <bool kBreaks>
[[gnu::target("arch=x86-64-v4"), gnu::always_inline]] inline void one(const PmbView& v,
                                                                      std::size_t i, std::size_t b0,
                                                                      std::size_t b, std::size_t b1,
                                                                      Sums s, double* acc) {
  const Xi8 xi = xi8(v.x + i * v.nA);
  // Two groups at a time: the second's loads and square root overlap the first's division.
  for (; b + 16 <= b1; b += 16) {
    const Force8 f = eight<kBreaks>(v, xi, four(v, b0, b), four(v, b0, b + 4), 0xff);
    const Force8 g = eight<kBreaks>(v, xi, four(v, b0, b + 8), four(v, b0, b + 12), 0xff);
    add(s, f, 0xff);
    add(s, g, 0xff);
  }
  for (; b + 8 <= b1; b += 8)
    add(s, eight<kBreaks>(v, xi, four(v, b0, b), four(v, b0, b + 4), 0xff), 0xff);
  if (b < b1) {
    Copy8 copy;
    const Last8 t = last8(v.rows.at, v.rows.pair, b, b1, v.bonds->count(), copy);
    add(s, eight<kBreaks>(v, xi, {t.j, t.k, b0, b}, {t.j + 4, t.k + 4, b0, b + 4}, t.in), t.in);
  }
  acc[0] = finish8(s.x);
  acc[1] = finish8(s.y);
  acc[2] = finish8(s.z);
}

// Both particles' lane sums, the first's in the low half.
[[gnu::target("arch=x86-64-v4")]] inline void add(Force8& s, const Force8& f) {
  s.x = _mm512_add_pd(s.x, f.x);
  s.y = _mm512_add_pd(s.y, f.y);
  s.z = _mm512_add_pd(s.z, f.z);
}

// Particles i and i + 1 (bonds [a0, b0) and [b0, b1)): four bonds of each to a group while
// both have four left, then what one of them has left beside the other's next four, then each
// on its own.
template <bool kBreaks>
[[gnu::target("arch=x86-64-v4")]] inline void two(const PmbView& v, std::size_t i, std::size_t a0,
                                                  std::size_t b0, std::size_t b1, double* accA,
                                                  double* accB) {
  const Xi8 xi = xi8(v.x + i * v.nA, v.x + (i + 1) * v.nA);
  Force8 s{_mm512_setzero_pd(), _mm512_setzero_pd(), _mm512_setzero_pd()};
  std::size_t a = a0, b = b0;
  for (; a + 8 <= b0 && b + 8 <= b1; a += 8, b += 8) {
    const Force8 f = eight<kBreaks>(v, xi, four(v, a0, a), four(v, b0, b), 0xff);
    const Force8 g = eight<kBreaks>(v, xi, four(v, a0, a + 4), four(v, b0, b + 4), 0xff);
    add(s, f);
    add(s, g);
  }
  for (; a + 4 <= b0 && b + 4 <= b1; a += 4, b += 4)
    add(s, eight<kBreaks>(v, xi, four(v, a0, a), four(v, b0, b), 0xff));
  if (a < b0 && b < b1) {  // one of them, or both, with fewer than four left
    const std::size_t na = std::min<std::size_t>(b0 - a, 4), nb = std::min<std::size_t>(b1 - b, 4);
    Copy8 ca, cb;
    const Last8 ta = last8(v.rows.at, v.rows.pair, a, a + na, v.bonds->count(), ca);
    const Last8 tb = last8(v.rows.at, v.rows.pair, b, b + nb, v.bonds->count(), cb);
    const auto in = static_cast<__mmask8>(ta.in | tb.in << 4);
    const Force8 f = eight<kBreaks>(v, xi, {ta.j, ta.k, a0, a}, {tb.j, tb.k, b0, b}, in);
    s.x = _mm512_mask_add_pd(s.x, in, s.x, f.x);
    s.y = _mm512_mask_add_pd(s.y, in, s.y, f.y);
    s.z = _mm512_mask_add_pd(s.z, in, s.z, f.z);
    a += na;
    b += nb;
  }
  one<kBreaks>(v, i, a0, a, b0, {half(s.x, 0), half(s.y, 0), half(s.z, 0)}, accA);
  one<kBreaks>(v, i + 1, b0, b, b1, {half(s.x, 1), half(s.y, 1), half(s.z, 1)}, accB);
}

template <bool kBreaks>
[[gnu::target("arch=x86-64-v4")]] void particles(const PmbView& v, std::size_t i0, std::size_t i1,
                                                 double* acc, std::size_t stride) {
  std::size_t i = i0;
  for (; i + 2 <= i1; i += 2)
    two<kBreaks>(v, i, v.bonds->begin(i), v.bonds->begin(i + 1), v.bonds->end(i + 1),
                 acc + i * stride, acc + (i + 1) * stride);
  if (i < i1) {
    const __m256d zero = _mm256_setzero_pd();
    one<kBreaks>(v, i, v.bonds->begin(i), v.bonds->begin(i), v.bonds->end(i), {zero, zero, zero},
                 acc + i * stride);
  }
}

}  // namespace

void pmbKernelAvx512(const PmbView& v, std::size_t i0, std::size_t i1, double* acc,
                     std::size_t stride) {
  if (v.criticalStretch > 0)
    particles<true>(v, i0, i1, acc, stride);
  else
    particles<false>(v, i0, i1, acc, stride);
}

}  // namespace pdq::peri
