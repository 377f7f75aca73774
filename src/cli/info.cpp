// pdq info: what a scenario will do, from its setup, without stepping or writing files.
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/summary.hpp"
#include "scenario/scenario.hpp"

namespace pdq::cli {

void infoCommand(const InfoOptions& o) {
  Comm comm(MPI_COMM_WORLD);
  Scenario sc = loadScenario(o.input);
  Problem& pb = sc.problem;
  const std::string modelName = pb.modelName;
  RunConfig cfg = pb.run;
  cfg.outDir.assign(1, '.');  // setup creates the output folder; info writes nothing
  Simulation sim(std::move(pb.model), std::move(pb.particles), cfg, comm);
  sim.setup();
  const std::string text = summary(sim, modelName, o.input, o.ranks);
  if (comm.root()) {
    std::printf("%s", text.c_str());
    std::printf("output        %s\n", pb.run.outDir.c_str());
  }
}

}  // namespace pdq::cli
