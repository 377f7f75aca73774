#include "models/mplm/strength.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "engine/model.hpp"
#include "engine/simulation.hpp"
#include "models/mplm/attributes.hpp"

namespace pdq::mplm {
namespace {

double globalValue(const std::vector<std::string>& names, const std::vector<double>& values,
                   const std::string& name) {
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return values[k];
  return 0;
}

// Where the badly damaged (ω ≥ ½) concrete interactions are: mostly compressive → "compression";
// plates otherwise → "tension"; beams → "flexural" when most lie in the middle third of the span,
// else "shear".
std::string failureMode(const Example& ex, Context& ctx) {
  const Particles& P = ctx.particles;
  const Bonds& B = ctx.bonds;
  double tensile = 0, compressive = 0, middle = 0, total = 0;
  ExactSum t, c, m, all;
  for (std::size_t i = 0; i < P.owned(); ++i) {
    if (isSteel(P.fixed(i))) continue;
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      const double* st = B.attr(b);
      if (std::max(st[OMEGA_T], st[OMEGA_C]) < 0.5) continue;
      (st[OMEGA_C] >= st[OMEGA_T] ? c : t).add(1);
      all.add(1);
      if (std::fabs(P.fixed(i)[FX_X] - ex.span / 2) < ex.span / 6) m.add(1);
    }
  }
  tensile = ctx.sum(t);
  compressive = ctx.sum(c);
  middle = ctx.sum(m);
  total = ctx.sum(all);
  if (total == 0) return "none";
  if (compressive > tensile) return "compression";
  if (!ex.beam) return "tension";
  return middle > total / 2 ? "flexural" : "shear";
}

}  // namespace

namespace {

std::unique_ptr<Simulation> makeSimulation(const Example& ex, const Params& p, long steps,
                                           Comm& comm) {
  auto model = ModelRegistry::create("mplm2d");
  model->configure(p);
  p.checkAllUsed();
  RunConfig cfg;
  cfg.steps = steps;
  cfg.outDir = "strength_out";
  auto sim = std::make_unique<Simulation>(std::move(model), ex.particles, cfg, comm);
  sim->setup();
  return sim;
}

}  // namespace

Trial runTrial(const Example& ex, double load, Comm& comm, const StrengthOptions& opt) {
  Params p("strength trial");
  for (const auto& [k, v] : ex.params) p.set(k, v);
  for (const auto& [k, v] : opt.overrides) p.set(k, v);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", load);
  p.set("load_scale", buf);
  long steps = ex.steps;
  if (opt.stableStep) {
    const double duration = ex.steps * p.number("dt", 0.0);
    p.set("dt", "0");
    const double dt = makeSimulation(ex, p, 1, comm)->context().dt();
    if (duration > 0) steps = static_cast<long>(std::ceil(duration / dt));
  }
  std::snprintf(buf, sizeof buf, "%.17g", opt.holdDamping);
  p.set("hold_damping_ratio", buf);
  // The example's ramp, then its hold stretched by holdLength.
  const double exRamp = p.number("ramp_fraction", 0.75);
  const long rampSteps = static_cast<long>(std::ceil(exRamp * steps));
  steps = rampSteps + static_cast<long>(std::ceil(opt.holdLength * (steps - rampSteps)));
  const double rampFraction = static_cast<double>(rampSteps) / steps;
  std::snprintf(buf, sizeof buf, "%.17g", rampFraction);
  p.set("ramp_fraction", buf);
  auto simPtr = makeSimulation(ex, p, steps, comm);
  Simulation& sim = *simPtr;
  const auto names = sim.model().globals();
  const long holdStart = static_cast<long>(std::ceil(rampFraction * steps));
  const long mid = holdStart + (steps - holdStart) / 2;
  const long check = std::max(1L, steps / 100);
  Trial tr;
  tr.load = load;
  bool runaway = false;
  while (sim.advance()) {
    const long step = sim.step();
    if (step != holdStart && step != mid && step % check != 0) continue;
    const auto values = sim.model().globalValues(sim.context());
    const double u = std::hypot(globalValue(names, values, "ux"), globalValue(names, values, "uy"));
    if (!std::isfinite(u)) {
      runaway = true;
      break;
    }
    if (step == holdStart) tr.uHold = u;
    if (step == mid) {
      tr.uMid = u;
      tr.brokenMid = globalValue(names, values, "broken");
    }
    if (step >= holdStart && tr.uHold > 0 && u > opt.runaway * tr.uHold) {
      runaway = true;
      break;
    }
  }
  tr.steps = sim.step();
  const auto values = sim.model().globalValues(sim.context());
  tr.uEnd = std::hypot(globalValue(names, values, "ux"), globalValue(names, values, "uy"));
  tr.brokenEnd = globalValue(names, values, "broken");
  tr.holds = !runaway && std::isfinite(tr.uEnd) &&
             tr.brokenEnd - tr.brokenMid <= opt.lateBreaks * tr.brokenEnd + 1 &&
             std::fabs(tr.uEnd - tr.uMid) <= opt.settle * std::fabs(tr.uMid);
  tr.mode = failureMode(ex, sim.context());
  tr.log = sim.debugText();
  return tr;
}

Strength findStrength(const Example& ex, double lo, double hi, Comm& comm,
                      const StrengthOptions& opt) {
  Strength out;
  auto trial = [&](double load) {
    out.trials.push_back(runTrial(ex, load, comm, opt));
    return out.trials.back();
  };
  Trial failing;
  while (!trial(lo).holds && static_cast<int>(out.trials.size()) < opt.maxTrials) {
    failing = out.trials.back();
    hi = lo;
    lo /= 2;
  }
  if (failing.load == 0) {
    while (true) {
      const Trial t = trial(hi);
      if (!t.holds) {
        failing = t;
        break;
      }
      lo = hi;
      hi *= 2;
      if (static_cast<int>(out.trials.size()) >= opt.maxTrials) break;
    }
  }
  while (hi - lo > opt.relTol * lo && static_cast<int>(out.trials.size()) < opt.maxTrials) {
    const double midLoad = 0.5 * (lo + hi);
    const Trial t = trial(midLoad);
    if (t.holds) {
      lo = midLoad;
    } else {
      hi = midLoad;
      failing = t;
    }
  }
  out.lower = lo;
  out.upper = hi;
  out.mode = failing.mode;
  return out;
}

}  // namespace pdq::mplm
