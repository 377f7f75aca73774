#pragma once
// The micropolar elastic constants a (axial, N) and b (bending, N·m²) of one interaction of
// the 2D hexagonal lattice (thesis §4.3.1). Each form equates the strain energy of the
// lattice under a uniform strain to that of the classical continuum, so the lattice gives
// back E and ν exactly away from boundaries (checked by tests/mplm/patch_test.cpp).
#include <string>

namespace pdq::mplm {

struct ElasticConstants {
  double a = 0;  // axial stiffness × length: force = (a/s)·elongation
  double b = 0;  // bending stiffness: end moment = (b/s)(4θi + 2θj − 6φ)
};

// Eq. 4.5: a = E s t / (√3 (1−ν)), b = E s³ (1−3ν) t / (12√3 (1−ν²)); needs ν < 1/3.
ElasticConstants planeStress(double E, double nu, double s, double t);
// Eq. 4.6 as printed implies two different thicknesses; energy equivalence gives
// a = E s t / (√3 (1+ν)(1−2ν)), b = E s³ t (1−4ν) / (12√3 (1+ν)(1−2ν)); needs ν < 1/4.
ElasticConstants planeStrain(double E, double nu, double s, double t);

// The constants for a named form ("plane_stress", "plane_strain"); throws std::domain_error
// when ν makes b negative.
ElasticConstants forContinuum(const std::string& form, double E, double nu, double s, double t);

}  // namespace pdq::mplm
