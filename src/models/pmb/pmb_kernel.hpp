#pragma once
// The PMB force kernel: the accelerations of a range of particles from their bonds (particle
// i's are v.bonds->begin(i) .. end(i)). Each particle's bonds are summed in four interleaved
// lanes (bond k of the particle goes to lane k mod 4) and the lanes are added as
// (l0 + l1) + (l2 + l3), so an AVX2 version can do four bonds at once and an AVX-512 one
// eight (two fours of one particle in turn, or four of each of two particles side by side);
// the portable version follows exactly the same order, so all give the same bits, on any
// machine and for any number of ranks or threads.
#include <cstddef>
#include <cstdint>

#include "engine/bonds.hpp"
#include "models/peri/bond_classes.hpp"
#include "models/peri/simd.hpp"

namespace pdq::peri {

struct PmbView {
  const std::int32_t* partner;  // local index of each bond's partner
  double* attr;                 // per bond: reference length, weight (0 once broken)
  BondRows rows;                // the same two by row, and the partners' rows (the vector
                                // kernels')
  const double* x;              // position rows (x, y, z first), nA doubles each
  std::size_t nA;
  double criticalStretch;  // 0: bonds never break
  Bonds* bonds;            // a bond that breaks is also killed here (the engine's flag)
};

// Particles [i0, i1); particle i's acceleration goes to acc[stride i ..].
using PmbForce = void (*)(const PmbView& v, std::size_t i0, std::size_t i1, double* acc,
                          std::size_t stride);

struct PmbKernel {
  PmbForce force;
  bool readRows;  // it reads PmbView::rows (else only attr)
};

// The kernel of the given width, or of the processor's widest if that is narrower.
PmbKernel pmbKernel(Simd width = widestSimd());
void pmbKernelPortable(const PmbView& v, std::size_t i0, std::size_t i1, double* acc,
                       std::size_t stride);
void pmbKernelAvx512(const PmbView& v, std::size_t i0, std::size_t i1, double* acc,
                     std::size_t stride);

}  // namespace pdq::peri
