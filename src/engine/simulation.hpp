#pragma once
// The driver: builds the decomposition and procCube, lets the model set up, and runs the
// time loop of thesis §3.3.2:
//     force -> integrate -> exchange (halo) or shuffle -> outputs
// with timers for every phase and a stop the model may request.
#include <array>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "engine/atomic_file.hpp"
#include "engine/bonds.hpp"
#include "engine/comm.hpp"
#include "engine/context.hpp"
#include "engine/decomposition.hpp"
#include "engine/integrator.hpp"
#include "engine/model.hpp"
#include "engine/output.hpp"
#include "engine/particle_set.hpp"
#include "engine/proccube.hpp"
#include "engine/timers.hpp"

namespace pdq {

struct RunConfig {
  std::array<int, 3> procs{0, 0, 0};  // processors per axis; 0 = automatic
  double minCellSize = 0;             // 0 = the model's own (Model::minCellSize)
  double margin = -1;                 // Δ around the particles' bounding box; <0 = horizon
  std::array<bool, 3> periodic{false, false, false};
  std::array<double, 3> boxLo{}, boxHi{};  // the box along periodic axes
  int dim = 0;                             // 0 = from the particles (flat in Z -> 2D)
  long steps = 0;                          // < 0: as long as the load protocol's ramp and hold
  long firstStep = 0;                      // a restarted run continues from here
  Loading loading;                         // the load protocol
  Solver solver;                           // dynamic, or quasi-static: a step is a load step
  std::string outDir = ".";
  std::string source = "input";  // file named in configuration errors
  int particlesLine = 0;         // its line that gives the particles (generator or files)
  // Check for instability (non-finite attributes or forces, a particle moving further
  // than the skin, motion growing without bound) every N steps (0: only the non-finite
  // values, at steps that save restart files).
  long checkEvery = 1;
};

// What a restart brings back beyond the particles' attributes: the bonds, keyed by (owner,
// partner) IDs, and what the engine and the model keep between steps.
struct RestartState {
  std::vector<Gid> owner, partner;
  std::vector<std::uint8_t> dead;
  std::vector<double> attrs;  // nBondAttr per bond
  bool hasState = false;      // false: a restart file without its state file
  double dt = 0;
  // The time step the model set up in the run that wrote it (Simulation::setupDt); with
  // `adoptDt` (a checkpoint of another scenario resumed by force) a run whose model sets up
  // another continues with its own.
  double setupDt = 0;
  bool adoptDt = false;
  std::vector<double> integrator, model;
  std::vector<double> checks;  // the instability checks' (Simulation::checkState), if saved
};

struct StepStats {
  std::uint64_t haloMessages = 0, haloBytes = 0, haloWallParticles = 0;
  std::uint64_t maxShuffleMessages = 0, shuffles = 0;
};

class Simulation {
 public:
  Simulation(std::unique_ptr<Model> model, ParticleSet particles, RunConfig config, Comm& comm);
  ~Simulation();

  void addOutput(std::unique_ptr<Output> out);
  void restore(RestartState state) { restart_ = std::move(state); }

  // Asked on every rank once a step: 0 to go on, or a positive code to stop early. The
  // largest code over the ranks stops every rank after the same step, with the state
  // written there by the outputs written on a stop (Output::writtenOnStop: checkpoints)
  // even where they are not due; stopCode() then holds it. The cli stops this way on signals and a
  // wall-time limit.
  void setStopCheck(std::function<int()> check) { stopCheck_ = std::move(check); }
  int stopCode() const { return stopCode_; }

  void setup();    // decomposition, distribution, model setup; called by run() if needed
  void run();      // all steps
  bool advance();  // one step; false when the run has ended (steps done or stop requested)
  void finish();   // final outputs and timing.out

  Model& model() { return *model_; }
  Context& context() { return *ctx_; }
  Particles& particles() { return particles_; }
  Bonds& bonds() { return bonds_; }
  const Decomposition& decomposition() const { return *dec_; }
  ProcCube& procCube() { return *cube_; }
  Comm& comm() { return comm_; }
  Timers& timers() { return timers_; }
  const StepStats& stats() const { return stats_; }
  const RunConfig& config() const { return cfg_; }
  long step() const { return step_; }
  // The time step the model chose in Model::setup (from the scenario; 0 when it derives
  // one later, from the lattice): what a checkpoint records beside the state's own.
  double setupDt() const { return setupDt_; }
  std::string debugText() const { return debug_.str(); }

  // Quasi-static: the last converged load step (the fraction of load_scale reached, the
  // load factor, the curve's load and displacement, the relative residual, the iterations
  // and the broken interactions; when the run ended for want of equilibrium, `beyond`).
  struct LoadStep {
    double fraction = 0, factor = 0, load = 0, displacement = 0, relative = 0;
    long iterations = 0, broken = 0;
    double beyond = 0;  // the smallest load factor tried beyond it that found no equilibrium
  };
  const LoadStep& lastLoadStep() const { return last_; }
  // Quasi-static: when the load path reaches load_scale with every load step in
  // equilibrium, `more` is asked (on every rank, collectively) whether to go on; if it says
  // so the run goes on towards twice the load, its increments doubled with it, instead of
  // ending.
  void setRaise(std::function<bool()> more) { raise_ = std::move(more); }
  // Quasi-static: `seen` is called (on every rank, collectively) with the state of each load
  // step that found no equilibrium in place — the tries beyond the peak among them — before
  // the last equilibrium is put back; the ghosts are up to date.
  void setAbandoned(std::function<void()> seen) { abandoned_ = std::move(seen); }

 private:
  Domain makeDomain() const;
  void writeOutputs(bool last, bool stopped = false);
  double firstUnstable() const;  // -(smallest unstable particle's ID) on this rank, or -inf
  // From what the integrator saw of the step: the largest move of an owned particle
  // (localMove_), which particle made it (movedMost_), and whether the particle followed
  // from the step before went back, further (bounced_).
  void takeMoves(const Integrator::Watch& w);
  // The checks' state (the same on every rank; collective), as restart files save it, and
  // back from them.
  std::vector<double> checkState();
  void restoreChecks(const std::vector<double>& saved);
  // The checks of motion (every rank alike, `move` and `bounced` those of all ranks).
  void checkMotion(double move, bool bounced);
  [[noreturn]] void reportInstability(Gid id, const std::string& what);
  void writeLogs();  // debug.txt (appended) and timing.out (rewritten); collective
  bool relaxLoadStep();
  void stopBelow(double previous, double beyond, const std::string& what);
  bool endStep(bool interrupted);
  double staticFactor(double progress) const;
  long brokenInteractions();  // collective

  std::unique_ptr<Model> model_;
  ParticleSet initial_;
  RunConfig cfg_;
  Comm& comm_;
  Particles particles_;
  Bonds bonds_;
  std::unique_ptr<Decomposition> dec_;
  std::unique_ptr<ProcCube> cube_;
  std::ostringstream debug_;
  std::size_t debugWritten_ = 0;  // characters of debug_ already in debug.txt
  AppendFile debugFile_;          // rank 0
  std::string timingBefore_;      // timing.out of the runs this one continues
  std::unique_ptr<Context> ctx_;
  std::vector<std::unique_ptr<Output>> outputs_;
  std::optional<RestartState> restart_;
  Timers timers_;
  std::unique_ptr<Integrator> integrator_;
  StepStats stats_;
  long step_ = 0;
  double slack_ = 0, setupDt_ = 0;
  bool timedOutputs_ = false, requestedNow_ = false;
  std::vector<int> forceColumns_;  // the motion's force and moment columns (integ)
  long checkedStep_ = 0;           // the step of the last check of motion
  static constexpr std::size_t kNone = Integrator::kNoParticle;
  std::size_t movedMost_ = kNone;  // the owned particle that moved most in the checked step
  std::array<double, 3> mostStep_{};
  double localMove_ = 0, localMost_ = 0;  // its move per step, and its square
  bool bounced_ = false;
  std::size_t tracked_ = kNone;  // the fastest particle of the last check, if owned here
  std::array<double, 3> trackedStep_{};
  double trackedMove_ = 0;  // the square of its move then
  double lastMove_ = 0;     // the last check's largest move per step (all ranks)
  double growthFrom_ = 0;   // that move before the present run of growing checks
  int growing_ = 0;         // checks in a row at which the fastest particle bounced
  static constexpr double kGrowth = 1.5;
  static constexpr int kGrowthSteps = 3;
  std::function<int()> stopCheck_;
  std::function<bool()> raise_;
  std::function<void()> abandoned_;
  int stopCode_ = 0;
  bool setUp_ = false, ended_ = false, resumed_ = false;
  std::string loadSteps_;  // quasi_static.csv so far (rank 0)
  int brokenGlobal_ = -1;  // the model's global counting broken interactions, or -1: dead bonds
  LoadStep last_;
};

}  // namespace pdq
