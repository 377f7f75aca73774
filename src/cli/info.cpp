// pdq info: what a scenario will do, from its setup, without stepping or writing files.
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/summary.hpp"
#include "io/standard_outputs.hpp"
#include "scenario/scenario.hpp"

namespace pdq::cli {

void infoCommand(const InfoOptions& o) {
  Comm comm;
  Scenario sc = loadScenario(o.input);
  Problem& pb = sc.problem;
  std::string sets;
  for (const auto& s : sc.setCounts)
    sets += "particles.set " + pb.source + ":" + std::to_string(s.line) + ": " + s.attribute +
            " on " + std::to_string(s.particles) + " particle" + (s.particles == 1 ? "" : "s") +
            "\n";
  const std::string modelName = pb.modelName, outDir = pb.run.outDir;
  pb.run.outDir.assign(1, '.');  // setup creates the output folder; info writes nothing
  pb.output = {.finalRestart = false};
  const auto sim = makeSimulation(std::move(pb), comm);
  sim->setup();
  const std::string text = summary(*sim, modelName, o.input, o.ranks);
  if (comm.root()) {
    std::printf("%s%s", text.c_str(), sets.c_str());
    std::printf("output        %s\n", outDir.c_str());
  }
}

}  // namespace pdq::cli
