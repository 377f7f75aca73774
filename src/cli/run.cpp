// pdq run: a scenario (or the thesis's .dat files) from step 0 or from a restart file.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include "cli/commands.hpp"
#include "cli/guard.hpp"
#include "cli/stop.hpp"
#include "cli/summary.hpp"
#include "engine/error.hpp"
#include "io/checkpoint.hpp"
#include "io/restart.hpp"
#include "io/standard_outputs.hpp"
#include "scenario/scenario.hpp"

namespace pdq::cli {

int runCommand(const RunOptions& o) {
  Comm comm;
  Scenario sc = loadScenario(o.input);
  Problem& pb = sc.problem;
  if (!o.out.empty()) pb.run.outDir = o.out;
  if (!o.resume.empty()) pb.run.outDir = o.resume;
  if (o.steps >= 0) pb.run.steps = o.steps;
  const std::uint64_t hash = scenarioHash(o.input, pb.particles);
  if (!o.restart.empty()) pb.restart = readRestart(o.restart, pb);
  if (!o.resume.empty()) {
    Resumed r = resumeFromCheckpoint(o.resume, hash, o.force, pb);
    if (comm.root()) {
      for (const auto& w : r.warnings) printError(w, "pdq: warning: ");
      if (o.verbosity != Verbosity::Quiet)
        std::printf("resuming from %s (step %ld)\n", r.path.c_str(), pb.run.firstStep);
    }
    pb.restart = std::move(r.state);
  }
  const double particles = static_cast<double>(pb.particles.size());
  const std::string modelName = pb.modelName;
  // Checkpoints as the scenario asks, and always one when a signal or the wall-time limit
  // stops the run.
  auto checkpoints = std::make_unique<CheckpointOutput>(pb.output, hash);
  const auto simulation = makeSimulation(std::move(pb), comm);
  Simulation& sim = *simulation;
  sim.addOutput(std::move(checkpoints));
  StopRequest stopRequest(o.maxWallTime);
  sim.setStopCheck([&] { return stopRequest.poll(); });
  sim.setup();
  if (comm.root())
    for (const auto& w : sim.context().warnings()) printError(w, "pdq: warning: ");
  const bool talk = comm.root() && o.verbosity != Verbosity::Quiet;
  const std::string about = summary(sim, modelName, o.input);
  if (talk && o.verbosity == Verbosity::Verbose) std::printf("%s", about.c_str());
  // Under mpirun the ranks' output may be a pseudo-terminal whatever mpirun's own output
  // is (OpenMPI does this), so a launched run always writes plain lines.
  const bool launched = std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE");
  const bool terminal = isatty(STDOUT_FILENO) != 0 && !launched;
  std::function<Progress::LoadStatus()> loadStatus;
  if (sim.config().solver.quasiStatic)
    loadStatus = [&sim] {
      const Simulation::LoadStep& s = sim.lastLoadStep();
      char text[200];
      std::snprintf(text, sizeof text,
                    "load factor %.6g  load %.4g  displacement %.4g  residual %.2g", s.factor,
                    s.load, s.displacement, s.relative);
      return Progress::LoadStatus{s.fraction, text};
    };
  Progress progress(talk, terminal, particles, sim.config().firstStep, sim.config().steps,
                    sim.context().dt(), loadStatus);
  while (sim.advance()) progress.update(sim.step());
  sim.finish();
  progress.finish(sim.step());
  if (sim.stopCode() > 0) {
    if (comm.root())
      printError("stopped at step " + std::to_string(sim.step()) + " by " +
                     StopRequest::describe(sim.stopCode()) + "; continue with: pdq run " + o.input +
                     " --resume " + sim.config().outDir,
                 "pdq: ");
    return Interrupted;
  }
  if (talk) {
    if (!sim.context().stopReason().empty())
      std::printf("stopped at step %ld: %s\n", sim.step(), sim.context().stopReason().c_str());
    std::printf("output in %s\n", sim.config().outDir.c_str());
    if (o.verbosity == Verbosity::Verbose) {
      std::FILE* f = std::fopen((sim.config().outDir + "/timing.out").c_str(), "r");
      if (f) {
        char buf[512];
        while (std::fgets(buf, sizeof buf, f)) std::fputs(buf, stdout);
        std::fclose(f);
      }
    }
  }
  return Ok;
}

}  // namespace pdq::cli
