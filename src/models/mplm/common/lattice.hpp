#pragma once
// What an MPLM model does alike in 2D and 3D with its particles and interactions: building
// the interactions, masses and supports per particle, counting damaged interactions and
// telling how a member failed.
#include <algorithm>
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
// any; "compression" when crushing dominates; "tension" with no supports; else "flexural"
// when most lie at particles i where inZone(i) (where flexure fails the member), "shear"
// otherwise.
template <class Zone>
std::string failureMode(const Context& ctx, bool supported, Zone inZone) {
  const Particles& P = ctx.particles;
  const Bonds& B = ctx.bonds;
  ExactSum tensile, compressive, critical, all;
  for (std::size_t i = 0; i < P.owned(); ++i) {
    if (isSteel(P.fixed(i))) continue;
    const bool zone = inZone(i);
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      const double* st = B.attr(b);
      if (std::max(st[OMEGA_T], st[OMEGA_C]) < 0.5) continue;
      (st[OMEGA_C] >= st[OMEGA_T] ? compressive : tensile).add(1);
      all.add(1);
      if (zone) critical.add(1);
    }
  }
  const double t = ctx.sum(tensile), c = ctx.sum(compressive), m = ctx.sum(critical);
  const double total = ctx.sum(all);
  if (total == 0) return "none";
  if (c > t) return "compression";
  if (!supported) return "tension";
  return m > total / 2 ? "flexural" : "shear";
}

}  // namespace pdq::mplm
