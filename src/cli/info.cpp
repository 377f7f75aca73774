// pdq info: what a scenario will do, from its setup, without stepping or writing files.
#include <cstdio>
#include <filesystem>

#include "cli/commands.hpp"
#include "cli/summary.hpp"
#include "io/standard_outputs.hpp"
#include "scenario/scenario.hpp"
#include "studies/reference.hpp"

namespace pdq::cli {

void infoCommand(const InfoOptions& o) {
  Comm comm;
  // The sizes first, from the scenario alone; a problem too large for the memory available
  // is reported and not made. One that fits is made, and the estimate printed after what
  // was made.
  std::string estimate;
  if (!std::filesystem::is_directory(o.input)) {
    const Scenario est = readScenario(o.input, true);
    if (est.estimate) {
      bool fits = true;
      estimate = estimateSummary(*est.estimate, *est.problem.model, fits);
      if (!fits) {
        if (comm.root())
          std::printf(
              "input         %s\n%snot made      it would not fit in the memory available: "
              "make the lattice coarser or the specimen smaller, or run on more nodes\n",
              o.input.c_str(), estimate.c_str());
        return;
      }
    }
  }
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
  // The textbook strength the specimen's generator knows, beside the scenario's own
  // reference (the examples give the thesis's strength there), as pdq strength reports them.
  const Reference ref = referenceFor(sc, sc.modelParams);
  const auto given = sc.strength.raw("reference");
  if (comm.root()) {
    std::printf("%s%s", text.c_str(), sets.c_str());
    if (ref.value > 0)
      std::printf("reference     %s: %.4g %s (%s)\n", ref.label.c_str(), ref.value,
                  ref.unit.c_str(), ref.mode.c_str());
    if (given)
      std::printf("reference     [strength] reference: %s %s\n", given->text.c_str(),
                  ref.unit.c_str());
    std::printf("output        %s\n%s", outDir.c_str(), estimate.c_str());
  }
}

}  // namespace pdq::cli
