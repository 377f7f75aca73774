#pragma once
// Test support: run one problem on a sub-communicator of chosen size and gather its final
// state, so a single mpirun can compare 1, 2, 3 and 4 ranks (and several processor grids)
// bit for bit.
#include <mpi.h>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engine/model.hpp"
#include "engine/params.hpp"
#include "engine/particle_set.hpp"
#include "engine/simulation.hpp"

namespace pdq::test {

// A communicator of the first `n` world ranks (MPI_COMM_NULL on the others).
MPI_Comm firstRanks(int n);

// Rows of (gid, alterable attributes) sorted by gid, on the sub-communicator's rank 0
// (empty elsewhere); bonds as (owner, partner, dead, attrs...) rows.
struct State {
  std::vector<double> particles;
  std::vector<double> bonds;
  bool operator==(const State& o) const;
};
State gatherState(Simulation& sim);

// Sends a State from world rank `from` to world rank 0.
State toWorldRoot(const State& s, int from);

// A simple-cubic block of nx*ny*nz particles at spacing h, gids 1.., with extra columns zeroed.
ParticleSet cubicBlock(const Schema& schema, int nx, int ny, int nz, double h);

// Parameters from (key, value) texts, as a scenario's table gives them.
Params params(const std::vector<std::pair<std::string, std::string>>& kv);

// `model` configured with `params`, on `particles`, set up on `comm` to run `steps` steps
// under the load protocol `loading`.
std::unique_ptr<Simulation> simulation(Comm& comm, const std::string& model, const Params& params,
                                       ParticleSet particles, long steps,
                                       const Loading& loading = {});

// A global of the model by name (load, displacement, energies): a collective call.
double global(Simulation& sim, const std::string& name);

}  // namespace pdq::test
