#pragma once
// What an MPLM interaction is whatever the lattice's dimension (thesis §4.3, §4.4): which
// particles interact, of which kind, the steel bars' elastic–perfectly plastic stretch, the
// stiffness of a steel–concrete link, and the damping of eq. 4.21.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "models/mplm/common/damage.hpp"

namespace pdq::mplm {

// Concrete interactions damage; Elastic ones (steel–concrete links, or concrete with damage
// off) never do; Bar ones are steel, elastic–perfectly plastic in stretch.
enum class Kind : std::uint8_t { Concrete, Elastic, Bar };

// One end of a candidate pair as the interaction rule sees it.
struct End {
  bool steel;
  double bar;   // which bar (steel particles of different bars never interact)
  bool linked;  // steel bonded to the concrete around it
};

// Concrete–concrete within the horizon; steel–steel of the same bar within one spacing; a
// linked steel particle with concrete within one spacing (not at distance zero).
inline bool interacts(const End& i, const End& j, double distance, double horizon, double s) {
  const double within = s * (1 + 1e-6);
  if (!i.steel && !j.steel) return distance <= horizon;
  if (i.steel && j.steel) return i.bar == j.bar && distance <= within;
  return (i.steel ? i.linked : j.linked) && distance > 0 && distance <= within;
}

inline Kind kindOf(bool steelI, bool steelJ, bool damage) {
  if (steelI && steelJ) return Kind::Bar;
  if (steelI || steelJ) return Kind::Elastic;  // links never damage (§4.4)
  return damage ? Kind::Concrete : Kind::Elastic;
}

// The plastic strain of a bar after a total axial strain `strain`: it follows the yield
// limit ±epsY once the elastic part would exceed it, and stays otherwise.
inline double plasticStrain(double strain, double plastic, double epsY) {
  const double elastic = strain - plastic;
  if (elastic > epsY) return strain - epsY;
  if (elastic < -epsY) return strain + epsY;
  return plastic;
}

// What an interaction's strain energy carries at the damage and plastic strain held in
// `state` (ω_t, ω_c, plastic strain; null: undamaged), for elongation da of a reference
// length L0: the axial and the bending/torsion factors and the elastic stretch.
struct Held {
  double axialKeep, bendKeep, stretch;
};
inline Held held(Kind kind, double da, double L0, const DamageLaw& law, const double* state) {
  Held h{1, 1, da};
  if (state && kind == Kind::Concrete) {
    h.bendKeep = 1 - std::max(state[0], state[1]);
    h.axialKeep = da >= 0 ? h.bendKeep : (law.crushing ? 1 - state[1] : 1.0);
  } else if (state && kind == Kind::Bar) {
    h.stretch = da - state[2] * L0;
  }
  return h;
}

// Stiffness of a steel–concrete link of length L from a concrete constant c of a lattice at
// spacing s. "concrete": the translational stiffness of a concrete interaction whatever the
// distance, so a short link does not stiffen the lattice (axial c/s; a bending constant b
// acts across as 12 b/L³, hence b L²/s³); "length": the interaction's form with the actual
// length (c/L).
inline double linkAxial(const std::string& mode, double a, double s, double L) {
  return mode == "concrete" ? a / s : a / L;
}
inline double linkBending(const std::string& mode, double b, double s, double L) {
  return mode == "concrete" ? b * L * L / (s * s * s) : b / L;
}

// Eq. 4.21 with ω_n = √(k/m) of the interaction: c = 2ζ √(k m), m the pair's harmonic
// mean mass (the particle mass for like particles). For rotation pass the rotational
// stiffness and the moments of inertia.
inline double dampingCoefficient(double zeta, double k, double mi, double mj) {
  const double m = 2 * mi * mj / (mi + mj);
  return 2 * zeta * std::sqrt(k * m);
}

}  // namespace pdq::mplm
