// The quasi-static solver (adaptive dynamic relaxation) on mplm2d:
//   * the patch test: a boundary layer moved by a uniform strain, the interior relaxes to
//     that strain (the exact solution) within 1e-6;
//   * a cantilever under a tip load relaxes to the lattice's linear static solution (K
//     assembled by finite differences, solved directly) within 1e-6;
//   * with damage, every load step's converged state balances the loads of the damaged
//     lattice: the forces evaluated again there leave an out-of-balance force below the
//     tolerance;
//   * past its peak under force control, the structure's failure is detected within a load
//     step's first iterations and reported, never looped on.
//   * a load step may take ten times the first load step's iterations when that is more than
//     max_iterations, also after a restart;
//   * a load step that softened (over 1.75 times the secant's compliance) halves the next
//     increment.
#include "quasi_static.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>

#include "engine/error.hpp"
#include "harness.hpp"
#include "io/standard_outputs.hpp"
#include "models/mplm/2d/attributes.hpp"
#include "prep/hexagonal.hpp"
#include "prep/mplm/specimen.hpp"
#include "support/static_reference.hpp"

namespace pdq::mplm {
namespace {

// Force control towards kBeyondPeak × the unit line load, far above the small beam's strength,
// in kLoadSteps: the first holds (the beam cracks at 120).
constexpr double kBeyondPeak = 2000;
constexpr long kLoadSteps = 16;

TEST(QuasiStatic, PatchTestRelaxesToTheUniformStrain) {
  constexpr double s = 0.02, L = 0.3, exx = 1e-4, eyy = -3e-5, exy = 0;
  ParticleSet ps = newParticleSet();
  addConcrete(ps, prep::hexagonalRectangle(L, L, s, prep::HexOrientation::BondsAlongX));
  auto edge = select(ps, [&](const double* f) {
    return f[0] < 1.5 * s || f[0] > L - 1.5 * s || f[1] < 1.5 * s || f[1] > L - 1.5 * s;
  });
  for (std::size_t k : edge) {
    const double X = ps.fixedRow(k)[0] - L / 2, Y = ps.fixedRow(k)[1] - L / 2;
    constrain(ps, {k}, FIX_X | FIX_Y | FIX_T, {exx * X + exy * Y, exy * X + eyy * Y, 0});
  }
  Comm comm;
  // α_t = 10 as when the test was written: the boundary layer's jump stretches its neighbours
  // past ε_t for a while, and with the default's slower softening that transient damage gets
  // the single load step cut back (two load steps instead of one).
  auto sim =
      test::quasiStatic(comm, test::params({{"kinematics", "small"}, {"tensile_ratio", "10"}}), ps,
                        test::solver(1e-10), "qs_patch_out");
  sim->run();
  const auto rows = test::loadStepRows("qs_patch_out");
  ASSERT_EQ(rows.size(), 1u);
  if (comm.root()) std::printf("patch test: %g iterations\n", rows[0][2]);
  Particles& P = sim->particles();
  double worst = 0;
  for (std::size_t i = 0; i < P.owned(); ++i) {
    const double X = P.fixed(i)[FX_X] - L / 2, Y = P.fixed(i)[FX_Y] - L / 2;
    const double ux = P.alter(i)[AX] - P.fixed(i)[FX_X], uy = P.alter(i)[AY] - P.fixed(i)[FX_Y];
    const double w = std::max({std::fabs(ux - exx * X - exy * Y), std::fabs(uy - exy * X - eyy * Y),
                               std::fabs(P.alter(i)[THETA]) * s});
    worst = std::max(worst, w);
  }
  worst = sim->context().max(worst);
  // Relative to the largest displacement of the field.
  EXPECT_LT(worst / (std::fabs(exx) + std::fabs(exy)) / (L / 2), 1e-6) << worst;
}

// A clamped cantilever, 8 rows by 61 columns, a tip load P spread over the tip column.
struct Cantilever {
  ParticleSet ps = newParticleSet();
  std::vector<std::size_t> clamped, tip;
};

Cantilever cantilever(double P) {
  constexpr double s = 0.02;
  constexpr int rows = 8, columns = 61;
  const double p = prep::hexPitch(s);
  const double length = (columns - 1) * p, depth = (rows - 0.5) * s;
  Cantilever c;
  addConcrete(c.ps, prep::hexagonalRectangle(length, depth, s, prep::HexOrientation::BondsAlongY));
  c.clamped = select(c.ps, [&](const double* f) { return f[0] < 0.5 * p; });
  c.tip = select(c.ps, [&](const double* f) { return f[0] > length - 0.5 * p; });
  constrain(c.ps, c.clamped, FIX_X | FIX_Y | FIX_T);
  load(c.ps, c.tip, 0, -P / rows);
  monitor(c.ps, c.tip);
  return c;
}

// The cantilever relaxed with the given fictitious masses against the lattice's linear static
// solution; returns the iterations.
double expectLinearStaticSolution(Solver::Masses masses, const std::string& dir) {
  Comm comm;
  EXPECT_EQ(comm.size(), 1) << "the direct reference solve runs on one rank";
  const Cantilever c = cantilever(2000);
  const Params p =
      test::params({{"thickness", "0.1"}, {"damage", "false"}, {"kinematics", "small"}});
  Solver solver = test::solver(1e-7);
  solver.masses = masses;
  auto sim = test::quasiStatic(comm, p, c.ps, solver, dir);
  sim->run();
  const auto rows = test::loadStepRows(dir);
  EXPECT_EQ(rows.size(), 1u);
  if (rows.size() != 1) return 0;
  EXPECT_LE(rows[0][5], 1e-7);

  auto ref = test::quasiStatic(comm, p, c.ps, test::solver(1e-10), "qs_cantilever_ref");
  Particles& R = ref->particles();
  std::vector<pdq::test::FreeDof> dofs;
  for (std::size_t i = 0; i < R.owned(); ++i) {
    if (R.fixed(i)[CONSTRAINT] != 0) continue;
    const double* f = R.fixed(i);
    dofs.push_back({i, AX, FORCE_X, 1, f[LOAD_X]});
    dofs.push_back({i, AY, FORCE_Y, 1, f[LOAD_Y]});
    dofs.push_back({i, THETA, MOMENT, 1, f[LOAD_M]});
  }
  const std::vector<double> u = pdq::test::linearStatic(*ref, dofs, 1e-6);
  // Particles of both runs sit alike (same problem, one rank).
  Particles& P = sim->particles();
  double du = 0, nu = 0, dt = 0, nt = 0, tip = 0, tipRef = 0;
  for (std::size_t k = 0; k < dofs.size(); ++k) {
    const std::size_t i = dofs[k].particle;
    EXPECT_EQ(P.gid(i), R.gid(i));
    const int col = dofs[k].alter;
    const double got = P.alter(i)[col] - (col == THETA ? 0.0 : P.fixed(i)[col]);
    (col == THETA ? dt : du) += (got - u[k]) * (got - u[k]);
    (col == THETA ? nt : nu) += u[k] * u[k];
    if (col == AY && P.fixed(i)[MONITOR] != 0) tip += got, tipRef += u[k];
  }
  const double errU = std::sqrt(du / nu), errT = std::sqrt(dt / nt);
  std::printf(
      "cantilever: %g iterations, |u - u_K|/|u_K| = %.2e (translations), %.2e "
      "(rotations), tip %.9g m vs %.9g m\n",
      rows[0][2], errU, errT, tip / 8, tipRef / 8);
  EXPECT_LT(errU, 1e-6);
  EXPECT_LT(errT, 1e-6);
  EXPECT_NEAR(tip, tipRef, 1e-6 * std::fabs(tipRef));
  return rows[0][2];
}

TEST(QuasiStatic, CantileverRelaxesToTheLinearStaticSolution) {
  expectLinearStaticSolution(Solver::Masses::Stiffness, "qs_cantilever_out");
}

// With the assembled stiffness the relaxation is a modified Newton iteration: on the linear
// lattice its first step is the solution but for the finite differences' error, where the
// dynamic relaxation takes thousands of iterations (docs/quasi-static.md, "Assembled
// stiffness").
TEST(QuasiStatic, AssembledStiffnessSolvesTheCantileverInAFewIterations) {
  const double its = expectLinearStaticSolution(Solver::Masses::Assembled, "qs_cantilever_asm");
  EXPECT_GE(its, 1);
  EXPECT_LE(its, 3);
}

// With damage: at every load step's converged state, the forces evaluated again (with the
// damage kept) balance the loads to the tolerance, in the solver's norm (free DOFs, each
// force over its mass or inertia).
// Returns the iterations of the three load steps.
double expectDamagedEquilibrium(Solver::Masses masses, const std::string& dir) {
  Comm comm;
  const double tol = 1e-6, scale = 120;
  Solver solver = test::solver(tol, 3);
  solver.masses = masses;
  auto sim = test::quasiStatic(comm, test::params({}), test::smallBeam(), solver, dir, scale);
  Context& ctx = sim->context();
  std::vector<Body> bodies(sim->particles().owned());
  sim->model().bodies(ctx, bodies);
  while (sim->advance()) {
  }
  sim->finish();
  EXPECT_EQ(sim->step(), 3);
  EXPECT_GT(test::global(*sim, "damaged"), 0) << "the load should damage the root";
  Particles& P = sim->particles();
  sim->model().force(ctx);
  const double factor = ctx.loadFactor();
  EXPECT_EQ(factor, scale);
  const double r2 = ctx.sumOwned([&](std::size_t i) {
    double s = 0;
    for (int d = 0; d < 3; ++d) {
      if (bodies[i].constraint[d] != pdq::Constraint::Free) continue;
      const double f = P.integ(i)[d] + bodies[i].load[d] * factor;
      s += f * f / (d < 2 ? bodies[i].mass : bodies[i].inertia);
    }
    return s;
  });
  const double p2 = ctx.sumOwned([&](std::size_t i) {
    double s = 0;
    for (int d = 0; d < 3; ++d)
      s += std::pow(bodies[i].load[d] * factor, 2) / (d < 2 ? bodies[i].mass : bodies[i].inertia);
    return s;
  });
  EXPECT_GT(p2, 0);
  EXPECT_LE(std::sqrt(r2), tol * std::sqrt(p2));
  const auto rows = test::loadStepRows(dir);
  EXPECT_EQ(rows.size(), 3u);
  if (rows.size() != 3) return 0;
  for (const auto& row : rows) EXPECT_LE(row[5], tol);
  if (comm.root())
    std::printf("damaged beam (%s): %g, %g, %g iterations; %g damaged interactions\n", dir.c_str(),
                rows[0][2], rows[1][2], rows[2][2], test::global(*sim, "damaged"));
  return rows[0][2] + rows[1][2] + rows[2][2];
}

TEST(QuasiStatic, DamagedStateIsInEquilibrium) {
  expectDamagedEquilibrium(Solver::Masses::Stiffness, "qs_damage_out");
}

// The modified Newton iteration of the assembled stiffness reaches the damaged lattice's
// equilibrium too, in fewer iterations than the dynamic relaxation.
TEST(QuasiStatic, AssembledStiffnessBalancesTheDamagedBeamInFewerIterations) {
  const double newton = expectDamagedEquilibrium(Solver::Masses::Assembled, "qs_damage_asm");
  const double relaxation = expectDamagedEquilibrium(Solver::Masses::Stiffness, "qs_damage_dr");
  EXPECT_GT(newton, 0);
  EXPECT_LT(newton, relaxation);
}

// Force control beyond the beam's strength: once a load step finds no equilibrium, the run
// stops at the last one and says why; each try is stopped by the solver's early look at its
// motion (runaway or a crack running), not by max_iterations, which here is far more than
// the test could wait for.
TEST(QuasiStatic, PeakUnderForceControlIsDetectedAndReported) {
  Comm comm;
  Solver solver = test::solver(1e-6, kLoadSteps, 100000000);
  solver.maxCutBacks = 1;
  auto sim = test::quasiStatic(comm, test::params({}), test::smallBeam(), solver, "qs_peak_out",
                               kBeyondPeak);
  while (sim->advance()) {
  }
  sim->finish();
  const Simulation::LoadStep& last = sim->lastLoadStep();
  const std::string& reason = sim->context().stopReason();
  EXPECT_GT(last.factor, 0) << "a first load step holds";
  EXPECT_LT(last.factor, kBeyondPeak);
  EXPECT_GT(last.beyond, last.factor);
  EXPECT_LE(last.beyond - last.factor, kBeyondPeak / kLoadSteps / 2) << "cut back once";
  EXPECT_THAT(reason, ::testing::HasSubstr("no equilibrium beyond load factor"));
  EXPECT_THAT(reason, ::testing::HasSubstr("has no equilibrium near the last"));
  EXPECT_THAT(reason, ::testing::HasSubstr("passed its peak load"));
  EXPECT_GT(test::global(*sim, "damaged"), 0);
  if (comm.root()) std::printf("stopped: %s\n", reason.c_str());
}

// A load step may take up to ten times the first load step's iterations even when that is
// more than max_iterations (the first, elastic from rest, measures how slowly the lattice
// relaxes), also in a run restarted after the first load step. With max_iterations set to
// the first load step's iterations, the later load steps, which need more, converge exactly
// as without a cap; capped at max_iterations they would be cut back.
TEST(QuasiStatic, IterationCapScalesWithTheFirstLoadStep) {
  const double scale = 120;
  auto problem = [&](long maxIterations, const std::string& dir) {
    RunConfig run;
    run.solver = test::solver(1e-6, 3, maxIterations);
    run.steps = 3;
    run.loading.scale = scale;
    run.outDir = dir;
    Problem pb = makeProblem("mplm2d", test::params({}), test::smallBeam(), run);
    pb.output.restartEvery = 1;
    return pb;
  };
  auto runWith = [&](long maxIterations, const std::string& dir,
                     std::optional<long> restartFrom = {}, const std::string& from = "") {
    pdq::test::State s;
    test::runOnRanks(
        1, 1, [&](Comm&) { return problem(maxIterations, dir); }, from, restartFrom,
        [&](Simulation& sim) { s = pdq::test::gatherState(sim); });
    return s;
  };
  const pdq::test::State free = runWith(200000, "qs_cap_free");
  const auto rows = test::loadStepRows("qs_cap_free");
  ASSERT_EQ(rows.size(), 3u);
  const long first = static_cast<long>(rows[0][2]);
  ASSERT_GT(std::max(rows[1][2], rows[2][2]), rows[0][2])
      << "the test needs a later load step slower than the first";
  const pdq::test::State capped = runWith(first, "qs_cap_first");
  const auto cappedRows = test::loadStepRows("qs_cap_first");
  ASSERT_EQ(cappedRows.size(), 3u) << "a load step was cut back";
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_EQ(cappedRows[k][2], rows[k][2]) << "load step " << k + 1;
  EXPECT_TRUE(capped == free);
  const pdq::test::State resumed = runWith(first, "qs_cap_resumed", 1, "qs_cap_first");
  EXPECT_TRUE(resumed == free) << "restarted after the first load step";
  if (Comm().root())
    std::printf("iteration cap: max_iterations %ld, load steps of %g, %g, %g iterations\n", first,
                rows[0][2], rows[1][2], rows[2][2]);
}

// The fictitious masses from the stiffness's Gershgorin bounds (the default) against the
// model's masses scaled by ω_max²: the small reinforced beam, whose bar is stiffer than the
// concrete, relaxes its first load step (elastic, from rest) in fewer iterations, to the
// same equilibrium.
TEST(QuasiStatic, GershgorinMassesRelaxAReinforcedBeamFaster) {
  Comm comm;
  const Params p = test::params({{"damage", "false"}});
  Solver model = test::solver(1e-9);
  model.masses = pdq::Solver::Masses::Model;
  auto byModel = test::quasiStatic(comm, p, test::smallBeam(), model, "qs_masses_model", 60);
  auto byStiffness =
      test::quasiStatic(comm, p, test::smallBeam(), test::solver(1e-9), "qs_masses_stiffness", 60);
  byModel->run();
  byStiffness->run();
  const auto m = test::loadStepRows("qs_masses_model");
  const auto g = test::loadStepRows("qs_masses_stiffness");
  ASSERT_EQ(m.size(), 1u);
  ASSERT_EQ(g.size(), 1u);
  EXPECT_LT(g[0][2], m[0][2]);
  // The same displacements, to what the tolerance leaves.
  Particles& A = byModel->particles();
  Particles& B = byStiffness->particles();
  double diff = 0, size = 0;
  for (std::size_t i = 0; i < A.owned(); ++i) {
    ASSERT_EQ(A.gid(i), B.gid(i));
    for (int c : {AX, AY}) {
      const double a = A.alter(i)[c] - A.fixed(i)[c], b = B.alter(i)[c] - B.fixed(i)[c];
      diff = std::max(diff, std::fabs(a - b));
      size = std::max(size, std::fabs(a));
    }
  }
  diff = byModel->context().max(diff);
  size = byModel->context().max(size);
  EXPECT_LT(diff, 1e-6 * size);
  if (comm.root())
    std::printf(
        "reinforced beam, first load step: %g iterations (model's masses), %g "
        "(Gershgorin), displacements alike to %.1e\n",
        m[0][2], g[0][2], diff / size);
}

// peak_tolerance: under force control past the peak, the run ends as soon as the lowest
// load found to have no equilibrium lies within the tolerance of the last equilibrium
// (the bisection's bracket), before the increment reaches its smallest; without it the
// run refines the same peak further.
TEST(QuasiStatic, PeakToleranceEndsTheRunAtTheBracket) {
  Comm comm;
  auto peak = [&](double tolerance, const std::string& dir) {
    Solver solver = test::solver(1e-6, kLoadSteps, 100000000);
    solver.maxCutBacks = 10;
    solver.peakTolerance = tolerance;
    auto sim =
        test::quasiStatic(comm, test::params({}), test::smallBeam(), solver, dir, kBeyondPeak);
    while (sim->advance()) {
    }
    sim->finish();
    return std::make_pair(sim->lastLoadStep(), sim->context().stopReason());
  };
  const auto [coarse, why] = peak(0.05, "qs_peak_tolerance");
  const auto [fine, whyFine] = peak(0, "qs_peak_fine");
  EXPECT_THAT(why, ::testing::HasSubstr("within peak_tolerance (0.05)"));
  EXPECT_GT(coarse.factor, 0);
  EXPECT_LE(coarse.beyond - coarse.factor, 0.05 * coarse.factor);
  EXPECT_GT(coarse.beyond - coarse.factor, kBeyondPeak / kLoadSteps / 1024) << "not the smallest";
  EXPECT_THAT(whyFine, ::testing::Not(::testing::HasSubstr("peak_tolerance")));
  EXPECT_LT(fine.beyond - fine.factor, coarse.beyond - coarse.factor);
  EXPECT_GE(fine.factor, coarse.factor);
  EXPECT_LE(fine.beyond, coarse.beyond);
  if (comm.root())
    std::printf("peak: %g to %g with peak_tolerance 0.05, %g to %g without\n", coarse.factor,
                coarse.beyond, fine.factor, fine.beyond);
}

// Nearing the peak under force control: a load step of the modified Newton iteration (the
// assembled stiffness) over 1.75 times as compliant as the secant of the last equilibrium
// (its displacement along the loads per load, over u/λ) halves the next increment, so that
// the try beyond the peak starts close to it; the load steps before it keep or double
// theirs. Dynamic relaxation (the Gershgorin masses), whose load steps cost the lattice's
// relaxation time whatever their increment, keeps its increments. The first load factor
// tried after each load step is read from the log (6 significant digits).
TEST(QuasiStatic, SofteningHalvesTheNextIncrement) {
  Comm comm;
  for (const auto masses : {Solver::Masses::Assembled, Solver::Masses::Stiffness}) {
    const bool newton = masses == Solver::Masses::Assembled;
    SCOPED_TRACE(newton ? "assembled stiffness" : "Gershgorin masses");
    Solver solver = test::solver(1e-6, kLoadSteps, 100000000);
    solver.maxCutBacks = 10;
    solver.masses = masses;
    const std::string dir = newton ? "qs_softening" : "qs_softening_gershgorin";
    auto sim =
        test::quasiStatic(comm, test::params({}), test::smallBeam(), solver, dir, kBeyondPeak / 5);
    while (sim->advance()) {
    }
    sim->finish();
    if (!comm.root()) continue;
    const auto rows = test::loadStepRows(dir);  // load_step, load_factor, ..., displacement (7)
    std::ifstream log(dir + "/debug.txt");
    std::stringstream text;
    text << log.rdbuf();
    auto firstTried = [&](long step) {  // the load factor of load step `step`'s first try
      const std::string what = "load step " + std::to_string(step);
      std::size_t at = text.str().find(what + " (load factor ");
      const std::size_t converged = text.str().find(what + ": load factor ");
      at = std::min(at, converged);
      if (at == std::string::npos) return -1.0;
      return std::stod(text.str().substr(text.str().find("load factor ", at) + 12));
    };
    long softened = 0;
    for (std::size_t k = 1; k + 1 < rows.size(); ++k) {
      const double before = rows[k][1] - rows[k - 1][1];
      const double softening =
          (rows[k][7] - rows[k - 1][7]) / before / (rows[k - 1][7] / rows[k - 1][1]);
      const double tried = firstTried(static_cast<long>(rows[k + 1][0])) - rows[k][1];
      const double tolerance = 1e-5 * rows[k][1];
      if (softening <= 1.75) {
        EXPECT_GE(tried, before - tolerance) << "after load step " << rows[k][0];
      } else if (newton) {
        ++softened;
        EXPECT_NEAR(tried, before / 2, tolerance) << "after load step " << rows[k][0];
      } else if (++softened == 1) {  // later ones follow the tries beyond the peak
        EXPECT_GE(tried, before - tolerance) << "after load step " << rows[k][0];
      }
      std::printf("load step %g: %.3g times as compliant, increment %g, the next tried %g\n",
                  rows[k][0], softening, before, tried);
    }
    EXPECT_GT(softened, 0) << "no load step softened past 1.75 before the peak";
  }
}

// A load step in which interactions break: K̂, the secant of the load step's start, is
// stiffer than the cracking lattice, and modified Newton steps alone approach its
// equilibrium in ever smaller moves (as many iterations as the diagonal relaxation); once
// they slow, the iteration takes up momentum and converges in a fraction of them.
TEST(QuasiStatic, AssembledStiffnessTakesUpMomentumInACrackingLoadStep) {
  const double tol = 1e-6, scale = 240;
  std::vector<std::vector<double>> last;
  for (auto masses : {Solver::Masses::Assembled, Solver::Masses::Stiffness}) {
    Comm comm;
    Solver solver = test::solver(tol, 3);
    solver.masses = masses;
    const std::string dir = masses == Solver::Masses::Assembled ? "qs_crack_asm" : "qs_crack_dr";
    auto sim = test::quasiStatic(comm, test::params({}), test::smallBeam(), solver, dir, scale);
    while (sim->advance()) {
    }
    sim->finish();
    EXPECT_EQ(sim->step(), 3);
    const auto rows = test::loadStepRows(dir);
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_LE(rows[2][5], tol);
    EXPECT_GT(rows[2][8], 0) << "the last load step should break interactions";
    last.push_back(rows[2]);
    if (comm.root()) {  // the log says when the cracking load step took up momentum
      std::ifstream log(dir + "/debug.txt");
      std::string line, third;
      while (std::getline(log, line))
        if (line.rfind("load step 3:", 0) == 0) third = line;
      EXPECT_EQ(third.find("(momentum from iteration ") != std::string::npos,
                masses == Solver::Masses::Assembled)
          << third;
    }
    if (comm.root())
      std::printf("cracking load step (%s): %g iterations, %g broken interactions\n", dir.c_str(),
                  rows[2][2], rows[2][8]);
  }
  EXPECT_LT(5 * last[0][2], last[1][2]);
}

}  // namespace
}  // namespace pdq::mplm
