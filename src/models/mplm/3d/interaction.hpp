#pragma once
// One interaction ij of the 3D MPLM as particle i sees it: a 12 × 12 Euler–Bernoulli frame
// element (u, v, w, θx, θy, θz at each end) in the interaction's local frame (e1 along the
// chord): axial a/d, torsion c/d, and two bending planes with the 12b/d³, 6b/d², 4b/d,
// 2b/d pattern of thesis eq. 4.3. Written so that i and j, each computing the interaction
// from its own side, get the same bits for the shared quantities (stretch, curvatures,
// damage): swapping the ends negates the chord, e1 and e2 exactly and keeps e3, and every
// symmetric quantity is formed from commutative operations.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "engine/rotation.hpp"
#include "models/mplm/common/damage.hpp"
#include "models/mplm/common/interactions.hpp"

namespace pdq::mplm3d {

using mplm::Kind;

// The constants of an interaction; a lattice has few distinct sets, stored once each.
struct Stiffness {
  double ka = 0;         // axial stiffness a/d (N/m)
  double kb = 0;         // b/d: end moment M_i = kb (4θ̄_i + 2θ̄_j) in each bending plane
  double kt = 0;         // c/d: torsional moment kt (θ̄x_j − θ̄x_i)
  double c = 0, cr = 0;  // damping of relative velocity and angular velocity
  double epsY = 0;       // bars: yield stretch F_y/E_s
  Kind kind = Kind::Concrete;
  auto operator<=>(const Stiffness&) const = default;
};

// The geometry of one interaction end as its particle sees it: the reference direction n0
// of the chord X_j − X_i, the frame's second and third axes e2 and e3 = n0 × e2, the length
// d, and which Stiffness it has. Interactions share these (a lattice has few directions).
struct Interaction {
  Vec n0{}, e2{}, e3{};
  double L0 = 0, invL0 = 0;
  std::uint32_t type = 0;  // its Stiffness in the model's table
  auto operator<=>(const Interaction&) const = default;
};

// The reference frame (n0, e2, e3) of an interaction: e2 ⟂ n0 from the global axis along
// which n0 has its smallest component (first such axis on ties), e3 = n0 × e2. Under
// n0 → −n0: e2 → −e2 and e3 → e3, bit for bit.
inline void referenceFrame(const Vec& n0, Vec& e2, Vec& e3) {
  const double ax = std::fabs(n0[0]), ay = std::fabs(n0[1]), az = std::fabs(n0[2]);
  const int k = (ax <= ay && ax <= az) ? 0 : (ay <= az ? 1 : 2);
  Vec h{0, 0, 0};
  h[k] = 1;
  e2 = cross(n0, h);
  const double inv = 1 / std::sqrt(dot(e2, e2));
  e2 = {e2[0] * inv, e2[1] * inv, e2[2] * inv};
  e3 = cross(n0, e2);
}

// Sets the interaction's reference geometry from its chord r0: d, 1/d, n0, e2, e3.
inline void setReference(Interaction& k, const Vec& r0) {
  k.L0 = std::sqrt(dot(r0, r0));
  k.invL0 = 1 / k.L0;
  k.n0 = {r0[0] * k.invL0, r0[1] * k.invL0, r0[2] * k.invL0};
  referenceFrame(k.n0, k.e2, k.e3);
}

// The interaction as its other end holds it: n0 and e2 negate exactly, and e3 = n0 × e2
// stays (referenceFrame).
inline Interaction reversed(const Interaction& k) {
  Interaction r = k;
  r.n0 = {-k.n0[0], -k.n0[1], -k.n0[2]};
  r.e2 = {-k.e2[0], -k.e2[1], -k.e2[2]};
  return r;
}

// Two doubles side by side (GCC's vector extension): the co-rotational form carries the
// axes e2 and e3 together, in the two halves of one SSE register.
using Pair = double __attribute__((vector_size(16)));
inline Pair swapped(Pair p) { return Pair{p[1], p[0]}; }

// The co-rotational form's current geometry: the chord's direction e1 and the interaction's
// reference axes e2, e3 carried by each end's triad, t2 = R e2 and t3 = R e3, by component:
// ti[c] = (t2i[c], t3i[c]).
struct Frame {
  Vec e1;
  Pair ti[3], tj[3];
};

// Deformation of the interaction in its local frame: elongation, chord length, the end
// rotations relative to the chord in local components (θ̄x torsion, θ̄y, θ̄z bending; the
// co-rotational form holds the twist θ̄x_j − θ̄x_i in tj[0] and 0 in ti[0]), and (co-rotational
// form) the frame.
struct Chord {
  double da, invL;
  Vec ti, tj;
  Frame frame;
  bool rotated;
};

// Small deformation: reference geometry, linearised stretch and chord rotation
// φ = n0 × (u_j − u_i)/d; the end rotations are the rotation vectors minus φ.
inline Chord smallChord(const Interaction& k, const Vec& d, const Vec& thi, const Vec& thj) {
  const Vec phi = cross(k.n0, d);
  const Vec &e2 = k.e2, &e3 = k.e3;
  const Vec bi{thi[0] - phi[0] * k.invL0, thi[1] - phi[1] * k.invL0, thi[2] - phi[2] * k.invL0};
  const Vec bj{thj[0] - phi[0] * k.invL0, thj[1] - phi[1] * k.invL0, thj[2] - phi[2] * k.invL0};
  Chord c;  // its frame belongs to the co-rotational form: left unset, not zeroed each time
  c.da = dot(d, k.n0);
  c.invL = k.invL0;
  c.ti = {dot(bi, k.n0), dot(bi, e2), dot(bi, e3)};
  c.tj = {dot(bj, k.n0), dot(bj, e2), dot(bj, e3)};
  c.rotated = false;
  return c;
}

// Co-rotational: each end's triad carries the interaction's reference axes e2, e3 along;
// the end's bending rotations are read against the current chord direction e1, θ̄y = t3·e1
// and θ̄z = −t2·e1, and the twist between the ends is ½ (t3i·t2j − t2i·t3j). They are dot
// products of rotated vectors, so rigid motions of any size leave them unchanged (no force),
// and to first order they are the small form's θ̄ (the same stiffness at small deformation).
// Ri, Rj: the particles' rotation matrices.
inline Chord corotChord(const Interaction& k, const Vec& r, const Mat& Ri, const Mat& Rj) {
  const double L = std::sqrt(dot(r, r)), invL = 1 / L;
  Frame fr;
  fr.e1 = {r[0] * invL, r[1] * invL, r[2] * invL};
  const Pair c0{k.e2[0], k.e3[0]}, c1{k.e2[1], k.e3[1]}, c2{k.e2[2], k.e3[2]};
  for (int c = 0; c < 3; ++c) {
    fr.ti[c] = Ri[3 * c] * c0 + Ri[3 * c + 1] * c1 + Ri[3 * c + 2] * c2;
    fr.tj[c] = Rj[3 * c] * c0 + Rj[3 * c + 1] * c1 + Rj[3 * c + 2] * c2;
  }
  // (t2·e1, t3·e1) at each end, and (t2i·t3j, t3i·t2j).
  const Pair si = fr.ti[0] * fr.e1[0] + fr.ti[1] * fr.e1[1] + fr.ti[2] * fr.e1[2];
  const Pair sj = fr.tj[0] * fr.e1[0] + fr.tj[1] * fr.e1[1] + fr.tj[2] * fr.e1[2];
  Pair tw = fr.ti[0] * swapped(fr.tj[0]);
  for (int c = 1; c < 3; ++c) tw += fr.ti[c] * swapped(fr.tj[c]);
  return {L - k.L0, invL, {0, si[1], -si[0]}, {0.5 * (tw[1] - tw[0]), sj[1], -sj[0]}, fr, true};
}

// The force and moments of the co-rotational form, exactly minus the gradient of the
// element's energy U(L, θ̄): N = ∂U/∂L, T = ∂U/∂(twist), M = ∂U/∂θ̄ (My, Mz at each end).
// With global turns δφ of the triads (δt = δφ × t) and δe1 = (I − e1 e1ᵀ) δr / L:
//   force on i  N e1 + (v − (v·e1) e1)/L,  v = My_i t3i − Mz_i t2i + My_j t3j − Mz_j t2j,
//   moment on i e1 × (My_i t3i − Mz_i t2i) − T w,   on j  e1 × (My_j t3j − Mz_j t2j) + T w,
// w = ½ (t3i × t2j − t2i × t3j); the force on j is minus that on i.
inline void corotLoad(const Frame& fr, double invL, double N, double T, double Myi, double Mzi,
                      double Myj, double Mzj, Vec& f, Vec& m, Vec* mj) {
  const Vec& e1 = fr.e1;
  const Pair Mi{-Mzi, Myi}, Mj{-Mzj, Myj};
  Vec bi, bj, v, w;
  for (int c = 0; c < 3; ++c) {
    const Pair pi = fr.ti[c] * Mi, pj = fr.tj[c] * Mj;
    bi[c] = pi[0] + pi[1];
    bj[c] = pj[0] + pj[1];
    v[c] = bi[c] + bj[c];
  }
  for (int c = 0; c < 3; ++c) {
    const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
    // (t2i × t3j, t3i × t2j) component c
    const Pair x = fr.ti[c1] * swapped(fr.tj[c2]) - fr.ti[c2] * swapped(fr.tj[c1]);
    w[c] = 0.5 * (x[1] - x[0]);
  }
  const Vec ci = cross(e1, bi);
  const double along = dot(v, e1);
  for (int d = 0; d < 3; ++d) {
    f[d] = N * e1[d] + (v[d] - along * e1[d]) * invL;
    m[d] = ci[d] - T * w[d];
  }
  if (!mj) return;
  const Vec cj = cross(e1, bj);
  for (int d = 0; d < 3; ++d) (*mj)[d] = cj[d] + T * w[d];
}

struct EndLoad {
  Vec f, m;     // force and moment of the interaction on particle i
  double keep;  // 1 − ω while the interaction carries axial force (damping follows it)
};

// The elastic force on i after damage, updating the interaction's state (ω_t, ω_c, plastic
// stretch) in `state` when `update`; a null `state` gives the undamaged elastic interaction.
// With `mj`, also the moment on j (whose force is −f and whose `keep` is the same), so that
// one evaluation serves both ends.
inline EndLoad elasticForce(const Interaction& g, const Stiffness& k, const Chord& ch,
                            const mplm::DamageLaw& law, double* state, bool update,
                            Vec* mj = nullptr) {
  const Vec& ti = ch.ti;
  const Vec& tj = ch.tj;
  const double epsA = ch.da * g.invL0;  // eq. 4.7
  double axialKeep = 1, bendKeep = 1, stretch = ch.da;
  if (state && k.kind == Kind::Concrete) {
    // ε_mp± = ε_a ± β d ψ, ψ = √(ψx² + ψy² + ψz²) at the end where it is larger (eqs.
    // 4.8–4.12): ψx = |θ̄x_j − θ̄x_i|/d, bending (2/d)|2θ̄_end + θ̄_other| in each plane.
    const double px = tj[0] - ti[0];
    const double yi = 2 * (2 * ti[1] + tj[1]), zi = 2 * (2 * ti[2] + tj[2]);
    const double yj = 2 * (2 * tj[1] + ti[1]), zj = 2 * (2 * tj[2] + ti[2]);
    const double psi = std::sqrt(px * px + std::max(yi * yi + zi * zi, yj * yj + zj * zj));
    const double curv = law.beta * psi;
    double omT = state[0], omC = state[1];
    const double omega = law.update(epsA + curv, epsA - curv, omT, omC);
    if (update) {
      state[0] = omT;
      state[1] = omC;
    }
    bendKeep = 1 - omega;  // eqs. 4.19, 4.20: shear, moments and torsion always
    axialKeep = epsA >= 0 ? bendKeep : (law.crushing ? 1 - omC : 1.0);
  } else if (state && k.kind == Kind::Bar) {
    const double plastic = mplm::plasticStrain(epsA, state[2], k.epsY);
    if (update) state[2] = plastic;
    stretch = ch.da - plastic * g.L0;
  }
  const double N = k.ka * stretch * axialKeep;  // tension positive: pulls i toward j
  const double kb = k.kb * bendKeep;
  const double Myi = kb * (4 * ti[1] + 2 * tj[1]), Myj = kb * (2 * ti[1] + 4 * tj[1]);
  const double Mzi = kb * (4 * ti[2] + 2 * tj[2]), Mzj = kb * (2 * ti[2] + 4 * tj[2]);
  const double T = k.kt * bendKeep * (tj[0] - ti[0]);
  const Vec& e2 = g.e2;
  const Vec& e3 = g.e3;
  Vec f, m;
  if (ch.rotated) {
    corotLoad(ch.frame, ch.invL, N, T, Myi, Mzi, Myj, Mzj, f, m, mj);
    return {f, m, axialKeep};
  }
  // Local components on i: force (N, −(Mz_i+Mz_j)/L, (My_i+My_j)/L), moment (T, −My_i, −Mz_i).
  const double f2 = -(Mzi + Mzj) * ch.invL, f3 = (Myi + Myj) * ch.invL;
  for (int d = 0; d < 3; ++d) {
    f[d] = N * g.n0[d] + f2 * e2[d] + f3 * e3[d];
    m[d] = T * g.n0[d] - Myi * e2[d] - Mzi * e3[d];
  }
  if (mj)
    for (int d = 0; d < 3; ++d) (*mj)[d] = -T * g.n0[d] - Myj * e2[d] - Mzj * e3[d];
  return {f, m, axialKeep};
}

// The strain energy of the interaction at the damage and plastic stretch held in `state`
// (null: undamaged), which it leaves alone: elasticForce at that state is minus its gradient
// (in the small form with respect to the rotation vectors the chord was given).
inline double elasticEnergy(const Interaction& g, const Stiffness& k, const Chord& ch,
                            const mplm::DamageLaw& law, const double* state) {
  const Vec& ti = ch.ti;
  const Vec& tj = ch.tj;
  const mplm::Held h = mplm::held(k.kind, ch.da, g.L0, law, state);
  // ½ N·stretch, ½ T (θ̄x_j − θ̄x_i) and ½ (M_i θ̄_i + M_j θ̄_j) in each bending plane.
  const double twist = tj[0] - ti[0];
  return 0.5 * k.ka * h.stretch * h.stretch * h.axialKeep +
         (0.5 * k.kt * twist * twist + 2 * k.kb * (ti[1] * ti[1] + ti[1] * tj[1] + tj[1] * tj[1]) +
          2 * k.kb * (ti[2] * ti[2] + ti[2] * tj[2] + tj[2] * tj[2])) *
             h.bendKeep;
}

}  // namespace pdq::mplm3d
