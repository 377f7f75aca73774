// A slender lattice cantilever under a small tip load settles (dynamic relaxation) to the
// tip deflection of beam theory, bending plus shear (Timoshenko), within 3%.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "harness.hpp"
#include "models/mplm/2d/attributes.hpp"
#include "prep/hexagonal.hpp"
#include "prep/mplm/specimen.hpp"

namespace pdq::mplm {
namespace {

TEST(Cantilever, TipDeflectionMatchesBeamTheory) {
  constexpr double E = 24.86e9, nu = 0.2, rho = 2323, s = 0.02, t = 0.1, P = 2000;
  constexpr int rows = 8, columns = 61;
  const double p = prep::hexPitch(s);
  // The lattice acts as a continuum filling its bounding box: with `rows` particles per
  // column, alternate columns shifted by s/2, the depth is (rows − ½) s (checked at 4, 8
  // and 16 rows: the deflection follows this depth, not rows × s).
  const double length = (columns - 1) * p, depth = (rows - 0.5) * s;
  // Columns of `rows` particles (bonds along Y), so each end is one clean column.
  ParticleSet ps = newParticleSet();
  addConcrete(ps, prep::hexagonalRectangle(length, depth, s, prep::HexOrientation::BondsAlongY));
  const auto clamped = select(ps, [&](const double* f) { return f[0] < 0.5 * p; });
  const auto tip = select(ps, [&](const double* f) { return f[0] > length - 0.5 * p; });
  ASSERT_EQ(clamped.size(), static_cast<std::size_t>(rows));
  ASSERT_EQ(tip.size(), static_cast<std::size_t>(rows));
  constrain(ps, clamped, FIX_X | FIX_Y | FIX_T);
  load(ps, tip, 0, -P / rows);
  monitor(ps, tip);

  // Beam theory: δ = P L³ / (3 E I) + P L / (κ G A).
  const double I = t * depth * depth * depth / 12, A = t * depth, G = E / (2 * (1 + nu));
  const double expected = P * std::pow(length, 3) / (3 * E * I) + P * length / (5.0 / 6 * G * A);
  // Critical viscous damping of the first mode, ω₁ = 3.516 √(EI / (ρ A L⁴)).
  const double omega1 = 3.516 * std::sqrt(E * I / (rho * A * std::pow(length, 4)));

  Comm comm;
  auto run = [&](long steps) {
    return test::simulation(comm,
                            test::params({{"thickness", std::to_string(t)},
                                          {"damage", "false"},
                                          {"viscous_damping", std::to_string(2 * omega1)}}),
                            ps, steps);
  };
  auto probe = run(1);
  const double dt = probe->context().dt();
  const long steps = static_cast<long>(4 * 2 * M_PI / omega1 / dt);
  auto sim = run(steps);
  sim->run();
  const double deflection = -test::global(*sim, "uy");
  std::cout << "deflection error " << (deflection - expected) / expected << "\n";
  EXPECT_NEAR(deflection, expected, 0.03 * expected)
      << "lattice " << deflection << " m, beam theory " << expected << " m, " << steps << " steps";
  // Settled: the kinetic energy is negligible against the work of the load.
  EXPECT_LT(test::global(*sim, "kinetic"), 1e-6 * P * expected);
}

}  // namespace
}  // namespace pdq::mplm
