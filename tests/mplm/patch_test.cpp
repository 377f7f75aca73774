// Patch test: a uniform strain imposed on a large lattice gives back the continuum's E and
// ν in the interior (virial stress), for plane stress and plane strain, in both lattice
// orientations.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "harness.hpp"
#include "models/mplm/2d/attributes.hpp"
#include "prep/hexagonal.hpp"
#include "prep/mplm/specimen.hpp"

namespace pdq::mplm {
namespace {

constexpr double E = 24.86e9, nu = 0.2, s = 0.02, L = 0.6;

struct Stress {
  double xx, yy, xy;
};

// Mean virial stress of the particles at least 3 s from every edge under the strain
// (exx, eyy, exy) imposed on every particle.
Stress interiorStress(const std::string& form, const std::string& orientation, double exx,
                      double eyy, double exy) {
  Comm comm;
  ParticleSet ps = newParticleSet();
  addConcrete(ps, prep::hexagonalRectangle(L, L, s, prep::hexOrientation(orientation)));
  for (std::size_t k = 0; k < ps.size(); ++k) {
    const double X = ps.fixedRow(k)[0] - L / 2, Y = ps.fixedRow(k)[1] - L / 2;
    ps.alterRow(k)[AX] = ps.fixedRow(k)[0] + exx * X + exy * Y;
    ps.alterRow(k)[AY] = ps.fixedRow(k)[1] + exy * X + eyy * Y;
  }
  auto sim = test::simulation(comm, test::params({{"elasticity", form}}), std::move(ps), 1);
  Context& ctx = sim->context();
  const std::size_t n = ctx.particles.owned();
  std::vector<double> sxx(n), syy(n), sxy(n);
  const auto names = sim->model().fields();
  auto fieldIndex = [&](const std::string& f) {
    return static_cast<int>(std::find(names.begin(), names.end(), f) - names.begin());
  };
  sim->model().field(ctx, fieldIndex("sxx"), sxx);
  sim->model().field(ctx, fieldIndex("syy"), syy);
  sim->model().field(ctx, fieldIndex("sxy"), sxy);
  auto interior = [&](std::size_t i) {
    const double* X = ctx.particles.fixed(i);
    const double m = 3 * s;
    return X[0] > m && X[0] < L - m && X[1] > m && X[1] < L - m;
  };
  const double count = ctx.sumOwned([&](std::size_t i) { return interior(i) ? 1.0 : 0.0; });
  auto mean = [&](const std::vector<double>& v) {
    return ctx.sumOwned([&](std::size_t i) { return interior(i) ? v[i] : 0.0; }) / count;
  };
  EXPECT_GT(count, 100);
  return {mean(sxx), mean(syy), mean(sxy)};
}

// E and ν from the response to a uniaxial strain exx = e.
std::pair<double, double> recovered(const std::string& form, const Stress& st, double e) {
  const double r = st.yy / st.xx;
  if (form == "plane_stress") {
    const double v = r;
    return {st.xx * (1 - v * v) / e, v};
  }
  const double v = r / (1 + r);
  return {st.xx * (1 + v) * (1 - 2 * v) / ((1 - v) * e), v};
}

class PatchTest : public ::testing::TestWithParam<std::string> {};

TEST_P(PatchTest, UniformStrainGivesBackEAndNu) {
  const std::string form = GetParam();
  const double e = 1e-4;
  std::pair<double, double> got[2];
  const char* orientations[2] = {"x", "y"};
  for (int o = 0; o < 2; ++o) {
    const Stress st = interiorStress(form, orientations[o], e, 0, 0);
    got[o] = recovered(form, st, e);
    EXPECT_NEAR(got[o].first, E, 0.01 * E) << form << " orientation " << orientations[o];
    EXPECT_NEAR(got[o].second, nu, 0.01 * nu) << form << " orientation " << orientations[o];
    EXPECT_NEAR(st.xy, 0, 1e-6 * st.xx);
  }
  EXPECT_NEAR(got[0].first, got[1].first, 0.01 * got[0].first);
  EXPECT_NEAR(got[0].second, got[1].second, 0.01 * got[0].second);
}

// Isotropy beyond the axes: pure shear exy gives σ_xy = E/(1+ν) exy in both orientations.
TEST_P(PatchTest, ShearModulus) {
  const std::string form = GetParam();
  const double e = 1e-4;
  for (const char* o : {"x", "y"}) {
    const Stress st = interiorStress(form, o, 0, 0, e);
    EXPECT_NEAR(st.xy, E / (1 + nu) * e, 0.01 * E / (1 + nu) * e) << form << " " << o;
    EXPECT_NEAR(st.xx, 0, 1e-3 * st.xy);
  }
}

INSTANTIATE_TEST_SUITE_P(Forms, PatchTest, ::testing::Values("plane_stress", "plane_strain"));

}  // namespace
}  // namespace pdq::mplm
