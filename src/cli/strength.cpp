// pdq strength: the failure-load search of the scenario's model (studies/strength_registry.hpp).
#include "studies/strength_registry.hpp"

#include "cli/commands.hpp"
#include "cli/options.hpp"

namespace pdq::cli {

void strengthCommand(const StrengthCommandOptions& o) {
  Comm comm(MPI_COMM_WORLD);
  Scenario sc = loadScenario(o.input);
  const auto& driver = StrengthRegistry::get(sc.problem.modelName, o.input);
  Params options = sc.strength;  // the scenario's [strength] table, then --set items
  setFromCommandLine(options, o.set);
  driver(sc, options, comm);
  options.checkAllUsed();
}

}  // namespace pdq::cli
