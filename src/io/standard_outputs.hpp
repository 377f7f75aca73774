#pragma once
// A problem's Simulation, with the outputs the problem asks for attached: restart files,
// timehist.dat, history.csv, ParaView series and pictures.
#include <memory>

#include "engine/problem.hpp"
#include "engine/simulation.hpp"

namespace pdq {

// Ready to run (with a restart's bond state to restore); set up by the first advance() or by
// setup() when the caller needs the context (time step, decomposition) before stepping.
std::unique_ptr<Simulation> makeSimulation(Problem problem, Comm& comm);

void addStandardOutputs(Simulation& sim, const OutputSettings& settings);

}  // namespace pdq
