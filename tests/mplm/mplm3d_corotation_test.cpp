// A rigid rotation of 90° about an arbitrary axis (plus a translation) leaves the internal
// forces and moments of the 3D lattice at round-off in the co-rotational form; the
// small-deformation form, on the same motion, does not (so the test can fail).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/rotation.hpp"
#include "harness.hpp"
#include "models/mplm/3d/attributes.hpp"
#include "models/mplm/3d/elastic_constants.hpp"
#include "prep/fcc.hpp"
#include "prep/mplm/specimen3d.hpp"

namespace pdq::mplm3d {
namespace {

constexpr double s = 0.02;

// Largest |force| and |moment| on any particle after rotating a block by `angle` about
// `axis` through its centre and translating it.
std::pair<double, double> internalAfterRotation(const std::string& kinematics, Vec axis,
                                                double angle) {
  ParticleSet ps = newParticleSet();
  addConcrete(ps, closePackedBox({s, 0, 2}, {0.12, 0.1, 0.08}));
  const double na = std::sqrt(dot(axis, axis));
  const Vec th{axis[0] / na * angle, axis[1] / na * angle, axis[2] / na * angle};
  const Quat q = expRot(th);
  for (std::size_t k = 0; k < ps.size(); ++k) {
    const double* X = ps.fixedRow(k);
    const Vec x = rotate(q, {X[0] - 0.06, X[1] - 0.05, X[2] - 0.04});
    double* a = ps.alterRow(k);
    a[AX] = 0.3 + x[0];
    a[AY] = -0.2 + x[1];
    a[AZ] = 0.1 + x[2];
    a[QW] = q.w;
    a[QX] = q.x;
    a[QY] = q.y;
    a[QZ] = q.z;
  }
  Comm comm;
  auto sim = mplm::test::simulation(
      comm, mplm::test::params({{"kinematics", kinematics}, {"damage", "false"}}), std::move(ps), 1,
      "mplm3d");
  sim->model().force(sim->context());
  const Particles& P = sim->context().particles;
  double f = 0, m = 0;
  for (std::size_t i = 0; i < P.owned(); ++i)
    for (int d = 0; d < 3; ++d) {
      f = std::max(f, std::fabs(P.integ(i)[FORCE_X + d]));
      m = std::max(m, std::fabs(P.integ(i)[MOMENT_X + d]));
    }
  return {sim->context().max(f), sim->context().max(m)};
}

TEST(Mplm3dCorotation, RigidRotationLeavesNoInternalForce) {
  // Scales: a (N) for forces, b/s (N·m) for moments, at the default E and ν.
  const ElasticConstants k = isotropicFcc(24.86e9, 0.2, s);
  for (const Vec& axis : {Vec{1, 2, 3}, Vec{-0.3, 0.9, 0.1}, Vec{0, 0, 1}}) {
    const auto [f, m] = internalAfterRotation("corotational", axis, std::numbers::pi / 2);
    EXPECT_LT(f, 1e-13 * k.a) << "axis " << axis[0] << " " << axis[1] << " " << axis[2];
    EXPECT_LT(m, 1e-13 * k.b / s) << "axis " << axis[0] << " " << axis[1] << " " << axis[2];
  }
  const auto [f, m] = internalAfterRotation("corotational", {0.2, -1, 0.5}, 3.0);
  EXPECT_LT(f, 1e-13 * k.a);
  EXPECT_LT(m, 1e-13 * k.b / s);
  const auto [fs, ms] = internalAfterRotation("small", {1, 2, 3}, std::numbers::pi / 2);
  EXPECT_GT(fs, 1e-3 * k.a);
  EXPECT_GT(ms, 1e-3 * k.b / s);
}

}  // namespace
}  // namespace pdq::mplm3d
