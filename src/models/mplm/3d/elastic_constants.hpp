#pragma once
// The elastic constants of the 3D fcc lattice (12 nearest neighbours at s, 6 second
// nearest at √2 s). Nearest neighbours are frame elements (axial a, bending b, torsion c);
// the 12 alone are isotropic only at ν = 0, so the second nearest carry an axial spring a₂.
// Equating the lattice's strain energy under a uniform strain to the continuum's gives
//   a = E s² / (2√2 (1+ν)(1−2ν)),  b = E s⁴ (1−4ν) / (24√2 (1+ν)(1−2ν)),
//   a₂ = E s² ν / (2 (1+ν)(1−2ν)),
// (needs 0 ≤ ν < 1/4; checked by tests/mplm3d/patch_test.cpp). Torsion does not enter a
// uniform strain; c = b/(1+ν), the ratio G J / E I of a circular section.
namespace pdq::mplm3d {

struct ElasticConstants {
  double a = 0;   // nearest neighbours: axial force = (a/d)·elongation (N)
  double b = 0;   // bending: end moment = (b/d)(4θ̄_i + 2θ̄_j) (N·m²)
  double c = 0;   // torsion: moment = (c/d)(θ̄x_j − θ̄x_i) (N·m²)
  double a2 = 0;  // second nearest: axial force = (a₂/d)·elongation (N)
};

// Throws std::domain_error unless 0 ≤ ν < 1/4.
ElasticConstants isotropicFcc(double E, double nu, double s);

// The fracture energy G_F a crack normal to a bond direction dissipates when every
// interaction crossing it breaks, and the α_t that gives it. The lattice has √2/s³
// particles per unit volume; of its bond directions, the 6 nearest (length s) have
// Σ|d·n| = 3s and the 3 second nearest (√2 s) Σ|d·n| = 2s, so per unit area 3√2/s² nearest
// and 2√2/s² second-nearest interactions cross the plane. Under linear softening each
// dissipates ½ (a/L) L² ε_t² α_t = ½ a L ε_t² α_t (a₂ for the second nearest), so
//   G_F = (ε_t² α_t / s)(3a/√2 + 2a₂) = E s ε_t² α_t (3/4 + ν) / ((1+ν)(1−2ν)),
// proportional to s at a fixed α_t; hence α_t = G_F s / (ε_t² (3√2/2 a + 2 a₂)).
double alphaFromFractureEnergy(const ElasticConstants& k, double s, double GF, double epsT);

}  // namespace pdq::mplm3d
