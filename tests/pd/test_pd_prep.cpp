// The lattice generators and the thesis cantilever preprocessor (Table 3.1).
#include <gtest/gtest.h>

#include "engine/error.hpp"
#include "engine/model.hpp"
#include "io/thesis_input.hpp"
#include "prep/cantilever.hpp"
#include "prep/lattice.hpp"

namespace pdq::prep {
namespace {

TEST(PdPrep, CubicLatticeIdsRunXFastest) {
  ParticleSet ps;
  const std::size_t first = appendLattice(ps, cubicLattice(3, 4, 5, 0.5, {1, 2, 3}));
  EXPECT_EQ(first, 0u);
  ASSERT_EQ(ps.size(), 60u);
  // Particle (i, j, k) = (2, 1, 3) is row 2 + 3 (1 + 4 * 3) = 41, ID 42.
  EXPECT_EQ(ps.gid[41], 42);
  EXPECT_DOUBLE_EQ(ps.fixedRow(41)[0], 1 + 2 * 0.5);
  EXPECT_DOUBLE_EQ(ps.fixedRow(41)[1], 2 + 1 * 0.5);
  EXPECT_DOUBLE_EQ(ps.fixedRow(41)[2], 3 + 3 * 0.5);
  EXPECT_DOUBLE_EQ(ps.alterRow(41)[2], ps.fixedRow(41)[2]);
  EXPECT_THROW(appendLattice(ps, squareLattice(0, 3, 1.0)), InputError);
}

TEST(PdPrep, ThesisCantilever) {
  CantileverSpec spec;
  spec.m = 20;
  spec.n = 6;
  const CantileverProblem pb = thesisCantilever(spec);
  const Schema schema = ModelRegistry::create("lps")->schema();
  ASSERT_EQ(pb.particles.size(), 21u * 7u);
  EXPECT_EQ(pb.monitored, 21 * 7);
  const double* corner = pb.particles.fixedRow(pb.particles.size() - 1);
  EXPECT_DOUBLE_EQ(corner[0], 20 * 0.0254);
  EXPECT_DOUBLE_EQ(corner[1], 6 * 0.0254);
  int supported = 0, loaded = 0;
  double load = 0;
  for (std::size_t k = 0; k < pb.particles.size(); ++k) {
    const double* f = pb.particles.fixedRow(k);
    supported += f[schema.fixedIndex("bc_x")] == 1 && f[schema.fixedIndex("bc_y")] == 1;
    loaded += f[schema.fixedIndex("fy")] != 0;
    load += f[schema.fixedIndex("fy")];
    EXPECT_DOUBLE_EQ(f[schema.fixedIndex("volume")], 0.0254 * 0.0254 * 0.0254);
  }
  EXPECT_EQ(supported, 3 * 7);  // X = 0, s, 2s: closer than δ = 3 s to the left end
  EXPECT_EQ(loaded, 7);
  EXPECT_DOUBLE_EQ(load, 7.0);
  EXPECT_DOUBLE_EQ(pb.run.minCellSize, 1.2 * 3 * 0.0254);
  EXPECT_EQ(pb.run.steps, 200);
  EXPECT_EQ(pb.params.number("nu"), 0.22);
  EXPECT_EQ(pb.params.number("dt"), 3.36e-6);
  spec.model = "pmb";
  EXPECT_FALSE(thesisCantilever(spec).params.has("nu"));
  spec.model = "mplm";
  EXPECT_THROW(thesisCantilever(spec), InputError);
}

// The preprocessor's thesis input files read back into the same problem.
TEST(PdPrep, ThesisCantileverFilesRoundTrip) {
  CantileverSpec spec;
  spec.m = 12;
  spec.n = 4;
  const CantileverProblem direct = thesisCantilever(spec);
  writeThesisCantilever(spec, "pd_prep_files");
  const Problem read = readThesisInput("pd_prep_files");
  EXPECT_EQ(read.modelName, "lps");
  EXPECT_EQ(read.run.steps, 200);
  EXPECT_EQ(read.run.minCellSize, direct.run.minCellSize);
  EXPECT_EQ(read.particles.gid, direct.particles.gid);
  EXPECT_EQ(read.particles.fixed, direct.particles.fixed);
  EXPECT_EQ(read.particles.alter, direct.particles.alter);
}

}  // namespace
}  // namespace pdq::prep
