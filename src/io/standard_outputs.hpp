#pragma once
// The outputs a problem asks for, attached to its Simulation: restart files, timehist.dat,
// history.csv, ParaView series and pictures.
#include "engine/simulation.hpp"
#include "engine/problem.hpp"

namespace pdq {

void addStandardOutputs(Simulation& sim, const OutputSettings& settings);

}  // namespace pdq
