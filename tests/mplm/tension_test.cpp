// Fracture: the tension plate of §4.4.1 (examples/mplm/tension_x.toml: bonds along X, the
// load across them) fails within 5% of f_t = E ε_t, found by the strength search.
#include <gtest/gtest.h>

#include "engine/comm.hpp"
#include "harness.hpp"
#include "models/mplm/common/parameters.hpp"
#include "studies/strength_study.hpp"

namespace pdq::mplm {
namespace {

TEST(Tension, PlateFailsAtTensileStrength) {
  Comm comm;
  const Scenario sc = test::example("tension_x");
  const strength::Case c = strengthCase(sc);
  strength::Options opt;
  opt.relTol = 0.01;
  const strength::Result st = strength::findStrength(c, 2.0, 4.0, comm, opt);
  Parameters par;
  par.read(sc.modelParams);
  const double ft = par.E * par.law.epsT / 1e6, strength = 0.5 * (st.lower + st.upper);
  EXPECT_NEAR(strength, ft, 0.05 * ft) << "bracket [" << st.lower << ", " << st.upper << "]";
  EXPECT_LE(st.upper - st.lower, 0.01 * st.lower);
  EXPECT_EQ(st.mode, "tension");
}

}  // namespace
}  // namespace pdq::mplm
