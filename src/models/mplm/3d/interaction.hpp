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

// The geometry of one interaction end: the reference direction n0 of the chord X_j − X_i
// and the frame's second axis e2 (the third, e3 = n0 × e2, is formed when needed), its
// length d, and where its constants and its partner are.
struct Interaction {
  std::int32_t j = 0;      // partner's local index
  std::uint32_t rev = 0;   // an owned partner's bond back to this particle
  std::uint32_t type = 0;  // its Stiffness in the model's table
  Vec n0{}, e2{};
  double L0 = 0, invL0 = 0;
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

// Sets the interaction's reference geometry from its chord r0: d, 1/d, n0, e2.
inline void setReference(Interaction& k, const Vec& r0) {
  k.L0 = std::sqrt(dot(r0, r0));
  k.invL0 = 1 / k.L0;
  k.n0 = {r0[0] * k.invL0, r0[1] * k.invL0, r0[2] * k.invL0};
  Vec e3;
  referenceFrame(k.n0, k.e2, e3);
}

// The interaction as its other end holds it (partner i): n0 and e2 negate exactly, and
// e3 = n0 × e2 stays (referenceFrame).
inline Interaction reversed(const Interaction& k, std::int32_t i) {
  Interaction r = k;
  r.j = i;
  r.n0 = {-k.n0[0], -k.n0[1], -k.n0[2]};
  r.e2 = {-k.e2[0], -k.e2[1], -k.e2[2]};
  return r;
}

// What the co-rotational form needs beyond the end rotations to turn the element's end
// loads into the gradient of its energy: the frame qb = qs ⊗ qm built from the mean triad qm
// = p/|p| (p = q_i ± q_j) and the smallest rotation qs from a = R(qm) n0 to the chord's
// direction e1; the end rotations vi, vj = log(qb* ⊗ q) in reference components; sgn the
// sign that put q_j on q_i's hemisphere in p.
struct Frame {
  Quat qb, qs, p, qi, qj;
  Vec a, e1, vi, vj;
  double L, sgn;
};

// Deformation of the interaction in its local frame: elongation, chord length, the end
// rotations relative to the frame in local components (θ̄x torsion, θ̄y, θ̄z bending), and
// (co-rotational form) the frame.
struct Chord {
  double da, invL;
  Vec ti, tj;
  Vec e2, e3;  // the reference frame's second and third axes
  Frame frame;
  bool rotated;
};

// Small deformation: reference geometry, linearised stretch and chord rotation
// φ = n0 × (u_j − u_i)/d; the end rotations are the rotation vectors minus φ.
inline Chord smallChord(const Interaction& k, const Vec& d, const Vec& thi, const Vec& thj) {
  const Vec phi = cross(k.n0, d);
  const Vec &e2 = k.e2, e3 = cross(k.n0, e2);
  const Vec bi{thi[0] - phi[0] * k.invL0, thi[1] - phi[1] * k.invL0, thi[2] - phi[2] * k.invL0};
  const Vec bj{thj[0] - phi[0] * k.invL0, thj[1] - phi[1] * k.invL0, thj[2] - phi[2] * k.invL0};
  Chord c;  // its frame belongs to the co-rotational form: left unset, not zeroed each time
  c.da = dot(d, k.n0);
  c.invL = k.invL0;
  c.ti = {dot(bi, k.n0), dot(bi, e2), dot(bi, e3)};
  c.tj = {dot(bj, k.n0), dot(bj, e2), dot(bj, e3)};
  c.e2 = e2;
  c.e3 = e3;
  c.rotated = false;
  return c;
}

// Co-rotational (after Crisfield): the frame is the mean of the two end triads, turned by
// the smallest rotation that lays its first axis on the current chord r; each end's
// rotation relative to that frame bends and twists the element. Rigid motions of any size
// thus give no force. qi, qj: the particles' orientations.
inline Chord corotChord(const Interaction& k, const Vec& r, const Quat& qi, const Quat& qj) {
  const double L = std::sqrt(dot(r, r)), invL = 1 / L;
  // Mean triad: q and −q are one rotation, so add the pair on the same hemisphere.
  const double sgn = qi.w * qj.w + qi.x * qj.x + qi.y * qj.y + qi.z * qj.z >= 0 ? 1.0 : -1.0;
  const Quat p{qi.w + sgn * qj.w, qi.x + sgn * qj.x, qi.y + sgn * qj.y, qi.z + sgn * qj.z};
  const Quat qm = normalised(p);
  const Vec a = rotate(qm, k.n0);
  const Vec e1{r[0] * invL, r[1] * invL, r[2] * invL};
  const Vec ax = cross(a, e1);
  const Quat qs = normalised({1 + dot(a, e1), ax[0], ax[1], ax[2]});
  const Quat qb = mul(qs, qm);
  const Quat qbc = conj(qb);
  const Vec vi = logRot(mul(qbc, qi)), vj = logRot(mul(qbc, qj));
  const Vec &e2 = k.e2, e3 = cross(k.n0, e2);
  return {L - k.L0,
          invL,
          {dot(vi, k.n0), dot(vi, e2), dot(vi, e3)},
          {dot(vj, k.n0), dot(vj, e2), dot(vj, e3)},
          e2,
          e3,
          {qb, qs, p, qi, qj, a, e1, vi, vj, L, sgn},
          true};
}

// The force and moment on i in the co-rotational form, exactly minus the gradient of the
// element's energy U(L, t_i, t_j): N = ∂U/∂L, gi and gj = ∂U/∂t (reference components).
// With global turns δφ of the triads and the frame's turn δβ,
//   δU = N e1·δr + h_i·(δφ_i − δβ) + h_j·(δφ_j − δβ),  h = R(qb) J⁻ᵀ(v) g,
// and δβ = (spin of qs) + R(qs) (spin of qm) follows from the chord (δe1 = P δr / L,
// P = I − e1 e1ᵀ) and from the triads through the mean p = q_i ± q_j; with H = h_i + h_j:
//   H·δβ = δr·P G_b / L + δμ·G,  δμ·G = δφ_i·(u₀ G + u × G)/|p|² + (j's part),
// (u₀, u) = q_i ⊗ p*, G_b = W × a − κ a, G = a × (e1 × W − κ e1) + R(qs)ᵀ H,
// W = H − (c × H)/(1 + a·e1), κ = (H·c)/(1 + a·e1), c = a × e1. The moment on j (when `mj`
// is given) is the same with h_j and ± (q_j ⊗ p*) (p holds ± q_j); the force on j is −f.
inline void corotLoad(const Frame& fr, double N, const Vec& gi, const Vec& gj, Vec& f, Vec& m,
                      Vec* mj) {
  const Vec hi = rotate(fr.qb, turnGradient(fr.vi, gi));
  const Vec hj = rotate(fr.qb, turnGradient(fr.vj, gj));
  const Vec H{hi[0] + hj[0], hi[1] + hj[1], hi[2] + hj[2]};
  const Vec& a = fr.a;
  const Vec& e1 = fr.e1;
  const Vec c = cross(a, e1);
  const double inv = 1 / (1 + dot(a, e1)), kappa = dot(H, c) * inv;
  const Vec cH = cross(c, H);
  const Vec W{H[0] - cH[0] * inv, H[1] - cH[1] * inv, H[2] - cH[2] * inv};
  const Vec Wa = cross(W, a), eW = cross(e1, W);
  const Vec Gb{Wa[0] - kappa * a[0], Wa[1] - kappa * a[1], Wa[2] - kappa * a[2]};
  const Vec Ga{eW[0] - kappa * e1[0], eW[1] - kappa * e1[1], eW[2] - kappa * e1[2]};
  const Vec aGa = cross(a, Ga), sH = rotate(conj(fr.qs), H);
  const Vec G{aGa[0] + sH[0], aGa[1] + sH[1], aGa[2] + sH[2]};
  const double along = dot(Gb, e1), invL = 1 / fr.L;
  const Quat u = mul(fr.qi, conj(fr.p));
  const double invP = 1 / (fr.p.w * fr.p.w + fr.p.x * fr.p.x + fr.p.y * fr.p.y + fr.p.z * fr.p.z);
  const Vec uG = cross({u.x, u.y, u.z}, G);
  for (int d = 0; d < 3; ++d) {
    f[d] = N * e1[d] - (Gb[d] - along * e1[d]) * invL;
    m[d] = -hi[d] + (u.w * G[d] + uG[d]) * invP;
  }
  if (!mj) return;
  const Quat uj = mul(fr.qj, conj(fr.p));
  const Vec ujG = cross({uj.x, uj.y, uj.z}, G);
  for (int d = 0; d < 3; ++d) (*mj)[d] = -hj[d] + fr.sgn * (uj.w * G[d] + ujG[d]) * invP;
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
  const Vec& e2 = ch.e2;
  const Vec& e3 = ch.e3;
  Vec f, m;
  if (ch.rotated) {
    // ∂U/∂t at each end: (−T, My_i, Mz_i) and (T, My_j, Mz_j).
    Vec gi, gj;
    for (int d = 0; d < 3; ++d) {
      gi[d] = -T * g.n0[d] + Myi * e2[d] + Mzi * e3[d];
      gj[d] = T * g.n0[d] + Myj * e2[d] + Mzj * e3[d];
    }
    corotLoad(ch.frame, N, gi, gj, f, m, mj);
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
