#pragma once
// Running mplm2d (or mplm3d) with the quasi-static solver in a test, and reading its
// quasi_static.csv.
#include <mpi.h>
#include <omp.h>

#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "engine/problem.hpp"
#include "io/restart.hpp"
#include "io/standard_outputs.hpp"
#include "support/harness.hpp"

namespace pdq::mplm::test {

inline std::unique_ptr<Simulation> quasiStatic(Comm& comm, const Params& p, ParticleSet ps,
                                               const Solver& solver, const std::string& dir,
                                               double scale = 1,
                                               const std::string& model = "mplm2d") {
  RunConfig run;
  run.solver = solver;
  run.steps = solver.loadSteps;
  run.loading.scale = scale;
  run.outDir = dir;
  auto sim = makeSimulation(makeProblem(model, p, std::move(ps), run), comm);
  sim->setup();
  return sim;
}

// The quasi-static `problem` (built on the communicator, a restart read from `restartDir`'s
// file at `restartFrom` if given) run on the first `ranks` world ranks with `threads`
// threads; `done` is called on those ranks with the finished simulation.
template <class MakeProblem, class Done>
void runOnRanks(int ranks, int threads, MakeProblem&& problem, const std::string& restartDir,
                std::optional<long> restartFrom, Done&& done) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  MPI_Comm sub = pdq::test::firstRanks(ranks);
  if (sub != MPI_COMM_NULL) {
    Comm comm(sub);
    Problem pb = problem(comm);
    if (restartFrom) pb.restart = readRestart(restartPath(restartDir, *restartFrom), pb);
    auto sim = makeSimulation(std::move(pb), comm);
    sim->run();
    done(*sim);
    MPI_Comm_free(&sub);
  }
  omp_set_num_threads(before);
}

inline Solver solver(double tolerance, long loadSteps = 1, long maxIterations = 200000) {
  Solver s;
  s.quasiStatic = true;
  s.tolerance = tolerance;
  s.loadSteps = loadSteps;
  s.maxIterations = maxIterations;
  return s;
}

// quasi_static.csv's rows (after the header) as numbers.
inline std::vector<std::vector<double>> loadStepRows(const std::string& dir) {
  std::ifstream in(dir + "/quasi_static.csv");
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace pdq::mplm::test
