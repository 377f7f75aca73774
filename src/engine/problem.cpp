#include "engine/problem.hpp"

namespace pdq {

Problem makeProblem(const std::string& modelName, const Params& params, ParticleSet particles,
                    RunConfig run) {
  Problem pb;
  pb.source = run.source;
  pb.modelName = modelName;
  pb.model = ModelRegistry::create(modelName, params);
  pb.particles = std::move(particles);
  pb.run = std::move(run);
  pb.output.finalRestart = false;
  return pb;
}

}  // namespace pdq
