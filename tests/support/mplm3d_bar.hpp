#pragma once
// A 0.3 × 0.1 × 0.08 m mplm3d bar at s = 2 cm, clamped at X = 0, its far end pulled and
// pushed down (prescribed, by the run's load protocol) far enough to break interactions.
#include "engine/problem.hpp"
#include "models/mplm/3d/attributes.hpp"
#include "prep/fcc.hpp"
#include "prep/mplm/specimen.hpp"
#include "prep/mplm/specimen3d.hpp"
#include "support/harness.hpp"

namespace pdq::test {

inline Problem crackingBar3d() {
  using namespace mplm3d;
  constexpr double s = 0.02;
  Problem pb = makeProblem("mplm3d", params({{"spacing", "0.02"}}), newParticleSet());
  ParticleSet& ps = pb.particles;
  addConcrete(ps, closePackedBox({s, 0, 2}, {0.3, 0.1, 0.08}));
  const double xmax = mplm::maxCoord(ps, 0);
  constrain(ps, mplm::select(ps, [&](const double* f) { return f[0] < s; }), FIX_ALL);
  constrain(ps, mplm::select(ps, [&](const double* f) { return f[0] > xmax - s / 4; }),
            FIX_X | FIX_Y, {1e-3, -5e-4, 0, 0, 0, 0});
  return pb;
}

}  // namespace pdq::test
