#include "studies/strength_study.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>

#include "engine/atomic_file.hpp"
#include "engine/error.hpp"
#include "engine/model.hpp"
#include "io/checkpoint.hpp"
#include "studies/reference.hpp"
#include "studies/strength_journal.hpp"

namespace pdq {

strength::Case strengthCase(const Scenario& sc) {
  const Problem& pb = sc.problem;
  strength::Case c;
  c.source = pb.source;
  c.model = pb.modelName;
  c.params = sc.modelParams;
  for (const auto& k : sc.strengthModel.keys()) {
    const auto v = sc.strengthModel.raw(k);
    c.params.set(k, v->text, v->file, v->line);
  }
  auto model = ModelRegistry::create(c.model, c.params, c.source);
  if (model->strengthSpec().load.empty())
    throw InputError(pb.source, 0,
                     "model " + c.model +
                         " declares no strength spec, so pdq strength cannot judge its trials "
                         "(engine/model.hpp, StrengthSpec)");
  c.particles = pb.particles;
  c.run = pb.run;
  c.unitLoad = referenceFor(sc, c.params).unitLoad;
  return c;
}

namespace {

namespace fs = std::filesystem;
using strength::Trial;

strength::Options readOptions(const Params& o, const std::string& outDir) {
  strength::Options opt;
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

std::string trialHeader(const Reference& ref) {
  return fmt::format("  {:>5}  {:>12}  {:<6}  {:>14}  {:>7}  {}\n", "trial",
                     "load (" + ref.unit + ")", "result", "end |u| (mm)", "broken", "damage");
}

std::string trialLine(const Trial& t) {
  return fmt::format("  {:>5}  {:>12.6g}  {:<6}  {:>14.4g}  {:>7}  {}\n", t.index, t.load,
                     t.holds ? "holds" : "fails", 1e3 * t.uEnd, t.brokenEnd, t.mode);
}

}  // namespace

void strengthStudy(const Scenario& sc, const Params& o, Comm& comm, bool resume, bool force) {
  const Problem& pb = sc.problem;
  const strength::Case c = strengthCase(sc);
  const Reference ref = referenceFor(sc, c.params);
  const std::string dir = pb.run.outDir + "/strength";
  strength::Options opt = readOptions(o, dir);
  const bool known = ref.value > 0;
  const auto need = [&](const char* key, double fallback) {
    if (!o.has(key) && !known)
      throw InputError(pb.source, 0,
                       std::string("give the search's starting bracket: [strength] ") + key +
                           " (or --set " + key + "=...), in " + ref.unit);
    return o.number(key, fallback, 1e-300, 1e300);
  };
  const double lo = need("lo", 0.5 * ref.value), hi = need("hi", 1.5 * ref.value);
  const double reference = o.number("reference", 0.0);
  if (!(hi > lo))
    throw InputError(pb.source, o.raw("hi") ? o.raw("hi")->line : 0, "hi must exceed lo");
  // The method: the dynamic bisection, or one quasi-static run towards hi.
  const bool oneRun =
      o.choice("method", "bisection", {"bisection", "quasi_static"}) == "quasi_static";
  strength::StaticOptions so;
  so.tolerance = o.number("qs_tolerance", so.tolerance, 1e-300, 1);
  so.loadSteps = static_cast<long>(o.number("qs_load_steps", so.loadSteps, 1, 1e9));
  so.maxIterations = static_cast<long>(o.number("qs_max_iterations", so.maxIterations, 1, 1e12));
  so.maxBroken = static_cast<long>(o.number("qs_max_broken", so.maxBroken, 0, 1e12));
  so.maxCutBacks = static_cast<int>(o.number("qs_max_cut_backs", so.maxCutBacks, 0, 50));
  so.peakTolerance = opt.relTol;  // the bracket the bisection stops at
  // The assembled stiffness where it applies (supported 2D members): fewer iterations.
  so.masses = readMasses(o, "qs_masses", "assembled");
  so.outDir = dir;
  o.checkAllUsed();  // before hours of trials
  const std::uint64_t search = strength::searchHash(scenarioHash(pb.source, pb.particles), o);
  const std::string journal = strength::journalPath(dir);
  if (resume) opt.done = strength::readJournal(journal, search, force);
  std::vector<Trial> finished;
  if (comm.root()) {
    createFolder(dir);
    if (!resume) strength::writeJournal(journal, search, finished);
    std::printf("%s", fmt::format("pdq strength: {}, {} particles, {} steps{}; {} load{} per "
                                  "round\n",
                                  pb.source, c.particles.size(), c.run.steps,
                                  opt.timeScale != 1 ? fmt::format(" x {}", opt.timeScale) : "",
                                  opt.atOnce, opt.atOnce > 1 ? "s" : "")
                          .c_str());
    std::printf("%s", trialHeader(ref).c_str());
    std::fflush(stdout);
  }
  opt.onTrial = [&](const Trial& t) {
    if (!comm.root()) return;
    finished.push_back(t);
    strength::writeJournal(journal, search, finished);
    std::string line = trialLine(t);
    if (t.fromJournal) line.insert(line.size() - 1, "  (done before: from journal.txt)");
    std::printf("%s", line.c_str());
    std::fflush(stdout);
  };
  if (oneRun && comm.root())
    std::printf(
        "quasi-static: one run towards %.6g %s in %ld load steps (going on towards twice "
        "as far while it holds)\n",
        hi, ref.unit.c_str(), so.loadSteps);
  const strength::Result st = oneRun ? strength::staticStrength(c, hi, comm, so)
                                     : strength::findStrength(c, lo, hi, comm, opt);
  if (oneRun)
    for (const Trial& t : st.trials) opt.onTrial(t);
  if (!comm.root()) return;

  std::string report;  // the result; strength.txt has the trials above it
  if (st.lower >= 0 && st.upper >= 0) {
    report +=
        fmt::format("strength: {:.4g} to {:.4g} {} (holds at the first, fails at the second)\n",
                    st.lower, st.upper, ref.unit);
    report += "failure mode: " + st.mode + "\n";
    for (const Trial& t : st.trials)
      if (t.load == st.upper)
        report += fmt::format(
            "failing trial: {} (draw it: pdq post picture {} --restart "
            "{}/ParticleAlterAttrs.{}.rst)\n",
            t.dir, pb.source, t.dir, t.steps);
  } else if (st.upper < 0 && oneRun) {
    report +=
        fmt::format("in equilibrium up to {:.4g} {} (16 times hi): raise hi\n", st.lower, ref.unit);
  } else if (st.upper < 0) {
    report += fmt::format("no failure found up to {:.4g} {}: raise hi or max_trials\n",
                          st.trials.empty() ? hi : st.trials.back().load, ref.unit);
  } else {
    report +=
        fmt::format("fails at every load tried, down to {:.4g} {}: lower lo\n", st.upper, ref.unit);
  }
  if (known)
    report += fmt::format("{}: {:.4g} {} ({})\n", ref.label, ref.value, ref.unit, ref.mode);
  if (reference > 0) {
    report += fmt::format("reference: {:.4g} {}", reference, ref.unit);
    if (st.lower >= 0 && st.upper >= 0)
      report += fmt::format(" (pdq / reference = {:.3f})", 0.5 * (st.lower + st.upper) / reference);
    report += "\n";
  }
  report += "outputs: " + dir + "/ (strength.txt, trials.csv, trial_NN/)\n";
  std::string trials = fmt::format("# pdq strength: {} (model {})\n", pb.source, c.model);
  trials += trialHeader(ref);
  for (const Trial& t : st.trials) trials += trialLine(t);
  std::string csv = "trial,load,holds,u_hold,u_mid,u_end,broken_mid,broken_end,steps,mode\n";
  for (const Trial& t : st.trials)
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", t.index, t.load, t.holds ? 1 : 0, t.uHold,
                       t.uMid, t.uEnd, t.brokenMid, t.brokenEnd, t.steps, t.mode);
  writeFileAtomically(dir + "/trials.csv", csv);
  writeFileAtomically(dir + "/strength.txt", trials + report);
  std::printf("%s", report.c_str());
}

}  // namespace pdq
