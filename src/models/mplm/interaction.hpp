#pragma once
// One interaction ij of the 2D MPLM (thesis eq. 4.3, Fig. 4.2) as the particle i sees it:
// constants fixed at start-up, and the force and moment it exerts on i. Everything is
// written so that i and j, each computing the interaction from its own side, get the same
// bits for the shared quantities (stretch, chord rotation, damage): swapping ends negates
// both the chord and the reference direction exactly, and the two end curvatures enter
// through a commutative max.
#include <cmath>
#include <cstdint>
#include <numbers>

#include "models/mplm/damage.hpp"

namespace pdq::mplm {

// Concrete interactions damage; Elastic ones (steel–concrete links, or concrete with damage
// off) never do; Bar ones are steel, elastic–perfectly plastic in stretch.
enum class Kind : std::uint8_t { Concrete, Elastic, Bar };

struct Interaction {
  std::int32_t j = 0;  // partner's local index
  Kind kind = Kind::Concrete;
  double r0x = 0, r0y = 0;   // reference chord X_j − X_i
  double n0x = 0, n0y = 0;   // its direction
  double L0 = 0, invL0 = 0;  // reference length d
  double ka = 0;             // axial stiffness a/d (N/m)
  double kb = 0;             // b/d: end moment M_i = kb (4θ̄_i + 2θ̄_j)
  double c = 0, cr = 0;      // damping of relative velocity and angular velocity
  double epsY = 0;           // bars: yield stretch F_y/E_s
};

// Deformation of the interaction: elongation, chord rotation φ and chord direction e.
struct Chord {
  double da, phi, L, ex, ey;
};

// Small deformation: reference geometry, linearised stretch and chord rotation.
inline Chord smallChord(const Interaction& k, double dux, double duy) {
  const double da = dux * k.n0x + duy * k.n0y;
  const double dt = duy * k.n0x - dux * k.n0y;
  return {da, dt * k.invL0, k.L0, k.n0x, k.n0y};
}

// Co-rotational (Crisfield): the current chord carries the local frame; φ is its rotation
// from the reference direction, so rigid motions of any size give no force.
inline Chord corotChord(const Interaction& k, double rx, double ry) {
  const double L = std::sqrt(rx * rx + ry * ry);
  const double phi = std::atan2(k.n0x * ry - k.n0y * rx, k.n0x * rx + k.n0y * ry);
  return {L - k.L0, phi, L, rx / L, ry / L};
}

// θ − φ brought into (−π, π], so particles that have spun whole turns stay consistent.
inline double wrapAngle(double a) {
  constexpr double twoPi = 2 * std::numbers::pi;
  if (a > std::numbers::pi || a < -std::numbers::pi) a -= twoPi * std::nearbyint(a / twoPi);
  return a;
}

struct EndLoad {
  double fx, fy, m;  // force and moment of the interaction on particle i
  double keep;       // 1 − ω while the interaction carries axial force (damping follows it)
};

// The elastic force on i after damage, given end rotations relative to the chord
// (ti, tj), updating the interaction's state (ω_t, ω_c, plastic stretch) in `state`.
// `update` is false for read-only evaluation (stress output), which leaves state alone;
// a null `state` gives the undamaged elastic interaction (frequency estimate).
inline EndLoad elasticForce(const Interaction& k, const Chord& ch, double ti, double tj,
                            const DamageLaw& law, double* state, bool update) {
  const double epsA = ch.da * k.invL0;  // eq. 4.7
  double axialKeep = 1, bendKeep = 1, stretch = ch.da;
  if (state && k.kind == Kind::Concrete) {
    // β d ψ with ψ = max end curvature (2/d)|2θ̄_end + θ̄_other| (eqs. 4.10–4.12).
    const double curv = 2 * law.beta * std::max(std::fabs(2 * ti + tj), std::fabs(2 * tj + ti));
    double omT = state[0], omC = state[1];
    const double omega = law.update(epsA + curv, epsA - curv, omT, omC);
    if (update) {
      state[0] = omT;
      state[1] = omC;
    }
    bendKeep = 1 - omega;                    // eqs. 4.19, 4.20: shear and moment always
    axialKeep = epsA >= 0 ? bendKeep : 1.0;  // axial only in tension (K* in compression)
  } else if (state && k.kind == Kind::Bar) {
    // Elastic–perfectly plastic axial force: the plastic stretch follows the yield limit.
    double plastic = state[2];
    const double elastic = epsA - plastic;
    if (elastic > k.epsY)
      plastic = epsA - k.epsY;
    else if (elastic < -k.epsY)
      plastic = epsA + k.epsY;
    if (update) state[2] = plastic;
    stretch = ch.da - plastic * k.L0;
  }
  const double N = k.ka * stretch * axialKeep;            // tension positive: pulls i toward j
  const double Mi = k.kb * (4 * ti + 2 * tj) * bendKeep;  // end moments on the element
  const double Mj = k.kb * (2 * ti + 4 * tj) * bendKeep;
  const double V = (Mi + Mj) / ch.L;  // element end shear at i, along e⊥ = (−e_y, e_x)
  return {N * ch.ex + V * ch.ey, N * ch.ey - V * ch.ex, -Mi, axialKeep};
}

}  // namespace pdq::mplm
