#pragma once
// What a set-up simulation is: model, particles, bonds, time step, domain, cells,
// processor grid and memory; printed by `pdq info` and by `pdq run --verbose`.
#include <string>

#include "engine/simulation.hpp"

namespace pdq::cli {

// Collective; the text on rank 0 (empty elsewhere). `ranks` > 0 adds the processor grid
// pdq would choose for that many ranks.
std::string summary(Simulation& sim, const std::string& modelName, const std::string& source,
                    int ranks = 0);

}  // namespace pdq::cli
