#pragma once
// What a set-up simulation is: model, particles, bonds, time step, domain, cells,
// processor grid and memory; printed by `pdq info` and by `pdq run --verbose`.
#include <string>

#include "engine/simulation.hpp"
#include "prep/generator.hpp"

namespace pdq::cli {

// Collective; the text on rank 0 (empty elsewhere). `ranks` > 0 adds the processor grid
// pdq would choose for that many ranks.
std::string summary(Simulation& sim, const std::string& modelName, const std::string& source,
                    int ranks = 0);

// The sizes of a problem estimated before anything is made (prep/generator.hpp): particles,
// bonds (the lattice's pairs within the model's horizon), cells, attributes and the memory
// of the particle and bond tables, against what the machine has. `fits`: whether that
// memory is available.
std::string estimateSummary(const SizeEstimate& e, const Model& model, bool& fits);

}  // namespace pdq::cli
