#pragma once
// Damage of a concrete interaction (thesis §4.3.2, eqs. 4.7–4.20). The thesis gives the
// shapes Ω_t, Ω_c only as a figure (4.3); we take linear force softening, which matches its
// numbers: the force rises elastically to the limit strain and falls linearly to zero at
// α times it, i.e. Ω(ε) = [α/(α−1)] (1 − ε_lim/ε). Both damages never decrease.
#include <algorithm>
#include <cmath>

namespace pdq::mplm {

struct DamageLaw {
  // Calibrated as §4.3.2 prescribes rather than copied from Table 4.2 (1.26e-4, β = 0.1):
  // ε_t ≈ f_t/E (2.758 MPa / 24.86 GPa), and β where the compressive/tensile strength
  // ratio, which §4.3.2 wants near 10, is highest on this lattice (docs/mplm.md).
  double epsT = 1.109e-4;  // ε_t: tensile limit of ε_mp+
  double alphaT = 10;      // α_t: ε_mp+ = α_t ε_t breaks the interaction
  double epsC = -1e-3;     // ε_c < 0: compressive limit of ε_mp−
  double alphaC = 5.728;   // α_c
  double beta = 0.05;      // β: weight of the curvature in ε_mp± (eqs. 4.11, 4.12)
  // Eq. 4.20 keeps the axial force of a compressed interaction whatever its damage, so a
  // lattice loaded along its bonds never crushes; `crushing` (default) lets ω_c take the
  // compressive axial force too (docs/mplm.md compares the two).
  bool crushing = true;

  // Ω of eqs. 4.13–4.18 for one limit: 0 up to it, 1 from α times it (eps/lim = ratio).
  static double omega(double ratio, double alpha) {
    if (ratio >= alpha) return 1;
    return alpha / (alpha - 1) * (1 - 1 / ratio);
  }
  // Updates ω_t, ω_c from ε_mp+ and ε_mp−; returns ω = max(ω_t, ω_c).
  double update(double epsPlus, double epsMinus, double& omegaT, double& omegaC) const {
    if (epsPlus > epsT) omegaT = std::max(omegaT, omega(epsPlus / epsT, alphaT));
    if (epsMinus < epsC) omegaC = std::max(omegaC, omega(epsMinus / epsC, alphaC));
    return std::max(omegaT, omegaC);
  }
};

}  // namespace pdq::mplm
