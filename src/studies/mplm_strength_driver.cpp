// `pdq strength` for mplm2d: the scenario becomes an Example (its particles, model
// parameters and steps; an mplm_beam or mplm_plate generator also gives the load's unit,
// the span and the ACI 318 / classical value), the [strength] table and --set items the
// search's options. Prints each trial as it ends and the result, and writes
// <output>/strength/: strength.txt (the report), trials.csv, and trial_NN/ with each
// trial's load-displacement history and final restart files (for `pdq post picture`).
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "engine/atomic_file.hpp"
#include "engine/error.hpp"
#include "engine/model.hpp"
#include "prep/mplm/generators.hpp"
#include "studies/mplm_strength.hpp"
#include "studies/strength_registry.hpp"

namespace pdq::mplm {
namespace {

namespace fs = std::filesystem;

Example fromScenario(const Scenario& sc) {
  const Problem& pb = sc.problem;
  Example ex;
  if (sc.generator == "mplm_beam") {
    ex = beam(beamSpec(sc.generatorParams, sc.modelParams));
  } else if (sc.generator == "mplm_plate") {
    ex = plate(plateSpec(sc.generatorParams, sc.modelParams));
  } else {
    ex.unit = "x load_scale";  // loads as the particle files give them, times load_scale
  }
  ex.name = fs::path(pb.source).stem().string();
  ex.title = pb.source;
  ex.particles = pb.particles;
  ex.params.clear();
  for (const auto& k : sc.modelParams.keys()) ex.params[k] = sc.modelParams.raw(k)->text;
  ex.steps = pb.run.steps;
  // [strength.model] overrides, checked here so that a wrong key is named at its line.
  Params check = sc.modelParams;
  for (const auto& k : sc.strengthModel.keys()) {
    const auto v = sc.strengthModel.raw(k);
    ex.params[k] = v->text;
    check.set(k, v->text, v->file, v->line);
  }
  ModelRegistry::create("mplm2d")->configure(check);
  check.checkAllUsed();
  return ex;
}

StrengthOptions readOptions(const Params& o, const std::string& outDir) {
  StrengthOptions opt;
  opt.relTol = o.number("rel_tol", opt.relTol, 1e-6, 10);
  opt.maxTrials = static_cast<int>(o.number("max_trials", opt.maxTrials, 1, 1000));
  opt.atOnce = static_cast<int>(o.number("at_once", 2, 1, 64));
  opt.stableStep = o.flag("stable_step", opt.stableStep);
  opt.timeScale = o.number("time_scale", opt.timeScale, 1e-6, 1e6);
  opt.holdLength = o.number("hold_length", opt.holdLength, 0.01, 1e6);
  opt.holdDamping = o.number("hold_damping", opt.holdDamping, 0, 100);
  opt.settle = o.number("settle", opt.settle, 0, 100);
  opt.lateBreaks = o.number("late_breaks", opt.lateBreaks, 0, 1);
  opt.runaway = o.number("runaway", opt.runaway, 1, 1e12);
  opt.outDir = outDir;
  return opt;
}

std::string trialHeader(const Example& ex) {
  return fmt::format("  {:>5}  {:>12}  {:<6}  {:>14}  {:>7}  {}\n", "trial",
                     "load (" + ex.unit + ")", "result", "end |u| (mm)", "broken", "damage");
}

std::string trialLine(const Trial& t, const Example& ex) {
  return fmt::format("  {:>5}  {:>12.6g}  {:<6}  {:>14.4g}  {:>7}  {}\n", t.index, t.load,
                     t.holds ? "holds" : "fails", 1e3 * t.uEnd, t.brokenEnd,
                     t.mode + (ex.beam || t.mode == "none" ? "" : " damage"));
}

void mplmStrength(Scenario& sc, const Params& o, Comm& comm) {
  const Problem& pb = sc.problem;
  const Example ex = fromScenario(sc);
  const std::string dir = pb.run.outDir + "/strength";
  StrengthOptions opt = readOptions(o, dir);
  const bool known = ex.aci > 0;
  const auto need = [&](const char* key, double fallback) {
    if (!o.has(key) && !known)
      throw InputError(pb.source, 0,
                       std::string("give the search's starting bracket: [strength] ") + key +
                           " (or --set " + key + "=...), in units of load_scale");
    return o.number(key, fallback, 1e-300, 1e300);
  };
  const double lo = need("lo", 0.5 * ex.aci), hi = need("hi", 1.5 * ex.aci);
  const double reference = o.number("reference", 0.0);
  if (!(hi > lo))
    throw InputError(pb.source, o.raw("hi") ? o.raw("hi")->line : 0, "hi must exceed lo");
  o.checkAllUsed();  // before hours of trials
  if (comm.root()) {
    fs::create_directories(dir);
    std::printf("%s", fmt::format("pdq strength: {}, {} particles, {} steps{}; {} load{} per "
                                  "round\n",
                                  pb.source, ex.particles.size(), ex.steps,
                                  opt.timeScale != 1 ? fmt::format(" x {}", opt.timeScale) : "",
                                  opt.atOnce, opt.atOnce > 1 ? "s" : "")
                          .c_str());
    std::printf("%s", trialHeader(ex).c_str());
    std::fflush(stdout);
  }
  opt.onTrial = [&](const Trial& t) {
    if (!comm.root()) return;
    std::printf("%s", trialLine(t, ex).c_str());
    std::fflush(stdout);
  };
  const Strength st = findStrength(ex, lo, hi, comm, opt);
  if (!comm.root()) return;

  std::string report;  // the result; strength.txt has the trials above it
  if (st.lower >= 0 && st.upper >= 0) {
    report +=
        fmt::format("strength: {:.4g} to {:.4g} {} (holds at the first, fails at the second)\n",
                    st.lower, st.upper, ex.unit);
    report += "failure mode: " + st.mode + "\n";
    for (const Trial& t : st.trials)
      if (t.load == st.upper)
        report += fmt::format(
            "failing trial: {} (draw it: pdq post picture {} --restart "
            "{}/ParticleAlterAttrs.{}.rst)\n",
            t.dir, pb.source, t.dir, t.steps);
  } else if (st.upper < 0) {
    report += fmt::format("no failure found up to {:.4g} {}: raise hi or max_trials\n",
                          st.trials.empty() ? hi : st.trials.back().load, ex.unit);
  } else {
    report +=
        fmt::format("fails at every load tried, down to {:.4g} {}: lower lo\n", st.upper, ex.unit);
  }
  if (known)
    report += fmt::format("{}: {:.4g} {} ({})\n", ex.beam ? "ACI 318" : "classical", ex.aci,
                          ex.unit, ex.aciMode);
  if (reference > 0) {
    report += fmt::format("reference: {:.4g} {}", reference, ex.unit);
    if (st.lower >= 0 && st.upper >= 0)
      report += fmt::format(" (pdq / reference = {:.3f})", 0.5 * (st.lower + st.upper) / reference);
    report += "\n";
  }
  report += "outputs: " + dir + "/ (strength.txt, trials.csv, trial_NN/)\n";
  std::string trials = fmt::format("# pdq strength: {} (model mplm2d)\n", pb.source);
  trials += trialHeader(ex);
  for (const Trial& t : st.trials) trials += trialLine(t, ex);
  std::string csv = "trial,load,holds,u_hold,u_mid,u_end,broken_mid,broken_end,steps,mode\n";
  for (const Trial& t : st.trials)
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", t.index, t.load, t.holds ? 1 : 0, t.uHold,
                       t.uMid, t.uEnd, t.brokenMid, t.brokenEnd, t.steps, t.mode);
  writeFileAtomically(dir + "/trials.csv", csv);
  writeFileAtomically(dir + "/strength.txt", trials + report);
  std::printf("%s", report.c_str());
}

}  // namespace

PDQ_REGISTER_STRENGTH(mplmStrength, "mplm2d",
                      "peak load still reaching static equilibrium, by bisection (thesis §4.4)");

}  // namespace pdq::mplm
