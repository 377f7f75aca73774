#pragma once
// ACI 318-11 strengths of a rectangular reinforced concrete section, as the thesis compares
// its MPLM results with (§4.4): flexure by the equivalent rectangular stress block, shear
// as V_c + V_s, both nominal (no strength-reduction factor φ), converted into a line load on
// a simply supported span or a cantilever's tip load. SI units throughout: m, m², Pa, N, N·m. The
// materials come from the scenario (studies/mplm_reference.hpp), so nothing here has a default
// strength.
#include <string>

namespace pdq::aci318 {

struct Section {
  double b = 0, h = 0, d = 0;  // width, total depth, effective depth (to the steel centroid)
  double As = 0;               // tension steel area
  double fc = 0;               // f'c
  double fy = 0, Es = 0;       // steel yield strength and modulus
  double Av = 0, sv = 0;       // stirrup area per spacing (all legs) and spacing; 0: none
  double fyt = 0;              // stirrup yield strength
  double lambda = 1;           // lightweight-concrete factor
};

// β₁ of §10.2.7.3: 0.85 up to 28 MPa, less 0.05 per 7 MPa above, not below 0.65.
double beta1(double fc);
// Depth c of the neutral axis from 0.85 f'c b β₁ c = A_s f_s, with f_s = min(f_y, E_s ε_s)
// and ε_s = 0.003 (d − c)/c (strain compatibility; the steel need not yield).
double neutralAxis(const Section& s);
// M_n = A_s f_s (d − a/2), a = β₁ c.
double flexuralStrength(const Section& s);
// M_cr = f_t b h² / 6: the classical "bending stress reaches f_t" strength of a plain beam.
double crackingMoment(double ft, double b, double h);
// V_c = 0.17 λ √f'c b d (eq. 11-3, f'c in MPa); V_s = A_v f_yt d / s ≤ 0.66 √f'c b d.
double concreteShear(const Section& s);
double steelShear(const Section& s);
double shearStrength(const Section& s);  // V_c + V_s

// Line load w (N/m) on a simply supported span L: from moment, w = 8M/L²; from shear,
// V at the critical section a distance d from the support (§11.1.3.1), w = V/(L/2 − d),
// or at the support itself, w = 2V/L.
double uniformLoadFromMoment(double M, double span);
double uniformLoadFromShear(double V, double span, double d, bool atCriticalSection = true);

struct Capacity {
  double flexure = 0, shear = 0;  // in the load form (N/m or N)
  double governing() const { return flexure < shear ? flexure : shear; }
  std::string mode() const { return flexure < shear ? "flexural" : "shear"; }
};
Capacity simplySupportedUniform(const Section& s, double span, bool atCriticalSection = true);
// A cantilever of length L under a tip load P (N): from moment, P = M/L (M at the support);
// from shear, P = V (the shear is P all along).
Capacity cantileverTip(const Section& s, double length);

}  // namespace pdq::aci318
