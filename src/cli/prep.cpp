// pdq prep: the particle and input files a scenario generates, in the thesis's format, so
// `pdq run <folder>` (or any tool that reads the thesis's files) runs the same problem.
#include <cstdio>

#include "cli/commands.hpp"
#include "engine/comm.hpp"
#include "io/thesis_input.hpp"
#include "scenario/scenario.hpp"

namespace pdq::cli {

void prepCommand(const PrepOptions& o) {
  Comm comm;
  Scenario sc = readScenario(o.input);
  if (comm.root()) {
    writeThesisInput(o.out, sc.problem, sc.modelParams);
    std::printf(
        "wrote %s/{pdQInput.dat, pdQUserInput.dat, ParticleFixedAttrs.dat, "
        "ParticleAlterAttrs.dat}: %zu particles of model %s\n",
        o.out.c_str(), sc.problem.particles.size(), sc.problem.modelName.c_str());
  }
  comm.barrier();
}

}  // namespace pdq::cli
