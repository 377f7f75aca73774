#pragma once
// The damage a restart gives the interactions: ω_t and ω_c must lie in [0, 1]. A Bonds
// file edited or damaged to hold `omega_t = 7` would otherwise run on with a negative
// stiffness.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "engine/context.hpp"
#include "engine/error.hpp"
#include "models/mplm/common/attributes.hpp"

namespace pdq::mplm {

// Collective: every rank throws the same InputError, naming the smallest particle ID that
// holds an interaction with damage outside [0, 1].
inline void checkDamageRange(Context& ctx, const std::string& model) {
  const Particles& P = ctx.particles;
  const Bonds& B = ctx.bonds;
  double first = -std::numeric_limits<double>::infinity();  // -ID: the smallest wins the max
  for (std::size_t i = 0; i < P.owned(); ++i)
    for (std::size_t b = B.begin(i); b < B.end(i); ++b)
      for (const int k : {OMEGA_T, OMEGA_C}) {
        const double w = B.attr(b)[k];
        if (!(w >= 0 && w <= 1)) first = std::max(first, -static_cast<double>(P.gid(i)));
      }
  first = ctx.max(first);
  if (std::isfinite(first))
    throw InputError(model, 0,
                     "particle " + std::to_string(static_cast<Gid>(-first)) +
                         " has an interaction whose damage omega_t or omega_c is outside [0, 1] "
                         "(a restart's Bonds file edited or damaged?)");
}

}  // namespace pdq::mplm
