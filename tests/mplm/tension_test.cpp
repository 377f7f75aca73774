// Fracture: the tension plate of §4.4.1 (examples/mplm/tension_x.toml: bonds along X, the
// load across them), pulled by a uniform traction (`traction = true`, so that no loaded
// corner cracks first), fails within 5% of the stress at which the uniform strain brings
// its inclined interactions to ε_t, found by the strength search. Under σ along Y an
// interaction at 60° to X stretches by (3 − ν)/4 σ/E and its chord turns by
// φ = (1 + ν)(√3/4) σ/E, which the curvature term adds as β d ψ = 6β|φ| (docs/mplm.md), so
// ε_mp+ = ε_t at σ₁ = E ε_t / ((3 − ν)/4 + (3√3/2) β (1 + ν)). With α_t from the fracture
// energy the softening is slow, yet across the bonds no other interaction takes the load:
// the plate fails where its first interactions soften.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/comm.hpp"
#include "harness.hpp"
#include "models/mplm/common/parameters.hpp"
#include "studies/strength_study.hpp"

namespace pdq::mplm {
namespace {

TEST(Tension, PlateFailsWhereItsInclinedInteractionsReachTheTensileStrain) {
  Comm comm;
  const std::string src = std::string(std::getenv("PDQ_SOURCE_DIR")) + "/examples/mplm/";
  std::stringstream text;
  text << std::ifstream(src + "tension_x.toml").rdbuf();
  std::string toml = text.str();
  const std::string loading = "loading = \"tension\"\n";
  const auto at = toml.find(loading);
  ASSERT_NE(at, std::string::npos);
  toml.insert(at + loading.size(), "traction = true\n");
  const std::string path = "tension_test_out/tension_x_traction.toml";
  if (comm.rank() == 0) {
    std::filesystem::create_directories("tension_test_out");
    std::ofstream(path) << toml;
  }
  comm.barrier();
  const Scenario sc = readScenario(path);
  const strength::Case c = strengthCase(sc);
  strength::Options opt;
  opt.relTol = 0.01;
  const strength::Result st = strength::findStrength(c, 2.0, 4.0, comm, opt);
  Parameters par;
  par.read(sc.modelParams);
  const double ft = par.E * par.law.epsT / 1e6;
  const double onset = ft / ((3 - par.nu) / 4 + 1.5 * std::sqrt(3.0) * par.law.beta * (1 + par.nu));
  const double strength = 0.5 * (st.lower + st.upper);
  EXPECT_NEAR(strength, onset, 0.05 * onset) << "bracket [" << st.lower << ", " << st.upper << "]";
  EXPECT_LE(st.upper - st.lower, 0.01 * st.lower);
  EXPECT_EQ(st.mode, "tension");
}

}  // namespace
}  // namespace pdq::mplm
