// Rigid motions through the co-rotational form leave the internal forces at round-off;
// the small-deformation form, evaluated on the same motion, does not (so the test can fail).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "harness.hpp"
#include "models/mplm/2d/attributes.hpp"
#include "prep/hexagonal.hpp"
#include "prep/mplm/specimen.hpp"

namespace pdq::mplm {
namespace {

constexpr double s = 0.02;

// Largest |force| and |moment| on any particle after a rigid rotation by `angle` about
// (0.1, 0.05) and a translation.
std::pair<double, double> internalAfterRotation(const std::string& kinematics, double angle) {
  ParticleSet ps = newParticleSet();
  addConcrete(ps, prep::hexagonalRectangle(0.2, 0.1, s, prep::HexOrientation::BondsAlongX));
  const double c = angle == std::numbers::pi / 2 ? 0.0 : std::cos(angle);
  const double sn = angle == std::numbers::pi / 2 ? 1.0 : std::sin(angle);
  for (std::size_t k = 0; k < ps.size(); ++k) {
    const double X = ps.fixedRow(k)[0] - 0.1, Y = ps.fixedRow(k)[1] - 0.05;
    ps.alterRow(k)[AX] = 0.3 + c * X - sn * Y;
    ps.alterRow(k)[AY] = -0.2 + sn * X + c * Y;
    ps.alterRow(k)[THETA] = angle;
  }
  // Elastic interactions: the small form's spurious strains would otherwise break them all.
  Comm comm;
  auto sim = test::simulation(comm, test::params({{"kinematics", kinematics}, {"damage", "false"}}),
                              std::move(ps), 1);
  sim->model().force(sim->context());
  const Particles& P = sim->context().particles;
  double f = 0, m = 0;
  for (std::size_t i = 0; i < P.owned(); ++i) {
    f = std::max({f, std::fabs(P.integ(i)[FORCE_X]), std::fabs(P.integ(i)[FORCE_Y])});
    m = std::max(m, std::fabs(P.integ(i)[MOMENT]));
  }
  return {sim->context().max(f), sim->context().max(m)};
}

TEST(Corotation, RigidRotationLeavesNoInternalForce) {
  // Scales: a (N) for forces, b/s (N·m) for moments, at ν = 0.2, t = 0.12 (the defaults).
  const double a = 4.305e7, bOverS = 478.3 / s;
  for (double angle : {std::numbers::pi / 2, 0.7, -2.5}) {
    const auto [f, m] = internalAfterRotation("corotational", angle);
    EXPECT_LT(f, 1e-13 * a) << "angle " << angle;
    EXPECT_LT(m, 1e-13 * bOverS) << "angle " << angle;
  }
  const auto [f, m] = internalAfterRotation("small", std::numbers::pi / 2);
  EXPECT_GT(f, 1e-3 * a);
  (void)m;
}

}  // namespace
}  // namespace pdq::mplm
