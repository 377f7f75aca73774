#pragma once
// The force kernel of one particle: the sum of its Lennard-Jones pair forces (and pair
// energies and virials) over its Verlet list.
//
// Two passes. The first walks the list (sorted by global ID) and keeps the pairs closer
// than rc, in list order, without branches. The second evaluates the pair law on the kept
// pairs four at a time: kept pair q adds into accumulator lane q % 4, and the lanes are
// combined as (l0 + l1) + (l2 + l3). The kept pairs and their order depend only on the
// positions, never on the list's extra entries beyond rc, the memory layout or the time
// of the last rebuild, so the sums are the same bits on any processor grid and thread
// count. Lane-wise operations are plain IEEE additions, multiplications, divisions and
// square roots (no FMA contraction), so vector and scalar code agree bit for bit.
#include <cmath>
#include <cstdint>
#include <vector>

#include "models/lj/pair_lj.hpp"
#include "models/lj/verlet_list.hpp"

namespace pdq::lj {

// Per-thread buffers of the kept pairs (structure of arrays).
struct KernelScratch {
  std::vector<double> dx, dy, dz, r2;
  void reserve(std::size_t n) {
    const std::size_t m = n + 4;  // room for the padding of the last group of four
    if (dx.size() < m) dx.resize(m), dy.resize(m), dz.resize(m), r2.resize(m);
  }
};

struct PairSums {
  double f[3];  // force on the particle
  double u;     // sum of its pair energies (Energy only)
  double w;     // sum of its pair virials r·F(r) = r² F(r)/r (Energy only)
};

// xi: the particle's position; pos/stride: rows of positions (x, y, z first);
// [first, last): its Verlet list. `scratch` must hold last - first entries.
template <bool ForceShift, bool Energy>
[[gnu::always_inline]] inline PairSums pairSums(const PairLJ& pair, const double* xi,
                                                const double* pos, std::size_t stride,
                                                const std::uint32_t* first,
                                                const std::uint32_t* last, KernelScratch& scratch) {
  double* dx = scratch.dx.data();
  double* dy = scratch.dy.data();
  double* dz = scratch.dz.data();
  double* r2 = scratch.r2.data();
  const double x = xi[0], y = xi[1], z = xi[2], rc2 = pair.rc2;
  std::size_t m = 0;
  for (const std::uint32_t* k = first; k != last; ++k) {
    const double* xj = pos + std::size_t(*k) * stride;
    const double ex = x - xj[0], ey = y - xj[1], ez = z - xj[2];
    const double d2 = ex * ex + ey * ey + ez * ez;
    dx[m] = ex;
    dy[m] = ey;
    dz[m] = ez;
    r2[m] = d2;
    m += d2 < rc2;
  }
  // Pad the last group with harmless pairs: zero separation vector (so zero force) at
  // distance rc (finite terms); their energies are masked below.
  const std::size_t kept = m;
  for (; m % 4; ++m) dx[m] = dy[m] = dz[m] = 0, r2[m] = rc2;

  const double f12 = pair.f12, f6 = pair.f6, fc = pair.fc;
  double ax[4] = {0, 0, 0, 0}, ay[4] = {0, 0, 0, 0}, az[4] = {0, 0, 0, 0}, au[4] = {0, 0, 0, 0};
  double aw[4] = {0, 0, 0, 0};
  for (std::size_t q = 0; q < m; q += 4) {
    for (int l = 0; l < 4; ++l) {
      const double ir2 = 1 / r2[q + l];
      const double ir6 = ir2 * ir2 * ir2;
      double fr = (f12 * ir6 - f6) * ir6 * ir2;
      if constexpr (ForceShift) fr -= fc / std::sqrt(r2[q + l]);
      ax[l] += fr * dx[q + l];
      ay[l] += fr * dy[q + l];
      az[l] += fr * dz[q + l];
      if constexpr (Energy) {
        const double w = q + l < kept ? 1.0 : 0.0;
        au[l] += w * pair.energy(r2[q + l]);
        aw[l] += w * (fr * r2[q + l]);
      }
    }
  }
  PairSums s;
  s.f[0] = (ax[0] + ax[1]) + (ax[2] + ax[3]);
  s.f[1] = (ay[0] + ay[1]) + (ay[2] + ay[3]);
  s.f[2] = (az[0] + az[1]) + (az[2] + az[3]);
  s.u = (au[0] + au[1]) + (au[2] + au[3]);
  s.w = (aw[0] + aw[1]) + (aw[2] + aw[3]);
  return s;
}

// Forces (rows of three, unless `force` is null) and, if `energy` is not null, half the
// pair energy sums and half the pair virial sums (into `virial`) of particles
// [first, last), each along its list.
void pairSumsRange(const PairLJ& pair, const double* pos, std::size_t stride,
                   const VerletList& lists, long first, long last, double* force, double* energy,
                   double* virial, KernelScratch& scratch);

}  // namespace pdq::lj
