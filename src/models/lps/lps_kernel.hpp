#pragma once
// The LPS kernels: the dilatation sum and the acceleration of one particle from its bonds.
// As for PMB (pmb_kernel.hpp), bonds are summed in four interleaved lanes added as
// (l0 + l1) + (l2 + l3); the portable, AVX2 and AVX-512 versions give the same bits.
#include <cstddef>
#include <cstdint>

#include "engine/bonds.hpp"
#include "models/peri/bond_classes.hpp"
#include "models/peri/simd.hpp"

namespace pdq::peri {

struct LpsView {
  const std::int32_t* partner;  // local index of each bond's partner
  double* attr;                 // per bond: reference length, ω V_j w (0 once broken), 1/m_j
  BondRows rows;                // reference length and weight by row (the vector kernels')
  const double* x;              // position rows (x, y, z first), nA doubles each; the
                                // vector kernels read 1/m of the particle in column 3
  std::size_t nA;
  const double* theta;     // dilatation of every local particle (owned and ghosts)
  double a, b;             // A/ρ and B/ρ of the force state
  double criticalStretch;  // 0: bonds never break
  Bonds* bonds;            // a bond that breaks is also killed here (the engine's flag)
};

struct LpsKernels {
  // Σ_b ω V_j w |ξ| e over bonds [b0, b1) of particle i.
  double (*dilatation)(const LpsView& v, std::size_t i, std::size_t b0, std::size_t b1);
  // Acceleration of particle i (qi = θ_i / m_i, invMi = 1 / m_i); breaks overstretched bonds.
  void (*force)(const LpsView& v, std::size_t i, std::size_t b0, std::size_t b1, double qi,
                double invMi, double acc[3]);
  bool readRows;  // the kernels read LpsView::rows (else only attr)
};

// The kernels of the given width, or of the processor's widest if that is narrower.
LpsKernels lpsKernels(Simd width = widestSimd());
LpsKernels lpsKernelsPortable();
LpsKernels lpsKernelsAvx512();

}  // namespace pdq::peri
