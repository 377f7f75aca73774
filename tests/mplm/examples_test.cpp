// The generators: hexagonal lattices, bars, and the thesis's examples built from them.
#include <gtest/gtest.h>

#include <cmath>

#include "harness.hpp"
#include "models/mplm/2d/attributes.hpp"
#include "models/mplm/2d/parameters.hpp"
#include "prep/hexagonal.hpp"
#include "prep/mplm/specimen.hpp"
#include "prep/rebar.hpp"

namespace pdq::mplm {
namespace {

constexpr double s = 0.02;

int neighboursWithin(const std::vector<std::array<double, 2>>& pts, std::size_t i, double r) {
  int n = 0;
  for (std::size_t j = 0; j < pts.size(); ++j)
    if (j != i && std::hypot(pts[j][0] - pts[i][0], pts[j][1] - pts[i][1]) <= r) ++n;
  return n;
}

TEST(Hexagonal, SixNeighboursAtSpacingInBothOrientations) {
  for (auto o : {prep::HexOrientation::BondsAlongX, prep::HexOrientation::BondsAlongY}) {
    const auto pts = prep::hexagonalRectangle(0.2, 0.2, s, o);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double x = pts[i][0], y = pts[i][1];
      EXPECT_TRUE(x >= 0 && x <= 0.2 + 1e-12 && y >= 0 && y <= 0.2 + 1e-12);
      if (x > 2 * s && x < 0.2 - 2 * s && y > 2 * s && y < 0.2 - 2 * s) {
        EXPECT_EQ(neighboursWithin(pts, i, 1.0001 * s), 6);
        EXPECT_EQ(neighboursWithin(pts, i, 1.5 * s), 6);  // δ = 1.5 s: no second ring
        EXPECT_EQ(neighboursWithin(pts, i, 0.9999 * s), 0);
      }
    }
  }
  // Bonds along X: a row of 11 particles from 0 to 0.2; along Y: a column likewise.
  const auto row = prep::hexagonalRectangle(0.2, 0, s, prep::HexOrientation::BondsAlongX);
  EXPECT_EQ(row.size(), 11u);
  const auto col = prep::hexagonalRectangle(0, 0.2, s, prep::HexOrientation::BondsAlongY);
  EXPECT_EQ(col.size(), 11u);
  EXPECT_DOUBLE_EQ(col.back()[1], 0.2);
}

TEST(Rebar, BarsAndStirrups) {
  const prep::Bar bar = prep::longitudinalBar(0, 1.16, 0, 0.02, 0.0127);
  const auto pts = prep::barPoints(bar, s);
  EXPECT_EQ(pts.size(), 59u);
  EXPECT_NEAR(pts[1][0] - pts[0][0], s, 1e-12);
  EXPECT_NEAR(bar.section.area(), 1.26677e-4, 1e-9);
  const auto st = prep::stirrups(0.04, 0.15, 1.16 - 0.04 + 0.075, 0.02, 0.24, 0.01);
  ASSERT_EQ(st.size(), 8u);
  EXPECT_NEAR(st.back().from[0], 1.09, 1e-12);
  // A 0.22 m stirrup at spacing ≤ s: 11 segments of exactly 0.02 m.
  EXPECT_EQ(prep::barPoints(st[0], s).size(), 12u);
}

double total(const ParticleSet& ps, int column) {
  double t = 0;
  for (std::size_t k = 0; k < ps.size(); ++k) t += ps.fixedRow(k)[column];
  return t;
}

// The nine example files build the thesis's specimens: plates of 14 × 24 cm loaded by 1 MPa
// at load_scale 1, beams under 1 kN/m with their supports and bars.
TEST(Examples, LoadsSupportsAndBars) {
  for (const std::string& name : test::examples) {
    SCOPED_TRACE(name);
    const Scenario sc = test::example(name);
    EXPECT_EQ(sc.problem.modelName, "mplm2d");
    const ParticleSet& ps = sc.problem.particles;
    EXPECT_GT(total(ps, MONITOR), 0);
    Parameters2d par;
    par.read(sc.modelParams);
    EXPECT_EQ(par.thickness, name == "deep_beam" ? 0.41 : 0.12);
    EXPECT_EQ(par.dt, 1.808e-7);  // the thesis's Δt
    if (sc.generator == "mplm_plate") {
      EXPECT_EQ(sc.problem.run.steps, 10000);
      // 1 MPa on the 0.14 × 0.12 m section, balanced.
      double up = 0;
      for (std::size_t k = 0; k < ps.size(); ++k) up += std::max(0.0, ps.fixedRow(k)[LOAD_Y]);
      EXPECT_NEAR(up, 0.14 * 0.12 * 1e6, 1e-6);
      EXPECT_NEAR(total(ps, LOAD_Y), 0, 1e-6);
      EXPECT_EQ(total(ps, CONSTRAINT), 0);
      continue;
    }
    ASSERT_EQ(sc.generator, "mplm_beam");
    // 1 kN/m over the span, downward; pinned at the left end, roller at the right: the
    // bottom particles within 4 cm of each end. The 4.06 m beam rests on 20 cm bearings
    // (11 particles each, X held at the corner).
    const double span = name == "deep_beam" ? 4.06 : 1.16;
    EXPECT_NEAR(total(ps, LOAD_Y), -1e3 * span, 1e-6);
    auto count = [&](int bits) {
      return select(ps, [=](const double* f) { return f[CONSTRAINT] == bits; }).size();
    };
    if (name == "deep_beam") {
      EXPECT_EQ(count(REST_Y | FIX_X), 1u);
      EXPECT_EQ(count(REST_Y), 21u);
    } else {
      EXPECT_EQ(count(FIX_X | FIX_Y), 3u);
      EXPECT_EQ(count(FIX_Y), 3u);
    }
    // Every other steel particle of a bar links to concrete.
    const auto steel = select(ps, [](const double* f) { return isSteel(f); });
    const auto links = select(ps, [](const double* f) { return isSteel(f) && f[LINK] == 1; });
    double bars = 0;
    for (std::size_t k : steel) bars = std::max(bars, ps.fixedRow(k)[BAR]);
    if (name == "plain_beam") {
      EXPECT_TRUE(steel.empty());
    }
    if (name == "rc_beam") {
      EXPECT_EQ(steel.size(), 59u);
      EXPECT_EQ(links.size(), 30u);
      EXPECT_EQ(bars, 1);
    }
    if (name == "rc_beam_stirrups") {
      EXPECT_EQ(bars, 9);  // the bar and 8 stirrups
    }
    if (name == "deep_beam") {
      EXPECT_EQ(bars, 11);  // the bar and 10 stirrups
    }
  }
}

}  // namespace
}  // namespace pdq::mplm
