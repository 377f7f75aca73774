#pragma once
// What an MPLM model does alike in 2D and 3D with its particles and interactions: building
// the interactions, masses and supports per particle, counting damaged interactions and
// telling how a member failed.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "engine/context.hpp"
#include "engine/exact_sum.hpp"
#include "engine/integrator.hpp"
#include "models/mplm/common/attributes.hpp"

namespace pdq::mplm {

// Per owned particle, from its fixed row.
struct Inertia {
  std::vector<double> mass, inertia;
  std::vector<int> constraint;  // the CONSTRAINT bits
  template <class Mass, class Rotary>
  void fill(const Particles& P, Mass massOf, Rotary inertiaOf) {
    const std::size_t n = P.owned();
    mass.resize(n);
    inertia.resize(n);
    constraint.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      mass[i] = massOf(P.fixed(i));
      inertia[i] = inertiaOf(P.fixed(i));
      constraint[i] = static_cast<int>(P.fixed(i)[CONSTRAINT]);
    }
  }
  // The engine's Body of every owned particle: DOF d (translations, then rotations) is
  // prescribed when its constraint has bit[d]; its peak load and prescribed value are the
  // fixed columns load + d and disp + d; with `rest` but not `fixY` it rests on a support
  // in Y (a bearing).
  void bodies(const Particles& P, std::span<Body> owned, std::span<const int> bit, int load,
              int disp, int rest, int fixY) const {
    for (std::size_t i = 0; i < owned.size(); ++i) {
      const double* X = P.fixed(i);
      Body& b = owned[i];
      b.mass = mass[i];
      b.inertia = inertia[i];
      for (std::size_t d = 0; d < bit.size(); ++d) {
        b.load[d] = X[load + d];
        b.value[d] = X[disp + d];
        if (constraint[i] & bit[d]) b.constraint[d] = pdq::Constraint::Prescribed;
      }
      if ((constraint[i] & (rest | fixY)) == rest) b.constraint[1] = pdq::Constraint::Resting;
    }
  }
};

// Bonds every owned particle i with the particles j within reach that accept(i, j) takes.
template <class Accept>
void addInteractions(Context& ctx, Accept accept) {
  const Particles& P = ctx.particles;
  for (std::size_t i = 0; i < P.owned(); ++i)
    ctx.forEachNearby(i, [&](std::size_t j) {
      if (j != i && accept(i, j)) ctx.bonds.add(i, P.gid(j));
    });
}

// The number of interactions whose damage reached `threshold`, each counted once.
inline double damagedInteractions(const Context& ctx, double threshold) {
  const Bonds& B = ctx.bonds;
  return ctx.sumOwned([&](std::size_t i) {
    double c = 0;
    for (std::size_t b = B.begin(i); b < B.end(i); ++b)
      if (std::max(B.attr(b)[OMEGA_T], B.attr(b)[OMEGA_C]) >= threshold) c += 1;
    return c;
  }) / 2;
}

// How a member failed, from its concrete interactions damaged past ω = ½: "none" without
// any; "compression" when crushing dominates; "tension" when no particle is held (constraint
// 0 everywhere: a specimen pulled apart); else "flexural" or "shear" from the orientation of the
// open cracks in the elevation (the x–y plane, x along the member). The member is cut into slices
// half its depth wide along x; in each slice the tensile-damaged interactions that are open give
// the tensor T = Σ w e⊗e (w the interaction's elongation, e its reference direction in x–y), whose
// principal direction is the normal of the slice's crack: a crack cutting the lattice across
// normal n opens each family of interactions in proportion to n·e and cuts them in
// proportion to |n·e|, so T ∝ Σ (n·e)² e⊗e, which is a I + b n⊗n on a lattice whose
// fourth moment of directions is isotropic (the hexagonal one; the FCC one nearly).
// A flexural crack is vertical (normal along the axis); in the shear spans flexural cracks
// incline as they rise into the web (flexure–shear cracks); the diagonal tension crack of a
// shear failure runs at 45° to the axis or flatter (normal 45° or more). A slice's crack
// counts as shear from a normal of 33.75°, a quarter of the way from 45° towards the vertical,
// which leaves room for the scatter of a slice's estimate on a lattice (docs/mplm.md,
// "Failure mode"). "flexural" when the other slices hold most of the opening, "shear"
// otherwise: the widest cracks decide.
// Slicing keeps the mirror-image diagonal cracks of the two shear spans from cancelling.
// `current(i)` gives local particle i's current position.
template <class Current>
std::string failureMode(const Context& ctx, std::span<const int> constraint, Current current) {
  const Particles& P = ctx.particles;
  const Bonds& B = ctx.bonds;
  const bool held = std::any_of(constraint.begin(), constraint.end(), [](int c) { return c; });
  const bool supported = ctx.max(held ? 1.0 : 0.0) > 0;
  constexpr double huge = std::numeric_limits<double>::max();
  double xlo = huge, xhi = -huge, ylo = huge, yhi = -huge;
  for (std::size_t i = 0; i < P.owned(); ++i) {
    xlo = std::min(xlo, P.fixed(i)[FX_X]);
    xhi = std::max(xhi, P.fixed(i)[FX_X]);
    ylo = std::min(ylo, P.fixed(i)[FX_Y]);
    yhi = std::max(yhi, P.fixed(i)[FX_Y]);
  }
  xlo = ctx.min(xlo);
  xhi = ctx.max(xhi);
  const double slice = (ctx.max(yhi) - ctx.min(ylo)) / 2;
  const std::size_t slices =
      slice > 0 ? static_cast<std::size_t>(std::ceil((xhi - xlo) / slice)) + 1 : 1;
  // Per slice Txx, Tyy, Txy weighted by the opening, and by 1 (when no crack is open).
  std::vector<ExactSum> opened(3 * slices), counted(3 * slices);
  ExactSum tensile, compressive;
  for (std::size_t i = 0; i < P.owned(); ++i) {
    const double* Xi = P.fixed(i);
    if (isSteel(Xi)) continue;
    const double* xi = current(i);
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      const double* st = B.attr(b);
      if (std::max(st[OMEGA_T], st[OMEGA_C]) < 0.5) continue;
      if (st[OMEGA_C] >= st[OMEGA_T]) {
        compressive.add(1);
        continue;
      }
      tensile.add(1);
      const std::int32_t j = B.partner(b);
      if (j < 0) continue;
      const double* Xj = P.fixed(static_cast<std::size_t>(j));
      const double* xj = current(static_cast<std::size_t>(j));
      double r0[3], r[3];
      for (int a = 0; a < 3; ++a) r0[a] = Xj[FX_X + a] - Xi[FX_X + a], r[a] = xj[a] - xi[a];
      const double L0 = std::hypot(r0[0], r0[1], r0[2]);
      const double w = std::hypot(r[0], r[1], r[2]) - L0;
      const double ex = r0[0] / L0, ey = r0[1] / L0;
      const double mid = (Xi[FX_X] + Xj[FX_X]) / 2;
      const std::size_t k =
          slice > 0
              ? std::min(slices - 1,
                         static_cast<std::size_t>(std::max(0.0, std::floor((mid - xlo) / slice))))
              : 0;
      const double e[3] = {ex * ex, ey * ey, ex * ey};
      for (int c = 0; c < 3; ++c) {
        counted[3 * k + c].add(e[c]);
        if (w > 0) opened[3 * k + c].add(w * e[c]);
      }
    }
  }
  const double t = ctx.sum(tensile), c = ctx.sum(compressive);
  if (t + c == 0) return "none";
  if (c > t) return "compression";
  if (!supported) return "tension";
  std::vector<double> T(3 * slices), N(3 * slices);
  double open = 0;
  for (std::size_t k = 0; k < 3 * slices; ++k) {
    T[k] = ctx.sum(opened[k]);
    N[k] = ctx.sum(counted[k]);
    if (k % 3 != 2) open += T[k];
  }
  if (open == 0) T = N;  // every crack closed again: their directions alone
  double flexural = 0, all = 0;
  for (std::size_t k = 0; k < slices; ++k) {
    const double xx = T[3 * k], yy = T[3 * k + 1], xy = T[3 * k + 2];
    const double weight = xx + yy;
    if (weight == 0) continue;
    const double normal = std::fabs(std::atan2(2 * xy, xx - yy)) / 2;  // radians from x
    all += weight;
    if (normal < 3 * std::numbers::pi / 16) flexural += weight;
  }
  return flexural > all / 2 ? "flexural" : "shear";
}

}  // namespace pdq::mplm
