// pdq strength: the failure-load search of a scenario (studies/strength_study.hpp).
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "studies/strength_study.hpp"

namespace pdq::cli {

void strengthCommand(const StrengthCommandOptions& o) {
  Comm comm;
  const Scenario sc = loadScenario(o.input);
  Params options = sc.strength;  // the scenario's [strength] table, then --set items
  setFromCommandLine(options, o.set);
  strengthStudy(sc, options, comm);
}

}  // namespace pdq::cli
