// The failure classifier of `pdq strength` (mplm::failureMode) on real 2D and 3D members,
// on every rank count of the test alike: a crack is cut into the lattice (the interactions
// across a line of the elevation broken, the particles beyond it moved apart along its
// normal), and the classifier must name it by its orientation, wherever along the span it
// lies: a vertical crack is flexural even near a support, and so is a steep inclined
// (flexure–shear) crack, a diagonal one is shear even at midspan, two mirror-image diagonals in the
// two shear spans are shear, a crushed member is compression, and cracks closed again are judged by
// their interactions' directions.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "engine/model.hpp"
#include "io/standard_outputs.hpp"
#include "models/mplm/common/attributes.hpp"
#include "scenario/scenario.hpp"

namespace pdq::mplm {
namespace {

// A beam on two supports, 1.2 x 0.3 m in elevation (2D, s = 2 cm) or 1.2 x 0.32 x 0.12 m (3D,
// s = 4 cm), one bar near the bottom.
std::string member(bool threeD) {
  if (threeD)
    return R"(description = "3D beam for the failure classifier"
steps = 1
[model]
name = "mplm3d"
spacing = 0.04
[particles]
generator = "mplm3d_beam"
length = 1.2
depth = 0.32
width = 0.12
bonds_along = "x"
layers_along = "z"
supports = "simple"
loading = "top"
load = 1000.0
bar_size = "#13"
bar_count = 1
bar_face = "bottom"
bar_cover = 0.04
)";
  return R"(description = "2D beam for the failure classifier"
steps = 1
[model]
name = "mplm2d"
thickness = 0.12
[particles]
generator = "mplm_beam"
span = 1.2
depth = 0.3
bar_diameter = 0.0127
bar_centroid = 0.04
)";
}

std::unique_ptr<Simulation> build(bool threeD, Comm& comm) {
  const std::string dir = "out_failure_mode";
  std::filesystem::create_directories(dir);
  // Each rank reads its own copy: none reads a file another is writing.
  const std::string path = dir + "/member_" + std::to_string(comm.rank()) + ".toml";
  std::ofstream(path) << member(threeD);
  Scenario sc = readScenario(path);
  sc.problem.run.outDir = dir;
  auto sim = makeSimulation(std::move(sc.problem), comm);
  sim->setup();
  return sim;
}

// A crack through the point (x, y) of the elevation with unit normal (nx, ny): every
// concrete interaction across it gets damage 1 (tensile or compressive), and the particles on
// the normal's side move by `opening` along it.
struct Crack {
  double x, y, nx, ny;
};

struct Member {
  double xlo, xhi, ylo, yhi;
};

Member extent(Simulation& sim) {
  const Particles& P = sim.particles();
  Context& ctx = sim.context();
  Member m{1e300, -1e300, 1e300, -1e300};
  for (std::size_t i = 0; i < P.owned(); ++i) {
    m.xlo = std::min(m.xlo, P.fixed(i)[FX_X]);
    m.xhi = std::max(m.xhi, P.fixed(i)[FX_X]);
    m.ylo = std::min(m.ylo, P.fixed(i)[FX_Y]);
    m.yhi = std::max(m.yhi, P.fixed(i)[FX_Y]);
  }
  return {ctx.min(m.xlo), ctx.max(m.xhi), ctx.min(m.ylo), ctx.max(m.yhi)};
}

void cut(Simulation& sim, const std::vector<Crack>& cracks, double opening, int damage) {
  Particles& P = sim.particles();
  Bonds& B = sim.bonds();
  auto side = [&](std::size_t i, const Crack& c) {
    const double* X = P.fixed(i);
    return (X[FX_X] - c.x) * c.nx + (X[FX_Y] - c.y) * c.ny > 0;
  };
  for (std::size_t i = 0; i < P.local(); ++i)
    for (const Crack& c : cracks)
      if (side(i, c)) {
        P.alter(i)[0] += opening * c.nx;
        P.alter(i)[1] += opening * c.ny;
      }
  for (std::size_t i = 0; i < P.owned(); ++i)
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      const std::int32_t j = B.partner(b);
      if (j < 0 || isSteel(P.fixed(i)) || isSteel(P.fixed(static_cast<std::size_t>(j)))) continue;
      const auto k = static_cast<std::size_t>(j);
      for (const Crack& c : cracks)
        if (side(i, c) != side(k, c)) B.attr(b)[damage] = 1;
    }
}

std::string mode(Simulation& sim) { return sim.model().strengthSpec().failureMode(sim.context()); }

class FailureMode : public ::testing::TestWithParam<bool> {};

TEST_P(FailureMode, NamedByTheCracksOrientation) {
  const bool threeD = GetParam();
  Comm comm(MPI_COMM_WORLD);
  constexpr double kOpen = 1e-3;  // 1 mm
  const double diagonal = std::sqrt(0.5);
  auto fresh = [&] { return build(threeD, comm); };
  {
    auto sim = fresh();
    EXPECT_EQ(mode(*sim), "none");
  }
  const Member m = [&] {
    auto sim = fresh();
    return extent(*sim);
  }();
  const double span = m.xhi - m.xlo, mid = (m.xlo + m.xhi) / 2, ymid = (m.ylo + m.yhi) / 2;
  const double quarter = m.xlo + span / 4;
  {  // vertical, a quarter of the span from a support: outside the middle third
    auto sim = fresh();
    cut(*sim, {{quarter, ymid, 1, 0}}, kOpen, OMEGA_T);
    EXPECT_EQ(mode(*sim), "flexural");
  }
  {  // vertical at midspan
    auto sim = fresh();
    cut(*sim, {{mid, ymid, 1, 0}}, kOpen, OMEGA_T);
    EXPECT_EQ(mode(*sim), "flexural");
  }
  {  // flexure–shear: inclined 65° to the axis (its normal 25° from it)
    auto sim = fresh();
    const double a = 25 * std::numbers::pi / 180;
    cut(*sim, {{quarter, ymid, std::cos(a), std::sin(a)}}, kOpen, OMEGA_T);
    EXPECT_EQ(mode(*sim), "flexural");
  }
  {  // one diagonal at midspan
    auto sim = fresh();
    cut(*sim, {{mid, ymid, diagonal, diagonal}}, kOpen, OMEGA_T);
    EXPECT_EQ(mode(*sim), "shear");
  }
  {  // mirror-image diagonals in the two shear spans, opening towards the supports
    auto sim = fresh();
    cut(*sim, {{quarter, ymid, -diagonal, diagonal}}, kOpen, OMEGA_T);
    cut(*sim, {{m.xhi - span / 4, ymid, diagonal, diagonal}}, kOpen, OMEGA_T);
    EXPECT_EQ(mode(*sim), "shear");
  }
  {  // a wide vertical crack beside a hairline diagonal: the widest decides
    auto sim = fresh();
    cut(*sim, {{quarter, ymid, 1, 0}}, kOpen, OMEGA_T);
    cut(*sim, {{mid, ymid, diagonal, diagonal}}, kOpen / 20, OMEGA_T);
    EXPECT_EQ(mode(*sim), "flexural");
  }
  {  // and the other way round
    auto sim = fresh();
    cut(*sim, {{quarter, ymid, 1, 0}}, kOpen / 20, OMEGA_T);
    cut(*sim, {{mid, ymid, diagonal, diagonal}}, kOpen, OMEGA_T);
    EXPECT_EQ(mode(*sim), "shear");
  }
  {  // closed again: the interactions' directions alone
    auto sim = fresh();
    cut(*sim, {{quarter, ymid, 1, 0}}, 0, OMEGA_T);
    EXPECT_EQ(mode(*sim), "flexural");
    cut(*sim, {{mid, ymid, diagonal, diagonal}}, 0, OMEGA_T);
    cut(*sim, {{mid + span / 8, ymid, diagonal, diagonal}}, 0, OMEGA_T);
    EXPECT_EQ(mode(*sim), "shear");
  }
  {  // crushing: more interactions damaged in compression than in tension
    auto sim = fresh();
    cut(*sim, {{mid, ymid, 1, 0}}, 0, OMEGA_C);
    cut(*sim, {{quarter, ymid, 1, 0}}, 0, OMEGA_C);
    cut(*sim, {{mid + span / 8, ymid, 1, 0}}, kOpen, OMEGA_T);
    EXPECT_EQ(mode(*sim), "compression");
  }
}

INSTANTIATE_TEST_SUITE_P(Lattices, FailureMode, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "FCC3D" : "Hexagonal2D"; });

}  // namespace
}  // namespace pdq::mplm
