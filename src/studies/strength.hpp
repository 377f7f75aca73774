#pragma once
// Strength as the thesis defines it (§4.4): "the peak load at which static equilibrium
// can still be achieved", searched for any model that declares a StrengthSpec
// (engine/model.hpp): which global is the load, which the monitored displacement, which
// counts broken interactions, and how to name a failure. A trial runs the problem with its
// loads ramped to a peak and then held, with extra damping in the hold so that a structure
// that can stand comes to rest; equilibrium holds when, in the second half of the hold,
// hardly any more interactions break and the monitored displacement changes by at most
// `settle`. Bisection over the peak brackets the strength; with `atOnce` > 1 each round
// tries that many loads side by side on groups of ranks (the loads tried depend on atOnce
// only, never on the number of ranks, so results are the same on any number of ranks).
#include <functional>
#include <string>
#include <vector>

#include "engine/comm.hpp"
#include "engine/params.hpp"
#include "engine/particle_set.hpp"
#include "engine/simulation.hpp"

namespace pdq::strength {

struct Options {
  double settle = 0.02;  // allowed |u(end) − u(mid hold)| / |u(mid hold)|
  double runaway = 50;   // stop a trial once |u| exceeds this × |u| at the start of the hold
  double relTol = 0.02;  // bisection stops when (hi − lo) ≤ relTol · lo
  int maxTrials = 16;
  // Run the problem's simulated time with the model's stable time step instead of the
  // problem's own (the thesis's Δt is ~14 times smaller than needed for the beams).
  bool stableStep = false;
  // Critical-damping ratio of the fundamental mode added once the loads are held: a
  // structure that can stand comes to rest, one that cannot keeps moving and breaking.
  double holdDamping = 1;
  // The hold phase is this many times the problem's (its ramp unchanged), so that the
  // structure has time to settle.
  double holdLength = 3;
  // Interactions that may still break in the second half of the hold, as a fraction of
  // all broken ones (plus one): isolated late breaks do not make a structure fail.
  double lateBreaks = 0.05;
  // Trials simulate this multiple of the problem's time (ramp and hold alike): for a
  // structure whose fundamental period is not short against the problem's ramp.
  double timeScale = 1;
  int atOnce = 1;      // loads tried per round, side by side on groups of ranks
  std::string outDir;  // if set: each trial's history.csv and final restart in outDir/trial_NN
  std::function<void(const struct Trial&)> onTrial;  // called on every rank as trials end
  // Trials an earlier search finished (its journal): one asked for again, with the same
  // index and the same load to the bit, is taken from here rather than run.
  std::vector<struct Trial> done;
};

// What the trials run: the problem of a scenario with the model's parameters as text, so
// that every trial configures a model of its own with its own loading.
struct Case {
  std::string source;        // the scenario, named in messages
  std::string model;         // its name
  Params params{"[model]"};  // the scenario's [model], then [strength.model] overrides
  ParticleSet particles;
  RunConfig run;        // the scenario's run: its steps, its time step's duration
  double unitLoad = 1;  // the load, in the unit loads are given in, at load_scale = 1
};

struct Trial {
  int index = 0;  // 1, 2, ... in the order the search asked for them
  double load = 0;
  bool holds = false;
  double uHold = 0, uMid = 0, uEnd = 0;  // monitored displacement: hold start, mid, end
  double brokenMid = 0, brokenEnd = 0;   // broken interactions
  long steps = 0;                        // steps run (fewer when stopped as runaway)
  std::string mode;                      // the model's failure classifier, at the end
  std::string dir;                       // its outputs (Options::outDir)
  bool fromJournal = false;              // taken from Options::done, not run
};

struct Result {
  double lower = -1, upper = -1;  // holds at `lower`, fails at `upper` (-1: none found)
  std::string mode;               // judged at the lowest failing trial
  std::vector<Trial> trials;
};

// Bisection between a load that holds (lo) and one that fails (hi); the bracket is first
// widened (lo halved, hi doubled) until it is one. Each round tries opt.atOnce loads
// (evenly spaced inside the bracket). Loads are in the case's unit (load_scale × unitLoad).
Result findStrength(const Case& c, double lo, double hi, Comm& comm, const Options& opt = {});

// Strength in one run: the quasi-static solver (engine/relaxation.cpp) under force control
// raises the loads towards `hi` in load steps, cut back where they find no equilibrium, until
// even the smallest step finds none. The result brackets the peak between the last load in
// equilibrium (`lower`) and the smallest beyond it that found none (`upper`; -1 if even 16
// × `hi` was reached). A run that holds up to `hi` goes on towards twice as far (as the
// bisection widens its bracket); each load it held up to before going on is a trial, and
// its end another, its outputs (the curve and the state at the peak) in outDir/quasi_static.
struct StaticOptions {
  double tolerance = 1e-4;
  long loadSteps = 10, maxIterations = 50000, maxBroken = 0;
  int maxCutBacks = 5;
  double peakTolerance = 0.02;  // the bisection's relTol: the same bracket
  Solver::Masses masses = Solver::Masses::Assembled;
  std::string outDir;
};
Result staticStrength(const Case& c, double hi, Comm& comm, const StaticOptions& opt);

}  // namespace pdq::strength
