#pragma once
// The force kernel: Lennard-Jones pair forces (and pair energies and virials) over half
// Verlet lists, each pair computed once, summed EXACTLY so that the order of the pairs —
// which depends on the memory layout, the processor grid and the thread count — does not
// change a bit of the result.
//
// Exact sums. Every pair term t is split into t = h + l + e with h on a grid of step Q1
// and l on a grid of step Q2 = Q1 / 2^40, each by rounding to the nearest grid point
// ((t + M) - M with M = 1.5 * 2^52 * Q, exact for |t| < 2^51 Q); the remainder e is below
// Q2 / 2 and dropped. Sums of grid values stay on the grid and, while they are below
// 2^53 grid steps, are exact: the same bits in any order. A particle's value is then
// (sum of h) + (sum of l), rounded once. Q1 = 2^-20 and Q2 = 2^-60 of the term's scale
// (24 epsilon / sigma for forces, epsilon for energies and virials): the terms keep about
// 60 bits below their scale, finer than a double sum of them would; the model refuses
// pairs so close that a term could leave the grid's exact range (`closest`).
//
// The split is odd in t (rounding to nearest, ties to even, is symmetric), so the term
// the owned partner j receives, -h and -l, is exactly what j's own evaluation of the pair
// (separation x_j - x_i, the same distance) would give: a pair split across ranks (each
// rank computing its own side against a ghost) adds the same bits as the pair within one
// rank.
//
// Three passes per particle: the list's pairs closer than rc are kept without branches
// (structure of arrays; eight candidates at a time, gathered and compressed, where the
// processor has AVX-512); the pair law is evaluated on them four at a time, vectorised;
// the owned partners receive their terms (scalar scatter).
#include <cmath>
#include <cstdint>
#include <vector>

#include "models/lj/pair_lj.hpp"
#include "models/lj/verlet_list.hpp"

namespace pdq::lj {

// The two grids of one kind of term.
struct Grid {
  Grid() = default;
  explicit Grid(double scale) {
    const int e = std::ilogb(scale);
    m1 = std::ldexp(1.5, 52 + e - 20);
    m2 = std::ldexp(1.5, 52 + e - 60);
    limit = std::ldexp(1.0, e + 20);
  }
  // limit: the largest term allowed, 2^40 steps of Q1, so that 2^13 terms still sum
  // exactly (below 2^53 steps), and a term's remainder is at most 2^39 steps of Q2.
  double m1 = 0, m2 = 0, limit = 0;
};

[[gnu::always_inline]] inline void split(double t, const Grid& g, double& h, double& l) {
  h = (t + g.m1) - g.m1;
  l = ((t - h) + g.m2) - g.m2;
}

// Per-thread buffers of the kept pairs (structure of arrays).
struct KernelScratch {
  std::vector<double> dx, dy, dz, r2;
  std::vector<double> t[10];  // split terms of the kept pairs: f (h, l) x 3, u (h, l), w (h, l)
  std::vector<std::uint32_t> j;
  void reserve(std::size_t n) {
    const std::size_t m = n + 8;  // room for the padding, and for keepPairs' overrun
    if (dx.size() >= m) return;
    dx.resize(m), dy.resize(m), dz.resize(m), r2.resize(m), j.resize(m);
    for (auto& v : t) v.resize(m);
  }
};

// Accumulator rows per owned particle: force (hx, hy, hz, lx, ly, lz), and energy and
// virial (hu, lu, hw, lw).
constexpr int kForceRow = 6, kEnergyRow = 4;

struct KernelOut {
  double* force = nullptr;   // kForceRow per owned particle, added to
  double* energy = nullptr;  // kEnergyRow per owned particle, added to (null: forces only)
  double closest2 = 0;       // smallest r^2 of a kept pair, lowered
};

// The first pass for one particle at (x, y, z): of its partners k in [first, last) (rows
// `stride` doubles apart in pos, x y z first), those closer than sqrt(rc2) are appended at
// `m` to the kept pairs, with their separations x_i − x_k and squared distances; returns the
// new count. May write 8 entries past it.
std::size_t keepPairs(const double* pos, std::size_t stride, const std::uint32_t* first,
                      const std::uint32_t* last, double x, double y, double z, double rc2,
                      KernelScratch& s, std::size_t m);
// The same in AVX-512 (avx512.cpp), for processors that have it (x86-64-v4) and rows of at
// least four doubles (it loads four a row): the same operations, so the same bits.
std::size_t keepPairsAvx512(const double* pos, std::size_t stride, const std::uint32_t* first,
                            const std::uint32_t* last, double x, double y, double z, double rc2,
                            KernelScratch& s, std::size_t m);

// The third pass's forces: each owned partner j[q], q < owned, receives the opposite of
// the pair's force terms (its row of `force`, kForceRow wide, less t[0..5][q]).
void giveForces(const KernelScratch& s, std::size_t owned, double* force);
// The same in AVX-512 (avx512.cpp): a partner's row at once, the same subtractions.
void giveForcesAvx512(const KernelScratch& s, std::size_t owned, double* force);

// The passes the kernel uses: the AVX-512 ones where the processor has it, else the
// portable ones (and keepPairs for rows of fewer than four doubles).
using KeepPairs = std::size_t (*)(const double*, std::size_t, const std::uint32_t*,
                                  const std::uint32_t*, double, double, double, double,
                                  KernelScratch&, std::size_t);
KeepPairs chosenKeepPairs();
using GiveForces = void (*)(const KernelScratch&, std::size_t, double*);
GiveForces chosenGiveForces();

// Adds the terms of the pairs of owned particles [first, last) to `out`. pos/stride: rows
// of positions (x, y, z first) of the local particles. `portable`: the portable passes even
// where the processor has AVX-512 (the same bits, for checking).
void pairSumsRange(const PairLJ& pair, const Grid& forceGrid, const Grid& energyGrid,
                   const double* pos, std::size_t stride, const VerletList& lists, long first,
                   long last, KernelOut& out, KernelScratch& scratch, bool portable);

}  // namespace pdq::lj
