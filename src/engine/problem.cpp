#include "engine/problem.hpp"

namespace pdq {

Problem makeProblem(const std::string& modelName, const Params& params, ParticleSet particles,
                    RunConfig run) {
  Problem pb;
  pb.source = run.source;
  pb.modelName = modelName;
  pb.model = ModelRegistry::create(modelName, params);
  pb.particles = std::move(particles);
  if (pb.particles.size() == 0) {
    const Schema schema = pb.model->schema();
    pb.particles.nFixed = schema.nFixed();
    pb.particles.nAlter = schema.nAlter();
  }
  pb.run = std::move(run);
  pb.output.finalRestart = false;
  return pb;
}

}  // namespace pdq
