#pragma once
// One interaction ij of the 2D MPLM (thesis eq. 4.3, Fig. 4.2) as the particle i sees it:
// constants fixed at start-up, and the force and moment it exerts on i. Everything is
// written so that i and j, each computing the interaction from its own side, get the same
// bits for the shared quantities (stretch, chord rotation, damage): swapping ends negates
// both the chord and the reference direction exactly, and the two end curvatures enter
// through a commutative max.
#include <cmath>
#include <cstdint>

#include "models/mplm/common/damage.hpp"
#include "models/mplm/common/interactions.hpp"

namespace pdq::mplm {

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

// Deformation of the interaction: elongation, chord length and direction e, and the end
// rotations relative to the chord (θ̄_i, θ̄_j), which bend it.
struct Chord {
  double da, invL, ex, ey, ti, tj;  // invL: 1 / chord length
};

// Small deformation: reference geometry, linearised stretch and chord rotation φ.
inline Chord smallChord(const Interaction& k, double dux, double duy, double thi, double thj) {
  const double da = dux * k.n0x + duy * k.n0y;
  const double phi = (duy * k.n0x - dux * k.n0y) * k.invL0;
  return {da, k.invL0, k.n0x, k.n0y, thi - phi, thj - phi};
}

// The angle from the chord r (length L) to the particle's turned reference direction
// R(θ) n0, i.e. θ − φ of the co-rotational form, from (cos θ, sin θ); always in (−π, π],
// so particles that spun whole turns stay consistent. Intact interactions bend by small
// angles: there sin(θ − φ) = (r × R(θ)n0)/L and a short arcsine series is exact to
// round-off, much cheaper than atan2.
inline double relativeAngle(const Interaction& k, double rx, double ry, double invL, double c,
                            double s) {
  const double dx = c * k.n0x - s * k.n0y, dy = s * k.n0x + c * k.n0y;
  const double y = rx * dy - ry * dx, x = rx * dx + ry * dy;
  const double z = y * invL;
  if (x > 0 && std::fabs(z) <= 0.1) {
    const double z2 = z * z;  // asin z, error below 0.03 z¹¹ ≤ 3e-13 z
    return z * (1 + z2 * (1.0 / 6 + z2 * (3.0 / 40 + z2 * (5.0 / 112 + z2 * (35.0 / 1152)))));
  }
  return std::atan2(y, x);
}

// Co-rotational (Crisfield): the current chord carries the local frame, so rigid motions of
// any size give no force; (ci, si), (cj, sj) are cos and sin of the end rotations.
inline Chord corotChord(const Interaction& k, double rx, double ry, double ci, double si, double cj,
                        double sj) {
  const double L = std::sqrt(rx * rx + ry * ry), invL = 1 / L;
  return {L - k.L0,
          invL,
          rx * invL,
          ry * invL,
          relativeAngle(k, rx, ry, invL, ci, si),
          relativeAngle(k, rx, ry, invL, cj, sj)};
}

struct EndLoad {
  double fx, fy, m;  // force and moment of the interaction on particle i
  double keep;       // 1 − ω while the interaction carries axial force (damping follows it)
};

// The elastic force on i after damage, updating the interaction's state (ω_t, ω_c, plastic stretch)
// in `state`. `update` is false for read-only evaluation (stress output), which leaves state alone;
// a null `state` gives the undamaged elastic interaction (frequency estimate).
inline EndLoad elasticForce(const Interaction& k, const Chord& ch, const DamageLaw& law,
                            double* state, bool update) {
  const double ti = ch.ti, tj = ch.tj;
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
    bendKeep = 1 - omega;  // eqs. 4.19, 4.20: shear and moment always
    // Axial force only in tension (K* in compression), unless crushing is on: then the
    // compressive damage ω_c also takes the axial force in compression.
    axialKeep = epsA >= 0 ? bendKeep : (law.crushing ? 1 - omC : 1.0);
  } else if (state && k.kind == Kind::Bar) {
    const double plastic = plasticStrain(epsA, state[2], k.epsY);
    if (update) state[2] = plastic;
    stretch = ch.da - plastic * k.L0;
  }
  const double N = k.ka * stretch * axialKeep;            // tension positive: pulls i toward j
  const double Mi = k.kb * (4 * ti + 2 * tj) * bendKeep;  // end moments on the element
  const double Mj = k.kb * (2 * ti + 4 * tj) * bendKeep;
  const double V = (Mi + Mj) * ch.invL;  // element end shear at i, along e⊥ = (−e_y, e_x)
  return {N * ch.ex + V * ch.ey, N * ch.ey - V * ch.ex, -Mi, axialKeep};
}

// The strain energy of the interaction at the damage and plastic stretch held in `state`
// (null: undamaged), which it leaves alone: elasticForce at that state is minus its gradient.
inline double elasticEnergy(const Interaction& k, const Chord& ch, const DamageLaw& law,
                            const double* state) {
  const double ti = ch.ti, tj = ch.tj;
  const Held h = held(k.kind, ch.da, k.L0, law, state);
  // ½ N·stretch, and ½ (M_i θ̄_i + M_j θ̄_j) with the end moments of eq. 4.3.
  return 0.5 * k.ka * h.stretch * h.stretch * h.axialKeep +
         2 * k.kb * (ti * ti + ti * tj + tj * tj) * h.bendKeep;
}

}  // namespace pdq::mplm
