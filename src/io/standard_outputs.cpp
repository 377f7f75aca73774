#include "io/standard_outputs.hpp"

#include "io/history_output.hpp"
#include "io/restart.hpp"
#include "io/vtu_output.hpp"
#include "post/picture_output.hpp"

namespace pdq {

std::unique_ptr<Simulation> makeSimulation(Problem pb, Comm& comm) {
  auto sim = std::make_unique<Simulation>(std::move(pb.model), std::move(pb.particles),
                                          std::move(pb.run), comm);
  if (pb.restart) sim->restore(std::move(*pb.restart));
  addStandardOutputs(*sim, pb.output);
  return sim;
}

void addStandardOutputs(Simulation& sim, const OutputSettings& o) {
  // Histories first: when a restart file exists, so do the rows of its step.
  if (o.historyEvery > 0 && !o.historyIds.empty())
    sim.addOutput(std::make_unique<TimeHistoryOutput>(o.historyEvery, o.historyIds));
  if (o.globalsEvery > 0 && !sim.model().globals().empty())
    sim.addOutput(std::make_unique<GlobalsOutput>(o.globalsEvery));
  if (o.restartEvery > 0 || o.finalRestart)
    sim.addOutput(std::make_unique<RestartOutput>(o.restartEvery, o.finalRestart));
  if (o.paraview) sim.addOutput(std::make_unique<VtuOutput>(vtuOptions(*o.paraview)));
  if (o.picture)
    sim.addOutput(std::make_unique<post::PictureOutput>(post::pictureOptions(*o.picture)));
}

}  // namespace pdq
