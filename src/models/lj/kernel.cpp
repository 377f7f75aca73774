#include "models/lj/kernel.hpp"

#include <algorithm>
#include <cstring>

namespace pdq::lj {

namespace {

// Vectors of four doubles (GCC's vector extension): one ymm register where the clone has
// AVX, two xmm ones where not. The helpers are inlined, so the ABI note does not apply.
#pragma GCC diagnostic ignored "-Wpsabi"
using V4 = double __attribute__((vector_size(32)));
// Eight: one zmm register, for the clone that has AVX-512 (the others never take it).
using V8 = double __attribute__((vector_size(64)));
template <class V>
[[gnu::always_inline]] inline V load(const double* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <class V>
[[gnu::always_inline]] inline V splat(double x) {
  return V{} + x;
}

// Splits a vector of terms onto the grid (see kernel.hpp), stores the parts and adds them up.
template <class V>
[[gnu::always_inline]] inline void splitInto(V t, const Grid& g, double* h, double* l, V& sumH,
                                             V& sumL) {
  const V hi = (t + g.m1) - g.m1;
  const V lo = ((t - hi) + g.m2) - g.m2;
  std::memcpy(h, &hi, sizeof hi);
  std::memcpy(l, &lo, sizeof lo);
  sumH += hi;
  sumL += lo;
}

// The force of the pair law over r, f(r)/r, for a vector of squared distances.
template <bool ForceShift, class V>
[[gnu::always_inline]] inline V forceOverR(V d2, double f12, double f6, double fc) {
  const V ir2 = 1 / d2;
  const V ir6 = ir2 * ir2 * ir2;
  V fr = (f12 * ir6 - f6) * ir6 * ir2;
  if constexpr (ForceShift) {
    V r = {};
    for (unsigned l = 0; l < sizeof(V) / sizeof(double); ++l) r[l] = std::sqrt(d2[l]);
    fr -= fc / r;
  }
  return fr;
}

// The portable first pass (keepPairs), inlined into each clone of the kernel.
[[gnu::always_inline]] inline std::size_t keep(const double* pos, std::size_t stride,
                                               const std::uint32_t* k, const std::uint32_t* last,
                                               double x, double y, double z, double rc2,
                                               KernelScratch& s, std::size_t m) {
  double* dx = s.dx.data();
  double* dy = s.dy.data();
  double* dz = s.dz.data();
  double* r2 = s.r2.data();
  std::uint32_t* jj = s.j.data();
  for (; k != last; ++k) {
    const double* xj = pos + std::size_t(*k) * stride;
    const double ex = x - xj[0], ey = y - xj[1], ez = z - xj[2];
    const double d2 = ex * ex + ey * ey + ez * ez;
    dx[m] = ex;
    dy[m] = ey;
    dz[m] = ez;
    r2[m] = d2;
    jj[m] = *k;
    m += d2 < rc2;
  }
  return m;
}

// The portable third pass's forces (giveForces), inlined into each clone of the kernel.
[[gnu::always_inline]] inline void give(const KernelScratch& s, std::size_t owned, double* force) {
  for (std::size_t q = 0; q < owned; ++q) {
    double* fj = force + std::size_t(s.j[q]) * kForceRow;
    for (int c = 0; c < 6; ++c) fj[c] -= s.t[c][q];
  }
}

template <bool ForceShift, bool Energy>
[[gnu::always_inline]] inline void particle(const PairLJ& pair, const Grid& fg, const Grid& eg,
                                            std::size_t i, const double* pos, std::size_t stride,
                                            const VerletList& lists, KernelOut& out,
                                            KernelScratch& s, bool avx512, bool wide) {
  double* dx = s.dx.data();
  double* dy = s.dy.data();
  double* dz = s.dz.data();
  double* r2 = s.r2.data();
  const std::uint32_t* jj = s.j.data();
  const double* xi = pos + i * stride;
  const double x = xi[0], y = xi[1], z = xi[2], rc2 = pair.rc2;
  // 1. Keep the pairs closer than rc: owned partners first, then ghosts.
  std::size_t m = 0, owned = 0;
  if (wide) {
    owned = keepPairsAvx512(pos, stride, lists.begin(i), lists.ghosts(i), x, y, z, rc2, s, 0);
    m = keepPairsAvx512(pos, stride, lists.ghosts(i), lists.end(i), x, y, z, rc2, s, owned);
  } else {
    owned = keep(pos, stride, lists.begin(i), lists.ghosts(i), x, y, z, rc2, s, 0);
    m = keep(pos, stride, lists.ghosts(i), lists.end(i), x, y, z, rc2, s, owned);
  }
  // Pad the last group with harmless pairs: zero separation vector (so zero force) at
  // distance rc (finite terms); their energies are masked below.
  const std::size_t kept = m;
  for (; m % 4; ++m) dx[m] = dy[m] = dz[m] = 0, r2[m] = rc2;

  // 2. The pair law, four pairs at a time (one vector of four lanes), each term split
  //    onto the exact grids. Lane operations are plain IEEE ones, as in scalar code.
  const double f12 = pair.f12, f6 = pair.f6, fc = pair.fc;
  double* t[10];
  for (int c = 0; c < 10; ++c) t[c] = s.t[c].data();
  const double* d[3] = {dx, dy, dz};
  V4 acc[10] = {};
  V4 low = splat<V4>(rc2);
  std::size_t q = 0;
  if constexpr (!Energy) {
    if (avx512) {
      // Eight at a time while eight are left; the sums are exact, so their order is free.
      V8 acc8[6] = {};
      V8 low8 = splat<V8>(rc2);
      for (; q + 8 <= m; q += 8) {
        const V8 d2 = load<V8>(r2 + q);
        low8 = d2 < low8 ? d2 : low8;
        const V8 fr = forceOverR<ForceShift>(d2, f12, f6, fc);
        for (int a = 0; a < 3; ++a)
          splitInto(fr * load<V8>(d[a] + q), fg, t[a] + q, t[3 + a] + q, acc8[a], acc8[3 + a]);
      }
      for (int c = 0; c < 6; ++c) acc[c] += load<V4>(&acc8[c][0]) + load<V4>(&acc8[c][4]);
      const V4 lo = load<V4>(&low8[0]), hi = load<V4>(&low8[4]);
      low = lo < hi ? lo : hi;
    }
  }
  for (; q < m; q += 4) {
    const V4 d2 = load<V4>(r2 + q);
    low = d2 < low ? d2 : low;
    const V4 fr = forceOverR<ForceShift>(d2, f12, f6, fc);
    for (int a = 0; a < 3; ++a)
      splitInto(fr * load<V4>(d[a] + q), fg, t[a] + q, t[3 + a] + q, acc[a], acc[3 + a]);
    if constexpr (Energy) {
      // Half of each pair's energy and virial goes to each particle; padding adds nothing.
      V4 u;
      for (int l = 0; l < 4; ++l) u[l] = q + l < kept ? 0.5 * pair.energy(d2[l]) : 0.0;
      const V4 w = q + 4 <= kept ? splat<V4>(0.5)
                                 : V4{q < kept ? 0.5 : 0.0, q + 1 < kept ? 0.5 : 0.0,
                                      q + 2 < kept ? 0.5 : 0.0, 0.0};
      splitInto(u, eg, t[6] + q, t[7] + q, acc[6], acc[7]);
      splitInto(w * (fr * d2), eg, t[8] + q, t[9] + q, acc[8], acc[9]);
    }
  }
  // 3. The owned partners' terms: the opposite force, the same energy and virial.
  if (avx512)
    giveForcesAvx512(s, owned, out.force);
  else
    give(s, owned, out.force);
  if constexpr (Energy) {
    for (std::size_t q = 0; q < owned; ++q) {
      double* ej = out.energy + std::size_t(jj[q]) * kEnergyRow;
      for (int c = 0; c < 4; ++c) ej[c] += t[6 + c][q];  // the same half
    }
  }
  double* fi = out.force + i * kForceRow;
  for (int c = 0; c < 6; ++c) fi[c] += (acc[c][0] + acc[c][1]) + (acc[c][2] + acc[c][3]);
  if constexpr (Energy) {
    double* ei = out.energy + i * kEnergyRow;
    for (int c = 0; c < 4; ++c)
      ei[c] += (acc[6 + c][0] + acc[6 + c][1]) + (acc[6 + c][2] + acc[6 + c][3]);
  }
  out.closest2 = std::min({out.closest2, low[0], low[1], low[2], low[3]});
}

template <bool ForceShift, bool Energy>
[[gnu::always_inline]] inline void range(const PairLJ& pair, const Grid& fg, const Grid& eg,
                                         const double* pos, std::size_t stride,
                                         const VerletList& lists, long first, long last,
                                         KernelOut& out, KernelScratch& scratch, bool portable) {
  static const bool give512 = chosenGiveForces() == giveForcesAvx512;
  static const bool keep512 = chosenKeepPairs() == keepPairsAvx512;
  const bool avx512 = give512 && !portable;
  const bool wide = keep512 && !portable && stride >= 4;  // keepPairsAvx512 loads 4 a row
  for (long i = first; i < last; ++i)
    particle<ForceShift, Energy>(pair, fg, eg, i, pos, stride, lists, out, scratch, avx512, wide);
}

}  // namespace

void giveForces(const KernelScratch& s, std::size_t owned, double* force) { give(s, owned, force); }

KeepPairs chosenKeepPairs() {
  return __builtin_cpu_supports("x86-64-v4") ? keepPairsAvx512 : keepPairs;
}

GiveForces chosenGiveForces() {
  return __builtin_cpu_supports("x86-64-v4") ? giveForcesAvx512 : giveForces;
}

std::size_t keepPairs(const double* pos, std::size_t stride, const std::uint32_t* first,
                      const std::uint32_t* last, double x, double y, double z, double rc2,
                      KernelScratch& s, std::size_t m) {
  return keep(pos, stride, first, last, x, y, z, rc2, s, m);
}

// Compiled for several instruction sets, chosen at load time. The arithmetic is the same
// IEEE operations on each (no FMA contraction), and the sums are exact anyway.
[[gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")]] void pairSumsRange(
    const PairLJ& pair, const Grid& fg, const Grid& eg, const double* pos, std::size_t stride,
    const VerletList& lists, long first, long last, KernelOut& out, KernelScratch& scratch,
    bool portable) {
  const bool fs = pair.shift == Shift::Force;
  if (out.energy) {
    if (fs)
      range<true, true>(pair, fg, eg, pos, stride, lists, first, last, out, scratch, portable);
    else
      range<false, true>(pair, fg, eg, pos, stride, lists, first, last, out, scratch, portable);
  } else {
    if (fs)
      range<true, false>(pair, fg, eg, pos, stride, lists, first, last, out, scratch, portable);
    else
      range<false, false>(pair, fg, eg, pos, stride, lists, first, last, out, scratch, portable);
  }
}

}  // namespace pdq::lj
