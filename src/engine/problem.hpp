#pragma once
// A problem ready to run: which model with which parameters, every particle, the engine's
// run configuration and the outputs wanted. Both input forms produce one: the thesis's
// .dat files (io/thesis_input.hpp) and TOML scenario files (scenario/scenario.hpp); code
// that builds its particles itself (tests, studies) calls makeProblem. makeSimulation
// (io/standard_outputs.hpp) turns any of them into a running Simulation.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/model.hpp"
#include "engine/params.hpp"
#include "engine/particle_set.hpp"
#include "engine/simulation.hpp"

namespace pdq {

struct OutputSettings {
  long restartEvery = 0;     // ParticleAlterAttrs.<step>.rst (+ Bonds.<step>.rst)
  bool finalRestart = true;  // also at the last step
  long historyEvery = 0;     // timehist.dat rows for historyIds
  std::vector<Gid> historyIds{};
  long globalsEvery = 0;  // history.csv: the model's global values
  // `pdq run`'s checkpoints (io/checkpoint.hpp): every N steps and/or T minutes of wall
  // time (0: neither; a signal or --max-wall-time writes one anyway), the newest K kept.
  long checkpointEvery = 0;
  double checkpointMinutes = 0;
  long checkpointsKept = 2;
  std::unique_ptr<Params> paraview{};  // [output.paraview] table, if any (io/vtu_output.hpp)
  std::unique_ptr<Params> picture{};   // [output.picture] table, if any (post/picture_output.hpp)
};

struct Problem {
  std::string source;  // the scenario or input file, for messages
  std::string modelName;
  std::unique_ptr<Model> model;  // created and configured
  ParticleSet particles;
  RunConfig run;
  OutputSettings output;
  std::optional<RestartState> restart;  // from a restart file: restored at set-up
};

// Model `modelName` created and configured with `params` (every one of which it must read),
// on `particles`, with no outputs unless asked for. Empty `particles` get the model's
// attribute widths, for the caller to fill.
Problem makeProblem(const std::string& modelName, const Params& params, ParticleSet particles,
                    RunConfig run = {});

}  // namespace pdq
