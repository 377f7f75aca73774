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

}  // namespace pdq::mplm3d
