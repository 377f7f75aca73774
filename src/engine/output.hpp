#pragma once
// Outputs written during a run (restart files, time histories, visual output). Each is
// called on every rank at its steps and gathers what it needs through the engine.
#include <string>
#include <vector>

#include "engine/comm.hpp"
#include "engine/context.hpp"

namespace pdq {

class Model;

struct OutputContext {
  Context& ctx;
  Model& model;
  Comm& comm;
  const std::string& outDir;
  long step;
  double setupDt;  // Simulation::setupDt
  // The instability checks' state, saved in restart files with the integrator's (when an
  // output that captures the state is due).
  std::vector<double> checks = {};
};

class Output {
 public:
  explicit Output(long every) : every_(every) {}
  virtual ~Output() = default;
  // Due at multiples of `every` (0: never during the run) and, if finalToo(), at the end.
  virtual bool due(long step) const { return every_ > 0 && step % every_ == 0; }
  virtual bool atEnd() const { return false; }
  // True for outputs a run can restart from (the engine shuffles before writing them).
  virtual bool capturesState() const { return false; }
  // True for what a run stopped early (a signal, the wall-time limit) writes at the step it
  // stops: the state it is continued from (checkpoints), and nothing slower, so that it
  // stops promptly.
  virtual bool writtenOnStop() const { return false; }
  // True for an output also written on wall time (checkpoints every T minutes): then
  // requested() is asked once a step on every rank, and a yes from any rank (combined in
  // the step's one reduction) makes it due at that step on all of them.
  virtual bool timed() const { return false; }
  virtual bool requested() { return false; }
  // Called once on every rank before the first write, at the run's first step; `resumed`:
  // the run continues from a restart file, so files that grow during a run are continued
  // rather than started anew.
  virtual void begin(OutputContext&, bool /*resumed*/) {}
  virtual void write(OutputContext& out) = 0;
  // Called once after the last step (rename temporary files into place, etc.).
  virtual void finish(OutputContext&) {}
  long every() const { return every_; }

 private:
  long every_;
};

}  // namespace pdq
