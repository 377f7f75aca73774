// Fracture: the tension plate of §4.4.1 (vertical orientation, load across the bonds)
// fails within 5% of f_t.
#include <gtest/gtest.h>

#include "engine/comm.hpp"
#include "prep/mplm/examples.hpp"
#include "studies/mplm_strength.hpp"

namespace pdq::mplm {
namespace {

TEST(Tension, PlateFailsAtTensileStrength) {
  Comm comm(MPI_COMM_WORLD);
  const Example ex = plate("x", false);
  StrengthOptions opt;
  opt.relTol = 0.01;
  const Strength st = findStrength(ex, 2.0, 4.0, comm, opt);
  const double ft = 2.758, strength = 0.5 * (st.lower + st.upper);
  EXPECT_NEAR(strength, ft, 0.05 * ft) << "bracket [" << st.lower << ", " << st.upper << "]";
  EXPECT_LE(st.upper - st.lower, 0.01 * st.lower);
  EXPECT_EQ(st.mode, "tension");
}

}  // namespace
}  // namespace pdq::mplm
