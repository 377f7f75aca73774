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

// The co-rotational form's arithmetic is written once for a number type T: double, or a
// vector of doubles (GCC's vector extension) holding several interactions, one per lane.
// Each lane then sees the same operations in the same order as the scalar form, so the
// same bits whatever the width.
inline double sqrtOf(double x) { return std::sqrt(x); }
template <class T>
T sqrtOf(T x) {
  for (int k = 0; k < int(sizeof(T) / sizeof(double)); ++k) x[k] = std::sqrt(x[k]);
  return x;
}
// std::max's choice (a when neither is larger), lane by lane for vectors.
inline double maxOf(double a, double b) { return std::max(a, b); }
template <class T>
T maxOf(T a, T b) {
  return a < b ? b : a;
}

// The co-rotational form's current geometry: the chord's direction e1 and the interaction's
// reference axes e2, e3 carried by each end's triad, t2 = R e2 and t3 = R e3, by component.
template <class T>
struct Frame {
  T e1[3];
  T t2i[3], t3i[3], t2j[3], t3j[3];
};

// Co-rotational: each end's triad carries the interaction's reference axes e2, e3 along;
// the end's bending rotations are read against the current chord direction e1, θ̄y = t3·e1
// and θ̄z = −t2·e1, and the twist between the ends is ½ (t3i·t2j − t2i·t3j). They are dot
// products of rotated vectors, so rigid motions of any size leave them unchanged (no force),
// and to first order they are the small form's θ̄ (the same stiffness at small deformation).
// r: the chord, Ri, Rj: the particles' rotation matrices (row-major), e2, e3: the reference
// axes. Sets the elongation da, 1/L, the end rotations ti, tj (as in Chord) and the frame.
template <class T>
void corotMeasures(const T r[3], const T Ri[9], const T Rj[9], const T e2[3], const T e3[3], T L0,
                   T& da, T& invL, T ti[3], T tj[3], Frame<T>& fr) {
  const T L = sqrtOf(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
  invL = 1.0 / L;
  for (int c = 0; c < 3; ++c) {
    fr.e1[c] = r[c] * invL;
    fr.t2i[c] = Ri[3 * c] * e2[0] + Ri[3 * c + 1] * e2[1] + Ri[3 * c + 2] * e2[2];
    fr.t3i[c] = Ri[3 * c] * e3[0] + Ri[3 * c + 1] * e3[1] + Ri[3 * c + 2] * e3[2];
    fr.t2j[c] = Rj[3 * c] * e2[0] + Rj[3 * c + 1] * e2[1] + Rj[3 * c + 2] * e2[2];
    fr.t3j[c] = Rj[3 * c] * e3[0] + Rj[3 * c + 1] * e3[1] + Rj[3 * c + 2] * e3[2];
  }
  auto along = [&](const T* t) { return t[0] * fr.e1[0] + t[1] * fr.e1[1] + t[2] * fr.e1[2]; };
  // t2i·t3j and t3i·t2j
  const T x = fr.t2i[0] * fr.t3j[0] + fr.t2i[1] * fr.t3j[1] + fr.t2i[2] * fr.t3j[2];
  const T y = fr.t3i[0] * fr.t2j[0] + fr.t3i[1] * fr.t2j[1] + fr.t3i[2] * fr.t2j[2];
  da = L - L0;
  ti[0] = T{};
  ti[1] = along(fr.t3i);
  ti[2] = -along(fr.t2i);
  tj[0] = 0.5 * (y - x);
  tj[1] = along(fr.t3j);
  tj[2] = -along(fr.t2j);
}

// Deformation of the interaction in its local frame: elongation, chord length, the end
// rotations relative to the chord in local components (θ̄x torsion, θ̄y, θ̄z bending; the
// co-rotational form holds the twist θ̄x_j − θ̄x_i in tj[0] and 0 in ti[0]), and (co-rotational
// form) the frame.
struct Chord {
  double da, invL;
  Vec ti, tj;
  Frame<double> frame;
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

inline Chord corotChord(const Interaction& k, const Vec& r, const Mat& Ri, const Mat& Rj) {
  Chord c;
  corotMeasures<double>(r.data(), Ri.data(), Rj.data(), k.e2.data(), k.e3.data(), k.L0, c.da,
                        c.invL, c.ti.data(), c.tj.data(), c.frame);
  c.rotated = true;
  return c;
}

// ψ = √(ψx² + ψy² + ψz²) · d at the end where it is larger (eqs. 4.8–4.12): ψx d = |θ̄x_j −
// θ̄x_i|, bending 2|2θ̄_end + θ̄_other| in each plane.
template <class T>
T curvature(const T ti[3], const T tj[3]) {
  const T px = tj[0] - ti[0];
  const T yi = 2.0 * (2.0 * ti[1] + tj[1]), zi = 2.0 * (2.0 * ti[2] + tj[2]);
  const T yj = 2.0 * (2.0 * tj[1] + ti[1]), zj = 2.0 * (2.0 * tj[2] + ti[2]);
  return sqrtOf(px * px + maxOf(yi * yi + zi * zi, yj * yj + zj * zj));
}

// The damage step of one interaction: from its axial strain εa (eq. 4.7), the curvature
// term β ψ of ε_mp± (concrete) and its elongation da, the factors it keeps and its elastic
// stretch, updating its state (ω_t, ω_c, plastic stretch; null: undamaged) when `update`.
inline mplm::Held damageStep(const Stiffness& k, const mplm::DamageLaw& law, double epsA,
                             double curv, double da, double L0, double* state, bool update) {
  mplm::Held h{1, 1, da};
  if (state && k.kind == Kind::Concrete) {
    double omT = state[0], omC = state[1];
    const double omega = law.update(epsA + curv, epsA - curv, omT, omC);
    if (update) {
      state[0] = omT;
      state[1] = omC;
    }
    h.bendKeep = 1 - omega;  // eqs. 4.19, 4.20: shear, moments and torsion always
    h.axialKeep = epsA >= 0 ? h.bendKeep : (law.crushing ? 1 - omC : 1.0);
  } else if (state && k.kind == Kind::Bar) {
    const double plastic = mplm::plasticStrain(epsA, state[2], k.epsY);
    if (update) state[2] = plastic;
    h.stretch = da - plastic * L0;
  }
  return h;
}

// The element's resultants after damage: the axial force N (tension positive: pulls i
// toward j), the torsional moment T and the end moments My, Mz of the two bending planes.
template <class T>
struct Resultants {
  T N, T_, Myi, Mzi, Myj, Mzj;
};
template <class T>
Resultants<T> resultants(T ka, T kb, T kt, T stretch, T axialKeep, T bendKeep, const T ti[3],
                         const T tj[3]) {
  Resultants<T> r;
  r.N = ka * stretch * axialKeep;
  const T b = kb * bendKeep;
  r.Myi = b * (4.0 * ti[1] + 2.0 * tj[1]);
  r.Myj = b * (2.0 * ti[1] + 4.0 * tj[1]);
  r.Mzi = b * (4.0 * ti[2] + 2.0 * tj[2]);
  r.Mzj = b * (2.0 * ti[2] + 4.0 * tj[2]);
  r.T_ = kt * bendKeep * (tj[0] - ti[0]);
  return r;
}

// The force and moments of the co-rotational form, exactly minus the gradient of the
// element's energy U(L, θ̄): N = ∂U/∂L, T = ∂U/∂(twist), M = ∂U/∂θ̄ (My, Mz at each end).
// With global turns δφ of the triads (δt = δφ × t) and δe1 = (I − e1 e1ᵀ) δr / L:
//   force on i  N e1 + (v − (v·e1) e1)/L,  v = My_i t3i − Mz_i t2i + My_j t3j − Mz_j t2j,
//   moment on i e1 × (My_i t3i − Mz_i t2i) − T w,   on j  e1 × (My_j t3j − Mz_j t2j) + T w,
// w = ½ (t3i × t2j − t2i × t3j); the force on j is minus that on i.
template <class T>
void corotLoad(const Frame<T>& fr, T invL, const Resultants<T>& q, T f[3], T m[3], T* mj) {
  const T* e1 = fr.e1;
  T bi[3], bj[3], v[3], w[3];
  for (int c = 0; c < 3; ++c) {
    bi[c] = fr.t2i[c] * -q.Mzi + fr.t3i[c] * q.Myi;
    bj[c] = fr.t2j[c] * -q.Mzj + fr.t3j[c] * q.Myj;
    v[c] = bi[c] + bj[c];
  }
  for (int c = 0; c < 3; ++c) {
    const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
    // (t2i × t3j)_c and (t3i × t2j)_c
    const T x = fr.t2i[c1] * fr.t3j[c2] - fr.t2i[c2] * fr.t3j[c1];
    const T y = fr.t3i[c1] * fr.t2j[c2] - fr.t3i[c2] * fr.t2j[c1];
    w[c] = 0.5 * (y - x);
  }
  const T along = v[0] * e1[0] + v[1] * e1[1] + v[2] * e1[2];
  for (int d = 0; d < 3; ++d) {
    const int d1 = (d + 1) % 3, d2 = (d + 2) % 3;
    f[d] = q.N * e1[d] + (v[d] - along * e1[d]) * invL;
    m[d] = (e1[d1] * bi[d2] - e1[d2] * bi[d1]) - q.T_ * w[d];
    if (mj) mj[d] = (e1[d1] * bj[d2] - e1[d2] * bj[d1]) + q.T_ * w[d];
  }
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
  const double* ti = ch.ti.data();
  const double* tj = ch.tj.data();
  const double epsA = ch.da * g.invL0;  // eq. 4.7
  const double curv =
      state && k.kind == Kind::Concrete ? law.beta * curvature<double>(ti, tj) : 0.0;
  const mplm::Held h = damageStep(k, law, epsA, curv, ch.da, g.L0, state, update);
  const Resultants<double> q =
      resultants<double>(k.ka, k.kb, k.kt, h.stretch, h.axialKeep, h.bendKeep, ti, tj);
  Vec f, m;
  if (ch.rotated) {
    corotLoad<double>(ch.frame, ch.invL, q, f.data(), m.data(), mj ? mj->data() : nullptr);
    return {f, m, h.axialKeep};
  }
  // Local components on i: force (N, −(Mz_i+Mz_j)/L, (My_i+My_j)/L), moment (T, −My_i, −Mz_i).
  const Vec& e2 = g.e2;
  const Vec& e3 = g.e3;
  const double f2 = -(q.Mzi + q.Mzj) * ch.invL, f3 = (q.Myi + q.Myj) * ch.invL;
  for (int d = 0; d < 3; ++d) {
    f[d] = q.N * g.n0[d] + f2 * e2[d] + f3 * e3[d];
    m[d] = q.T_ * g.n0[d] - q.Myi * e2[d] - q.Mzi * e3[d];
  }
  if (mj)
    for (int d = 0; d < 3; ++d) (*mj)[d] = -q.T_ * g.n0[d] - q.Myj * e2[d] - q.Mzj * e3[d];
  return {f, m, h.axialKeep};
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
