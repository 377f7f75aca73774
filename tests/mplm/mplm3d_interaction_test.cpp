// The 3D frame interaction in its small-deformation form is the gradient of its strain
// energy U = ½ (a/d) Δ² + (b/d) Σ_planes 2(θ̄_i² + θ̄_i θ̄_j + θ̄_j²) + ½ (c/d)(θ̄x_j − θ̄x_i)²:
// the force on i is ∂U/∂(u_j − u_i) and the moment on i is −∂U/∂θ_i (central differences).
#include <gtest/gtest.h>

#include <cmath>

#include "models/mplm/3d/interaction.hpp"

namespace pdq::mplm3d {
namespace {

double energy(const Interaction& g, const Stiffness& k, const Vec& d, const Vec& ti,
              const Vec& tj) {
  const Chord c = smallChord(g, d, ti, tj);
  double U = 0.5 * k.ka * c.da * c.da + 0.5 * k.kt * (c.tj[0] - c.ti[0]) * (c.tj[0] - c.ti[0]);
  for (int p = 1; p < 3; ++p)
    U += 2 * k.kb * (c.ti[p] * c.ti[p] + c.ti[p] * c.tj[p] + c.tj[p] * c.tj[p]);
  return U;
}

TEST(Mplm3dInteraction, ForceAndMomentAreMinusGradientOfEnergy) {
  for (const Vec& dir : {Vec{1, 1, 0}, Vec{0.3, -0.5, 0.8}, Vec{0, 0, -1}}) {
    Interaction g;
    Stiffness k;
    const double n = std::sqrt(dot(dir, dir));
    setReference(g, {0.02 * dir[0] / n, 0.02 * dir[1] / n, 0.02 * dir[2] / n});
    k.ka = 2.4e8;
    k.kb = 1600;
    k.kt = 1300;
    const Vec d{1e-6, -2e-6, 0.5e-6}, ti{1e-4, 3e-5, -2e-4}, tj{-5e-5, 2e-4, 1e-4};
    const EndLoad e =
        elasticForce(g, k, smallChord(g, d, ti, tj), mplm::DamageLaw{}, nullptr, false);
    for (int c = 0; c < 3; ++c) {
      const double hd = 1e-9, ht = 1e-7;
      Vec dp = d, dm = d, tp = ti, tm = ti;
      dp[c] += hd;
      dm[c] -= hd;
      tp[c] += ht;
      tm[c] -= ht;
      const double dUdd = (energy(g, k, dp, ti, tj) - energy(g, k, dm, ti, tj)) / (2 * hd);
      const double dUdt = (energy(g, k, d, tp, tj) - energy(g, k, d, tm, tj)) / (2 * ht);
      EXPECT_NEAR(e.f[c], dUdd, 1e-6 * (std::fabs(dUdd) + k.ka * 1e-6)) << "force " << c;
      EXPECT_NEAR(e.m[c], -dUdt, 1e-6 * (std::fabs(dUdt) + k.kb * 1e-4)) << "moment " << c;
    }
  }
}

}  // namespace
}  // namespace pdq::mplm3d
