// pdq strength: the failure-load search of a scenario (studies/strength_study.hpp).
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "studies/strength_study.hpp"

namespace pdq::cli {

void strengthCommand(const StrengthCommandOptions& o) {
  Comm comm;
  Scenario sc = loadScenario(o.input);
  if (!o.resume.empty()) sc.problem.run.outDir = o.resume;
  Params options = sc.strength;  // the scenario's [strength] table, then --set items
  setFromCommandLine(options, o.set);
  strengthStudy(sc, options, comm, !o.resume.empty(), o.force);
}

}  // namespace pdq::cli
